#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <thinlayer/analysis/coupled_system.h>
#include <thinlayer/parallel/mpi.h>
#include <thinlayer/solvers/singular_matrix.h>

#include <algorithm>

namespace thinlayer
{
  CoupledSystem::CoupledSystem(
    const std::vector<const AffineConstraints<double> *> &mode_constraints,
    const types::global_dof_index                         n_dofs,
    const std::vector<IndexSet>                          &owned_per_rank,
    const bool                                            symmetric,
    const FactorisedStiffness::Method                     method)
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
          std::make_unique<DistributedFactorisation>(symmetric);
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
    try
      {
        if (factorisation)
          {
            matrix = 0;
            add_matrices([&](const std::vector<types::global_dof_index> &dofs,
                             const FullMatrix<double> &cell_matrix) {
              constraints.distribute_local_to_global(cell_matrix, dofs, matrix);
            });
            factorisation->factorize(matrix);
          }
        else
          {
            *distributed_matrix = 0;
            add_matrices([&](const std::vector<types::global_dof_index> &dofs,
                             const FullMatrix<double> &cell_matrix) {
              constraints.distribute_local_to_global(cell_matrix,
                                                     renumbered(dofs),
                                                     *distributed_matrix);
            });
            distributed_matrix->compress(VectorOperation::add);
            distributed_factorisation->factorize(*distributed_matrix,
                                                 rows_per_rank);
          }
      }
    catch (const SingularMatrix &)
      {
        return false;
      }
    return true;
  }


  void
  CoupledSystem::solve(const ModeVectors &residual, ModeVectors &correction)
  {
    if (factorisation)
      {
        for (unsigned int m = 0; m < n_modes; ++m)
          for (types::global_dof_index i = 0; i < n; ++i)
            vector[index(m, i)] = residual[m][i];
        factorisation->solve(make_array_view(vector));
        constraints.distribute(vector);
        for (unsigned int m = 0; m < n_modes; ++m)
          for (types::global_dof_index i = 0; i < n; ++i)
            correction[m][i] = vector[index(m, i)];
        return;
      }
    // The rank's rows: its own DoFs of each mode in turn (index()).
    const types::global_dof_index n_rows = n_owned[mpi::rank()];
    for (unsigned int m = 0; m < n_modes; ++m)
      for (types::global_dof_index k = 0; k < n_rows; ++k)
        vector[m * n_rows + k] = residual[m].local_element(k);
    distributed_factorisation->solve(make_array_view(vector));
    for (unsigned int m = 0; m < n_modes; ++m)
      {
        for (types::global_dof_index k = 0; k < n_rows; ++k)
          correction[m].local_element(k) = vector[m * n_rows + k];
        distribute(*mode_constraints[m], correction[m]);
      }
  }
} // namespace thinlayer
