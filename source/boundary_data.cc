#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/vector_tools.h>

#include <thinlayer/boundary_data.h>

namespace thinlayer
{
  namespace
  {
    /**
     * A vector-valued FunctionParser from ';'-separated expressions; a
     * single expression stands for every component.
     */
    template <int dim>
    std::unique_ptr<FunctionParser<dim>>
    make_function(const std::string                   &expressions,
                  const unsigned int                   n_components,
                  const std::map<std::string, double> &geometry_parameters)
    {
      auto parts = Utilities::split_string_list(expressions, ';');
      if (parts.size() == 1 && n_components > 1)
        parts.assign(n_components, parts[0]);
      auto constants  = geometry_parameters;
      constants["pi"] = numbers::PI;
      auto f          = std::make_unique<FunctionParser<dim>>(n_components);
      f->initialize((dim == 2) ? "x,y" : "x,y,z", parts, constants);
      return f;
    }

    bool
    is_zero(const std::string &expressions)
    {
      for (const auto &e : Utilities::split_string_list(expressions, ';'))
        if (e != "0")
          return false;
      return true;
    }
  } // namespace


  template <int dim>
  BoundaryData<dim>::BoundaryData(const Parameters &p)
  {
    for (const auto &[id, b] : p.boundaries)
      {
        Condition        &c = conditions[id];
        std::vector<bool> mask(b.constrained_components);
        mask.resize(dim, false);
        c.constrained = ComponentMask(mask);
        c.displacement =
          make_function<dim>(b.displacement, dim, p.geometry_parameters);
        c.traction = make_function<dim>(b.traction, dim, p.geometry_parameters);
        c.pressure = make_function<dim>(b.pressure, 1, p.geometry_parameters);
        c.loaded   = !(is_zero(b.traction) && is_zero(b.pressure));
      }
  }


  template <int dim>
  void
  BoundaryData<dim>::make_zero_constraints(
    const DoFHandler<dim>     &dof_handler,
    AffineConstraints<double> &constraints) const
  {
    for (const auto &[id, c] : conditions)
      if (c.constrained.n_selected_components(dim) > 0)
        VectorTools::interpolate_boundary_values(dof_handler,
                                                 id,
                                                 Functions::ZeroFunction<dim>(
                                                   dim),
                                                 constraints,
                                                 c.constrained);
  }


  template <int dim>
  std::map<types::global_dof_index, double>
  BoundaryData<dim>::prescribed_values(const Mapping<dim>    &mapping,
                                       const DoFHandler<dim> &dof_handler) const
  {
    // Later ids overwrite earlier ones at shared nodes: going from the
    // highest id down makes the lowest id win, the documented rule.
    std::map<types::global_dof_index, double> values;
    for (auto c = conditions.rbegin(); c != conditions.rend(); ++c)
      if (c->second.constrained.n_selected_components(dim) > 0)
        VectorTools::interpolate_boundary_values(mapping,
                                                 dof_handler,
                                                 c->first,
                                                 *c->second.displacement,
                                                 values,
                                                 c->second.constrained);
    return values;
  }


  template <int dim>
  void
  BoundaryData<dim>::assemble_load_vector(const Mapping<dim>    &mapping,
                                          const DoFHandler<dim> &dof_handler,
                                          Vector<double>        &load) const
  {
    load                                    = 0;
    const FiniteElement<dim>            &fe = dof_handler.get_fe();
    const QGauss<dim - 1>                quadrature(fe.degree + 2);
    FEFaceValues<dim>                    fe_face(mapping,
                              fe,
                              quadrature,
                              update_values | update_normal_vectors |
                                update_quadrature_points | update_JxW_values);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    Vector<double>                       cell_load(fe.n_dofs_per_cell());
    Vector<double>                       traction(dim);

    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const auto f : cell->face_indices())
        {
          if (!cell->face(f)->at_boundary())
            continue;
          const auto c = conditions.find(cell->face(f)->boundary_id());
          if (c == conditions.end() || !c->second.loaded)
            continue;
          fe_face.reinit(cell, f);
          cell_load = 0;
          for (const unsigned int q : fe_face.quadrature_point_indices())
            {
              const Point<dim> &x = fe_face.quadrature_point(q);
              c->second.traction->vector_value(x, traction);
              const double pressure = c->second.pressure->value(x);
              for (const unsigned int i : fe_face.dof_indices())
                {
                  const unsigned int k = fe.system_to_component_index(i).first;
                  const double       t =
                    traction[k] - pressure * fe_face.normal_vector(q)[k];
                  cell_load[i] +=
                    t * fe_face.shape_value(i, q) * fe_face.JxW(q);
                }
            }
          cell->get_dof_indices(dofs);
          for (const unsigned int i : fe_face.dof_indices())
            load[dofs[i]] += cell_load[i];
        }
  }


  template <int dim>
  bool
  BoundaryData<dim>::has_constraints() const
  {
    for (const auto &[id, c] : conditions)
      if (c.constrained.n_selected_components(dim) > 0)
        return true;
    return false;
  }


  template class BoundaryData<2>;
} // namespace thinlayer
