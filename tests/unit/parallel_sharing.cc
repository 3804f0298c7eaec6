// Truths checked for the parallel room (thinlayer::mpi, partition_cells()),
// run on three ranks:
// 1. The partition gives every cell one rank, the same on every rank, and
//    each rank a share within 20% of an equal one; on one rank every cell
//    is rank 0's.
//    The mesh split by it (distribute_mesh()): each rank holds its own
//    cells and the cells that share a vertex with them, with their
//    material ids, CellIds and owners (partition_of()). Its DoFs numbered
//    rank by rank: the sets contiguous ranges in rank order, each DoF on a
//    cell of its rank; cell_of() finds a cell by its CellId.
//    Joined cells (the sides of zero-thickness elements) share a rank,
//    directly or through another, also when there are fewer cells than
//    ranks.
// 2. A summed vector is the exact sum of every rank's values, bit for bit
//    the same on every rank.
// 3. Profile values (sum_over_ranks()): every rank receives each sample's
//    values from the rank that computed them, every member and the flag,
//    a NaN mobilised strength too.
// 4. An InputError met by rank 0 in on_root() is thrown on every rank with
//    the same file, entry and expectation; rank 0's text reaches all.
// Each rank checks; rank 0 prints whether every rank's check held.
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>

#include <thinlayer/base/input_error.h>
#include <thinlayer/elements/interface_values.h>
#include <thinlayer/parallel/cell_partition.h>
#include <thinlayer/parallel/distributed_mesh.h>
#include <thinlayer/parallel/mpi.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <sstream>

#include "../common/parallel_truths.h"

using namespace thinlayer;


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi_session(argc, argv, 1);
  const unsigned int               n = mpi::n_ranks(), me = mpi::rank();
  if (mpi::is_root())
    std::cout << "ranks: " << n << '\n';

  if (mpi::is_root())
    std::cout << "1. Partition\n";
  {
    Triangulation<2> tria;
    GridGenerator::subdivided_hyper_cube(tria, 12);
    const CellPartition       partition = partition_cells(tria, n, me);
    std::vector<unsigned int> count(n, 0);
    bool                      valid = partition.owner.size() == 144;
    for (const unsigned int r : partition.owner)
      if (r < n)
        ++count[r];
      else
        valid = false;
    truths::expect_everywhere(valid, "every cell has one rank of the run");
    const std::vector<unsigned int> roots =
      Utilities::MPI::broadcast(mpi::communicator(), partition.owner, 0);
    truths::expect_everywhere(roots == partition.owner,
                              "the same on every rank");
    const double equal = 144. / n;
    truths::expect_everywhere(*std::min_element(count.begin(), count.end()) >=
                                  0.8 * equal &&
                                *std::max_element(count.begin(), count.end()) <=
                                  1.2 * equal,
                              "every rank's share within 20% of an equal one");
    truths::expect_everywhere(partition.owned_cells().size() == count[me],
                              "owned_cells() lists this rank's cells");
    // The split mesh: each rank's own cells those the partition gives it,
    // its ghosts every other cell that shares a vertex with one of them,
    // material ids and CellIds kept.
    for (const auto &cell : tria.active_cell_iterators())
      cell->set_material_id(cell->active_cell_index() % 7);
    const auto        part = distribute_mesh(tria, partition);
    std::vector<bool> near_own(tria.n_active_cells(), false);
    for (const auto &cell : tria.active_cell_iterators())
      if (partition.owner[cell->active_cell_index()] == me)
        for (const unsigned int v : cell->vertex_indices())
          for (const auto &other : tria.active_cell_iterators())
            for (const unsigned int w : other->vertex_indices())
              if (other->vertex_index(w) == cell->vertex_index(v))
                near_own[other->active_cell_index()] = true;
    bool         same_cells = true, same_ids = true;
    unsigned int n_own = 0, n_held = 0;
    for (const auto &cell : part->active_cell_iterators())
      if (!cell->is_artificial())
        {
          const unsigned int c = cell->id().get_coarse_cell_id();
          ++n_held;
          n_own += cell->is_locally_owned() ? 1 : 0;
          same_cells =
            same_cells && near_own[c] &&
            cell->subdomain_id() == partition.owner[c] &&
            cell->center().distance(
              tria.create_cell_iterator(cell->id())->center()) < 1e-12;
          same_ids = same_ids && cell->material_id() == c % 7;
        }
    truths::expect_everywhere(
      same_cells && n_own == count[me] &&
        n_held == static_cast<unsigned int>(
                    std::count(near_own.begin(), near_own.end(), true)),
      "the split mesh: the rank's own cells and those that share a vertex "
      "with them");
    truths::expect_everywhere(same_ids, "material ids kept");
    const CellPartition held   = partition_of(*part, n, me);
    bool                agrees = held.owned_cells().size() == count[me];
    for (const auto &cell : part->active_cell_iterators())
      agrees =
        agrees && held.owner[cell->active_cell_index()] ==
                    (cell->is_artificial() ? numbers::invalid_unsigned_int
                                           : cell->subdomain_id());
    truths::expect_everywhere(agrees,
                              "partition_of() gives the held cells' owners");

    // The DoFs of the split mesh: each rank's one range, in rank order, as
    // the ModeVectors and the distributed matrices take them.
    DoFHandler<2> dof_handler(*part);
    dof_handler.distribute_dofs(FESystem<2>(FE_Q<2>(2), 2));
    const std::vector<IndexSet> owned =
      Utilities::MPI::all_gather(mpi::communicator(),
                                 dof_handler.locally_owned_dofs());
    types::global_dof_index next       = 0;
    bool                    contiguous = owned.size() == n;
    for (const IndexSet &set : owned)
      {
        contiguous = contiguous && set.is_contiguous() &&
                     (set.n_elements() == 0 || *set.begin() == next);
        next += set.n_elements();
      }
    truths::expect_everywhere(contiguous && next == dof_handler.n_dofs(),
                              "the DoFs of each rank one range, in rank order");
    IndexSet                             on_own_cell(dof_handler.n_dofs());
    std::vector<types::global_dof_index> dofs(
      dof_handler.get_fe().n_dofs_per_cell());
    bool found = true;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          on_own_cell.add_indices(dofs.begin(), dofs.end());
          found = found && cell_of(dof_handler, cell->id()) == cell;
        }
    IndexSet elsewhere = owned[me];
    elsewhere.subtract_set(on_own_cell);
    truths::expect_everywhere(elsewhere.n_elements() == 0,
                              "every DoF on a cell of its rank");
    truths::expect_everywhere(found, "cell_of() finds a cell by its CellId");
    const CellPartition one = partition_cells(tria, 1, 0);
    truths::expect_everywhere(std::all_of(one.owner.begin(),
                                          one.owner.end(),
                                          [](const unsigned int r) {
                                            return r == 0;
                                          }),
                              "on one rank, every cell is rank 0's");

    // Opposite corners, joined; the far corner also to a middle cell, so
    // that the three go together; and a mesh of fewer cells than ranks.
    const std::vector<std::pair<unsigned int, unsigned int>> joined = {
      {0, 143}, {143, 78}, {5, 100}};
    const CellPartition together = partition_cells(tria, n, me, joined);
    truths::expect_everywhere(
      together.owner[0] == together.owner[143] &&
        together.owner[143] == together.owner[78] &&
        together.owner[5] == together.owner[100],
      "joined cells on one rank, directly or through another");
    Triangulation<2> two;
    GridGenerator::subdivided_hyper_rectangle(two,
                                              {2, 1},
                                              Point<2>(0, 0),
                                              Point<2>(2, 1));
    const CellPartition few = partition_cells(two, n, me, {{1, 0}});
    truths::expect_everywhere(few.owner[0] == few.owner[1],
                              "joined on one rank with fewer cells than ranks");
  }

  if (mpi::is_root())
    std::cout << "2. Sums\n";
  {
    Vector<double> v(1000);
    for (unsigned int i = 0; i < v.size(); ++i)
      v[i] = (me + 1) * 0.1 * (i + 1);
    mpi::sum(v);
    bool exact = true;
    for (unsigned int i = 0; i < v.size(); ++i)
      {
        double expected = 0;
        for (unsigned int r = 0; r < n; ++r)
          expected += (r + 1) * 0.1 * (i + 1);
        exact = exact && std::abs(v[i] - expected) <= 1e-12 * expected;
      }
    truths::expect_everywhere(exact,
                              "the sum of every rank's values (to 1e-12)");
    const Vector<double> roots =
      Utilities::MPI::broadcast(mpi::communicator(), v, 0);
    bool same = true;
    for (unsigned int i = 0; i < v.size(); ++i)
      same = same && roots[i] == v[i];
    truths::expect_everywhere(same, "bit for bit the same on every rank");
    truths::expect_everywhere(mpi::sum(me + 1) == n * (n + 1) / 2,
                              "counts summed exactly");
  }

  if (mpi::is_root())
    std::cout << "3. Profile values from their owners\n";
  {
    const unsigned int n_samples = 50;
    const auto owner = [n](const unsigned int k) { return (7 * k) % n; };
    // Sample k's values at its owner: k + j / 10 for member j, the flag
    // set for odd k, the mobilised strength NaN for every fifth.
    const auto expected = [](const unsigned int k) {
      const double    x = k;
      InterfaceValues v{x + 0.0,
                        x + 0.1,
                        x + 0.2,
                        x + 0.3,
                        x + 0.4,
                        x + 0.5,
                        x + 0.6,
                        x + 0.7,
                        k % 5 == 0 ? std::numeric_limits<double>::quiet_NaN()
                                   : x + 0.8,
                        k % 2 == 1};
      return v;
    };
    std::vector<InterfaceValues> values(n_samples);
    for (unsigned int k = 0; k < n_samples; ++k)
      if (owner(k) == me)
        values[k] = expected(k);
    sum_over_ranks(values);
    bool owners = true;
    for (unsigned int k = 0; k < n_samples; ++k)
      {
        const InterfaceValues &v = values[k], e = expected(k);
        owners =
          owners && v.slip == e.slip &&
          v.slip_out_of_plane == e.slip_out_of_plane &&
          v.opening == e.opening && v.slip_increment == e.slip_increment &&
          v.opening_increment == e.opening_increment &&
          v.shear_traction == e.shear_traction &&
          v.shear_traction_out_of_plane == e.shear_traction_out_of_plane &&
          v.normal_traction == e.normal_traction &&
          (k % 5 == 0 ? std::isnan(v.mobilised_strength)
                      : v.mobilised_strength == e.mobilised_strength) &&
          v.plastic == e.plastic;
      }
    truths::expect_everywhere(owners, "every sample's values are its owner's");
  }

  if (mpi::is_root())
    std::cout << "4. Work on rank 0\n";
  {
    bool same_error = false;
    try
      {
        mpi::on_root([]() -> std::string {
          throw InputError("scene.prm", "Mesh/File", "a .geo");
        });
      }
    catch (const InputError &e)
      {
        same_error = e.file == "scene.prm" && e.entry == "Mesh/File" &&
                     e.expected == "a .geo";
      }
    truths::expect_everywhere(same_error,
                              "rank 0's InputError is thrown on every rank");
    const std::string text =
      mpi::on_root([]() { return std::string("staging-1"); });
    truths::expect_everywhere(text == "staging-1",
                              "rank 0's text reaches every rank");
  }

  const int failures =
    Utilities::MPI::max(truths::failures, mpi::communicator());
  if (mpi::is_root())
    return truths::conclude();
  return failures == 0 ? 0 : 1;
}
