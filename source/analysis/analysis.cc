#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparsity_tools.h>

#include <thinlayer/analysis/analysis.h>
#include <thinlayer/base/input_error.h>
#include <thinlayer/base/work_counts.h>
#include <thinlayer/discretisation/body_loads.h>
#include <thinlayer/discretisation/mode_constraints.h>
#include <thinlayer/discretisation/serendipity_constraints.h>
#include <thinlayer/mesh/interface_pairing.h>
#include <thinlayer/parallel/cell_partition.h>
#include <thinlayer/parallel/distributed_mesh.h>
#include <thinlayer/parallel/mpi.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace thinlayer
{
  namespace
  {
    Kinematics
    make_kinematics(const KinematicsParameters &p)
    {
      if (p.fourier)
        return Kinematics::make_fourier(p.harmonics,
                                        p.station_angles,
                                        p.antisymmetric);
      return p.dimension == 3 ? Kinematics::make_solid()
                              : Kinematics::make_plane_strain();
    }
  } // namespace


  template <int dim>
  Analysis<dim>::Analysis(const Parameters         &parameters,
                          const Triangulation<dim> &tria)
    : parameters(parameters)
    , tria(tria)
    , kinematics(make_kinematics(parameters.kinematics))
    , fe(FE_Q<dim>(2), kinematics.n_components())
    , mapping(2)
    , quadrature(parameters.discretisation.gauss_points_per_direction)
    , dof_handler(tria)
    , accepted_lambda(0)
    , current_lambda(0)
    , pending(false)
    , substitution_time(0)
    , linear_solver(
        choose_linear_solver(parameters.solver, mpi::n_ranks(), dim))
  {
    AssertThrow(kinematics.mesh_dimension() == dim,
                ExcMessage("The kinematics' mesh dimension is the mesh's."));
    boundary_data.push_back(
      std::make_unique<BoundaryData>(parameters.boundaries,
                                     parameters.mesh.geometry_parameters,
                                     kinematics,
                                     parameters.parameter_file));
    for (const LoadingPhaseParameters &phase : parameters.loading_phases)
      boundary_data.push_back(
        std::make_unique<BoundaryData>(phase.boundaries,
                                       parameters.mesh.geometry_parameters,
                                       kinematics,
                                       parameters.parameter_file));
  }


  template <int dim>
  Analysis<dim>::~Analysis() = default;


  template <int dim>
  void
  Analysis<dim>::setup()
  {
    if (!boundary_data.front()->has_constraints())
      throw InputError(parameters.parameter_file,
                       "Boundary <id>/Constrained components",
                       "no displacement component is constrained anywhere; "
                       "the body must be restrained against rigid-body "
                       "motion");

    setup_dofs_and_constraints();
    setup_dof_partitioner();
    setup_dof_components();
    setup_mode_vectors();
    assemble_stiffness();
    set_phase_loads(PhaseLoads::boundaries_and_weight);
    factorise_stiffness();
  }


  template <int dim>
  ModeVectors
  Analysis<dim>::new_mode_vectors() const
  {
    ModeVectors vectors(kinematics.n_modes());
    for (ModeVector &v : vectors)
      v.reinit(dof_partitioner);
    return vectors;
  }


  template <int dim>
  Vector<double>
  Analysis<dim>::whole(const ModeVector &v) const
  {
    Vector<double> result;
    mpi::all_gather(dof_parts, owned_entries(v), result);
    return result;
  }


  template <int dim>
  void
  Analysis<dim>::setup_mode_vectors()
  {
    std::map<types::material_id, double> weights;
    for (const auto &[id, material] : parameters.materials)
      weights[id] = material.unit_weight;
    const double surcharge = parameters.initial_state.surcharge;
    const double level     = surcharge > 0 ? ground_level(tria) : 0;
    // Boundaries whose vertical displacement is prescribed carry no
    // surcharge (a footing pushed into the ground).
    std::set<types::boundary_id> held;
    for (const auto &[id, boundary] : parameters.boundaries)
      if (boundary.constrained_components.size() > 1 &&
          boundary.constrained_components[1])
        held.insert(id);
    for (unsigned int m = 0; m < kinematics.n_modes(); ++m)
      {
        ModeSystem &mode = *systems[m];
        if (mpi::n_ranks() == 1)
          {
            mode.stiffness.reinit(sparsity);
            mode.condensed_stiffness.reinit(sparsity);
          }

        // Prescribed displacements at unit load factor; the nodes tied to
        // them (centre nodes, the axis) follow through the structural lines.
        mode.boundary_values.resize(boundary_data.size());
        for (unsigned int k = 0; k < boundary_data.size(); ++k)
          {
            ModeSystem::BoundaryValues &values = mode.boundary_values[k];
            ModeVector                 &u      = values.prescribed_displacement;
            u.reinit(dof_partitioner);
            for (const auto &[dof, value] :
                 boundary_data[k]->prescribed_values(mapping, dof_handler, m))
              if (u.in_local_range(dof))
                u(dof) = value;
            distribute(mode.structural_constraints, u);

            values.load.reinit(dof_partitioner);
            boundary_data[k]->assemble_load_vector(mapping,
                                                   dof_handler,
                                                   m,
                                                   values.load);
            values.rhs.reinit(dof_partitioner);
          }
        mode.weight_load.reinit(dof_partitioner);
        add_weight(
          mapping, dof_handler, kinematics, weights, m, mode.weight_load);
        add_ground_pressure(mapping,
                            dof_handler,
                            kinematics,
                            level,
                            surcharge,
                            held,
                            m,
                            mode.weight_load);
        for (ModeVector *v : {&mode.held_load,
                              &mode.unit_prescribed_displacement,
                              &mode.unit_load,
                              &mode.unit_rhs})
          v->reinit(dof_partitioner);
      }
    for (ModeVectors *vectors :
         {&solution_vectors, &increment_vectors, &internal_force_vectors})
      *vectors = new_mode_vectors();
  }


  template <int dim>
  void
  Analysis<dim>::assemble_stiffness()
  {
    for (unsigned int m = 0; m < kinematics.n_modes(); ++m)
      {
        ModeSystem &mode = *systems[m];
        if (mpi::n_ranks() == 1)
          {
            for (const auto &group : groups)
              group->assemble_elastic(
                m, [&](const auto &dofs, const FullMatrix<double> &matrix) {
                  mode.stiffness.add(dofs, matrix);
                  mode.constraints.distribute_local_to_global(
                    matrix, dofs, mode.condensed_stiffness);
                });
            // One rank owns every entry, in order.
            for (ModeSystem::BoundaryValues &values : mode.boundary_values)
              {
                Vector<double> u(values.prescribed_displacement.begin(),
                                 values.prescribed_displacement.end()),
                  Ku(u.size());
                mode.stiffness.vmult(Ku, u);
                std::copy(Ku.begin(), Ku.end(), values.rhs.begin());
              }
          }
        else
          {
            // The raw stiffness is not kept: each rank adds its cells'
            // K u_prescribed.
            std::vector<std::unique_ptr<GhostValues>> ghosts;
            for (const auto &values : mode.boundary_values)
              ghosts.push_back(
                std::make_unique<GhostValues>(values.prescribed_displacement));
            Vector<double> u, Ku;
            for (const auto &group : groups)
              group->assemble_elastic(
                m, [&](const auto &dofs, const FullMatrix<double> &matrix) {
                  mode.constraints.distribute_local_to_global(
                    matrix, dofs, *mode.distributed_stiffness);
                  u.reinit(dofs.size());
                  Ku.reinit(dofs.size());
                  for (ModeSystem::BoundaryValues &values :
                       mode.boundary_values)
                    {
                      for (unsigned int i = 0; i < dofs.size(); ++i)
                        u[i] = values.prescribed_displacement[dofs[i]];
                      matrix.vmult(Ku, u);
                      for (unsigned int i = 0; i < dofs.size(); ++i)
                        values.rhs[dofs[i]] += Ku[i];
                    }
                });
            mode.distributed_stiffness->compress(VectorOperation::add);
            for (ModeSystem::BoundaryValues &values : mode.boundary_values)
              values.rhs.compress(VectorOperation::add);
          }
        // f - K u_prescribed.
        for (ModeSystem::BoundaryValues &values : mode.boundary_values)
          values.rhs.sadd(-1, 1, values.load);
      }
  }


  template <int dim>
  StateCheck
  Analysis<dim>::end_attempt(const double load_factor)
  {
    current_lambda = load_factor;
    pending        = true;

    // Overflow anywhere is no state: the step fails, never converges.
    StateCheck check;
    for (const auto &increment : increment_vectors)
      check.finite = check.finite && std::isfinite(increment.l1_norm());
    for (const auto &group : groups)
      group->check_state(check);
    if (mpi::n_ranks() > 1)
      {
        // Each rank checked its own points. A rank none of whose points
        // can yield has no ratio (NaN), which the maximum passes over.
        check.finite        = mpi::sum(check.finite ? 0u : 1u) == 0;
        const double lowest = -std::numeric_limits<double>::infinity();
        const double ratio  = mpi::max(
          std::isnan(check.max_yield_ratio) ? lowest : check.max_yield_ratio);
        check.max_yield_ratio =
          ratio == lowest ? std::numeric_limits<double>::quiet_NaN() : ratio;
      }
    compute_internal_forces();
    for (const auto &forces : internal_force_vectors)
      check.finite = check.finite && std::isfinite(forces.linfty_norm());
    return check;
  }


  template <int dim>
  void
  Analysis<dim>::compute_internal_forces()
  {
    for (auto &forces : internal_force_vectors)
      forces = 0;
    for (const auto &group : groups)
      group->add_internal_forces(internal_force_vectors);
    // Each rank's cells' share, added into the DoFs' owners.
    for (auto &forces : internal_force_vectors)
      forces.compress(VectorOperation::add);
  }


  template <int dim>
  void
  Analysis<dim>::accept_step()
  {
    Assert(pending, ExcMessage("There is no pending step to accept."));
    accept_step(current_lambda);
  }


  template <int dim>
  void
  Analysis<dim>::accept_step(const double load_factor)
  {
    for (unsigned int m = 0; m < systems.size(); ++m)
      solution_vectors[m] += increment_vectors[m];
    for (const auto &group : groups)
      group->accept();
    // The internal forces are the accepted state's (its last evaluation).
    accepted_forces = 0;
    for (const auto &forces : internal_force_vectors)
      accepted_forces = std::max(accepted_forces, forces.linfty_norm());
    accepted_lambda = load_factor;
    current_lambda  = load_factor;
    pending         = false;
  }


  template <int dim>
  void
  Analysis<dim>::reject_step()
  {
    for (auto &increment : increment_vectors)
      increment = 0;
    for (const auto &group : groups)
      group->reject();
    current_lambda = accepted_lambda;
    pending        = false;
    compute_internal_forces();
  }


  template <int dim>
  double
  Analysis<dim>::secant_stiffness_ratio() const
  {
    const double dlambda      = current_lambda - accepted_lambda;
    double       elastic_work = 0, work = 0;
    ModeVector   load(dof_partitioner), elastic_increment(dof_partitioner);
    for (unsigned int m = 0; m < systems.size(); ++m)
      {
        load = systems[m]->unit_rhs;
        load *= dlambda;
        systems[m]->condense(load);
        elastic_increment = load;
        systems[m]->solve(elastic_increment);
        elastic_work += load * elastic_increment;
        work += load * increment_vectors[m];
      }
    if (elastic_work == 0)
      return std::numeric_limits<double>::quiet_NaN();
    return elastic_work / work;
  }


  template <int dim>
  unsigned int
  Analysis<dim>::viscoplastic_update(ModeVectors &body_load_change)
  {
    ++work_counts().sweeps;
    // Each rank adds its points' loads, into its ghosts where another rank
    // owns the DoF; compress() adds those to their owners.
    unsigned int n_yielding = 0;
    {
      const GhostValues ghosts(increment_vectors);
      for (auto &v : body_load_change)
        v.zero_out_ghost_values();
      for (const auto &group : groups)
        n_yielding +=
          group->viscoplastic_update(increment_vectors, body_load_change);
    }
    for (auto &v : body_load_change)
      v.compress(VectorOperation::add);
    return mpi::sum(n_yielding);
  }


  template <int dim>
  unsigned int
  Analysis<dim>::return_mapping_update(const bool   with_tangents,
                                       ModeVectors &stress_excess)
  {
    ++work_counts().sweeps;
    for (unsigned int m = 0; m < systems.size(); ++m)
      {
        internal_force_vectors[m] = 0;
        stress_excess[m]          = 0;
      }
    unsigned int n_yielding = 0;
    {
      const GhostValues ghosts(increment_vectors);
      for (const auto &group : groups)
        n_yielding += group->return_mapping_update(increment_vectors,
                                                   with_tangents,
                                                   internal_force_vectors,
                                                   stress_excess);
    }
    for (unsigned int m = 0; m < systems.size(); ++m)
      {
        internal_force_vectors[m].compress(VectorOperation::add);
        stress_excess[m].compress(VectorOperation::add);
      }
    return mpi::sum(n_yielding);
  }


  template <int dim>
  void
  Analysis<dim>::add_coupled_sparsity(const DofSink &add)
  {
    for (const auto &group : groups)
      group->add_coupled_sparsity(add);
  }


  template <int dim>
  void
  Analysis<dim>::add_coupled_tangent(const CellMatrixSink &add)
  {
    for (const auto &group : groups)
      group->add_coupled_tangent(add);
  }


  template <int dim>
  std::vector<NamedProfile>
  Analysis<dim>::profiles() const
  {
    std::vector<NamedProfile> result;
    GhostValues               ghosts(solution_vectors);
    for (const ModeVector &v : increment_vectors)
      ghosts.add(v);
    for (const auto &group : groups)
      for (auto &profile :
           group->profiles(solution_vectors, increment_vectors, pending))
        result.push_back(std::move(profile));
    return result;
  }


  template <int dim>
  ModeVector
  Analysis<dim>::displacement_at(const double theta, const bool increment) const
  {
    return displacement_at(theta, displacements(increment));
  }


  template <int dim>
  ModeVectors
  Analysis<dim>::displacements(const bool increment) const
  {
    // Sized first: a copy of a vector (as a growing std::vector makes)
    // drops its ghost values.
    ModeVectors modes(systems.size());
    for (unsigned int m = 0; m < systems.size(); ++m)
      {
        modes[m] = increment ? increment_vectors[m] : solution_vectors[m];
        // A pending step's state is the accepted one plus its increment.
        if (pending && !increment)
          modes[m] += increment_vectors[m];
        modes[m].update_ghost_values();
      }
    return modes;
  }


  template <int dim>
  ModeVector
  Analysis<dim>::displacement_at(const double       theta,
                                 const ModeVectors &modes) const
  {
    // Entry by entry, ghosts too: each rank has what its cells read.
    ModeVector         u(dof_partitioner);
    const unsigned int n = dof_component.size();
    for (unsigned int m = 0; m < systems.size(); ++m)
      {
        const double t[3] = {kinematics.T_at(0, m, theta),
                             kinematics.T_at(1, m, theta),
                             kinematics.T_at(2, m, theta)};
        for (unsigned int k = 0; k < n; ++k)
          u.local_element(k) += t[dof_component[k]] * modes[m].local_element(k);
      }
    u.set_ghost_state(true);
    return u;
  }


  template <int dim>
  bool
  Analysis<dim>::has_external_load() const
  {
    for (const auto &system : systems)
      if (system->unit_load.linfty_norm() > 0)
        return true;
    return false;
  }


  template <int dim>
  bool
  Analysis<dim>::all_laws_associated() const
  {
    bool associated = true;
    for (const auto &group : groups)
      associated = associated && group->all_associated();
    return associated;
  }


  template <int dim>
  std::string
  Analysis<dim>::warnings() const
  {
    // Each rank found those at the nodes it holds, each naming the first
    // node (in parentheses) where it met them: the lowest rank's stands.
    std::vector<std::string> all;
    for (const auto &data : boundary_data)
      for (const std::string &w : data->get_warnings())
        all.push_back(w);
    if (mpi::n_ranks() > 1)
      {
        const std::vector<std::string> mine = all;
        all.clear();
        const auto what = [](const std::string &w) {
          return w.substr(0, w.find('('));
        };
        for (const auto &part :
             Utilities::MPI::all_gather(mpi::communicator(), mine))
          for (const auto &w : part)
            if (std::none_of(all.begin(), all.end(), [&](const auto &seen) {
                  return what(seen) == what(w);
                }))
              all.push_back(w);
      }
    std::string text;
    for (const auto &w : all)
      text += (text.empty() ? "" : "; ") + w;
    return text;
  }


  template class Analysis<2>;
  template class Analysis<3>;
} // namespace thinlayer
