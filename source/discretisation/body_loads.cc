#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <thinlayer/discretisation/body_loads.h>

#include <vector>

namespace thinlayer
{
  template <int dim>
  void
  add_weight(const Mapping<dim>                         &mapping,
             const DoFHandler<dim>                      &dof_handler,
             const Kinematics                           &kinematics,
             const std::map<types::material_id, double> &unit_weights,
             const unsigned int                          m,
             ModeVector                                 &load)
  {
    // The vertical component, and the mode's share of a body force along
    // it that is the same at every angle: int T(n theta) dtheta over the
    // circle (1 in plane strain and 3D). The trapezoidal rule is exact for
    // the trigonometric polynomials of the harmonics.
    constexpr unsigned int vertical = 1;
    double                 share    = 1;
    if (kinematics.is_fourier())
      {
        constexpr unsigned int n = 64;
        share                    = 0;
        for (unsigned int j = 0; j < n; ++j)
          share += kinematics.T_at(vertical, m, 2 * numbers::PI * j / n) * 2 *
                   numbers::PI / n;
      }
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


  template void
  add_weight(const Mapping<2> &,
             const DoFHandler<2> &,
             const Kinematics &,
             const std::map<types::material_id, double> &,
             const unsigned int,
             ModeVector &);
  template void
  add_weight(const Mapping<3> &,
             const DoFHandler<3> &,
             const Kinematics &,
             const std::map<types::material_id, double> &,
             const unsigned int,
             ModeVector &);
} // namespace thinlayer
