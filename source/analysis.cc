#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <thinlayer/analysis.h>
#include <thinlayer/elasticity.h>
#include <thinlayer/input_error.h>
#include <thinlayer/kinematics.h>
#include <thinlayer/serendipity_constraints.h>

#include <algorithm>
#include <limits>

namespace thinlayer
{
  template <int dim>
  Analysis<dim>::Analysis(const Parameters         &parameters,
                          const Triangulation<dim> &tria)
    : parameters(parameters)
    , tria(tria)
    , fe(FE_Q<dim>(2), dim)
    , mapping(2)
    , quadrature(parameters.gauss_points_per_direction)
    , dof_handler(tria)
    , boundary_data(parameters)
    , load_factor(0)
  {
    static_assert(dim == 2, "Only plane strain is implemented so far.");
  }


  template <int dim>
  void
  Analysis<dim>::setup()
  {
    if (!boundary_data.has_constraints())
      throw InputError(parameters.parameter_file,
                       "Boundary <id>/Constrained components",
                       "no displacement component is constrained anywhere; "
                       "the body must be restrained against rigid-body "
                       "motion");

    dof_handler.distribute_dofs(fe);

    element_constraints.clear();
    if (parameters.serendipity)
      make_serendipity_constraints(dof_handler, element_constraints);
    element_constraints.close();

    constraints.clear();
    constraints.merge(element_constraints);
    boundary_data.make_zero_constraints(dof_handler, constraints);
    constraints.close();

    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler,
                                    dsp,
                                    constraints,
                                    /*keep_constrained_dofs=*/true);
    sparsity.copy_from(dsp);
    stiffness.reinit(sparsity);
    condensed_stiffness.reinit(sparsity);

    for (const auto &[id, m] : parameters.materials)
      elasticity[id] = isotropic_elasticity(m.youngs_modulus, m.poissons_ratio);

    // Prescribed displacements at unit load factor; the centre nodes of
    // cells touching them follow through the serendipity lines.
    unit_prescribed_displacement.reinit(dof_handler.n_dofs());
    for (const auto &[dof, value] :
         boundary_data.prescribed_values(mapping, dof_handler))
      unit_prescribed_displacement[dof] = value;
    element_constraints.distribute(unit_prescribed_displacement);

    unit_load.reinit(dof_handler.n_dofs());
    boundary_data.assemble_load_vector(mapping, dof_handler, unit_load);

    assemble_stiffness();

    unit_lift.reinit(dof_handler.n_dofs());
    stiffness.vmult(unit_lift, unit_prescribed_displacement);
    unit_lift *= -1;

    try
      {
        factorisation.factorize(condensed_stiffness);
      }
    catch (const ExceptionBase &)
      {
        throw InputError(parameters.parameter_file,
                         "Boundary <id>/Constrained components",
                         "the stiffness matrix is singular: constrain enough "
                         "displacement components to prevent rigid-body "
                         "motion");
      }

    const auto component_mask = [](const unsigned int c) {
      std::vector<bool> mask(dim, false);
      mask[c] = true;
      return ComponentMask(mask);
    };
    reaction_dofs =
      DoFTools::extract_boundary_dofs(dof_handler,
                                      component_mask(parameters.load_component),
                                      {parameters.load_boundary_id});
    monitored_dofs =
      DoFTools::extract_boundary_dofs(dof_handler,
                                      component_mask(
                                        parameters.displacement_component),
                                      {parameters.displacement_boundary_id});

    solution.reinit(dof_handler.n_dofs());
    internal_forces.reinit(dof_handler.n_dofs());
    stresses.assign(tria.n_active_cells() * quadrature.size(),
                    SymmetricTensor<2, 3>());
  }


  template <int dim>
  void
  Analysis<dim>::assemble_stiffness()
  {
    FEValues<dim>                        fe_values(mapping,
                            fe,
                            quadrature,
                            update_gradients | update_JxW_values);
    const FEValuesExtractors::Vector     displacement(0);
    const unsigned int                   n = fe.n_dofs_per_cell();
    FullMatrix<double>                   cell_matrix(n, n);
    std::vector<types::global_dof_index> dofs(n);
    std::vector<SymmetricTensor<2, 3>>   strain(n), stress(n);

    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        fe_values.reinit(cell);
        cell_matrix                    = 0;
        const SymmetricTensor<4, 3> &C = elasticity.at(cell->material_id());
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            for (const unsigned int i : fe_values.dof_indices())
              {
                strain[i] = plane_strain(
                  fe_values[displacement].symmetric_gradient(i, q));
                stress[i] = C * strain[i];
              }
            const double JxW = fe_values.JxW(q);
            for (const unsigned int i : fe_values.dof_indices())
              for (const unsigned int j : fe_values.dof_indices())
                cell_matrix(i, j) += (strain[i] * stress[j]) * JxW;
          }
        cell->get_dof_indices(dofs);
        stiffness.add(dofs, cell_matrix);
        constraints.distribute_local_to_global(cell_matrix,
                                               dofs,
                                               condensed_stiffness);
      }
  }


  template <int dim>
  StepResult
  Analysis<dim>::solve(const double new_load_factor)
  {
    load_factor = new_load_factor;

    Vector<double> rhs(unit_load);
    rhs.sadd(load_factor, load_factor, unit_lift);
    constraints.condense(rhs);
    factorisation.solve(rhs);
    constraints.distribute(rhs);

    solution = rhs;
    solution.add(load_factor, unit_prescribed_displacement);

    update_stresses_and_internal_forces();
    return {1, true, std::numeric_limits<double>::quiet_NaN(), 0};
  }


  template <int dim>
  void
  Analysis<dim>::update_stresses_and_internal_forces()
  {
    FEValues<dim>                        fe_values(mapping,
                            fe,
                            quadrature,
                            update_gradients | update_JxW_values);
    const FEValuesExtractors::Vector     displacement(0);
    const unsigned int                   n = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> dofs(n);
    std::vector<SymmetricTensor<2, dim>> strains(quadrature.size());
    Vector<double>                       cell_forces(n);

    internal_forces = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        fe_values.reinit(cell);
        fe_values[displacement].get_function_symmetric_gradients(solution,
                                                                 strains);
        const SymmetricTensor<4, 3> &C = elasticity.at(cell->material_id());
        cell_forces                    = 0;
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            SymmetricTensor<2, 3> &sigma =
              stresses[cell->active_cell_index() * quadrature.size() + q];
            sigma = C * plane_strain(strains[q]);
            for (const unsigned int i : fe_values.dof_indices())
              cell_forces[i] +=
                (plane_strain(
                   fe_values[displacement].symmetric_gradient(i, q)) *
                 sigma) *
                fe_values.JxW(q);
          }
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < n; ++i)
          internal_forces[dofs[i]] += cell_forces[i];
      }
  }


  template <int dim>
  double
  Analysis<dim>::load() const
  {
    if (parameters.load_measure == LoadMeasure::load_factor)
      return parameters.load_scale * load_factor;

    // Reactions: the residual f_int - f_ext at the supported DoFs, after
    // the residuals of eliminated centre nodes are handed to their masters.
    Vector<double> residual(internal_forces);
    residual.add(-load_factor, unit_load);
    element_constraints.condense(residual);
    double sum = 0;
    for (const auto dof : reaction_dofs)
      sum += residual[dof];
    return parameters.load_scale * sum;
  }


  template <int dim>
  DisplacementMeasure
  Analysis<dim>::displacement() const
  {
    const QGauss<dim - 1>       face_quadrature(3);
    FEFaceValues<dim>           fe_face(mapping,
                              fe,
                              face_quadrature,
                              update_values | update_JxW_values);
    std::vector<Vector<double>> values(face_quadrature.size(),
                                       Vector<double>(dim));
    const unsigned int          c        = parameters.displacement_component;
    double                      integral = 0, length = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary() &&
            cell->face(f)->boundary_id() == parameters.displacement_boundary_id)
          {
            fe_face.reinit(cell, f);
            fe_face.get_function_values(solution, values);
            for (const unsigned int q : fe_face.quadrature_point_indices())
              {
                integral += values[q][c] * fe_face.JxW(q);
                length += fe_face.JxW(q);
              }
          }

    double min = std::numeric_limits<double>::max();
    double max = std::numeric_limits<double>::lowest();
    for (const auto dof : monitored_dofs)
      {
        min = std::min(min, solution[dof]);
        max = std::max(max, solution[dof]);
      }
    const double s = parameters.displacement_scale;
    return {s * integral / length,
            std::min(s * min, s * max),
            std::max(s * min, s * max)};
  }


  template <int dim>
  const DoFHandler<dim> &
  Analysis<dim>::get_dof_handler() const
  {
    return dof_handler;
  }


  template <int dim>
  const Mapping<dim> &
  Analysis<dim>::get_mapping() const
  {
    return mapping;
  }


  template <int dim>
  const Vector<double> &
  Analysis<dim>::get_solution() const
  {
    return solution;
  }


  template <int dim>
  const SymmetricTensor<2, 3> &
  Analysis<dim>::stress(const unsigned int cell, const unsigned int q) const
  {
    return stresses[cell * quadrature.size() + q];
  }


  template <int dim>
  unsigned int
  Analysis<dim>::n_quadrature_points() const
  {
    return quadrature.size();
  }


  template <int dim>
  types::global_dof_index
  Analysis<dim>::n_dofs() const
  {
    return dof_handler.n_dofs() - element_constraints.n_constraints();
  }


  template <int dim>
  types::global_dof_index
  Analysis<dim>::n_equations() const
  {
    return dof_handler.n_dofs() - constraints.n_constraints();
  }


  template class Analysis<2>;
} // namespace thinlayer
