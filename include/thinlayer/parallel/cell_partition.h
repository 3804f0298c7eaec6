#ifndef thinlayer_parallel_cell_partition_h
#define thinlayer_parallel_cell_partition_h

#include <deal.II/grid/tria.h>

#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /**
   * Which rank owns each active cell: the rank that runs the point rules
   * of its Gauss points and holds the authoritative copy of their states.
   * The same on every rank.
   */
  struct CellPartition
  {
    /// The rank of every active cell.
    std::vector<unsigned int> owner;
    /// This process's rank.
    unsigned int rank = 0;

    /// This rank's cells, ascending.
    std::vector<unsigned int>
    owned_cells() const;
  };


  /**
   * The active cells of @p tria split into @p n_ranks parts of about equal
   * size with short boundaries (METIS on the graph of cells that share a
   * face); the same split on every rank. On one rank every cell is
   * rank 0's.
   */
  template <int dim>
  CellPartition
  partition_cells(const Triangulation<dim> &tria,
                  const unsigned int        n_ranks,
                  const unsigned int        rank);
} // namespace thinlayer

#endif
