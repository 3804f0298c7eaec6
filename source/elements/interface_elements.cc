#include <deal.II/base/quadrature_lib.h>

#include <thinlayer/base/input_error.h>
#include <thinlayer/elements/interface_elements.h>
#include <thinlayer/parallel/distributed_mesh.h>
#include <thinlayer/parameters/parameters.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

namespace thinlayer
{


  template <int dim>
  bool
  InterfaceElements<dim>::empty() const
  {
    return elements.empty();
  }


  template <int dim>
  Tensor<1, 3>
  InterfaceElements<dim>::local_jump(const IntegrationPoint &point,
                                     const unsigned int      s,
                                     const ModeVectors      &vectors) const
  {
    const Element &element = elements[point.element];
    Tensor<1, 3>   jump; // (x, y, theta or z) summed over the modes
    for (unsigned int m = 0; m < vectors.size(); ++m)
      {
        const ModeVector &v    = vectors[m];
        const double      T[3] = {kinematics->T(0, m, s),
                                  kinematics->T(1, m, s),
                                  kinematics->T(2, m, s)};
        for (const Entry &e : point.entries)
          jump[e.component] +=
            T[e.component] * e.value * v[element.dofs[e.local_dof]];
      }
    return point.frame * jump;
  }


  template <int dim>
  void
  InterfaceElements<dim>::add_forces(const IntegrationPoint &point,
                                     const unsigned int      s,
                                     const Tensor<1, 3>     &traction,
                                     ModeVectors            &target) const
  {
    const Element &element = elements[point.element];
    const double   weight  = kinematics->station_weight(s) * point.weight;
    // The traction in (x, y, theta or z).
    const Tensor<1, 3> global = traction * point.frame;
    for (unsigned int m = 0; m < target.size(); ++m)
      {
        ModeVector  &v    = target[m];
        const double T[3] = {kinematics->T(0, m, s),
                             kinematics->T(1, m, s),
                             kinematics->T(2, m, s)};
        for (const Entry &e : point.entries)
          v[element.dofs[e.local_dof]] +=
            weight * T[e.component] * e.value * global[e.component];
      }
  }


  template <int dim>
  void
  InterfaceElements<dim>::jump_operator(const IntegrationPoint &point,
                                        const unsigned int      s,
                                        FullMatrix<double>     &G) const
  {
    const Element     &element = elements[point.element];
    const unsigned int n       = element.dofs.size();
    if (G.m() != 3 || G.n() != kinematics->n_modes() * n)
      G.reinit(3, kinematics->n_modes() * n);
    else
      G = 0;
    for (unsigned int m = 0; m < kinematics->n_modes(); ++m)
      {
        const double T[3] = {kinematics->T(0, m, s),
                             kinematics->T(1, m, s),
                             kinematics->T(2, m, s)};
        for (const Entry &e : point.entries)
          {
            const unsigned int column = m * n + e.local_dof;
            const double       value  = T[e.component] * e.value;
            for (unsigned int a = 0; a < 3; ++a)
              G(a, column) += value * point.frame[a][e.component];
          }
      }
  }


  template <int dim>
  void
  InterfaceElements<dim>::add_dofs(
    std::vector<types::global_dof_index> &dofs) const
  {
    for (unsigned int k = 0; k < elements.size(); ++k)
      if (owns_element(k))
        dofs.insert(dofs.end(),
                    elements[k].dofs.begin(),
                    elements[k].dofs.end());
  }


  template <int dim>
  void
  InterfaceElements<dim>::add_sparsity(
    DynamicSparsityPattern          &dsp,
    const AffineConstraints<double> &constraints) const
  {
    for (unsigned int k = 0; k < elements.size(); ++k)
      if (owns_element(k))
        constraints.add_entries_local_to_global(elements[k].dofs,
                                                dsp,
                                                /*keep_constrained=*/true);
  }


  template <int dim>
  void
  InterfaceElements<dim>::assemble_elastic(const unsigned int    m,
                                           const CellMatrixSink &add) const
  {
    // K_m = int (c1 G1^T K G1 + c2 G2^T K G2) w: the in-plane components
    // with T1, the out-of-plane one with T2, integrated exactly over the
    // circle (as the cells' stiffness), so the harmonics decouple. In plane
    // strain and 3D, c1 = 1.
    std::vector<FullMatrix<double>> matrices(elements.size());
    for (unsigned int k = 0; k < elements.size(); ++k)
      matrices[k].reinit(elements[k].dofs.size(), elements[k].dofs.size());
    for (const IntegrationPoint &point : points)
      {
        const Element     &element = elements[point.element];
        const unsigned int n       = element.dofs.size();
        const Tensor<2, 3> K       = element.law->elasticity();
        FullMatrix<double> G(3, n);
        for (const Entry &e : point.entries)
          for (unsigned int a = 0; a < 3; ++a)
            G(a, e.local_dof) += e.value * point.frame[a][e.component];
        // The frame of a curve keeps theta apart, so each local component
        // takes its global one's factor.
        const double        c[3] = {kinematics->c1(m),
                                    kinematics->c1(m),
                             kinematics->is_fourier() ? kinematics->c2(m)
                                                             : kinematics->c1(m)};
        FullMatrix<double> &A    = matrices[point.element];
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            for (unsigned int a = 0; a < 3; ++a)
              A(i, j) += point.weight * c[a] * G(a, i) * K[a][a] * G(a, j);
      }
    for (unsigned int k = 0; k < elements.size(); ++k)
      if (owns_element(k))
        add(elements[k].dofs, matrices[k]);
  }


  template <int dim>
  template <typename Rule>
  unsigned int
  InterfaceElements<dim>::for_each_point(const ModeVectors &step_increment,
                                         const Rule        &rule)
  {
    const unsigned int n_stations = kinematics->n_stations();
    unsigned int       n_yielding = 0;
    for (unsigned int p = 0; p < points.size(); ++p)
      if (owns_point(p))
        for (unsigned int s = 0; s < n_stations; ++s)
          n_yielding += rule(points[p],
                             s,
                             *elements[points[p].element].law,
                             states[p * n_stations + s],
                             local_jump(points[p], s, step_increment),
                             p * n_stations + s);
    return n_yielding;
  }


  template <int dim>
  unsigned int
  InterfaceElements<dim>::viscoplastic_update(const ModeVectors &step_increment,
                                              ModeVectors &body_load_change)
  {
    // The paper's rule: the traction of the step's jump less its
    // viscoplastic jump; where F > 0, a viscoplastic jump increment
    // dt F dQ/dt whose K-projection is a body load.
    return for_each_point(
      step_increment,
      [&](const IntegrationPoint &point,
          const unsigned int      s,
          const InterfaceLaw     &law,
          InterfacePointState    &state,
          const Tensor<1, 3>     &jump,
          const unsigned int /*point_station*/) {
        state.traction = state.converged_traction +
                         law.elastic_traction(jump - state.step_plastic_jump);
        state.pending_plastic_jump = 0;
        state.yielding             = false;
        if (!law.can_yield())
          return 0u;
        const double F = law.yield_function(state.traction);
        if (F <= 0)
          return 0u;
        state.yielding             = true;
        const Tensor<1, 3> plastic = (law.viscoplastic_time_step() * F) *
                                     law.flow_direction(state.traction);
        state.step_plastic_jump += plastic;
        state.pending_plastic_jump = plastic;
        add_forces(point, s, law.elastic_traction(plastic), body_load_change);
        return 1u;
      });
  }


  template <int dim>
  unsigned int
  InterfaceElements<dim>::return_mapping_update(
    const ModeVectors &step_increment,
    const bool         with_tangents,
    ModeVectors       &internal_forces,
    ModeVectors       &stress_excess)
  {
    // The trial traction returned to the admissible set: the traction
    // gives the internal forces, the excess a body load.
    return for_each_point(
      step_increment,
      [&](const IntegrationPoint &point,
          const unsigned int      s,
          const InterfaceLaw     &law,
          InterfacePointState    &state,
          const Tensor<1, 3>     &jump,
          const unsigned int      point_station) {
        const Tensor<1, 3> trial =
          state.converged_traction + law.elastic_traction(jump);
        const InterfaceReturnMapping r =
          law.return_mapping(trial, with_tangents);
        state.traction = r.traction;
        state.yielding = (r.region != InterfaceReturn::elastic);
        if (with_tangents)
          tangents[point_station] = r.tangent;
        state.step_plastic_jump = law.compliance() * (trial - r.traction);
        if (state.yielding)
          add_forces(point, s, trial - r.traction, stress_excess);
        add_forces(point, s, state.traction, internal_forces);
        return state.yielding ? 1u : 0u;
      });
  }


  template <int dim>
  void
  InterfaceElements<dim>::add_internal_forces(
    ModeVectors &internal_forces) const
  {
    const unsigned int n_stations = kinematics->n_stations();
    for (unsigned int p = 0; p < points.size(); ++p)
      if (owns_point(p))
        for (unsigned int s = 0; s < n_stations; ++s)
          add_forces(points[p],
                     s,
                     states[p * n_stations + s].traction,
                     internal_forces);
  }


  template <int dim>
  void
  InterfaceElements<dim>::accept()
  {
    for (InterfacePointState &state : states)
      {
        state.converged_traction = state.traction;
        state.plastic_jump +=
          state.step_plastic_jump - state.pending_plastic_jump;
        state.step_plastic_jump    = 0;
        state.pending_plastic_jump = 0;
      }
  }


  template <int dim>
  void
  InterfaceElements<dim>::reject()
  {
    for (InterfacePointState &state : states)
      {
        state.traction             = state.converged_traction;
        state.step_plastic_jump    = 0;
        state.pending_plastic_jump = 0;
      }
  }


  template <int dim>
  void
  InterfaceElements<dim>::check_state(StateCheck &check) const
  {
    const unsigned int n_stations = kinematics ? kinematics->n_stations() : 1;
    for (unsigned int p = 0; p < points.size(); ++p)
      {
        if (!owns_point(p))
          continue;
        const InterfaceLaw &law = *elements[points[p].element].law;
        for (unsigned int s = 0; s < n_stations; ++s)
          {
            const Tensor<1, 3> &t = states[p * n_stations + s].traction;
            check.finite          = check.finite && std::isfinite(t[0]) &&
                           std::isfinite(t[1]) && std::isfinite(t[2]);
            if (!law.can_yield())
              continue;
            const double ratio = law.yield_ratio(t);
            check.finite       = check.finite && std::isfinite(ratio);
            check.add_yield_ratio(ratio);
          }
      }
  }


  template <int dim>
  bool
  InterfaceElements<dim>::all_associated() const
  {
    for (const auto &[id, law] : laws)
      if (!law->is_associated())
        return false;
    return true;
  }


  template <int dim>
  void
  InterfaceElements<dim>::add_coupled_sparsity(const DofSink &add)
  {
    for (unsigned int k = 0; k < elements.size(); ++k)
      if (owns_element(k))
        add(elements[k].coupled_dofs);
  }


  template <int dim>
  void
  InterfaceElements<dim>::add_coupled_tangent(const CellMatrixSink &add)
  {
    const unsigned int n_stations = kinematics->n_stations();
    for (auto &matrix : coupled_matrices)
      matrix = 0;
    FullMatrix<double> &G = jump_scratch;
    for (unsigned int p = 0; p < points.size(); ++p)
      for (unsigned int s = 0; s < n_stations; ++s)
        {
          if (!owns_point(p))
            continue;
          jump_operator(points[p], s, G);
          const Tensor<2, 3> &C = tangents[p * n_stations + s];
          const double        weight =
            kinematics->station_weight(s) * points[p].weight;
          FullMatrix<double> &A = coupled_matrices[points[p].element];
          for (unsigned int i = 0; i < G.n(); ++i)
            for (unsigned int a = 0; a < 3; ++a)
              if (G(a, i) != 0)
                for (unsigned int b = 0; b < 3; ++b)
                  if (C[a][b] != 0)
                    for (unsigned int j = 0; j < G.n(); ++j)
                      A(i, j) += weight * G(a, i) * C[a][b] * G(b, j);
        }
    for (unsigned int k = 0; k < elements.size(); ++k)
      if (owns_element(k))
        add(elements[k].coupled_dofs, coupled_matrices[k]);
  }


  template <int dim>
  std::vector<NamedProfile>
  InterfaceElements<dim>::profiles(const ModeVectors &solution,
                                   const ModeVectors &step_increment,
                                   const bool         pending) const
  {
    std::vector<NamedProfile> result;
    for (const auto &[id, law] : laws)
      {
        const std::string name = "interface-" + std::to_string(id);
        Profile           raw  = profile(id, solution, step_increment, pending);
        Profile           recovered = raw;
        if (const auto r = recoveries.find(id); r != recoveries.end())
          r->second.recover(recovered);
        result.push_back({name, std::move(recovered)});
        result.push_back({name + "-gauss", std::move(raw), true});
      }
    return result;
  }


  template <int dim>
  Profile
  InterfaceElements<dim>::profile(const types::boundary_id curve,
                                  const ModeVectors       &solution,
                                  const ModeVectors       &step_increment,
                                  const bool               pending) const
  {
    const unsigned int        n_stations = kinematics->n_stations();
    Profile                   result;
    std::vector<unsigned int> indices;
    for (unsigned int p = 0; p < points.size(); ++p)
      if (points[p].curve == curve)
        {
          const IntegrationPoint &point = points[p];
          if constexpr (dim == 2)
            result.samples.push_back(
              {point.run,
               point.arc_length,
               Point<3>(point.position[0], point.position[1], 0)});
          else
            result.surface_samples.push_back(
              {point.position, point.frame[0], point.frame[1], point.patch});
          indices.push_back(p);
        }
    for (unsigned int s = 0; s < n_stations; ++s)
      {
        std::vector<InterfaceValues> &values = result.stations.emplace_back();
        for (const unsigned int p : indices)
          {
            if (!owns_point(p))
              {
                values.emplace_back();
                continue;
              }
            const InterfaceLaw        &law   = *elements[points[p].element].law;
            const InterfacePointState &state = states[p * n_stations + s];
            const Tensor<1, 3> djump = local_jump(points[p], s, step_increment);
            // The state: the accepted solution, plus the pending step.
            const Tensor<1, 3> jump = local_jump(points[p], s, solution) +
                                      (pending ? djump : Tensor<1, 3>());
            InterfaceValues v;
            v.slip                        = jump[0];
            v.opening                     = jump[1];
            v.slip_out_of_plane           = jump[2];
            v.slip_increment              = djump[0];
            v.opening_increment           = djump[1];
            v.shear_traction              = state.traction[0];
            v.normal_traction             = state.traction[1];
            v.shear_traction_out_of_plane = state.traction[2];
            v.mobilised_strength = law.mobilised_strength(state.traction);
            v.plastic            = state.yielding;
            values.push_back(v);
          }
        sum_over_ranks(values);
      }
    return result;
  }


  template class InterfaceElements<2>;
  template class InterfaceElements<3>;
} // namespace thinlayer
