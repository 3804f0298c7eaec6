#include <thinlayer/base/input_error.h>
#include <thinlayer/parameters/scene_checks.h>

#include <algorithm>
#include <set>

namespace thinlayer
{
  void
  check_monitors_and_phases(const Parameters &p)
  {
    using Load = MonitorParameters::LoadMeasure;
    if (p.monitors.load_measure == Load::reaction)
      {
        const auto boundary = p.boundaries.find(p.monitors.load_boundary_id);
        if (boundary == p.boundaries.end() ||
            std::none_of(boundary->second.constrained_components.begin(),
                         boundary->second.constrained_components.end(),
                         [](const bool c) { return c; }))
          throw InputError(
            p.parameter_file,
            "Monitors/Load boundary id",
            "boundary " + std::to_string(p.monitors.load_boundary_id) +
              " constrains no component ('Boundary " +
              std::to_string(p.monitors.load_boundary_id) +
              "/Constrained components'), so the reaction read off it is "
              "0 whatever the load; expected the id of a boundary that "
              "constrains the load's component");
      }
    std::set<std::string> names = {"initial state",
                                   "loading",
                                   "strength reduction"};
    for (unsigned int k = 0; k < p.loading_phases.size(); ++k)
      if (const std::string &name = p.loading_phases[k].name;
          !names.insert(name).second)
        throw InputError(p.parameter_file,
                         LoadingPhaseParameters::section(k + 2) + "/Name",
                         "'" + name +
                           "' names two phases (the initial state, the "
                           "loading and the strength reduction have their "
                           "names too); expected each phase named once, so "
                           "that history.csv tells them apart");
  }


  void
  check_initial_state(const Parameters &p)
  {
    // The weight acts along the axis, the same at every angle: only
    // harmonic 0 of the symmetric series carries it, and without it the
    // weight would silently be dropped.
    if (p.kinematics.fourier && (p.kinematics.antisymmetric ||
                                 std::find(p.kinematics.harmonics.begin(),
                                           p.kinematics.harmonics.end(),
                                           0u) == p.kinematics.harmonics.end()))
      for (const auto &[id, material] : p.materials)
        if (material.unit_weight > 0 || p.initial_state.surcharge > 0)
          throw InputError(
            p.parameter_file,
            "Kinematics/Harmonics",
            (material.unit_weight > 0
               ? "Material " + std::to_string(id) + " has a unit weight"
               : std::string("the initial state has a surcharge")) +
              ", which acts along the axis, the same at every angle: only "
              "harmonic 0 of the symmetric series carries it; expected "
              "Harmonics to include 0 (Series symmetric), or no weight");
    using Procedure           = InitialStateParameters::Procedure;
    const Procedure procedure = p.initial_state.procedure;
    if (procedure == Procedure::none)
      return;
    const std::string name =
      InitialStateParameters::procedure_names.name(procedure);
    const std::string entry  = "Initial state/Procedure";
    bool              weight = p.initial_state.surcharge > 0;
    for (const auto &[id, material] : p.materials)
      weight = weight || material.unit_weight > 0;
    if (!weight)
      throw InputError(p.parameter_file,
                       entry,
                       "expected a Material <id>/Unit weight > 0 or an "
                       "Initial state/Surcharge > 0 for the " +
                         name +
                         ": without them the initial state is "
                         "free of stress");
    if (procedure != Procedure::k0)
      return;
    if (p.kinematics.dimension == 3)
      throw InputError(p.parameter_file,
                       entry,
                       "the K0 procedure is built for 2D meshes (plane "
                       "strain, Fourier); expected 'gravity loading' in "
                       "3D");
    if (p.kinematics.fourier && (p.kinematics.antisymmetric ||
                                 std::find(p.kinematics.harmonics.begin(),
                                           p.kinematics.harmonics.end(),
                                           0u) == p.kinematics.harmonics.end()))
      throw InputError(p.parameter_file,
                       entry,
                       "the K0 stresses are the same at every angle: "
                       "expected Kinematics/Harmonics to include 0 "
                       "(symmetric)");
  }


  void
  check_entries_mean_something(const Parameters            &p,
                               const std::set<std::string> &given,
                               const std::set<std::string> &written)
  {
    const auto refuse_if_given = [&](const std::string &entry,
                                     const std::string &why) {
      if (given.count(entry) != 0)
        throw InputError(p.parameter_file,
                         entry,
                         "means nothing " + why + "; expected it unset");
    };
    if (!p.kinematics.fourier)
      for (const char *entry : {"Kinematics/Harmonics",
                                "Kinematics/Series",
                                "Kinematics/Stations",
                                "Kinematics/Axis boundary id",
                                "Monitors/Displacement angle"})
        refuse_if_given(entry,
                        "in plane strain or 3d (it is for "
                        "Kinematics/Type = fourier)");
    // Q8 is the default in 3D too, where it stands for Q20: written out,
    // it is a mistake.
    if (p.kinematics.dimension == 3 && p.discretisation.element_name == "Q8" &&
        written.count("Discretisation/Element") != 0)
      throw InputError(p.parameter_file,
                       "Discretisation/Element",
                       "Q8 is a quadrilateral; expected Q20 or Q27 in 3d");
    using Measure = MonitorParameters::DisplacementMeasure;
    if (p.monitors.displacement_measure == Measure::boundary_average)
      refuse_if_given("Monitors/Displacement point",
                      "with Displacement measure = boundary average "
                      "(it is for the point measure)");
    else
      refuse_if_given("Monitors/Displacement boundary id",
                      "with Displacement measure = point (it is for the "
                      "boundary average)");
    using Load = MonitorParameters::LoadMeasure;
    if (p.monitors.load_measure != Load::reaction)
      for (const char *entry :
           {"Monitors/Load boundary id", "Monitors/Load component"})
        refuse_if_given(entry,
                        "unless Load measure = reaction (it is for the "
                        "reactions' resultant)");
    if (p.monitors.load_measure != Load::stress_average)
      for (const char *entry :
           {"Monitors/Load material id", "Monitors/Load stress component"})
        refuse_if_given(entry,
                        "unless Load measure = stress average (it is for "
                        "the averaged stress)");
    if (p.solver.linear_solver != SolverParameters::LinearSolver::amg_cg)
      for (const char *entry : {"Solver/Linear solver tolerance",
                                "Solver/Linear solver iterations"})
        refuse_if_given(entry,
                        "unless Linear solver = amg cg (a factorisation "
                        "solves exactly, without iterations)");
    if (!p.adaptivity.active())
      for (const char *entry : {"Adaptivity/Indicator",
                                "Adaptivity/Marking",
                                "Adaptivity/Marking fraction",
                                "Adaptivity/Stop tolerance",
                                "Adaptivity/Maximum DoFs"})
        refuse_if_given(entry,
                        "with Adaptivity/Cycles = 0 (it is for the "
                        "refinement cycles)");
    else if (p.adaptivity.marking == AdaptivityParameters::Marking::uniform)
      refuse_if_given("Adaptivity/Marking fraction",
                      "with Adaptivity/Marking = uniform (every cell is "
                      "refined)");
    using LinearSolver = SolverParameters::LinearSolver;
    if (p.solver.linear_solver != LinearSolver::automatic &&
        p.solver.linear_solver != LinearSolver::block_low_rank)
      refuse_if_given("Solver/Block low-rank tolerance",
                      "unless Linear solver = automatic or block low-rank "
                      "(it is for MUMPS's compressed factor)");
  }


  void
  check_adaptivity(const Parameters &p)
  {
    if (!p.adaptivity.active())
      return;
    if (!p.sweep.values.empty())
      throw InputError(p.parameter_file,
                       "Adaptivity/Cycles",
                       "refinement cycles within a sweep are not supported; "
                       "expected 0 with Sweep/Values set (or no sweep)");
    if (!p.layers.material_ids.empty())
      throw InputError(p.parameter_file,
                       "Adaptivity/Cycles",
                       "a refined layer is more than one cell thick, and "
                       "the profiles of Layers/Material ids read a layer "
                       "one cell thick; expected 0 with layer profiles (or "
                       "no profiles)");
  }
} // namespace thinlayer
