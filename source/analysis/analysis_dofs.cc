#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <thinlayer/analysis/analysis.h>
#include <thinlayer/discretisation/mode_constraints.h>
#include <thinlayer/discretisation/serendipity_constraints.h>
#include <thinlayer/mesh/interface_pairing.h>
#include <thinlayer/parallel/cell_partition.h>
#include <thinlayer/parallel/distributed_mesh.h>
#include <thinlayer/parallel/mpi.h>

#include <algorithm>
#include <set>

// The analysis's DoFs: the mesh split over the ranks, the DoFs, their
// constraints and sparsity, and the layout of the mode vectors.
namespace thinlayer
{
  template <int dim>
  std::vector<FacingSides<dim>>
  Analysis<dim>::facing_sides(const DoFHandler<dim> &whole_mesh) const
  {
    std::vector<FacingSides<dim>> sides;
    if (!parameters.interface_elements.empty())
      {
        std::set<types::boundary_id> curves;
        for (const auto &[id, curve] : parameters.interface_elements)
          curves.insert(id);
        sides =
          pair_facing_sides(whole_mesh, curves, parameters.parameter_file);
      }
    return sides;
  }


  template <int dim>
  void
  Analysis<dim>::split_mesh(const std::vector<FacingSides<dim>> &sides)
  {
    std::vector<std::pair<unsigned int, unsigned int>> joined;
    for (const FacingSides<dim> &pair : sides)
      joined.emplace_back(pair.plus_cell->active_cell_index(),
                          pair.minus_cell->active_cell_index());
    whole_partition =
      partition_cells(tria, mpi::n_ranks(), mpi::rank(), joined);
    distributed_tria = distribute_mesh(tria, whole_partition);
    dof_handler.reinit(*distributed_tria);
    partition = partition_of(*distributed_tria, mpi::n_ranks(), mpi::rank());
  }


  template <int dim>
  void
  Analysis<dim>::setup_dofs_and_constraints()
  {
    // What needs the whole mesh is found on it before it is split: the
    // facing sides of the interface elements (their runs and arc lengths
    // span the ranks), and the partition, which keeps each element's two
    // cells on one rank.
    const DoFHandler<dim>               whole_mesh(tria);
    const std::vector<FacingSides<dim>> sides = facing_sides(whole_mesh);
    if (mpi::n_ranks() > 1)
      split_mesh(sides);
    dof_handler.distribute_dofs(fe);

    if (mpi::n_ranks() > 1)
      {
        owned_per_rank =
          Utilities::MPI::all_gather(mpi::communicator(),
                                     dof_handler.locally_owned_dofs());
        relevant_dofs = DoFTools::extract_locally_relevant_dofs(dof_handler);
        element_constraints.reinit(relevant_dofs);
      }
    else
      {
        relevant_dofs = complete_index_set(dof_handler.n_dofs());
        element_constraints.clear();
      }
    make_element_constraints(dof_handler,
                             parameters.discretisation.serendipity,
                             element_constraints);
    element_constraints.close();

    // UMFPACK where asked for; CHOLMOD otherwise (a harmonic factorised
    // whole on one of several ranks too).
    const auto factor_method =
      linear_solver.kind == LinearSolverChoice::Kind::umfpack
        ? FactorisedStiffness::Method::umfpack
        : FactorisedStiffness::Method::cholmod;
    systems.clear();
    for (unsigned int m = 0; m < kinematics.n_modes(); ++m)
      {
        systems.push_back(std::make_unique<ModeSystem>(factor_method));
        make_mode_constraints(dof_handler,
                              kinematics,
                              m,
                              parameters.kinematics.axis_boundary_id,
                              element_constraints,
                              *boundary_data.front(),
                              systems[m]->structural_constraints,
                              systems[m]->constraints);
      }
    count_constrained_dofs();

    // On many ranks, each holds and runs the points of its part of the
    // mesh.
    groups    = create_element_groups(parameters,
                                   dof_handler,
                                   mapping,
                                   quadrature,
                                   kinematics,
                                   partition,
                                   sides,
                                   whole_partition);
    continuum = dynamic_cast<const ContinuumCells<dim> *>(groups[0].get());
    Assert(continuum != nullptr,
           ExcMessage("The first element group must be the continuum."));

    setup_sparsity();
  }


  template <int dim>
  void
  Analysis<dim>::setup_sparsity()
  {
    if (mpi::n_ranks() == 1)
      {
        DynamicSparsityPattern dsp(dof_handler.n_dofs());
        for (const auto &group : groups)
          for (const auto &system : systems)
            group->add_sparsity(dsp, system->constraints);
        sparsity.copy_from(dsp);
      }
    else
      {
        // Each rank's rows, from every rank's cells.
        DynamicSparsityPattern dsp(relevant_dofs);
        for (const auto &group : groups)
          for (const auto &system : systems)
            group->add_sparsity(dsp, system->constraints);
        SparsityTools::distribute_sparsity_pattern(dsp,
                                                   owned_per_rank[mpi::rank()],
                                                   mpi::communicator(),
                                                   relevant_dofs);
        for (auto &system : systems)
          system->distributed_stiffness =
            std::make_unique<PETScWrappers::MPI::SparseMatrix>();
        for (auto &system : systems)
          system->distributed_stiffness->reinit(owned_per_rank[mpi::rank()],
                                                owned_per_rank[mpi::rank()],
                                                dsp,
                                                mpi::communicator());
      }
  }


  template <int dim>
  void
  Analysis<dim>::count_constrained_dofs()
  {
    // Each rank counts the lines of its own DoFs.
    const IndexSet &owned   = dof_handler.locally_owned_dofs();
    const auto      n_owned = [&owned](const AffineConstraints<double> &c) {
      types::global_dof_index n = 0;
      for (const auto &line : c.get_lines())
        if (owned.is_element(line.index))
          ++n;
      return n;
    };
    std::vector<types::global_dof_index> counts = {
      n_owned(element_constraints)};
    for (const auto &system : systems)
      counts.push_back(n_owned(system->constraints));
    for (auto &count : counts)
      count = mpi::sum(count);
    n_element_constrained = counts[0];
    n_constrained.assign(counts.begin() + 1, counts.end());
  }


  template <int dim>
  void
  Analysis<dim>::setup_dof_partitioner()
  {
    // Without mpirun MPI is never started: the serial layout needs none.
    if (mpi::n_ranks() == 1)
      {
        dof_partitioner =
          std::make_shared<Utilities::MPI::Partitioner>(dof_handler.n_dofs());
        dof_parts = mpi::parts(dof_handler.n_dofs());
        return;
      }
    const IndexSet                      &owned = owned_per_rank[mpi::rank()];
    std::vector<types::global_dof_index> dofs;
    for (const auto &group : groups)
      group->add_dofs(dofs);
    // The DoFs the rank's own constraint lines name, in every set of lines
    // a vector is distributed or condensed with: a hanging node's masters
    // lie on its coarse neighbour's side, not on the rank's cells, and
    // each set keeps masters that the further lines of the next eliminate
    // (the boundary's; the axis and the components a mode lacks).
    std::vector<const AffineConstraints<double> *> sets = {
      &element_constraints};
    for (const auto &system : systems)
      {
        sets.push_back(&system->structural_constraints);
        sets.push_back(&system->constraints);
      }
    for (const AffineConstraints<double> *lines : sets)
      for (const auto &line : lines->get_lines())
        if (owned.is_element(line.index))
          for (const auto &entry : line.entries)
            dofs.push_back(entry.first);
    std::sort(dofs.begin(), dofs.end());
    dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
    IndexSet relevant(dof_handler.n_dofs());
    relevant.add_indices(dofs.begin(), dofs.end());
    relevant.add_indices(owned);
    dof_partitioner =
      std::make_shared<Utilities::MPI::Partitioner>(owned,
                                                    relevant,
                                                    mpi::communicator());
    dof_parts = mpi::parts(owned.n_elements());
  }


  template <int dim>
  void
  Analysis<dim>::setup_dof_components()
  {
    // Every DoF a rank stores is on one of the cells it holds.
    const unsigned int n_local = dof_partitioner->locally_owned_size() +
                                 dof_partitioner->n_ghost_indices();
    dof_component.assign(n_local, numbers::invalid_unsigned_int);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (dof_partitioner->in_local_range(dofs[i]) ||
                dof_partitioner->is_ghost_entry(dofs[i]))
              dof_component[dof_partitioner->global_to_local(dofs[i])] =
                fe.system_to_component_index(i).first;
        }
  }


  template std::vector<FacingSides<2>>
  Analysis<2>::facing_sides(const DoFHandler<2> &) const;
  template void
  Analysis<2>::split_mesh(const std::vector<FacingSides<2>> &);
  template void
  Analysis<2>::setup_dofs_and_constraints();
  template void
  Analysis<2>::setup_sparsity();
  template void
  Analysis<2>::count_constrained_dofs();
  template void
  Analysis<2>::setup_dof_partitioner();
  template void
  Analysis<2>::setup_dof_components();
  template std::vector<FacingSides<3>>
  Analysis<3>::facing_sides(const DoFHandler<3> &) const;
  template void
  Analysis<3>::split_mesh(const std::vector<FacingSides<3>> &);
  template void
  Analysis<3>::setup_dofs_and_constraints();
  template void
  Analysis<3>::setup_sparsity();
  template void
  Analysis<3>::count_constrained_dofs();
  template void
  Analysis<3>::setup_dof_partitioner();
  template void
  Analysis<3>::setup_dof_components();
} // namespace thinlayer
