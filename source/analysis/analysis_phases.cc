// The phases of a run: the initial stresses of the K0 procedure, and the
// start of each phase, which holds the loads of the one before it. Members
// of Analysis, in a file of their own.
#include <thinlayer/analysis/analysis.h>
#include <thinlayer/base/input_error.h>
#include <thinlayer/base/text_format.h>
#include <thinlayer/discretisation/initial_stresses.h>
#include <thinlayer/materials/material_law.h>
#include <thinlayer/parallel/mpi.h>

#include <cmath>
#include <limits>

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
            mode.unit_prescribed_displacement =
              mode.boundary_prescribed_displacement;
            mode.unit_load = mode.boundary_load;
            mode.unit_rhs  = mode.boundary_rhs;
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
  Analysis<dim>::begin_phase(const PhaseLoads loads,
                             const bool       reset_displacements)
  {
    Assert(!pending, ExcMessage("A phase begins from an accepted state."));
    for (const auto &system : systems)
      system->held_load.add(accepted_lambda, system->unit_load);
    accepted_lambda = 0;
    current_lambda  = 0;
    set_phase_loads(loads);
    if (reset_displacements)
      for (ModeVector &u : solution_vectors)
        u = 0;
    for (ModeVector &u : increment_vectors)
      u = 0;
  }


  template <int dim>
  bool
  Analysis<dim>::applies_anything(const PhaseLoads loads) const
  {
    const bool boundaries = applies_boundaries(loads);
    const bool weight     = applies_weight(loads);
    bool       applies    = false;
    for (const auto &system : systems)
      applies =
        applies ||
        (boundaries &&
         (system->boundary_load.linfty_norm() > 0 ||
          system->boundary_prescribed_displacement.linfty_norm() > 0)) ||
        (weight && system->weight_load.linfty_norm() > 0);
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
        // The first group is the continuum (the one continuum points to).
        static_cast<ContinuumCells<dim> &>(*groups.front())
          .set_initial_stresses(
            [&](const Point<dim> &x, const types::material_id material) {
              return field.stress(x, material);
            });

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
        const double global_worst = mpi::max(worst);
        if (global_worst > 1e-9)
          {
            const bool   mine = worst == global_worst;
            const double x    = mpi::max(
              mine ? where[0] : -std::numeric_limits<double>::infinity());
            const double y = mpi::max(
              mine ? where[1] : -std::numeric_limits<double>::infinity());
            const auto id = static_cast<types::material_id>(
              mpi::max(mine ? where_material
                            : -std::numeric_limits<double>::infinity()));
            const MaterialParameters &material = parameters.materials.at(id);
            const double              s =
              std::sin(material.friction_angle * numbers::PI / 180);
            using text_format::printf;
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
                " in the cell centred at (" + printf("%g", x) + ", " +
                printf("%g", y) + "): yield ratio " +
                printf("%.3g", global_worst) +
                " (K0 = " + printf("%g", material.k0) +
                "); expected a K0 the material can carry at rest" + range);
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
  Analysis<2>::begin_phase(const PhaseLoads, const bool);
  template void
  Analysis<3>::begin_phase(const PhaseLoads, const bool);
  template bool
  Analysis<2>::applies_anything(const PhaseLoads) const;
  template bool
  Analysis<3>::applies_anything(const PhaseLoads) const;
  template void
  Analysis<2>::reduce_strength(const double);
  template void
  Analysis<3>::reduce_strength(const double);
  template double
  Analysis<2>::set_initial_stresses();
  template double
  Analysis<3>::set_initial_stresses();
} // namespace thinlayer
