#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/numerics/vector_tools.h>

#include <thinlayer/analysis.h>
#include <thinlayer/input_error.h>
#include <thinlayer/kinematics.h>
#include <thinlayer/serendipity_constraints.h>

#include <algorithm>
#include <limits>

namespace thinlayer
{
  namespace
  {
    /// max_i |v_i| of a vector after condensation onto the free DoFs.
    double
    condensed_max(const Vector<double>            &v,
                  const AffineConstraints<double> &constraints)
    {
      Vector<double> condensed(v);
      constraints.condense(condensed);
      return condensed.linfty_norm();
    }
  } // namespace


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
    , time_step(std::numeric_limits<double>::infinity())
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
      {
        laws[id]  = create_material_law(m);
        time_step = std::min(time_step, laws[id]->viscoplastic_time_step());
      }

    build_point_cache();

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

    unit_rhs.reinit(dof_handler.n_dofs());
    stiffness.vmult(unit_rhs, unit_prescribed_displacement);
    unit_rhs.sadd(-1, 1, unit_load);

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
    step_increment.reinit(dof_handler.n_dofs());
    internal_forces.reinit(dof_handler.n_dofs());
  }


  template <int dim>
  void
  Analysis<dim>::build_point_cache()
  {
    const unsigned int n_cells = tria.n_active_cells();
    const unsigned int n_q     = quadrature.size();
    const unsigned int n       = fe.n_dofs_per_cell();

    cell_law.resize(n_cells);
    cell_dofs.resize(n_cells * n);
    point_JxW.resize(n_cells * n_q);
    shape_strains.resize(n_cells * n_q * n);

    history_storage.initialize(tria.begin_active(), tria.end(), n_q);
    history.resize(n_cells * n_q);

    FEValues<dim>                        fe_values(mapping,
                            fe,
                            quadrature,
                            update_gradients | update_JxW_values);
    const FEValuesExtractors::Vector     displacement(0);
    std::vector<types::global_dof_index> dofs(n);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const unsigned int c = cell->active_cell_index();
        fe_values.reinit(cell);
        cell_law[c] = laws.at(cell->material_id()).get();
        cell->get_dof_indices(dofs);
        std::copy(dofs.begin(), dofs.end(), cell_dofs.begin() + c * n);

        const auto points = history_storage.get_data(cell);
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            point_JxW[c * n_q + q] = fe_values.JxW(q);
            for (const unsigned int i : fe_values.dof_indices())
              shape_strains[(c * n_q + q) * n + i] =
                plane_strain(fe_values[displacement].symmetric_gradient(i, q));
            history[c * n_q + q] = points[q].get();
            history[c * n_q + q]->stations.assign(1, PointState());
          }
      }
  }


  template <int dim>
  void
  Analysis<dim>::assemble_stiffness()
  {
    const unsigned int                   n   = fe.n_dofs_per_cell();
    const unsigned int                   n_q = quadrature.size();
    FullMatrix<double>                   cell_matrix(n, n);
    std::vector<types::global_dof_index> dofs(n);
    std::vector<SymmetricTensor<2, 3>>   stress(n);

    for (unsigned int c = 0; c < tria.n_active_cells(); ++c)
      {
        cell_matrix                    = 0;
        const SymmetricTensor<4, 3> &D = cell_law[c]->elasticity();
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const SymmetricTensor<2, 3> *B = &shape_strains[(c * n_q + q) * n];
            for (unsigned int i = 0; i < n; ++i)
              stress[i] = D * B[i];
            const double JxW = point_JxW[c * n_q + q];
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int j = 0; j < n; ++j)
                cell_matrix(i, j) += (B[i] * stress[j]) * JxW;
          }
        std::copy(cell_dofs.begin() + c * n,
                  cell_dofs.begin() + (c + 1) * n,
                  dofs.begin());
        stiffness.add(dofs, cell_matrix);
        constraints.distribute_local_to_global(cell_matrix,
                                               dofs,
                                               condensed_stiffness);
      }
  }


  template <int dim>
  void
  Analysis<dim>::solve_increment(const double          dlambda,
                                 const Vector<double> &body_loads,
                                 Vector<double>       &increment) const
  {
    increment = body_loads;
    increment.add(dlambda, unit_rhs);
    constraints.condense(increment);
    factorisation.solve(increment);
    constraints.distribute(increment);
    increment.add(dlambda, unit_prescribed_displacement);
  }


  template <int dim>
  unsigned int
  Analysis<dim>::update_stresses(const Vector<double> &increment,
                                 Vector<double>       &body_load_change)
  {
    const unsigned int  n          = fe.n_dofs_per_cell();
    const unsigned int  n_q        = quadrature.size();
    unsigned int        n_yielding = 0;
    std::vector<double> du(n);

    for (unsigned int c = 0; c < tria.n_active_cells(); ++c)
      {
        const MaterialLaw             &law  = *cell_law[c];
        const SymmetricTensor<4, 3>   &D    = law.elasticity();
        const types::global_dof_index *dofs = &cell_dofs[c * n];
        for (unsigned int i = 0; i < n; ++i)
          du[i] = increment[dofs[i]];

        for (unsigned int q = 0; q < n_q; ++q)
          {
            const SymmetricTensor<2, 3> *B = &shape_strains[(c * n_q + q) * n];
            PointState &state              = history[c * n_q + q]->stations[0];

            SymmetricTensor<2, 3> strain;
            for (unsigned int i = 0; i < n; ++i)
              strain += du[i] * B[i];
            state.stress =
              state.converged_stress + D * (strain - state.step_plastic_strain);

            state.yielding = false;
            if (!law.can_yield())
              continue;
            const double F = law.yield_function(state.stress);
            if (F <= 0)
              continue;

            state.yielding = true;
            ++n_yielding;
            const SymmetricTensor<2, 3> viscoplastic_strain =
              (time_step * F) * law.flow_direction(state.stress);
            state.step_plastic_strain += viscoplastic_strain;
            const SymmetricTensor<2, 3> stress_change =
              (D * viscoplastic_strain) * point_JxW[c * n_q + q];
            for (unsigned int i = 0; i < n; ++i)
              body_load_change[dofs[i]] += B[i] * stress_change;
          }
      }
    return n_yielding;
  }


  template <int dim>
  void
  Analysis<dim>::update_internal_forces()
  {
    const unsigned int n   = fe.n_dofs_per_cell();
    const unsigned int n_q = quadrature.size();
    internal_forces        = 0;
    for (unsigned int c = 0; c < tria.n_active_cells(); ++c)
      for (unsigned int q = 0; q < n_q; ++q)
        {
          const SymmetricTensor<2, 3> *B = &shape_strains[(c * n_q + q) * n];
          const SymmetricTensor<2, 3>  sigma_JxW =
            history[c * n_q + q]->stations[0].stress * point_JxW[c * n_q + q];
          for (unsigned int i = 0; i < n; ++i)
            internal_forces[cell_dofs[c * n + i]] += B[i] * sigma_JxW;
        }
  }


  template <int dim>
  StepResult
  Analysis<dim>::solve(const double new_load_factor)
  {
    const double dlambda = new_load_factor - load_factor;

    for (PointHistory *point : history)
      point->stations[0].step_plastic_strain = 0;

    Vector<double> body_loads(dof_handler.n_dofs());
    Vector<double> body_load_change(dof_handler.n_dofs());
    Vector<double> increment(dof_handler.n_dofs());
    Vector<double> previous_increment(dof_handler.n_dofs());

    StepResult result{0, false, 0, 0};
    while (result.iterations < parameters.max_iterations && !result.converged)
      {
        ++result.iterations;
        previous_increment.swap(increment);
        solve_increment(dlambda, body_loads, increment);

        body_load_change      = 0;
        result.plastic_points = update_stresses(increment, body_load_change);
        body_loads += body_load_change;

        if (result.plastic_points == 0)
          result.converged = true; // elastic: nothing will change
        else if (parameters.convergence_criterion ==
                 ConvergenceCriterion::body_loads)
          result.converged =
            condensed_max(body_load_change, constraints) <=
            parameters.tolerance * condensed_max(body_loads, constraints);
        else if (result.iterations > 1)
          {
            previous_increment -= increment;
            result.converged = previous_increment.linfty_norm() <=
                               parameters.tolerance * increment.linfty_norm();
          }
      }

    // The step's state is kept even if it failed, so that the mechanism at
    // failure can be seen.
    solution += increment;
    step_increment.swap(increment);
    load_factor            = new_load_factor;
    result.max_yield_ratio = std::numeric_limits<double>::quiet_NaN();
    for (unsigned int p = 0; p < history.size(); ++p)
      {
        PointState &state      = history[p]->stations[0];
        state.converged_stress = state.stress;
        state.plastic_strain += state.step_plastic_strain;
        const MaterialLaw &law = *cell_law[p / quadrature.size()];
        if (law.can_yield())
          result.max_yield_ratio =
            std::isnan(result.max_yield_ratio)
              ? law.yield_ratio(state.stress)
              : std::max(result.max_yield_ratio, law.yield_ratio(state.stress));
      }
    update_internal_forces();
    return result;
  }


  template <int dim>
  double
  Analysis<dim>::load() const
  {
    if (parameters.load_measure == LoadMeasure::load_factor)
      return parameters.load_scale * load_factor;

    if (parameters.load_measure == LoadMeasure::stress_average)
      {
        const auto [i, j]           = parameters.load_stress_component;
        const unsigned int n_q      = quadrature.size();
        double             integral = 0, area = 0;
        for (const auto &cell : tria.active_cell_iterators())
          if (cell->material_id() == parameters.load_material_id)
            for (unsigned int q = 0; q < n_q; ++q)
              {
                const unsigned int p = cell->active_cell_index() * n_q + q;
                integral += history[p]->stations[0].stress[i][j] * point_JxW[p];
                area += point_JxW[p];
              }
        return parameters.load_scale * integral / area;
      }

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
    const double       s = parameters.displacement_scale;
    const unsigned int c = parameters.displacement_component;
    if (parameters.displacement_measure == DisplacementMeasureType::point)
      {
        Point<dim> x;
        for (unsigned int d = 0; d < dim; ++d)
          x[d] = parameters.displacement_point[d];
        Vector<double> value(dim);
        VectorTools::point_value(mapping, dof_handler, solution, x, value);
        return {s * value[c], s * value[c], s * value[c]};
      }

    const QGauss<dim - 1>       face_quadrature(3);
    FEFaceValues<dim>           fe_face(mapping,
                              fe,
                              face_quadrature,
                              update_values | update_JxW_values);
    std::vector<Vector<double>> values(face_quadrature.size(),
                                       Vector<double>(dim));
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
  const Vector<double> &
  Analysis<dim>::get_step_increment() const
  {
    return step_increment;
  }


  template <int dim>
  const PointState &
  Analysis<dim>::point_state(const unsigned int cell,
                             const unsigned int q) const
  {
    return history[cell * quadrature.size() + q]->stations[0];
  }


  template <int dim>
  const SymmetricTensor<2, 3> &
  Analysis<dim>::stress(const unsigned int cell, const unsigned int q) const
  {
    return point_state(cell, q).stress;
  }


  template <int dim>
  const MaterialLaw &
  Analysis<dim>::material_law(const unsigned int cell) const
  {
    return *cell_law[cell];
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


  template <int dim>
  double
  Analysis<dim>::viscoplastic_time_step() const
  {
    return time_step;
  }


  template class Analysis<2>;
} // namespace thinlayer
