#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <thinlayer/discretisation/body_loads.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace thinlayer
{
  namespace
  {
    /// The vertical component.
    constexpr unsigned int vertical = 1;

    /// Mode @p m's share of a vertical force that is the same at every
    /// angle: int T(n theta) dtheta over the circle (1 in plane strain and
    /// 3D). The trapezoidal rule is exact for the trigonometric
    /// polynomials of the harmonics.
    double
    axisymmetric_share(const Kinematics &kinematics, const unsigned int m)
    {
      if (!kinematics.is_fourier())
        return 1;
      constexpr unsigned int n     = 64;
      double                 share = 0;
      for (unsigned int j = 0; j < n; ++j)
        share += kinematics.T_at(vertical, m, 2 * numbers::PI * j / n) * 2 *
                 numbers::PI / n;
      return share;
    }


    /// Whether face @p f of @p cell is on the boundary facing straight up
    /// at @p level (to a millionth of the cell's size).
    template <int dim>
    bool
    on_ground(const typename Triangulation<dim>::cell_iterator &cell,
              const unsigned int                                f,
              const double                                      level)
    {
      return cell->face(f)->at_boundary() &&
             outward_normal<dim>(cell, f)[vertical] > 1 - 1e-9 &&
             std::abs(cell->face(f)->center()[vertical] - level) <=
               1e-6 * cell->diameter();
    }
  } // namespace


  template <int dim>
  Tensor<1, dim>
  outward_normal(const typename Triangulation<dim>::cell_iterator &cell,
                 const unsigned int                                f)
  {
    const auto     face = cell->face(f);
    Tensor<1, dim> n;
    if constexpr (dim == 2)
      {
        const Tensor<1, 2> t = face->vertex(1) - face->vertex(0);
        n                    = Tensor<1, 2>({t[1], -t[0]});
      }
    else
      n = cross_product_3d(face->vertex(1) - face->vertex(0),
                           face->vertex(2) - face->vertex(0));
    n /= n.norm();
    if (n * (face->center() - cell->center()) < 0)
      n *= -1;
    return n;
  }


  template <int dim>
  void
  add_weight(const Mapping<dim>                         &mapping,
             const DoFHandler<dim>                      &dof_handler,
             const Kinematics                           &kinematics,
             const std::map<types::material_id, double> &unit_weights,
             const unsigned int                          m,
             ModeVector                                 &load)
  {
    const double share = axisymmetric_share(kinematics, m);
    if (std::abs(share) < 1e-12)
      return;

    const FiniteElement<dim>            &fe = dof_handler.get_fe();
    const QGauss<dim>                    quadrature(fe.degree + 1);
    FEValues<dim>                        fe_values(mapping,
                            fe,
                            quadrature,
                            update_values | update_quadrature_points |
                              update_JxW_values);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
        const auto weight = unit_weights.find(cell->material_id());
        if (weight == unit_weights.end() || weight->second == 0)
          continue;
        fe_values.reinit(cell);
        cell->get_dof_indices(dofs);
        for (const unsigned int i : fe_values.dof_indices())
          {
            if (fe.system_to_component_index(i).first != vertical)
              continue;
            double force = 0;
            for (const unsigned int q : fe_values.quadrature_point_indices())
              force += fe_values.shape_value(i, q) *
                       kinematics.area_factor(fe_values.quadrature_point(q)) *
                       fe_values.JxW(q);
            load(dofs[i]) -= weight->second * share * force;
          }
      }
    load.compress(VectorOperation::add);
  }


  template <int dim>
  double
  ground_level(const Triangulation<dim> &mesh)
  {
    double level = -std::numeric_limits<double>::infinity();
    for (const auto &cell : mesh.active_cell_iterators())
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary() &&
            outward_normal<dim>(cell, f)[vertical] > 1e-9)
          for (const unsigned int v : cell->face(f)->vertex_indices())
            level = std::max(level, cell->face(f)->vertex(v)[vertical]);
    return level;
  }


  template <int dim>
  void
  add_ground_pressure(const Mapping<dim>                 &mapping,
                      const DoFHandler<dim>              &dof_handler,
                      const Kinematics                   &kinematics,
                      const double                        level,
                      const double                        pressure,
                      const std::set<types::boundary_id> &held,
                      const unsigned int                  m,
                      ModeVector                         &load)
  {
    const double share = axisymmetric_share(kinematics, m);
    if (std::abs(share) < 1e-12 || pressure == 0)
      return;
    const FiniteElement<dim>            &fe = dof_handler.get_fe();
    const QGauss<dim - 1>                quadrature(fe.degree + 2);
    FEFaceValues<dim>                    fe_face(mapping,
                              fe,
                              quadrature,
                              update_values | update_quadrature_points |
                                update_JxW_values);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const auto f : cell->face_indices())
        {
          if (!cell->is_locally_owned() || !on_ground<dim>(cell, f, level) ||
              held.count(cell->face(f)->boundary_id()) > 0)
            continue;
          fe_face.reinit(cell, f);
          cell->get_dof_indices(dofs);
          for (const unsigned int i : fe_face.dof_indices())
            {
              if (fe.system_to_component_index(i).first != vertical)
                continue;
              double force = 0;
              for (const unsigned int q : fe_face.quadrature_point_indices())
                force += fe_face.shape_value(i, q) *
                         kinematics.area_factor(fe_face.quadrature_point(q)) *
                         fe_face.JxW(q);
              load(dofs[i]) -= pressure * share * force;
            }
        }
    load.compress(VectorOperation::add);
  }


#define THINLAYER_INSTANTIATE(dim)                                          \
  template Tensor<1, dim> outward_normal<dim>(                              \
    const Triangulation<dim>::cell_iterator &, const unsigned int);         \
  template double ground_level(const Triangulation<dim> &);                 \
  template void   add_ground_pressure(const Mapping<dim> &,                 \
                                      const DoFHandler<dim> &,              \
                                      const Kinematics &,                   \
                                      const double,                         \
                                      const double,                         \
                                      const std::set<types::boundary_id> &, \
                                      const unsigned int,                   \
                                      ModeVector &);                        \
  template void   add_weight(const Mapping<dim> &,                          \
                             const DoFHandler<dim> &,                       \
                             const Kinematics &,                            \
                             const std::map<types::material_id, double> &,  \
                             const unsigned int,                            \
                             ModeVector &);
  THINLAYER_INSTANTIATE(2)
  THINLAYER_INSTANTIATE(3)
#undef THINLAYER_INSTANTIATE
} // namespace thinlayer
