#ifndef thinlayer_parallel_distributed_mesh_h
#define thinlayer_parallel_distributed_mesh_h

#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/cell_id.h>
#include <deal.II/grid/tria.h>

#include <thinlayer/parallel/cell_partition.h>

#include <memory>

namespace thinlayer
{
  using namespace dealii;

  /**
   * The part of the coarse mesh @p serial that this rank needs: the cells
   * @p partition gives it, and one layer of ghost cells around them (the
   * cells that share a vertex with one of its own). Our meshes are all
   * coarse cells, so p4est, which keeps every coarse cell on every rank,
   * would save nothing; a fully distributed triangulation keeps only these.
   * The cells keep their material and boundary ids and their CellId, by
   * which a rank finds a cell of @p serial in its part (cell_of()). A
   * collective call; @p partition must be the same on every rank.
   */
  template <int dim>
  std::unique_ptr<parallel::fullydistributed::Triangulation<dim>>
  distribute_mesh(const Triangulation<dim> &serial,
                  const CellPartition      &partition);


  /**
   * The partition of a distributed mesh as CellPartition states it, over
   * the cells this rank holds: its own cells and its ghosts carry their
   * owner's rank, the artificial ones numbers::invalid_unsigned_int.
   */
  template <int dim>
  CellPartition
  partition_of(const Triangulation<dim> &tria,
               const unsigned int        n_ranks,
               const unsigned int        rank);


  /**
   * The cell @p id of the mesh of @p dof_handler, with its DoFs: how a
   * rank finds a cell of the whole mesh in its part. The cell must be one
   * the rank holds.
   */
  template <int dim>
  typename DoFHandler<dim>::active_cell_iterator
  cell_of(const DoFHandler<dim> &dof_handler, const CellId &id)
  {
    const auto cell = dof_handler.get_triangulation().create_cell_iterator(id);
    Assert(cell->is_active() && !cell->is_artificial(),
           ExcMessage("This rank does not hold the cell."));
    return typename DoFHandler<dim>::active_cell_iterator(
      &dof_handler.get_triangulation(),
      cell->level(),
      cell->index(),
      &dof_handler);
  }
} // namespace thinlayer

#endif
