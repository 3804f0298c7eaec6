#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/petsc_vector.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/sparsity_tools.h>

#include <thinlayer/analysis/coupled_system.h>
#include <thinlayer/base/work_counts.h>
#include <thinlayer/parallel/mpi.h>
#include <thinlayer/solvers/singular_matrix.h>

#include <algorithm>
#include <cmath>

#include <petscvec.h>

namespace thinlayer
{
  CoupledSystem::CoupledSystem(
    const std::vector<const AffineConstraints<double> *> &mode_constraints,
    const types::global_dof_index                         n_dofs,
    const std::vector<IndexSet>                          &owned_per_rank,
    const bool                                            symmetric,
    const FactorisedStiffness::Method                     method,
    const double block_low_rank_tolerance)
    : n_modes(mode_constraints.size())
    , n(n_dofs)
    , identity(owned_per_rank.empty() || mode_constraints.size() == 1)
    , mode_constraints(mode_constraints)
  {
    Assert(n_modes > 0, ExcMessage("A system needs a mode."));
    if (owned_per_rank.empty())
      factorisation = std::make_unique<FactorisedStiffness>(
        symmetric && method == FactorisedStiffness::Method::cholmod
          ? FactorisedStiffness::Method::cholmod
          : FactorisedStiffness::Method::umfpack);
    else
      {
        // Each rank's DoFs are contiguous and in rank order (as a
        // distributed DoFHandler numbers them).
        types::global_dof_index next = 0;
        for (const IndexSet &owned : owned_per_rank)
          {
            Assert(owned.n_elements() == 0 || owned.nth_index_in_set(0) == next,
                   ExcMessage("Each rank's DoFs must follow the last's."));
            first_dof.push_back(next);
            n_owned.push_back(owned.n_elements());
            next += owned.n_elements();
            IndexSet rows(n_modes * n);
            rows.add_range(n_modes * first_dof.back(), n_modes * next);
            rows_per_rank.push_back(rows);
          }
        distributed_factorisation =
          std::make_unique<DistributedFactorisation>(symmetric,
                                                     block_low_rank_tolerance);
        rows_of_a_mode = n_owned[mpi::rank()];
      }

    if (!owned_per_rank.empty())
      {
        // The system's rows of the DoFs this rank holds (each mode's
        // constraints keep their lines): the lines and couplings it keeps.
        std::vector<types::global_dof_index> rows;
        for (unsigned int m = 0; m < n_modes; ++m)
          for (const auto i : mode_constraints[m]->get_local_lines())
            rows.push_back(index(m, i));
        std::sort(rows.begin(), rows.end());
        held_rows.set_size(n_modes * n);
        held_rows.add_indices(rows.begin(), rows.end());
        held_rows.compress();
        constraints.reinit(held_rows);
      }
    // Each mode's constraints on its block.
    for (unsigned int m = 0; m < n_modes; ++m)
      if (owned_per_rank.empty())
        {
          AffineConstraints<double> shifted;
          shifted.copy_from(*mode_constraints[m]);
          shifted.shift(m * n);
          constraints.merge(shifted);
        }
      else
        for (const auto &line : mode_constraints[m]->get_lines())
          {
            const auto row = index(m, line.index);
            constraints.add_line(row);
            for (const auto &[column, weight] : line.entries)
              constraints.add_entry(row, index(m, column), weight);
            constraints.set_inhomogeneity(row, line.inhomogeneity);
          }
    constraints.close();
    vector.reinit(factorisation ? n_modes * n : n_modes * n_owned[mpi::rank()]);
  }


  CoupledSystem::~CoupledSystem() = default;


  types::global_dof_index
  CoupledSystem::index(const unsigned int            m,
                       const types::global_dof_index i) const
  {
    if (identity)
      return m * n + i;
    const unsigned int r =
      std::upper_bound(first_dof.begin(), first_dof.end(), i) -
      first_dof.begin() - 1;
    return n_modes * first_dof[r] + m * n_owned[r] + (i - first_dof[r]);
  }


  const std::vector<types::global_dof_index> &
  CoupledSystem::renumbered(
    const std::vector<types::global_dof_index> &dofs) const
  {
    renumbered_dofs.resize(dofs.size());
    for (unsigned int k = 0; k < dofs.size(); ++k)
      renumbered_dofs[k] = index(dofs[k] / n, dofs[k] % n);
    return renumbered_dofs;
  }


  void
  CoupledSystem::reinit(const std::function<void(const DofSink &)> &add_dofs)
  {
    // On several ranks, the rows of the DoFs this rank holds.
    DynamicSparsityPattern dsp = factorisation
                                   ? DynamicSparsityPattern(n_modes * n)
                                   : DynamicSparsityPattern(held_rows);
    add_dofs([&](const std::vector<types::global_dof_index> &dofs) {
      constraints.add_entries_local_to_global(renumbered(dofs),
                                              dsp,
                                              /*keep=*/true);
    });
    if (factorisation)
      {
        sparsity.copy_from(dsp);
        matrix.reinit(sparsity);
        return;
      }
    // Each rank's rows, from every rank's cells.
    const unsigned int me = mpi::rank();
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               rows_per_rank[me],
                                               mpi::communicator(),
                                               held_rows);
    distributed_matrix = std::make_unique<PETScWrappers::MPI::SparseMatrix>();
    distributed_matrix->reinit(rows_per_rank[me],
                               rows_per_rank[me],
                               dsp,
                               mpi::communicator());
  }


  bool
  CoupledSystem::factorise(
    const std::function<void(const CellMatrixSink &)> &add_matrices)
  {
    assemble(add_matrices);
    return factorise_assembled();
  }


  void
  CoupledSystem::assemble(
    const std::function<void(const CellMatrixSink &)> &add_matrices)
  {
    if (factorisation)
      {
        matrix = 0;
        add_matrices([&](const std::vector<types::global_dof_index> &dofs,
                         const FullMatrix<double> &cell_matrix) {
          constraints.distribute_local_to_global(cell_matrix, dofs, matrix);
        });
        return;
      }
    *distributed_matrix = 0;
    add_matrices([&](const std::vector<types::global_dof_index> &dofs,
                     const FullMatrix<double>                   &cell_matrix) {
      constraints.distribute_local_to_global(cell_matrix,
                                             renumbered(dofs),
                                             *distributed_matrix);
    });
    distributed_matrix->compress(VectorOperation::add);
  }


  bool
  CoupledSystem::factorise_assembled()
  {
    held_factor = false;
    try
      {
        if (factorisation)
          factorisation->factorize(matrix);
        else
          distributed_factorisation->factorize(*distributed_matrix,
                                               rows_per_rank);
      }
    catch (const SingularMatrix &)
      {
        return false;
      }
    held_factor = true;
    return true;
  }


  bool
  CoupledSystem::has_factor() const
  {
    return held_factor;
  }


  FactorCost
  CoupledSystem::factor_cost() const
  {
    if (!held_factor)
      return FactorCost();
    return factorisation ? factorisation->cost()
                         : distributed_factorisation->cost();
  }


  types::global_dof_index
  CoupledSystem::row(const unsigned int            m,
                     const types::global_dof_index k) const
  {
    // On several ranks the rank's rows: its own DoFs of each mode in turn
    // (index()).
    return factorisation ? index(m, k) : m * rows_of_a_mode + k;
  }


  void
  CoupledSystem::gather(const ModeVectors &residual)
  {
    const types::global_dof_index n_rows = residual[0].locally_owned_size();
    for (unsigned int m = 0; m < n_modes; ++m)
      for (types::global_dof_index k = 0; k < n_rows; ++k)
        vector[row(m, k)] = residual[m].local_element(k);
  }


  void
  CoupledSystem::scatter(ModeVectors &correction)
  {
    if (factorisation)
      constraints.distribute(vector);
    const types::global_dof_index n_rows = correction[0].locally_owned_size();
    for (unsigned int m = 0; m < n_modes; ++m)
      {
        for (types::global_dof_index k = 0; k < n_rows; ++k)
          correction[m].local_element(k) = vector[row(m, k)];
        if (!factorisation)
          distribute(*mode_constraints[m], correction[m]);
      }
  }


  void
  CoupledSystem::solve(const ModeVectors &residual, ModeVectors &correction)
  {
    Assert(held_factor, ExcMessage("No factor is held."));
    gather(residual);
    if (factorisation)
      factorisation->solve(make_array_view(vector));
    else
      distributed_factorisation->solve(make_array_view(vector));
    scatter(correction);
  }


  namespace
  {
    /**
     * Right-preconditioned GMRES on A x = b from x = 0, to |b - A x| <=
     * @p relative_tolerance |b|, its Krylov space as long as its iteration
     * limit (no restart: a preconditioner that needs a restart no longer
     * serves). Returns the iterations, or nothing if it did not converge.
     */
    template <typename VectorType, typename MatrixType, typename Precondition>
    std::optional<unsigned int>
    gmres(const MatrixType   &A,
          VectorType         &x,
          const VectorType   &b,
          const Precondition &preconditioner,
          const double        relative_tolerance,
          const unsigned int  max_iterations)
    {
      x                 = 0;
      const double norm = b.l2_norm();
      if (norm == 0)
        return 0;
      SolverControl                                    control(max_iterations,
                            relative_tolerance * norm,
                            /*log_history=*/false,
                            /*log_result=*/false);
      typename SolverGMRES<VectorType>::AdditionalData data(
        max_iterations + 2, /*right_preconditioning=*/true);
      SolverGMRES<VectorType> solver(control, data);
      try
        {
          solver.solve(A, x, b, preconditioner);
        }
      catch (const SolverControl::NoConvergence &)
        {
          work_counts().krylov_iterations += control.last_step();
          return {};
        }
      work_counts().krylov_iterations += control.last_step();
      if (!std::isfinite(control.last_value()))
        return {};
      return control.last_step();
    }


    /// A preconditioner from a solve in place of an array of rows.
    struct RowSolve
    {
      std::function<void(const ArrayView<double> &)> solve;

      void
      vmult(Vector<double> &dst, const Vector<double> &src) const
      {
        dst = src;
        solve(make_array_view(dst));
      }

      void
      vmult(PETScWrappers::MPI::Vector       &dst,
            const PETScWrappers::MPI::Vector &src) const
      {
        dst               = src;
        PetscScalar *rows = nullptr;
        PetscInt     n_rows;
        VecGetLocalSize(dst, &n_rows);
        VecGetArray(dst, &rows);
        solve(make_array_view(rows, rows + n_rows));
        VecRestoreArray(dst, &rows);
      }
    };
  } // namespace


  std::optional<unsigned int>
  CoupledSystem::solve_iteratively(const ModeVectors &residual,
                                   ModeVectors       &correction,
                                   const double       relative_tolerance,
                                   const unsigned int max_iterations,
                                   const ModeSolve   *elastic_solve)
  {
    Assert(elastic_solve || held_factor, ExcMessage("No factor is held."));
    RowSolve preconditioner;
    if (elastic_solve)
      {
        // The system's rows into the modes' vectors, each mode's elastic
        // solve, and back.
        mode_work            = residual;
        preconditioner.solve = [this,
                                elastic_solve](const ArrayView<double> &rows) {
          const types::global_dof_index n_rows =
            mode_work[0].locally_owned_size();
          for (unsigned int m = 0; m < n_modes; ++m)
            for (types::global_dof_index k = 0; k < n_rows; ++k)
              mode_work[m].local_element(k) = rows[row(m, k)];
          (*elastic_solve)(mode_work);
          for (unsigned int m = 0; m < n_modes; ++m)
            for (types::global_dof_index k = 0; k < n_rows; ++k)
              rows[row(m, k)] = mode_work[m].local_element(k);
        };
      }
    else if (factorisation)
      preconditioner.solve = [this](const ArrayView<double> &rows) {
        factorisation->solve(rows);
      };
    else
      preconditioner.solve = [this](const ArrayView<double> &rows) {
        distributed_factorisation->solve(rows);
      };

    gather(residual);
    std::optional<unsigned int> iterations;
    if (factorisation)
      {
        krylov_solution.reinit(vector.size(), /*omit_zeroing=*/true);
        iterations = gmres(matrix,
                           krylov_solution,
                           vector,
                           preconditioner,
                           relative_tolerance,
                           max_iterations);
        vector     = krylov_solution;
      }
    else
      {
        if (!distributed_rhs)
          {
            const IndexSet &rows = rows_per_rank[mpi::rank()];
            distributed_rhs =
              std::make_unique<PETScWrappers::MPI::Vector>(rows,
                                                           mpi::communicator());
            distributed_solution =
              std::make_unique<PETScWrappers::MPI::Vector>(rows,
                                                           mpi::communicator());
          }
        PetscScalar *entries = nullptr;
        VecGetArray(*distributed_rhs, &entries);
        std::copy(vector.begin(), vector.end(), entries);
        VecRestoreArray(*distributed_rhs, &entries);
        iterations = gmres(*distributed_matrix,
                           *distributed_solution,
                           *distributed_rhs,
                           preconditioner,
                           relative_tolerance,
                           max_iterations);
        VecGetArray(*distributed_solution, &entries);
        std::copy(entries, entries + vector.size(), vector.begin());
        VecRestoreArray(*distributed_solution, &entries);
      }
    if (iterations)
      scatter(correction);
    return iterations;
  }
} // namespace thinlayer
