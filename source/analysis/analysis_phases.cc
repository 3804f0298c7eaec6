// The phases of a run: the initial stresses of the K0 procedure, and the
// start of each phase, which holds the loads of the one before it. Members
// of Analysis, in a file of their own.
#include <thinlayer/analysis/analysis.h>
#include <thinlayer/base/input_error.h>
#include <thinlayer/base/text_format.h>
#include <thinlayer/discretisation/initial_stresses.h>
#include <thinlayer/elements/continuum_cells.h>
#include <thinlayer/elements/interface_elements.h>
#include <thinlayer/materials/material_law.h>
#include <thinlayer/parallel/mpi.h>

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace thinlayer
{
  namespace
  {
    /// Whether a phase of @p loads applies the Boundary sections' values,
    /// and whether it applies the weight.
    template <typename PhaseLoads>
    bool
    applies_boundaries(const PhaseLoads loads)
    {
      return loads == PhaseLoads::boundaries ||
             loads == PhaseLoads::boundaries_and_weight;
    }

    template <typename PhaseLoads>
    bool
    applies_weight(const PhaseLoads loads)
    {
      return loads == PhaseLoads::weight ||
             loads == PhaseLoads::boundaries_and_weight;
    }

    /// The largest of every rank's @p worst, and the @p facts (a place, a
    /// material) of the rank that has it: a collective call.
    std::pair<double, std::vector<double>>
    worst_over_ranks(const double worst, const std::vector<double> &facts)
    {
      const double        global = mpi::max(worst);
      const bool          mine   = worst == global;
      std::vector<double> found;
      for (const double fact : facts)
        found.push_back(
          mpi::max(mine ? fact : -std::numeric_limits<double>::infinity()));
      return {global, found};
    }


    /// An InputError where the K0 procedure's stress at the @p worst point
    /// (worst_over_ranks(): its yield ratio, and the place and material
    /// of its cell) lies outside its material's yield surface.
    void
    refuse_outside_yield(const Parameters &parameters,
                         const std::pair<double, std::vector<double>> &worst)
    {
      using text_format::printf;
      const auto &[global_worst, facts] = worst;
      if (global_worst > 1e-9)
        {
          const auto id = static_cast<types::material_id>(facts[2]);
          const MaterialParameters &material = parameters.materials.at(id);
          const double              s =
            std::sin(material.friction_angle * numbers::PI / 180);
          const std::string range =
            material.cohesion == 0 && s > 0
              ? " (without cohesion, between K_a = " +
                  printf("%.4g", (1 - s) / (1 + s)) +
                  " and K_p = " + printf("%.4g", (1 + s) / (1 - s)) + ")"
              : "";
          throw InputError(
            parameters.parameter_file,
            MaterialParameters::section(id) + "/K0",
            "the K0 procedure's initial stress lies outside the yield "
            "surface of material " +
              std::to_string(id) +
              (material.name.empty() ? "" : " (" + material.name + ")") +
              " in the cell centred at (" + printf("%g", facts[0]) + ", " +
              printf("%g", facts[1]) + "): yield ratio " +
              printf("%.3g", global_worst) +
              " (K0 = " + printf("%g", material.k0) +
              "); expected a K0 the material can carry at rest" + range);
        }
    }


    /// An InputError where the tractions @p found of interface elements
    /// (InterfaceElements::set_initial_tractions()) differ between the two
    /// sides or lie outside the slip surface, over the ranks.
    template <typename InitialTractions>
    void
    refuse_initial_tractions(const Parameters       &parameters,
                             const InitialTractions &found)
    {
      using text_format::printf;
      const auto [mismatch, at] =
        worst_over_ranks(found.mismatch,
                         {found.mismatch_at[0],
                          found.mismatch_at[1],
                          double(found.mismatch_curve),
                          double(found.mismatch_materials[0]),
                          double(found.mismatch_materials[1])});
      if (mismatch > 1e-9)
        throw InputError(
          parameters.parameter_file,
          MaterialParameters::section(static_cast<types::material_id>(at[3])) +
            "/K0",
          "the K0 procedure's stresses on the two sides of "
          "interface curve " +
            printf("%g", at[2]) + " (materials " + printf("%g", at[3]) +
            " and " + printf("%g", at[4]) +
            ") put different tractions on it at (" + printf("%g", at[0]) +
            ", " + printf("%g", at[1]) + "), by " + printf("%.3g", mismatch) +
            " of the larger; expected the same K0 on both sides of "
            "an interface that is not horizontal");
      const auto [ratio, place] = worst_over_ranks(found.yield_ratio,
                                                   {found.yield_at[0],
                                                    found.yield_at[1],
                                                    double(found.yield_curve)});
      if (ratio > 1e-9)
        throw InputError(
          parameters.parameter_file,
          InterfaceElementParameters::section(
            static_cast<unsigned int>(place[2])) +
            "/Friction angle",
          "the K0 procedure's initial traction on interface curve " +
            printf("%g", place[2]) + " at (" + printf("%g", place[0]) + ", " +
            printf("%g", place[1]) + ") lies outside its slip surface, by " +
            printf("%.3g", ratio) + " of the traction" +
            "; expected an interface that can carry the at-rest "
            "stresses (or K0s that put less shear on it)");
    }
  } // namespace


  template <int dim>
  void
  Analysis<dim>::set_phase_loads(const PhaseLoads loads)
  {
    const bool boundaries = applies_boundaries(loads);
    const bool weight     = applies_weight(loads);
    for (const auto &system : systems)
      {
        ModeSystem &mode = *system;
        for (ModeVector *v : {&mode.unit_prescribed_displacement,
                              &mode.unit_load,
                              &mode.unit_rhs})
          *v = 0;
        if (boundaries)
          {
            const ModeSystem::BoundaryValues &values =
              mode.boundary_values[boundary_set];
            mode.unit_prescribed_displacement = values.prescribed_displacement;
            mode.unit_load                    = values.load;
            mode.unit_rhs                     = values.rhs;
          }
        if (weight)
          {
            mode.unit_load += mode.weight_load;
            mode.unit_rhs += mode.weight_load;
          }
      }
  }


  template <int dim>
  void
  Analysis<dim>::begin_phase(const PhaseLoads   loads,
                             const bool         reset_displacements,
                             const unsigned int set)
  {
    Assert(!pending, ExcMessage("A phase begins from an accepted state."));
    AssertIndexRange(set, boundary_data.size());
    // The prescribed displacements stay where the phase left them: each
    // step prescribes only its increment.
    for (const auto &system : systems)
      system->held_load.add(accepted_lambda, system->unit_load);
    accepted_lambda = 0;
    current_lambda  = 0;
    boundary_set    = set;
    set_phase_loads(loads);
    if (reset_displacements)
      for (ModeVector &u : solution_vectors)
        u = 0;
    for (ModeVector &u : increment_vectors)
      u = 0;
  }


  template <int dim>
  bool
  Analysis<dim>::applies_anything(const PhaseLoads   loads,
                                  const unsigned int set) const
  {
    AssertIndexRange(set, boundary_data.size());
    const bool boundaries = applies_boundaries(loads);
    const bool weight     = applies_weight(loads);
    bool       applies    = false;
    for (const auto &system : systems)
      {
        const ModeSystem::BoundaryValues &values = system->boundary_values[set];
        applies =
          applies ||
          (boundaries && (values.load.linfty_norm() > 0 ||
                          values.prescribed_displacement.linfty_norm() > 0)) ||
          (weight && system->weight_load.linfty_norm() > 0);
      }
    return applies;
  }


  template <int dim>
  void
  Analysis<dim>::reduce_strength(const double factor)
  {
    for (const auto &group : groups)
      group->reduce_strength(parameters.strength_reduction, factor);
  }


  template <int dim>
  double
  Analysis<dim>::set_initial_stresses()
  {
    if constexpr (dim != 2)
      {
        Assert(false,
               ExcMessage("The K0 procedure is built for 2D meshes (the "
                          "parameters refuse it in 3D)."));
        return 0;
      }
    else
      {
        const KZeroStresses field(tria, parameters);
        const auto          initial = [&](const Point<dim>        &x,
                                 const types::material_id material) {
          return field.stress(x, material);
        };
        // The first group is the continuum (the one continuum points to).
        static_cast<ContinuumCells<dim> &>(*groups.front())
          .set_initial_stresses(initial);

        // The stresses start admissible: the worst point, over the ranks.
        double   worst = -std::numeric_limits<double>::infinity();
        Point<2> where;
        double   where_material = 0;
        for (const auto &cell : dof_handler.active_cell_iterators())
          {
            const unsigned int c = cell->active_cell_index();
            if (!cell->is_locally_owned() || !continuum->owns(c) ||
                !continuum->material_law(c).can_yield())
              continue;
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              {
                const double ratio = continuum->material_law(c).yield_ratio(
                  continuum->point_state(c, q, 0).stress);
                if (ratio > worst)
                  {
                    worst          = ratio;
                    where          = cell->center();
                    where_material = cell->material_id();
                  }
              }
          }
        refuse_outside_yield(
          parameters,
          worst_over_ranks(worst, {where[0], where[1], where_material}));

        // Interface elements start from the traction of the stresses beside
        // them: in equilibrium only where both sides put the same traction
        // on them, and a state of their law only where it is admissible.
        for (const auto &group : groups)
          if (auto *interfaces =
                dynamic_cast<InterfaceElements<dim> *>(group.get()))
            {
              refuse_initial_tractions(
                parameters, interfaces->set_initial_tractions(initial));
            }

        compute_internal_forces();
        double imbalance = 0, load = 0;
        for (unsigned int m = 0; m < systems.size(); ++m)
          {
            ModeSystem &mode = *systems[m];
            mode.held_load   = mode.weight_load;
            ModeVector r(mode.held_load);
            r -= internal_force_vectors[m];
            mode.condense(r);
            imbalance = std::max(imbalance, r.linfty_norm());
            load      = std::max(load, mode.held_load.linfty_norm());
          }
        return load > 0 ? imbalance / load : 0;
      }
  }


  template void
  Analysis<2>::set_phase_loads(const PhaseLoads);
  template void
  Analysis<3>::set_phase_loads(const PhaseLoads);
  template void
  Analysis<2>::begin_phase(const PhaseLoads, const bool, const unsigned int);
  template void
  Analysis<3>::begin_phase(const PhaseLoads, const bool, const unsigned int);
  template bool
  Analysis<2>::applies_anything(const PhaseLoads, const unsigned int) const;
  template bool
  Analysis<3>::applies_anything(const PhaseLoads, const unsigned int) const;
  template void
  Analysis<2>::reduce_strength(const double);
  template void
  Analysis<3>::reduce_strength(const double);
  template double
  Analysis<2>::set_initial_stresses();
  template double
  Analysis<3>::set_initial_stresses();
} // namespace thinlayer
