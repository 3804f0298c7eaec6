#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>

#include <thinlayer/analysis/analysis.h>
#include <thinlayer/analysis/rigid_body_modes.h>
#include <thinlayer/base/input_error.h>
#include <thinlayer/discretisation/mode_constraints.h>
#include <thinlayer/discretisation/serendipity_constraints.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace thinlayer
{
  namespace
  {
    /// max_i |v_i| of a vector after condensation onto the free DoFs;
    /// @p work holds the condensed copy (reused, so nothing is allocated
    /// in the iterations).
    double
    condensed_max(const Vector<double>            &v,
                  const AffineConstraints<double> &constraints,
                  Vector<double>                  &work)
    {
      work = v;
      constraints.condense(work);
      return work.linfty_norm();
    }

    Kinematics
    make_kinematics(const KinematicsParameters &p)
    {
      return p.fourier ? Kinematics::make_fourier(p.harmonics,
                                                  p.station_angles,
                                                  p.antisymmetric)
                       : Kinematics::make_plane_strain();
    }
  } // namespace


  template <int dim>
  Analysis<dim>::Analysis(const Parameters         &parameters,
                          const Triangulation<dim> &tria)
    : parameters(parameters)
    , tria(tria)
    , kinematics(make_kinematics(parameters.kinematics))
    , fe(FE_Q<dim>(2), kinematics.n_components())
    , mapping(2)
    , quadrature(parameters.discretisation.gauss_points_per_direction)
    , dof_handler(tria)
    , boundary_data(parameters.boundaries,
                    parameters.mesh.geometry_parameters,
                    kinematics,
                    parameters.parameter_file)
    , time_step(std::numeric_limits<double>::infinity())
    , accepted_lambda(0)
    , current_lambda(0)
    , pending(false)
    , substitution_time(0)
  {
    static_assert(dim == 2,
                  "The kinematics so far are plane strain and Fourier, both "
                  "on 2D meshes.");
  }


  template <int dim>
  Analysis<dim>::~Analysis() = default;


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

    setup_dofs_and_constraints();
    setup_points();
    setup_mode_vectors();
    point_loop.reinit(
      strain_operator, kinematics, quadrature.size(), cell_law, history);
    assemble_stiffness();
    factorise_stiffness();

    method = create_solution_method(parameters.solver, *this);
    method->initialize();
  }


  template <int dim>
  void
  Analysis<dim>::setup_dofs_and_constraints()
  {
    dof_handler.distribute_dofs(fe);
    dof_component.resize(dof_handler.n_dofs());
    for (unsigned int c = 0; c < kinematics.n_components(); ++c)
      {
        std::vector<bool> mask(kinematics.n_components(), false);
        mask[c] = true;
        for (const auto dof :
             DoFTools::extract_dofs(dof_handler, ComponentMask(mask)))
          dof_component[dof] = c;
      }

    element_constraints.clear();
    if (parameters.discretisation.serendipity)
      make_serendipity_constraints(dof_handler, element_constraints);
    element_constraints.close();

    const auto linear_solver =
      parameters.solver.linear_solver == SolverParameters::LinearSolver::cholmod
        ? FactorisedStiffness::Method::cholmod
        : FactorisedStiffness::Method::umfpack;
    modes.clear();
    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    for (unsigned int m = 0; m < kinematics.n_modes(); ++m)
      {
        modes.push_back(std::make_unique<ModeState>(linear_solver));
        make_mode_constraints(dof_handler,
                              kinematics,
                              m,
                              parameters.kinematics.axis_boundary_id,
                              element_constraints,
                              boundary_data,
                              modes[m]->structural_constraints,
                              modes[m]->constraints);
        DoFTools::make_sparsity_pattern(dof_handler,
                                        dsp,
                                        modes[m]->constraints,
                                        /*keep_constrained_dofs=*/true);
      }
    interface_elements.reinit(dof_handler,
                              mapping,
                              kinematics,
                              parameters.interface_elements,
                              parameters.materials,
                              parameters.parameter_file);
    for (unsigned int m = 0; m < kinematics.n_modes(); ++m)
      interface_elements.add_sparsity(dsp, modes[m]->constraints);
    sparsity.copy_from(dsp);
  }


  template <int dim>
  void
  Analysis<dim>::setup_points()
  {
    for (const auto &[id, material] : parameters.materials)
      {
        laws[id]  = create_material_law(material);
        time_step = std::min(time_step, laws[id]->viscoplastic_time_step());
      }

    const unsigned int n_q = quadrature.size();
    cell_law.resize(tria.n_active_cells());
    history_storage.initialize(tria.begin_active(), tria.end(), n_q);
    history.resize(tria.n_active_cells() * n_q);
    for (const auto &cell : tria.active_cell_iterators())
      {
        const unsigned int c = cell->active_cell_index();
        cell_law[c]          = laws.at(cell->material_id()).get();
        const auto points    = history_storage.get_data(cell);
        for (unsigned int q = 0; q < n_q; ++q)
          {
            history[c * n_q + q] = points[q].get();
            history[c * n_q + q]->stations.assign(kinematics.n_stations(),
                                                  PointState());
          }
      }

    strain_operator.reinit(dof_handler, mapping, quadrature, kinematics);
  }


  template <int dim>
  void
  Analysis<dim>::setup_mode_vectors()
  {
    const unsigned int n = dof_handler.n_dofs();
    for (unsigned int m = 0; m < kinematics.n_modes(); ++m)
      {
        ModeState &mode = *modes[m];
        mode.stiffness.reinit(sparsity);
        mode.condensed_stiffness.reinit(sparsity);

        // Prescribed displacements at unit load factor; the nodes tied to
        // them (centre nodes, the axis) follow through the structural lines.
        mode.unit_prescribed_displacement.reinit(n);
        for (const auto &[dof, value] :
             boundary_data.prescribed_values(mapping, dof_handler, m))
          mode.unit_prescribed_displacement[dof] = value;
        mode.structural_constraints.distribute(
          mode.unit_prescribed_displacement);

        mode.unit_load.reinit(n);
        boundary_data.assemble_load_vector(mapping,
                                           dof_handler,
                                           m,
                                           mode.unit_load);
        for (Vector<double> *v : {&mode.unit_rhs,
                                  &mode.solution,
                                  &mode.step_increment,
                                  &mode.internal_forces,
                                  &mode.body_loads,
                                  &mode.body_load_change,
                                  &mode.residual,
                                  &mode.condensed})
          v->reinit(n);
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
    std::vector<SymmetricTensor<2, 3>>   strain(n), stress(n);

    for (unsigned int m = 0; m < kinematics.n_modes(); ++m)
      for (unsigned int c = 0; c < tria.n_active_cells(); ++c)
        {
          cell_matrix                    = 0;
          const SymmetricTensor<4, 3> &D = cell_law[c]->elasticity();
          for (unsigned int q = 0; q < n_q; ++q)
            {
              const unsigned int p = c * n_q + q;
              // K_m = int (c1 B1^T D B1 + c2 B2^T D B2) dA_r: the exact
              // integral over the circle, with which the harmonics
              // decouple.
              for (unsigned int part = 0; part < strain_operator.n_parts();
                   ++part)
                {
                  const double weight =
                    (part == 0 ? kinematics.c1(m) : kinematics.c2(m)) *
                    strain_operator.point_weight(p);
                  if (weight == 0)
                    continue;
                  strain_operator.shape_strains(p, m, part, strain.data());
                  for (unsigned int i = 0; i < n; ++i)
                    stress[i] = D * strain[i];
                  for (unsigned int i = 0; i < n; ++i)
                    for (unsigned int j = 0; j < n; ++j)
                      cell_matrix(i, j) += (strain[i] * stress[j]) * weight;
                }
            }
          std::copy(strain_operator.cell_dofs(c),
                    strain_operator.cell_dofs(c) + n,
                    dofs.begin());
          modes[m]->stiffness.add(dofs, cell_matrix);
          modes[m]->constraints.distribute_local_to_global(
            cell_matrix, dofs, modes[m]->condensed_stiffness);
        }
    for (unsigned int m = 0; m < kinematics.n_modes(); ++m)
      interface_elements.assemble_elastic(m,
                                          modes[m]->stiffness,
                                          modes[m]->condensed_stiffness,
                                          modes[m]->constraints);
  }


  template <int dim>
  void
  Analysis<dim>::check_supports_and_load() const
  {
    bool loaded = false;
    for (const auto &mode : modes)
      loaded = loaded || mode->unit_load.linfty_norm() > 0 ||
               mode->unit_prescribed_displacement.linfty_norm() > 0;
    if (!loaded)
      throw InputError(parameters.parameter_file,
                       "Boundary <id>",
                       "nothing loads the body: every traction, pressure and "
                       "prescribed displacement is 0; expected at least one "
                       "that is not");

    if (kinematics.is_fourier())
      return;
    std::vector<Point<dim>> points(dof_handler.n_dofs());
    DoFTools::map_dofs_to_support_points(mapping, dof_handler, points);
    const std::string motion =
      free_rigid_body_motion(points,
                             dof_component,
                             modes[0]->constraints,
                             modes[0]->condensed_stiffness);
    if (!motion.empty())
      throw InputError(parameters.parameter_file,
                       "Boundary <id>/Constrained components",
                       "the supports leave the body free to move: " + motion +
                         " meets no constrained component; constrain enough "
                         "components to prevent every rigid-body motion");
  }


  template <int dim>
  void
  Analysis<dim>::factorise_stiffness()
  {
    check_supports_and_load();
    for (unsigned int m = 0; m < kinematics.n_modes(); ++m)
      {
        ModeState &mode = *modes[m];
        mode.stiffness.vmult(mode.unit_rhs, mode.unit_prescribed_displacement);
        mode.unit_rhs.sadd(-1, 1, mode.unit_load);
        try
          {
            mode.factorisation.factorize(mode.condensed_stiffness);
          }
        catch (const std::exception &)
          {
            const std::string matrix =
              "the stiffness matrix" +
              (kinematics.is_fourier()
                 ? " of harmonic " + std::to_string(kinematics.harmonic(m))
                 : std::string()) +
              " is singular: ";
            // With the supports holding every rigid motion (plane strain
            // checks them), soft interface elements are what is left.
            if (!kinematics.is_fourier() &&
                !parameters.interface_elements.empty())
              {
                const auto softest = std::min_element(
                  parameters.interface_elements.begin(),
                  parameters.interface_elements.end(),
                  [](const auto &a, const auto &b) {
                    return std::min(a.second.shear_stiffness,
                                    a.second.normal_stiffness) <
                           std::min(b.second.shear_stiffness,
                                    b.second.normal_stiffness);
                  });
                const auto &curve = softest->second;
                throw InputError(
                  parameters.parameter_file,
                  InterfaceElementParameters::section(softest->first) +
                    (curve.shear_stiffness <= curve.normal_stiffness
                       ? "/Shear stiffness"
                       : "/Normal stiffness"),
                  matrix + "the supports hold every rigid-body motion, but the "
                           "interface elements are too soft against the cells "
                           "beside them for round-off; expected a stiffness of "
                           "at least about 1e-8 E/h (E and h of the cells)");
              }
            // Q9 with 2x2 points has zero-energy modes of its own, which
            // few cells do not suppress: name the element, not the supports.
            if (!parameters.discretisation.serendipity &&
                parameters.discretisation.gauss_points_per_direction == 2)
              throw InputError(parameters.parameter_file,
                               "Discretisation/Element",
                               matrix +
                                 "Q9 with 2x2 Gauss points has spurious "
                                 "zero-energy modes that this mesh does not "
                                 "suppress; use Q8, or 3x3 points (or "
                                 "constrain enough components)");
            throw InputError(parameters.parameter_file,
                             "Boundary <id>/Constrained components",
                             matrix +
                               "constrain enough displacement components to "
                               "prevent rigid-body motion");
          }
      }

    // What one substitution costs, for the benchmarks' ratio of iteration
    // to substitution time.
    std::vector<double> times;
    Vector<double>      work(dof_handler.n_dofs());
    for (unsigned int k = 0; k < 10; ++k)
      {
        Timer timer;
        for (auto &mode : modes)
          {
            work = mode->unit_rhs;
            mode->constraints.condense(work);
            mode->factorisation.solve(work);
          }
        times.push_back(timer.wall_time());
      }
    std::sort(times.begin(), times.end());
    substitution_time = times[times.size() / 2];
  }


  template <int dim>
  StepResult
  Analysis<dim>::solve(const double new_load_factor)
  {
    StepResult result = method->solve_step(new_load_factor);
    current_lambda    = new_load_factor;
    pending           = true;

    for (const auto &mode : modes)
      if (!std::isfinite(mode->step_increment.l1_norm()))
        {
          result.non_finite = true;
          result.converged  = false;
        }
    // Overflow anywhere is no state: stresses whose invariants overflow
    // make the yield tests meaningless (NaN compares false, and a point
    // would count as elastic), so the step fails, never converges.
    bool finite            = interface_elements.all_finite();
    result.max_yield_ratio = std::numeric_limits<double>::quiet_NaN();
    for (unsigned int p = 0; p < history.size(); ++p)
      {
        const MaterialLaw &law = *cell_law[p / quadrature.size()];
        for (const PointState &state : history[p]->stations)
          {
            for (unsigned int k = 0;
                 k < SymmetricTensor<2, 3>::n_independent_components;
                 ++k)
              finite =
                finite && std::isfinite(state.stress.access_raw_entry(k));
            if (!law.can_yield())
              continue;
            const double ratio = law.yield_ratio(state.stress);
            finite             = finite && std::isfinite(ratio);
            result.max_yield_ratio =
              std::isnan(result.max_yield_ratio)
                ? ratio
                : std::max(result.max_yield_ratio, ratio);
          }
      }
    const double interface_ratio = interface_elements.max_yield_ratio();
    if (!std::isnan(interface_ratio))
      result.max_yield_ratio =
        std::isnan(result.max_yield_ratio)
          ? interface_ratio
          : std::max(result.max_yield_ratio, interface_ratio);
    point_loop.compute_internal_forces(modes);
    interface_elements.add_internal_forces(modes);
    for (const auto &mode : modes)
      finite = finite && std::isfinite(mode->internal_forces.linfty_norm());
    if (!finite)
      {
        result.non_finite = true;
        result.converged  = false;
      }
    return result;
  }


  template <int dim>
  void
  Analysis<dim>::accept_step()
  {
    Assert(pending, ExcMessage("There is no pending step to accept."));
    accept_step(current_lambda);
  }


  template <int dim>
  void
  Analysis<dim>::accept_step(const double load_factor)
  {
    for (auto &mode : modes)
      mode->solution += mode->step_increment;
    for (PointHistory *point : history)
      for (PointState &state : point->stations)
        {
          state.converged_stress = state.stress;
          state.plastic_strain +=
            state.step_plastic_strain - state.pending_plastic_strain;
          state.step_plastic_strain    = 0;
          state.pending_plastic_strain = 0;
        }
    interface_elements.accept();
    accepted_lambda = load_factor;
    current_lambda  = load_factor;
    pending         = false;
    method->state_accepted();
  }


  template <int dim>
  void
  Analysis<dim>::reject_step()
  {
    for (auto &mode : modes)
      mode->step_increment = 0;
    for (PointHistory *point : history)
      for (PointState &state : point->stations)
        {
          state.stress                 = state.converged_stress;
          state.step_plastic_strain    = 0;
          state.pending_plastic_strain = 0;
        }
    interface_elements.reject();
    current_lambda = accepted_lambda;
    pending        = false;
    point_loop.compute_internal_forces(modes);
    interface_elements.add_internal_forces(modes);
    method->state_rejected();
  }


  template <int dim>
  double
  Analysis<dim>::secant_stiffness_ratio() const
  {
    const double   dlambda      = current_lambda - accepted_lambda;
    double         elastic_work = 0, work = 0;
    Vector<double> load(dof_handler.n_dofs()),
      elastic_increment(dof_handler.n_dofs());
    for (const auto &mode : modes)
      {
        load = mode->unit_rhs;
        load *= dlambda;
        mode->constraints.condense(load);
        elastic_increment = load;
        mode->factorisation.solve(elastic_increment);
        elastic_work += load * elastic_increment;
        work += load * mode->step_increment;
      }
    if (elastic_work == 0)
      return std::numeric_limits<double>::quiet_NaN();
    return elastic_work / work;
  }


  template <int dim>
  unsigned int
  Analysis<dim>::update_viscoplastic_stresses()
  {
    return point_loop.viscoplastic_update(time_step, modes) +
           interface_elements.viscoplastic_update(modes);
  }


  template <int dim>
  ResidualNorms
  Analysis<dim>::evaluate_residual(const double                        target,
                                   std::vector<SymmetricTensor<4, 3>> *tangents)
  {
    ResidualNorms norms{
      point_loop.return_mapping_update(modes, tangents) +
        interface_elements.return_mapping_update(modes, tangents != nullptr),
      0,
      0,
      0,
      0};
    for (auto &mode : modes)
      {
        Vector<double> &r = mode->residual;
        r                 = mode->unit_load;
        r *= target;
        norms.forces = std::max(
          {norms.forces, r.linfty_norm(), mode->internal_forces.linfty_norm()});
        r -= mode->internal_forces;
        mode->constraints.condense(r);
        norms.max = std::max(norms.max, r.linfty_norm());
        norms.l2 += r.norm_sqr();
        norms.body_loads = std::max(norms.body_loads,
                                    condensed_max(mode->body_loads,
                                                  mode->constraints,
                                                  mode->condensed));
      }
    norms.l2 = std::sqrt(norms.l2);
    return norms;
  }


  template <int dim>
  Vector<double>
  Analysis<dim>::displacement_at(const double theta, const bool increment) const
  {
    Vector<double> u(dof_handler.n_dofs());
    for (unsigned int m = 0; m < modes.size(); ++m)
      {
        const Vector<double> &v =
          increment ? modes[m]->step_increment : modes[m]->solution;
        const double t1 = kinematics.T1_at(m, theta);
        const double t2 = kinematics.T2_at(m, theta);
        // A pending step's state is the accepted one plus its increment.
        const bool add_increment = pending && !increment;
        for (unsigned int i = 0; i < u.size(); ++i)
          u[i] += (dof_component[i] < 2 ? t1 : t2) *
                  (add_increment ? v[i] + modes[m]->step_increment[i] : v[i]);
      }
    return u;
  }


  template <int dim>
  bool
  Analysis<dim>::has_external_load() const
  {
    for (const auto &mode : modes)
      if (mode->unit_load.linfty_norm() > 0)
        return true;
    return false;
  }


  template <int dim>
  bool
  Analysis<dim>::all_laws_associated() const
  {
    bool associated = interface_elements.all_associated();
    for (const auto &[id, law] : laws)
      associated = associated && law->is_associated();
    return associated;
  }


  template <int dim>
  std::string
  Analysis<dim>::warnings() const
  {
    std::string text;
    for (const auto &w : boundary_data.get_warnings())
      text += (text.empty() ? "" : "; ") + w;
    return text;
  }


  template class Analysis<2>;
} // namespace thinlayer
