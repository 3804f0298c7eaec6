#include <deal.II/base/multithread_info.h>

#include <thinlayer/elements/point_loop.h>

#include <algorithm>

namespace thinlayer
{
  namespace
  {
    /**
     * The paper's point rule: the stress of the current strain less the
     * step's viscoplastic strain; where F > 0, a viscoplastic strain
     * increment dt F dQ/dsigma whose D-projection is a body load.
     */
    struct ViscoplasticRule
    {
      static constexpr bool with_internal_forces = false;

      double time_step;

      template <typename AddBodyLoad, typename AddForce>
      unsigned int
      operator()(const MaterialLaw           &law,
                 PointState                  &state,
                 const SymmetricTensor<2, 3> &strain,
                 const std::size_t /*point_station*/,
                 const AddBodyLoad &add_body_load,
                 const AddForce & /*add_force*/) const
      {
        state.stress = state.converged_stress +
                       law.elastic_stress(strain - state.step_plastic_strain);
        state.pending_plastic_strain = 0; // now in the stress
        state.yielding               = false;
        if (!law.can_yield())
          return 0;
        const double F = law.yield_function(state.stress);
        if (F <= 0)
          return 0;

        state.yielding = true;
        const SymmetricTensor<2, 3> viscoplastic_strain =
          (time_step * F) * law.flow_direction(state.stress);
        state.step_plastic_strain += viscoplastic_strain;
        state.pending_plastic_strain = viscoplastic_strain;
        // Project D (that strain) back onto every mode.
        add_body_load(law.elastic_stress(viscoplastic_strain));
        return 1;
      }
    };


    /**
     * The return-mapping point rule: the elastic trial stress of the step's
     * strain mapped back onto the yield surface; the stress excess is a
     * body load, the stress gives the internal forces.
     */
    struct ReturnMappingRule
    {
      static constexpr bool with_internal_forces = true;

      std::vector<SymmetricTensor<4, 3>> *tangents;

      template <typename AddBodyLoad, typename AddForce>
      unsigned int
      operator()(const MaterialLaw           &law,
                 PointState                  &state,
                 const SymmetricTensor<2, 3> &strain,
                 const std::size_t            point_station,
                 const AddBodyLoad           &add_body_load,
                 const AddForce              &add_force) const
      {
        const SymmetricTensor<2, 3> trial =
          state.converged_stress + law.elastic_stress(strain);
        unsigned int n_yielding = 0;
        state.yielding          = false;
        if (!law.can_yield())
          state.stress = trial;
        else
          {
            const ReturnMapping r =
              law.return_mapping(trial, tangents != nullptr);
            state.stress = r.stress;
            if (tangents != nullptr)
              (*tangents)[point_station] = r.tangent;
            if (r.region != ReturnRegion::elastic)
              {
                state.yielding = true;
                n_yielding     = 1;
                state.step_plastic_strain =
                  law.compliance() * (trial - r.stress);
                add_body_load(trial - r.stress);
              }
            else
              state.step_plastic_strain = 0;
          }
        add_force(state.stress);
        return n_yielding;
      }
    };
  } // namespace


  void
  PointLoop::reinit(const StrainOperator                   &strain_operator,
                    const Kinematics                       &kinematics,
                    const unsigned int                      n_q,
                    const std::vector<const MaterialLaw *> &cell_law,
                    const std::vector<unsigned int>        &cells,
                    std::vector<PointState>                &states)
  {
    this->strain_operator = &strain_operator;
    this->kinematics      = &kinematics;
    this->cell_law        = &cell_law;
    this->states          = &states;
    this->n_q             = n_q;
    this->cells           = cells;
    Assert(states.size() == point_index(cells.size(), 0, 0),
           ExcMessage("One state per point and station of the loop's cells."));

    const unsigned int n_local =
      kinematics.n_modes() * strain_operator.dofs_per_cell();
    ChunkScratch scratch;
    scratch.du.resize(n_local);
    scratch.mode_strain.resize(kinematics.n_modes() *
                               strain_operator.n_parts());
    chunk_scratch.assign(4 * MultithreadInfo::n_threads(), scratch);
    cell_body_loads.assign(cells.size() * n_local, 0.);
    cell_internal_forces.assign(cells.size() * n_local, 0.);
    cell_has_body_loads.assign(cells.size(), 0);
    // A few chunks per thread balance the plastic zone's extra work.
    chunks =
      std::min<unsigned int>(4 * MultithreadInfo::n_threads(), cells.size());
    tasks.reserve(chunks);
  }


  unsigned int
  PointLoop::viscoplastic_update(const double       time_step,
                                 const ModeVectors &step_increment,
                                 ModeVectors       &body_load_change)
  {
    return update(step_increment,
                  ViscoplasticRule{time_step},
                  body_load_change,
                  nullptr);
  }


  unsigned int
  PointLoop::return_mapping_update(const ModeVectors &step_increment,
                                   std::vector<SymmetricTensor<4, 3>> *tangents,
                                   ModeVectors &internal_forces,
                                   ModeVectors &stress_excess)
  {
    return update(step_increment,
                  ReturnMappingRule{tangents},
                  stress_excess,
                  &internal_forces);
  }


  template <typename PointRule>
  unsigned int
  PointLoop::update(const ModeVectors &step_increment,
                    const PointRule   &rule,
                    ModeVectors       &body_loads,
                    ModeVectors       *internal_forces)
  {
    // The task list keeps its capacity and each chunk has its work space
    // (chunk_scratch); only the task objects themselves are new.
    tasks.clear();
    for (unsigned int k = 0; k < chunks; ++k)
      tasks.push_back(Threads::new_task([this, k, &step_increment, &rule]() {
        return update_cells(chunk_begin(k),
                            chunk_begin(k + 1),
                            step_increment,
                            rule,
                            chunk_scratch[k]);
      }));
    unsigned int n_yielding = 0;
    for (auto &task : tasks)
      n_yielding += task.return_value();

    // The serial pass, in cell order.
    const unsigned int n       = strain_operator->dofs_per_cell();
    const unsigned int n_modes = step_increment.size();
    for (unsigned int m = 0; m < n_modes; ++m)
      {
        ModeVector &target = body_loads[m];
        for (unsigned int i = 0; i < cells.size(); ++i)
          {
            const types::global_dof_index *dofs =
              strain_operator->cell_dofs(cells[i]);
            const std::size_t slot = (std::size_t(i) * n_modes + m) * n;
            if (cell_has_body_loads[i])
              for (unsigned int i = 0; i < n; ++i)
                target[dofs[i]] += cell_body_loads[slot + i];
            if (PointRule::with_internal_forces)
              for (unsigned int i = 0; i < n; ++i)
                (*internal_forces)[m][dofs[i]] +=
                  cell_internal_forces[slot + i];
          }
      }
    return n_yielding;
  }


  template <typename PointRule>
  unsigned int
  PointLoop::update_cells(const unsigned int begin,
                          const unsigned int end,
                          const ModeVectors &step_increment,
                          const PointRule   &rule,
                          ChunkScratch      &scratch)
  {
    const StrainOperator &B           = *strain_operator;
    const Kinematics     &k           = *kinematics;
    const unsigned int    n           = B.dofs_per_cell();
    const unsigned int    n_modes     = k.n_modes();
    const unsigned int    n_parts     = B.n_parts();
    const unsigned int    n_stations  = k.n_stations();
    unsigned int          n_yielding  = 0;
    std::vector<double>  &du          = scratch.du;
    auto                 &mode_strain = scratch.mode_strain;

    for (unsigned int position = begin; position < end; ++position)
      {
        const unsigned int             c    = cells[position];
        const MaterialLaw             &law  = *(*cell_law)[c];
        const types::global_dof_index *dofs = B.cell_dofs(c);
        double                        *cell_loads =
          &cell_body_loads[std::size_t(position) * n_modes * n];
        double *cell_forces =
          PointRule::with_internal_forces
            ? &cell_internal_forces[std::size_t(position) * n_modes * n]
            : nullptr;
        bool has_body_loads = false;
        for (unsigned int m = 0; m < n_modes; ++m)
          for (unsigned int i = 0; i < n; ++i)
            du[m * n + i] = step_increment[m][dofs[i]];
        if (cell_forces != nullptr)
          std::fill(cell_forces, cell_forces + n_modes * n, 0.);

        for (unsigned int q = 0; q < n_q; ++q)
          {
            const unsigned int p = c * n_q + q;
            // The strain parts of each mode at this point.
            for (unsigned int m = 0; m < n_modes; ++m)
              for (unsigned int part = 0; part < n_parts; ++part)
                mode_strain[m * n_parts + part] =
                  B.strain(p, m, part, &du[m * n]);

            for (unsigned int s = 0; s < n_stations; ++s)
              {
                PointState &state = (*states)[point_index(position, q, s)];
                SymmetricTensor<2, 3> strain;
                for (unsigned int m = 0; m < n_modes; ++m)
                  {
                    strain += k.T1(m, s) * mode_strain[m * n_parts];
                    if (n_parts == 2)
                      strain += k.T2(m, s) * mode_strain[m * n_parts + 1];
                  }
                // Adds int (T1 B1 + T2 B2)^T t over this point and station
                // to every mode's part of the cell's slot @p target.
                const double weight  = k.station_weight(s) * B.point_weight(p);
                const auto   project = [&](const SymmetricTensor<2, 3> &t,
                                         double                      *target) {
                  for (unsigned int m = 0; m < n_modes; ++m)
                    {
                      B.add_projection(
                        p, m, 0, t * (weight * k.T1(m, s)), target + m * n);
                      if (n_parts == 2)
                        B.add_projection(
                          p, m, 1, t * (weight * k.T2(m, s)), target + m * n);
                    }
                };
                // The first body load of this cell clears its slot.
                const auto add_body_load = [&](const SymmetricTensor<2, 3> &t) {
                  if (!has_body_loads)
                    {
                      std::fill(cell_loads, cell_loads + n_modes * n, 0.);
                      has_body_loads = true;
                    }
                  project(t, cell_loads);
                };
                const auto add_force = [&](const SymmetricTensor<2, 3> &t) {
                  project(t, cell_forces);
                };
                n_yielding += rule(law,
                                   state,
                                   strain,
                                   point_index(position, q, s),
                                   add_body_load,
                                   add_force);
              }
          }
        cell_has_body_loads[position] = has_body_loads;
      }
    return n_yielding;
  }


  void
  PointLoop::add_internal_forces(ModeVectors &internal_forces) const
  {
    const StrainOperator &B       = *strain_operator;
    const Kinematics     &k       = *kinematics;
    const unsigned int    n       = B.dofs_per_cell();
    const unsigned int    n_modes = k.n_modes();
    std::vector<double>   cell_forces(n_modes * n);
    for (unsigned int position = 0; position < cells.size(); ++position)
      {
        const unsigned int c = cells[position];
        std::fill(cell_forces.begin(), cell_forces.end(), 0.);
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const unsigned int p = c * n_q + q;
            for (unsigned int s = 0; s < k.n_stations(); ++s)
              {
                const SymmetricTensor<2, 3> sigma =
                  (*states)[point_index(position, q, s)].stress *
                  (k.station_weight(s) * B.point_weight(p));
                for (unsigned int m = 0; m < n_modes; ++m)
                  for (unsigned int part = 0; part < B.n_parts(); ++part)
                    B.add_projection(p,
                                     m,
                                     part,
                                     sigma *
                                       (part == 0 ? k.T1(m, s) : k.T2(m, s)),
                                     &cell_forces[m * n]);
              }
          }
        for (unsigned int m = 0; m < n_modes; ++m)
          for (unsigned int i = 0; i < n; ++i)
            internal_forces[m][B.cell_dofs(c)[i]] += cell_forces[m * n + i];
      }
  }
} // namespace thinlayer
