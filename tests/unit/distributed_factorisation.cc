// DistributedFactorisation (MUMPS through PETSc) on two ranks, on the 3D
// seven-point Laplacian of an n^3 grid (symmetric positive definite, its
// fronts large enough for MUMPS to compress). Truths checked:
// 1. Without compression the solution of A x = b solves it to round-off:
//    max |A x - b| / max |b| below 1e-12.
// 2. With block low-rank compression to 1e-8 of the matrix's norm (what
//    Solver/Linear solver = automatic asks for on several ranks) the
//    solution is the uncompressed one's to 1e-5: the tolerance times the
//    matrix's condition number (about 700 for n = 40) bounds the error.
// 3. The tolerance is relative: the matrix in other units (times 1e5)
//    gives the same relative difference, to 1e-3 of it.
// 4. With a coarse compression (1e-2) the solution differs from the
//    uncompressed one by more than 1e-8 and less than 1: the tolerance
//    reaches MUMPS, and the factor is then an approximation (a
//    preconditioner, as the constant-stiffness methods use it).
#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/petsc_sparse_matrix.h>

#include <thinlayer/parallel/mpi.h>
#include <thinlayer/solvers/distributed_factorisation.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

#include "../common/parallel_truths.h"

using namespace thinlayer;

namespace
{
  constexpr unsigned int n    = 40;
  constexpr unsigned int size = n * n * n;

  /// The grid neighbours of unknown @p i (its stencil without itself).
  std::vector<unsigned int>
  neighbours(const unsigned int i)
  {
    const unsigned int        x = i % n, y = (i / n) % n, z = i / (n * n);
    std::vector<unsigned int> result;
    if (x > 0)
      result.push_back(i - 1);
    if (x + 1 < n)
      result.push_back(i + 1);
    if (y > 0)
      result.push_back(i - n);
    if (y + 1 < n)
      result.push_back(i + n);
    if (z > 0)
      result.push_back(i - n * n);
    if (z + 1 < n)
      result.push_back(i + n * n);
    return result;
  }


  /// The right-hand side: smooth, and nowhere zero.
  double
  rhs(const unsigned int i)
  {
    return 1. + std::sin(0.1 * i);
  }


  /// max |A x - b| / max |b| over the whole vector @p x.
  double
  residual(const std::vector<double> &x)
  {
    double worst = 0, largest = 0;
    for (unsigned int i = 0; i < size; ++i)
      {
        double ax = 6 * x[i];
        for (const unsigned int j : neighbours(i))
          ax -= x[j];
        worst   = std::max(worst, std::abs(ax - rhs(i)));
        largest = std::max(largest, std::abs(rhs(i)));
      }
    return worst / largest;
  }


  /// The whole solution of A x = b by a factorisation with compression to
  /// @p tolerance (0: none), on every rank.
  std::vector<double>
  solve(const PETScWrappers::MPI::SparseMatrix &matrix,
        const std::vector<IndexSet>            &owned_per_rank,
        const double                            tolerance)
  {
    DistributedFactorisation factor(/*symmetric=*/true, tolerance);
    factor.factorize(matrix, owned_per_rank);
    const IndexSet     &owned = owned_per_rank[mpi::rank()];
    std::vector<double> rows;
    for (const auto i : owned)
      rows.push_back(rhs(i));
    factor.solve(make_array_view(rows));
    std::vector<double> whole;
    for (const auto &part :
         Utilities::MPI::all_gather(mpi::communicator(), rows))
      whole.insert(whole.end(), part.begin(), part.end());
    return whole;
  }


  /// The Laplacian times @p scale, its rows distributed as
  /// @p owned_per_rank says.
  void
  laplacian(const std::vector<IndexSet>      &owned_per_rank,
            const double                      scale,
            PETScWrappers::MPI::SparseMatrix &matrix)
  {
    const IndexSet        &owned = owned_per_rank[mpi::rank()];
    DynamicSparsityPattern pattern(size, size, owned);
    for (const auto i : owned)
      {
        pattern.add(i, i);
        for (const unsigned int j : neighbours(i))
          pattern.add(i, j);
      }
    matrix.reinit(owned, owned, pattern, mpi::communicator());
    for (const auto i : owned)
      {
        matrix.set(i, i, 6. * scale);
        for (const unsigned int j : neighbours(i))
          matrix.set(i, j, -scale);
      }
    matrix.compress(VectorOperation::insert);
  }


  double
  relative_difference(const std::vector<double> &a,
                      const std::vector<double> &b)
  {
    double difference = 0, largest = 0;
    for (unsigned int i = 0; i < a.size(); ++i)
      {
        difference = std::max(difference, std::abs(a[i] - b[i]));
        largest    = std::max(largest, std::abs(b[i]));
      }
    return difference / largest;
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi_session(argc, argv, 1);
  truths::print_on_rank_zero();
  const unsigned int ranks = mpi::n_ranks();
  std::cout << "ranks: " << ranks << ", unknowns: " << size << '\n';

  // Each rank's contiguous rows, in rank order.
  std::vector<IndexSet> owned_per_rank;
  for (unsigned int r = 0; r < ranks; ++r)
    {
      IndexSet owned(size);
      owned.add_range(size * r / ranks, size * (r + 1) / ranks);
      owned_per_rank.push_back(owned);
    }
  PETScWrappers::MPI::SparseMatrix matrix, scaled;
  laplacian(owned_per_rank, 1, matrix);
  laplacian(owned_per_rank, 1e5, scaled);

  std::cout << "1. without compression\n";
  const std::vector<double> exact = solve(matrix, owned_per_rank, 0);
  truths::expect_everywhere(residual(exact) < 1e-12,
                            "max |A x - b| / max |b| below 1e-12");

  std::cout << "2. compressed to 1e-8\n";
  const std::vector<double> fine  = solve(matrix, owned_per_rank, 1e-8);
  const double              error = relative_difference(fine, exact);
  truths::expect_everywhere(error < 1e-5, "the uncompressed solution to 1e-5");

  std::cout << "3. the matrix times 1e5, compressed to 1e-8\n";
  std::vector<double> scaled_exact = solve(scaled, owned_per_rank, 0);
  std::vector<double> scaled_fine  = solve(scaled, owned_per_rank, 1e-8);
  const double error_scaled = relative_difference(scaled_fine, scaled_exact);
  truths::expect_everywhere(std::abs(error_scaled - error) <= 1e-3 * error,
                            "the same relative difference, to 1e-3 of it");

  std::cout << "4. compressed to 1e-2\n";
  const std::vector<double> coarse = solve(matrix, owned_per_rank, 1e-2);
  const double              off    = relative_difference(coarse, exact);
  truths::expect_everywhere(off > 1e-8 && off < 1,
                            "differs from the uncompressed solution by more "
                            "than 1e-8 and less than 1");

  return truths::conclude();
}
