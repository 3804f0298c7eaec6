#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <thinlayer/parallel/cell_partition.h>

namespace thinlayer
{
  std::vector<unsigned int>
  CellPartition::owned_cells() const
  {
    std::vector<unsigned int> cells;
    for (unsigned int c = 0; c < owner.size(); ++c)
      if (owner[c] == rank)
        cells.push_back(c);
    return cells;
  }


  template <int dim>
  CellPartition
  partition_cells(const Triangulation<dim> &tria,
                  const unsigned int        n_ranks,
                  const unsigned int        rank)
  {
    CellPartition partition;
    partition.rank = rank;
    partition.owner.assign(tria.n_active_cells(), 0);
    if (n_ranks == 1)
      return partition;
    // More ranks than cells: some ranks own none.
    if (tria.n_active_cells() <= n_ranks)
      {
        for (unsigned int c = 0; c < tria.n_active_cells(); ++c)
          partition.owner[c] = c;
        return partition;
      }
    DynamicSparsityPattern graph;
    GridTools::get_face_connectivity_of_cells(tria, graph);
    SparsityPattern pattern;
    pattern.copy_from(graph);
    SparsityTools::partition(pattern,
                             n_ranks,
                             partition.owner,
                             SparsityTools::Partitioner::metis);
    return partition;
  }


  template CellPartition
  partition_cells(const Triangulation<2> &,
                  const unsigned int,
                  const unsigned int);
  template CellPartition
  partition_cells(const Triangulation<3> &,
                  const unsigned int,
                  const unsigned int);
} // namespace thinlayer
