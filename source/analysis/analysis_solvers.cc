// The elastic system's solvers: the checks before the stiffness is
// factorised, its factors or AMG-CG, and what a singular stiffness says of
// the scene. Members of Analysis, in a file of their own.
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>

#include <thinlayer/analysis/analysis.h>
#include <thinlayer/analysis/rigid_body_modes.h>
#include <thinlayer/base/input_error.h>
#include <thinlayer/parallel/mpi.h>
#include <thinlayer/solvers/singular_matrix.h>

#include <algorithm>
#include <limits>

namespace thinlayer
{
  template <int dim>
  void
  Analysis<dim>::check_supports_and_load() const
  {
    bool loaded = false;
    for (const auto &system : systems)
      loaded = loaded || system->unit_load.linfty_norm() > 0 ||
               system->unit_prescribed_displacement.linfty_norm() > 0;
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
      mpi::n_ranks() == 1
        ? free_rigid_body_motion(points,
                                 dof_component,
                                 systems[0]->constraints,
                                 systems[0]->condensed_stiffness)
        : free_rigid_body_motion(points,
                                 dof_component,
                                 systems[0]->constraints,
                                 *systems[0]->distributed_stiffness);
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
    if (parameters.solver.linear_solver ==
        SolverParameters::LinearSolver::amg_cg)
      {
        set_up_iterative_solvers();
        return;
      }
    for (unsigned int m = 0; m < kinematics.n_modes(); ++m)
      {
        ModeSystem &mode = *systems[m];
        try
          {
            if (mpi::n_ranks() == 1)
              mode.factorisation.factorize(mode.condensed_stiffness);
            else
              {
                mode.distributed_factorisation =
                  std::make_unique<DistributedFactorisation>(
                    /*symmetric=*/true);
                mode.distributed_factorisation->factorize(
                  *mode.distributed_stiffness, owned_per_rank);
                // MUMPS holds its own copy of the entries; the matrix is
                // never needed again.
                mode.distributed_stiffness.reset();
              }
          }
        catch (const SingularMatrix &)
          {
            throw_singular(m);
          }
      }

    time_substitution();
  }


  template <int dim>
  void
  Analysis<dim>::set_up_iterative_solvers()
  {
    std::vector<Point<dim>> points(dof_handler.n_dofs());
    DoFTools::map_dofs_to_support_points(mapping, dof_handler, points);
    const auto motions =
      rigid_body_motions(points, dof_component, kinematics.n_components());
    // PETSc's aggregation groups a node's unknowns where they follow one
    // another in component order (deal.II numbers a node's together) and
    // no rank splits a node.
    unsigned int block_size = kinematics.n_components();
    for (unsigned int i = 0; i < dof_component.size(); ++i)
      if (dof_component[i] != i % block_size)
        block_size = 1;
    for (const IndexSet &owned : owned_per_rank)
      if (owned.n_elements() % block_size != 0)
        block_size = 1;
    for (auto &system : systems)
      {
        // The condensed stiffness keeps a constrained DoF apart, on its
        // diagonal: a motion is nearly free only where it is zero there.
        auto free_motions = motions;
        for (auto &motion : free_motions)
          for (unsigned int i = 0; i < motion.size(); ++i)
            if (system->constraints.is_constrained(i))
              motion[i] = 0;
        system->iterative = std::make_unique<AmgConjugateGradient>(
          parameters.solver.linear_solver_tolerance,
          parameters.solver.linear_solver_iterations);
        if (mpi::n_ranks() == 1)
          system->iterative->initialize(
            *petsc_copy(system->condensed_stiffness),
            {complete_index_set(dof_handler.n_dofs())},
            free_motions,
            block_size);
        else
          system->iterative->initialize(*system->distributed_stiffness,
                                        owned_per_rank,
                                        free_motions,
                                        block_size);
      }
    time_substitution();
  }


  template <int dim>
  double
  Analysis<dim>::linear_iterations_per_solve() const
  {
    unsigned long iterations = 0, solves = 0;
    for (const auto &system : systems)
      if (system->iterative)
        {
          iterations += system->iterative->total_iterations();
          solves += system->iterative->n_solves();
        }
    return solves > 0 ? double(iterations) / solves
                      : std::numeric_limits<double>::quiet_NaN();
  }


  template <int dim>
  void
  Analysis<dim>::time_substitution()
  {
    // What one substitution costs, for the benchmarks' ratio of iteration
    // to substitution time.
    std::vector<double> times;
    Vector<double>      work(dof_handler.n_dofs());
    for (unsigned int k = 0; k < 10; ++k)
      {
        Timer timer;
        for (auto &system : systems)
          {
            work = system->unit_rhs;
            system->constraints.condense(work);
            system->solve(work);
          }
        times.push_back(timer.wall_time());
      }
    std::sort(times.begin(), times.end());
    substitution_time = times[times.size() / 2];
  }


  template <int dim>
  void
  Analysis<dim>::throw_singular(const unsigned int m) const
  {
    const std::string matrix =
      "the stiffness matrix" +
      (kinematics.is_fourier()
         ? " of harmonic " + std::to_string(kinematics.harmonic(m))
         : std::string()) +
      " is singular: ";
    // With the supports holding every rigid motion (plane strain
    // checks them), soft interface elements are what is left.
    if (!kinematics.is_fourier() && !parameters.interface_elements.empty())
      {
        const auto softest =
          std::min_element(parameters.interface_elements.begin(),
                           parameters.interface_elements.end(),
                           [](const auto &a, const auto &b) {
                             return std::min(a.second.shear_stiffness,
                                             a.second.normal_stiffness) <
                                    std::min(b.second.shear_stiffness,
                                             b.second.normal_stiffness);
                           });
        const auto &curve = softest->second;
        throw InputError(parameters.parameter_file,
                         InterfaceElementParameters::section(softest->first) +
                           (curve.shear_stiffness <= curve.normal_stiffness
                              ? "/Shear stiffness"
                              : "/Normal stiffness"),
                         matrix +
                           "the supports hold every rigid-body motion, but the "
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
                       matrix + "Q9 with 2x2 Gauss points has spurious "
                                "zero-energy modes that this mesh does not "
                                "suppress; use Q8, or 3x3 points (or "
                                "constrain enough components)");
    throw InputError(parameters.parameter_file,
                     "Boundary <id>/Constrained components",
                     matrix + "constrain enough displacement components to "
                              "prevent rigid-body motion");
  }


  template void
  Analysis<2>::check_supports_and_load() const;
  template void
  Analysis<2>::factorise_stiffness();
  template void
  Analysis<2>::set_up_iterative_solvers();
  template double
  Analysis<2>::linear_iterations_per_solve() const;
  template void
  Analysis<2>::time_substitution();
  template void
  Analysis<2>::throw_singular(const unsigned int) const;
} // namespace thinlayer
