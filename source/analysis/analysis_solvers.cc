// The elastic system's solvers: the checks before the stiffness is
// factorised, its factors or AMG-CG, and what a singular stiffness says of
// the scene. Members of Analysis, in a file of their own.
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <thinlayer/analysis/analysis.h>
#include <thinlayer/analysis/rigid_body_modes.h>
#include <thinlayer/base/input_error.h>
#include <thinlayer/base/text_format.h>
#include <thinlayer/parallel/mpi.h>
#include <thinlayer/solvers/singular_matrix.h>

#include <algorithm>
#include <limits>
#include <tuple>

namespace thinlayer
{
  namespace
  {
    /**
     * The whole of the distributed matrix @p A on rank @p root, as
     * @p matrix on @p pattern (left empty on the other ranks): PETSc's
     * sub-matrix of all rows and columns, taken by every rank (a
     * collective call) and asked for only by @p root.
     */
    void
    gather_whole(const PETScWrappers::MPI::SparseMatrix &A,
                 const unsigned int                      root,
                 SparsityPattern                        &pattern,
                 SparseMatrix<double>                   &matrix)
    {
      const bool     here = mpi::rank() == root;
      const PetscInt n    = A.m();
      IS             all;
      ISCreateStride(PETSC_COMM_SELF, here ? n : 0, 0, 1, &all);
      Mat           *whole;
      PetscErrorCode ierr =
        MatCreateSubMatrices(A, 1, &all, &all, MAT_INITIAL_MATRIX, &whole);
      AssertThrow(ierr == 0, ExcPETScError(ierr));
      if (here)
        {
          // Each entry of the sub-matrix, row by row, to @p f(i, j, value).
          const auto for_each_entry = [&](const auto &f) {
            for (PetscInt i = 0; i < n; ++i)
              {
                PetscInt           n_columns;
                const PetscInt    *columns;
                const PetscScalar *values;
                MatGetRow(whole[0], i, &n_columns, &columns, &values);
                for (PetscInt k = 0; k < n_columns; ++k)
                  f(i, columns[k], values[k]);
                MatRestoreRow(whole[0], i, &n_columns, &columns, &values);
              }
          };
          DynamicSparsityPattern dsp(n);
          for_each_entry(
            [&](const PetscInt i, const PetscInt j, double) { dsp.add(i, j); });
          pattern.copy_from(dsp);
          matrix.reinit(pattern);
          for_each_entry([&](const PetscInt i,
                             const PetscInt j,
                             const double value) { matrix.set(i, j, value); });
        }
      MatDestroySubMatrices(1, &whole);
      ISDestroy(&all);
    }
  } // namespace


  template <int dim>
  void
  Analysis<dim>::elastic_solve(ModeVectors &rhs)
  {
    // Spread harmonics: each right-hand side gathered on its harmonic's
    // rank, the ranks substituting their own at once, and each rank's part
    // of the solutions sent back.
    for (unsigned int m = 0; m < systems.size(); ++m)
      if (!systems[m]->spread())
        systems[m]->solve(rhs[m]);
      else
        systems[m]->gather_on_owner(rhs[m]);
    for (auto &system : systems)
      if (system->spread())
        system->substitute_on_owner();
    for (unsigned int m = 0; m < systems.size(); ++m)
      if (systems[m]->spread())
        systems[m]->scatter_from_owner(rhs[m]);
  }


  template <int dim>
  OwnedDofPlaces
  Analysis<dim>::owned_dof_places() const
  {
    OwnedDofPlaces places;
    places.owned                = dof_handler.locally_owned_dofs();
    places.dimension            = dim;
    const unsigned int n        = places.owned.n_elements();
    const auto         embedded = [](const Point<dim> &x) {
      Point<3> y;
      for (unsigned int d = 0; d < dim; ++d)
        y[d] = x[d];
      return y;
    };
    if (mpi::n_ranks() == 1)
      {
        std::vector<Point<dim>> points(n);
        DoFTools::map_dofs_to_support_points(mapping, dof_handler, points);
        for (const auto &x : points)
          places.points.push_back(embedded(x));
      }
    else
      {
        std::map<types::global_dof_index, Point<dim>> points;
        DoFTools::map_dofs_to_support_points(mapping, dof_handler, points);
        for (const auto i : places.owned)
          places.points.push_back(embedded(points.at(i)));
      }
    // The owned DoFs come first in the mode vectors' layout.
    places.components.assign(dof_component.begin(), dof_component.begin() + n);
    return places;
  }


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
                       "nothing loads the body: every traction, pressure, "
                       "prescribed displacement and unit weight (of a "
                       "Fourier body: in harmonic 0, symmetric) is 0; "
                       "expected at least one that is not");
    for (const auto &system : systems)
      if (parameters.loading.control == LoadingParameters::Control::work &&
          system->unit_prescribed_displacement.linfty_norm() > 0)
        throw InputError(parameters.parameter_file,
                         "Loading/Control",
                         "'work' prescribes the work of the loads, but the "
                         "load factor also scales prescribed displacements "
                         "here (a Boundary's Displacement); expected 'load', "
                         "or a loading by tractions, pressures and weight");

    if (kinematics.is_fourier())
      return;
    const OwnedDofPlaces places = owned_dof_places();
    const FreeMotion     motion =
      mpi::n_ranks() == 1
            ? free_rigid_body_motion(places,
                                 systems[0]->constraints,
                                 systems[0]->condensed_stiffness)
            : free_rigid_body_motion(places,
                                 systems[0]->constraints,
                                 *systems[0]->distributed_stiffness);
    if (motion.description.empty())
      return;
    // Rounding leaves about 1e-15 of a motion nothing holds; more is a
    // motion the supports hold through a stiffness rounding swamps.
    if (motion.resistance > 1e-13)
      throw_ill_conditioned(motion.description, motion.resistance);
    throw InputError(parameters.parameter_file,
                     "Boundary <id>/Constrained components",
                     "the supports leave the body free to move: " +
                       motion.description +
                       " meets no constrained component; constrain enough "
                       "components to prevent every rigid-body motion");
  }


  template <int dim>
  void
  Analysis<dim>::throw_ill_conditioned(const std::string &motion,
                                       const double       resistance) const
  {
    using text_format::printf;
    // The largest ratio of bulk to shear modulus, K / G = 2 (1 + nu) /
    // (3 (1 - 2 nu)), and the range of Young's moduli.
    double             bulk_ratio = 0, stiffest = 0;
    double             softest        = std::numeric_limits<double>::max();
    types::material_id incompressible = 0, hard = 0, soft = 0;
    for (const auto &[id, material] : parameters.materials)
      {
        const double nu    = material.poissons_ratio;
        const double ratio = 2 * (1 + nu) / (3 * (1 - 2 * nu));
        if (ratio > bulk_ratio)
          std::tie(bulk_ratio, incompressible) = std::make_pair(ratio, id);
        if (material.youngs_modulus > stiffest)
          std::tie(stiffest, hard) =
            std::make_pair(material.youngs_modulus, id);
        if (material.youngs_modulus < softest)
          std::tie(softest, soft) = std::make_pair(material.youngs_modulus, id);
      }
    const std::string held =
      "the stiffness is too ill-conditioned for a solution to be trusted: "
      "the supports hold every rigid-body motion, but " +
      motion + " meets a stiffness only " + printf("%.1e", resistance) +
      " of the body's, which rounding (1e-15 of it) swamps: ";
    using Material = MaterialParameters;
    // The cause: the larger of the two ratios.
    if (bulk_ratio >= stiffest / softest && bulk_ratio > 100)
      throw InputError(
        parameters.parameter_file,
        Material::section(incompressible) + "/Poisson's ratio",
        held + "its Poisson's ratio " +
          printf("%.15g",
                 parameters.materials.at(incompressible).poissons_ratio) +
          " makes its bulk modulus " + printf("%.1e", bulk_ratio) +
          " times its shear modulus; expected a Poisson's "
          "ratio further from 0.5 (0.49 is nearly "
          "incompressible)");
    if (stiffest / softest > 100)
      throw InputError(parameters.parameter_file,
                       Material::section(soft) + "/Young's modulus",
                       held + "the Young's moduli range from " +
                         printf("%g", softest) + " (" +
                         Material::section(soft) + ") to " +
                         printf("%g", stiffest) + " (" +
                         Material::section(hard) + "), a ratio of " +
                         printf("%.1e", stiffest / softest) +
                         "; expected moduli closer to each other");
    if (!parameters.interface_elements.empty())
      throw InputError(parameters.parameter_file,
                       "Interface <id>/Normal stiffness",
                       held + "expected interface elements stiffer against the "
                              "cells beside them, or supports that hold the "
                              "body more firmly");
    throw InputError(parameters.parameter_file,
                     "Boundary <id>/Constrained components",
                     held + "expected supports that hold the body more firmly, "
                            "or cells of less extreme shape");
  }


  template <int dim>
  void
  Analysis<dim>::factorise_stiffness()
  {
    check_supports_and_load();
    if (linear_solver.kind == LinearSolverChoice::Kind::amg_cg)
      {
        set_up_iterative_solvers();
        return;
      }
    // Fourier harmonics are independent: with at least as many as ranks,
    // each rank factorises its harmonics whole and substitutes them at the
    // same time as the others (benchmarks/harmonics.py: substitutions 1.9
    // times faster than each harmonic split by MUMPS, for some 20% more
    // memory per rank).
    const bool spread = parameters.solver.spread_harmonics &&
                        mpi::n_ranks() > 1 &&
                        kinematics.n_modes() >= mpi::n_ranks();
    if (spread)
      linear_solver.description =
        "CHOLMOD for the harmonics' elastic stiffness, each whole on one "
        "rank (Spread harmonics over ranks); for Newton's tangents " +
        linear_solver.description;
    for (unsigned int m = 0; m < kinematics.n_modes(); ++m)
      {
        ModeSystem &mode = *systems[m];
        try
          {
            if (mpi::n_ranks() == 1)
              mode.factorisation.factorize(mode.condensed_stiffness);
            else if (spread)
              {
                mode.owner = m % mpi::n_ranks();
                mode.parts =
                  mpi::parts(owned_per_rank[mpi::rank()].n_elements());
                gather_whole(*mode.distributed_stiffness,
                             mode.owner,
                             mode.whole_sparsity,
                             mode.condensed_stiffness);
                mode.distributed_stiffness.reset();
                // Every rank learns whether the owner's factorisation
                // found the matrix singular.
                bool singular = false;
                if (mpi::rank() == mode.owner)
                  try
                    {
                      mode.factorisation.factorize(mode.condensed_stiffness);
                    }
                  catch (const SingularMatrix &)
                    {
                      singular = true;
                    }
                mode.condensed_stiffness.clear();
                if (mpi::sum(singular ? 1u : 0u) > 0)
                  throw SingularMatrix("CHOLMOD: the matrix is singular");
              }
            else
              {
                mode.distributed_factorisation =
                  std::make_unique<DistributedFactorisation>(
                    /*symmetric=*/true, linear_solver.block_low_rank_tolerance);
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
    const OwnedDofPlaces places = owned_dof_places();
    const auto motions = rigid_body_motions(places, kinematics.n_components());
    // PETSc's aggregation groups a node's unknowns where they follow one
    // another in component order (deal.II numbers a node's together) and
    // no rank splits a node.
    unsigned int block_size = kinematics.n_components();
    for (unsigned int k = 0; k < places.components.size(); ++k)
      if (places.components[k] != places.owned.nth_index_in_set(k) % block_size)
        block_size = 1;
    for (const IndexSet &owned : owned_per_rank)
      if (owned.n_elements() % block_size != 0)
        block_size = 1;
    if (mpi::n_ranks() > 1)
      block_size = Utilities::MPI::min(block_size, mpi::communicator());
    for (auto &system : systems)
      {
        // The condensed stiffness keeps a constrained DoF apart, on its
        // diagonal: a motion is nearly free only where it is zero there.
        auto free_motions = motions;
        for (auto &motion : free_motions)
          for (unsigned int k = 0; k < motion.size(); ++k)
            if (system->constraints.is_constrained(
                  places.owned.nth_index_in_set(k)))
              motion[k] = 0;
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
    ModeVectors         work = new_mode_vectors();
    for (unsigned int k = 0; k < 10; ++k)
      {
        Timer timer;
        for (unsigned int m = 0; m < systems.size(); ++m)
          {
            work[m] = systems[m]->unit_rhs;
            systems[m]->condense(work[m]);
          }
        elastic_solve(work);
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
    // few cells do not suppress: name the element, not the supports. So
    // have both hexahedra with 2x2x2 points (Q20's six modes die out in a
    // mesh of a few cells).
    if (parameters.discretisation.gauss_points_per_direction == 2)
      {
        if (dim == 3)
          throw InputError(parameters.parameter_file,
                           "Discretisation/Gauss points per direction",
                           matrix + "Q20 and Q27 with 2x2x2 Gauss points "
                                    "have spurious zero-energy modes that "
                                    "this mesh does not suppress; use more "
                                    "cells, or 3x3x3 points (or constrain "
                                    "enough components)");
        if (!parameters.discretisation.serendipity)
          throw InputError(parameters.parameter_file,
                           "Discretisation/Element",
                           matrix + "Q9 with 2x2 Gauss points has spurious "
                                    "zero-energy modes that this mesh does "
                                    "not suppress; use Q8, or 3x3 points (or "
                                    "constrain enough components)");
      }
    throw InputError(parameters.parameter_file,
                     "Boundary <id>/Constrained components",
                     matrix + "constrain enough displacement components to "
                              "prevent rigid-body motion");
  }


  template void
  Analysis<2>::elastic_solve(ModeVectors &);
  template OwnedDofPlaces
  Analysis<2>::owned_dof_places() const;
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
  template void
  Analysis<2>::throw_ill_conditioned(const std::string &, const double) const;
  template void
  Analysis<3>::elastic_solve(ModeVectors &);
  template OwnedDofPlaces
  Analysis<3>::owned_dof_places() const;
  template void
  Analysis<3>::check_supports_and_load() const;
  template void
  Analysis<3>::factorise_stiffness();
  template void
  Analysis<3>::set_up_iterative_solvers();
  template double
  Analysis<3>::linear_iterations_per_solve() const;
  template void
  Analysis<3>::time_substitution();
  template void
  Analysis<3>::throw_singular(const unsigned int) const;
  template void
  Analysis<3>::throw_ill_conditioned(const std::string &, const double) const;
} // namespace thinlayer
