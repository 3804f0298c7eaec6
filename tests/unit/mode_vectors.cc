// Truths checked for the distributed mode vectors (ModeVector, condense(),
// distribute(), Analysis::whole()), on the elastic cylinder under Fourier
// kinematics (harmonics 0, 1, 2: the axis lines of harmonic 1 tie u_r to
// u_theta; Q8: each centre node tied to its cell's other nodes), run on one
// rank and on three:
// 1. Layout: every DoF is owned by exactly one rank, the ranks' ranges
//    contiguous and in rank order; on several ranks a rank stores fewer
//    entries (its own and its ghosts) than the whole vector.
// 2. whole() gives every rank each DoF's value from its owner.
// 3. GhostValues: while it lives every ghost holds its owner's value;
//    afterwards the ghosts are zero again.
// 4. condense() and distribute() on the distributed vector (each rank
//    keeping the lines of the DoFs it holds) give what deal.II's
//    AffineConstraints, with every rank's lines, gives on the whole vector,
//    to 1e-14 of the vector's largest entry (the contributions a line adds
//    to another rank's DoF are summed in another order).
// 5. The elastic solve of the distributed right-hand side has the residual
//    of the whole one: |K u - f| <= 1e-10 |f| with K assembled whole.
// Each rank checks; rank 0 prints whether every rank's check held.
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>

#include <thinlayer/analysis/analysis.h>
#include <thinlayer/mesh/scene.h>
#include <thinlayer/parallel/mpi.h>
#include <thinlayer/parameters/parameter_reader.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "../common/parallel_truths.h"
#include "../common/scene_test_utilities.h"

using namespace thinlayer;

namespace
{
  /// A value for DoF @p i that no two DoFs share.
  double
  value_of(const types::global_dof_index i)
  {
    return std::sin(1. + 0.37 * i) + 0.001 * i;
  }


  /// @p v with value_of() at each owned DoF, its ghosts zero.
  void
  fill(ModeVector &v)
  {
    for (unsigned int k = 0; k < v.locally_owned_size(); ++k)
      v.local_element(k) = value_of(v.get_partitioner()->local_to_global(k));
  }


  /**
   * The lines of every DoF, each from the rank that owns it: each rank
   * keeps the lines of the DoFs it holds only, and deal.II's operations on
   * a whole vector need them all.
   */
  AffineConstraints<double>
  every_ranks_lines(const AffineConstraints<double> &constraints,
                    const DoFHandler<2>             &dof_handler)
  {
    using Line = std::pair<
      types::global_dof_index,
      std::pair<std::vector<std::pair<types::global_dof_index, double>>,
                double>>;
    std::vector<Line> own;
    for (const auto &line : constraints.get_lines())
      if (dof_handler.locally_owned_dofs().is_element(line.index))
        own.push_back({line.index, {line.entries, line.inhomogeneity}});
    AffineConstraints<double> whole;
    for (const auto &part :
         Utilities::MPI::all_gather(mpi::communicator(), own))
      for (const auto &[dof, line] : part)
        {
          whole.add_line(dof);
          whole.add_entries(dof, line.first);
          whole.set_inhomogeneity(dof, line.second);
        }
    whole.close();
    return whole;
  }


  double
  largest_difference(const Vector<double> &a, const Vector<double> &b)
  {
    double result = a.size() == b.size() ? 0 : 1e300;
    for (unsigned int i = 0; i < std::min(a.size(), b.size()); ++i)
      result = std::max(result, std::abs(a[i] - b[i]));
    return result;
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi_session(argc, argv, 1);
  const std::string                prm = thinlayer_tests::elastic_cylinder(
    "  set Harmonics = 0, 1, 2\n  set Stations = 0, 45, 90, 135, 180\n",
    "subsection Boundary 1\n"
                   "  set Constrained components = r, z, theta\n"
                   "end\n"
                   "subsection Boundary 3\n"
                   "  set Traction = 1; -2; 0.5\n"
                   "end\n");
  const Parameters   p = ParameterReader().read_from_string(prm, "vectors.prm");
  std::ostringstream quiet;
  const Scene<2>     scene(p, quiet);
  Analysis<2>        analysis(p, scene.triangulation());
  analysis.setup();
  const types::global_dof_index n       = analysis.get_dof_handler().n_dofs();
  ModeVectors                   vectors = analysis.new_mode_vectors();

  if (mpi::is_root())
    std::cout << "1. Layout\n";
  {
    const ModeVector &v      = vectors[0];
    const auto [first, last] = v.get_partitioner()->local_range();
    const auto firsts = Utilities::MPI::all_gather(mpi::communicator(), first);
    const auto lasts  = Utilities::MPI::all_gather(mpi::communicator(), last);
    bool       contiguous = firsts.front() == 0 && lasts.back() == n;
    for (unsigned int r = 1; r < firsts.size(); ++r)
      contiguous = contiguous && firsts[r] == lasts[r - 1];
    truths::expect_everywhere(contiguous,
                              "the ranks own contiguous ranges in rank order, "
                              "together every DoF once");
    const std::size_t stored =
      v.locally_owned_size() + v.get_partitioner()->n_ghost_indices();
    truths::expect_everywhere(
      mpi::n_ranks() == 1 ? stored == n : stored < n,
      "on several ranks a rank stores less than the whole "
      "vector");
  }

  if (mpi::is_root())
    std::cout << "2. whole()\n";
  {
    fill(vectors[0]);
    const Vector<double> whole = analysis.whole(vectors[0]);
    bool                 right = whole.size() == n;
    for (unsigned int i = 0; right && i < n; ++i)
      right = whole[i] == value_of(i);
    truths::expect_everywhere(
      right, "every DoF's value from its owner, on every rank");
  }

  if (mpi::is_root())
    std::cout << "3. Ghost values\n";
  {
    const ModeVector &v        = vectors[0];
    const IndexSet   &ghost    = v.get_partitioner()->ghost_indices();
    bool              imported = true, zeroed = true;
    {
      const GhostValues ghosts(v);
      for (const auto g : ghost)
        imported = imported && v(g) == value_of(g);
    }
    // The ghosts are stored after the rank's own entries; reading them
    // through the vector asserts that they are imported.
    zeroed = !v.has_ghost_elements();
    for (unsigned int k = 0; k < ghost.n_elements(); ++k)
      zeroed = zeroed && v.begin()[v.locally_owned_size() + k] == 0;
    truths::expect_everywhere(imported,
                              "while imported, each ghost is its owner's");
    truths::expect_everywhere(zeroed,
                              "afterwards the ghosts are zero, not imported");
  }

  if (mpi::is_root())
    std::cout << "4. condense() and distribute() against deal.II's, whole\n";
  {
    double condensed = 0, distributed = 0, scale = 0;
    for (unsigned int m = 0; m < analysis.n_modes(); ++m)
      {
        const AffineConstraints<double> &constraints =
          analysis.get_mode_system(m).constraints;
        const AffineConstraints<double> whole_constraints =
          every_ranks_lines(constraints, analysis.get_dof_handler());
        ModeVector &v = vectors[m];
        fill(v);
        Vector<double> serial = analysis.whole(v);
        scale                 = std::max(scale, serial.linfty_norm());
        whole_constraints.condense(serial);
        condense(constraints, v);
        condensed =
          std::max(condensed, largest_difference(analysis.whole(v), serial));

        fill(v);
        serial = analysis.whole(v);
        whole_constraints.distribute(serial);
        distribute(constraints, v);
        distributed =
          std::max(distributed, largest_difference(analysis.whole(v), serial));
      }
    truths::expect_everywhere(condensed <= 1e-14 * scale,
                              "condense(): the same");
    truths::expect_everywhere(distributed <= 1e-14 * scale,
                              "distribute(): the same");
  }

  if (mpi::is_root())
    std::cout << "5. The elastic solve\n";
  {
    // The condensed stiffness K of each mode as its factors have it: each
    // rank's cells' part, assembled as the analysis assembles it; K u is
    // the sum over the ranks of each part times the whole solution.
    bool small = true;
    for (unsigned int m = 0; m < analysis.n_modes(); ++m)
      {
        const ModeSystem &mode = analysis.get_mode_system(m);
        ModeVector        u(mode.unit_rhs);
        condense(mode.constraints, u);
        const Vector<double> f = analysis.whole(u);
        analysis.elastic_solve(m, u);
        const Vector<double> x = analysis.whole(u);

        DynamicSparsityPattern dsp(n);
        DoFTools::make_sparsity_pattern(analysis.get_dof_handler(),
                                        dsp,
                                        mode.constraints,
                                        /*keep_constrained_dofs=*/true);
        SparsityPattern pattern;
        pattern.copy_from(dsp);
        SparseMatrix<double> K(pattern);
        analysis.get_cells().assemble_elastic(
          m, [&](const auto &dofs, const FullMatrix<double> &matrix) {
            mode.constraints.distribute_local_to_global(matrix, dofs, K);
          });
        Vector<double> r(n);
        K.vmult(r, x);
        mpi::sum(r);
        r -= f;
        small = small && r.linfty_norm() <= 1e-10 * f.linfty_norm();
      }
    truths::expect_everywhere(small,
                              "|K u - f| <= 1e-10 |f| for every harmonic");
  }
  return mpi::is_root() ? truths::conclude() : (truths::failures > 0);
}
