#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <thinlayer/parallel/cell_partition.h>

#include <algorithm>

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
  partition_cells(
    const Triangulation<dim>                                 &tria,
    const unsigned int                                        n_ranks,
    const unsigned int                                        rank,
    const std::vector<std::pair<unsigned int, unsigned int>> &joined)
  {
    CellPartition partition;
    partition.rank    = rank;
    partition.n_ranks = n_ranks;
    partition.owner.assign(tria.n_active_cells(), 0);
    if (n_ranks == 1)
      return partition;
    // More ranks than cells: some ranks own none.
    if (tria.n_active_cells() <= n_ranks)
      for (unsigned int c = 0; c < tria.n_active_cells(); ++c)
        partition.owner[c] = c;
    else
      {
        DynamicSparsityPattern graph;
        GridTools::get_face_connectivity_of_cells(tria, graph);
        // Joined cells are neighbours to METIS too, so that keeping them
        // together costs it no cut.
        for (const auto &[a, b] : joined)
          {
            graph.add(a, b);
            graph.add(b, a);
          }
        SparsityPattern pattern;
        pattern.copy_from(graph);
        SparsityTools::partition(pattern,
                                 n_ranks,
                                 partition.owner,
                                 SparsityTools::Partitioner::metis);
      }

    // Each group of cells joined directly or through others goes whole to
    // the rank of its first cell (union-find, roots the lowest index).
    std::vector<unsigned int> root(tria.n_active_cells());
    for (unsigned int c = 0; c < root.size(); ++c)
      root[c] = c;
    const auto find = [&root](unsigned int c) {
      while (root[c] != c)
        c = root[c] = root[root[c]];
      return c;
    };
    for (const auto &[a, b] : joined)
      {
        const unsigned int ra = find(a), rb = find(b);
        root[std::max(ra, rb)] = std::min(ra, rb);
      }
    for (unsigned int c = 0; c < root.size(); ++c)
      partition.owner[c] = partition.owner[find(c)];
    return partition;
  }


  template CellPartition
  partition_cells(const Triangulation<2> &,
                  const unsigned int,
                  const unsigned int,
                  const std::vector<std::pair<unsigned int, unsigned int>> &);
  template CellPartition
  partition_cells(const Triangulation<3> &,
                  const unsigned int,
                  const unsigned int,
                  const std::vector<std::pair<unsigned int, unsigned int>> &);
} // namespace thinlayer
