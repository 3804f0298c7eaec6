#include <deal.II/grid/tria_description.h>

#include <thinlayer/parallel/distributed_mesh.h>
#include <thinlayer/parallel/mpi.h>

namespace thinlayer
{
  template <int dim>
  std::unique_ptr<parallel::fullydistributed::Triangulation<dim>>
  distribute_mesh(const Triangulation<dim> &serial,
                  const CellPartition      &partition)
  {
    // The description reads the partition from the cells' subdomain ids.
    Triangulation<dim> marked;
    marked.copy_triangulation(serial);
    for (const auto &cell : marked.active_cell_iterators())
      cell->set_subdomain_id(partition.owner[cell->active_cell_index()]);
    const auto description = TriangulationDescription::Utilities::
      create_description_from_triangulation(marked, mpi::communicator());
    auto tria =
      std::make_unique<parallel::fullydistributed::Triangulation<dim>>(
        mpi::communicator());
    // The description carries the manifold ids of the cells and faces, not
    // the manifolds. They are attached before the cells are made: the
    // cells of a refined mesh are made by refining its coarse cells again,
    // and a new vertex on a curved side lies on the curve only if its
    // manifold is there to place it.
    for (const types::manifold_id id : serial.get_manifold_ids())
      if (id != numbers::flat_manifold_id)
        tria->set_manifold(id, serial.get_manifold(id));
    tria->create_triangulation(description);
    return tria;
  }


  template <int dim>
  CellPartition
  partition_of(const Triangulation<dim> &tria,
               const unsigned int        n_ranks,
               const unsigned int        rank)
  {
    CellPartition partition;
    partition.rank    = rank;
    partition.n_ranks = n_ranks;
    partition.owner.assign(tria.n_active_cells(),
                           numbers::invalid_unsigned_int);
    for (const auto &cell : tria.active_cell_iterators())
      if (!cell->is_artificial())
        partition.owner[cell->active_cell_index()] = cell->subdomain_id();
    return partition;
  }


  template std::unique_ptr<parallel::fullydistributed::Triangulation<2>>
  distribute_mesh(const Triangulation<2> &, const CellPartition &);
  template std::unique_ptr<parallel::fullydistributed::Triangulation<3>>
  distribute_mesh(const Triangulation<3> &, const CellPartition &);
  template CellPartition
  partition_of(const Triangulation<2> &,
               const unsigned int,
               const unsigned int);
  template CellPartition
  partition_of(const Triangulation<3> &,
               const unsigned int,
               const unsigned int);
} // namespace thinlayer
