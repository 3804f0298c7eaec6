#ifndef thinlayer_parallel_cell_partition_h
#define thinlayer_parallel_cell_partition_h

#include <deal.II/grid/tria.h>

#include <utility>
#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /**
   * Which rank owns each active cell of a mesh: the rank that runs the
   * point rules of its Gauss points and holds the authoritative copy of
   * their states. Of the whole mesh (partition_cells()), the same on every
   * rank; of a rank's part of a distributed mesh (partition_of()), its
   * cells'.
   */
  struct CellPartition
  {
    /// The rank of every active cell (numbers::invalid_unsigned_int where
    /// the mesh is a rank's part and the cell one it does not hold).
    std::vector<unsigned int> owner;
    /// This process's rank, and the number of ranks.
    unsigned int rank    = 0;
    unsigned int n_ranks = 1;

    /// This rank's cells, ascending.
    std::vector<unsigned int>
    owned_cells() const;
  };


  /**
   * The active cells of @p tria split into @p n_ranks parts of about equal
   * size with short boundaries (METIS on the graph of cells that share a
   * face); the same split on every rank. On one rank every cell is
   * rank 0's.
   *
   * The cells of each pair in @p joined go to one rank: the two sides of a
   * zero-thickness interface element share no vertex, yet the rank that
   * runs the element needs both cells' DoFs and, on a distributed mesh,
   * both cells. A pair is an edge of METIS's graph as well, so the split
   * rarely has to move a cell to keep it.
   */
  template <int dim>
  CellPartition
  partition_cells(
    const Triangulation<dim>                                 &tria,
    const unsigned int                                        n_ranks,
    const unsigned int                                        rank,
    const std::vector<std::pair<unsigned int, unsigned int>> &joined = {});
} // namespace thinlayer

#endif
