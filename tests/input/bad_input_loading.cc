// Truth checked: a load programme the scene cannot have (its initial
// state, its further phases, its strength reduction) is refused with one
// clear message naming the file and the entry, a non-zero exit, and the
// previous run and a file of the user's beside it kept byte for byte.
// The initial state: a K0 that puts the at-rest stress outside the yield
// surface, the K0 procedure on ground that is not level or in 3D (its refusals
// at interface elements are in tests/verification/initial_tractions), gravity
// loading that does not add up to the whole weight, a
// procedure with no weight to start from, a K0 or a surcharge that is no
// number the entry takes, a strength reduction of an elastic material, of
// one the mesh does not have or by a factor that falls, and a loading that
// applies nothing after the initial state (with no strength reduction to
// follow). A further loading phase (Phase <n>): one that names a boundary
// the mesh lacks, one that changes which components are constrained, a gap
// in the phases' numbers or a Phase 1, a phase that applies nothing, an
// expression that is no function, a traction on a constrained component,
// and a load step of 0. Adaptive step lengths where the programme is run
// as given (Collapse resolution = 0), and on a programme, or a phase's,
// that unloads after it loads. Work control (Loading/Control = work) with
// the programme as given, with a method other than Newton's, with a
// strength reduction to follow, and where the load factor also scales a
// prescribed displacement.
#include "../common/bad_input_utilities.h"

using namespace bad_input;

namespace
{
  /// Initial states and strength reductions.
  void
  check_initial_states()
  {
    const std::string prm     = std::string(SOURCE_DIR) + "/../../prm/";
    const std::string k0      = "Initial state/Procedure=K0 procedure";
    const std::string gravity = "Initial state/Procedure=gravity loading";
    const std::string weight  = "Material 1/Unit weight=20";

    check("a K0 outside the yield surface (Tresca, c = 1, K0 = 0.2 under "
          "gamma = 20)",
          {"good.prm",
           "-s",
           k0,
           "-s",
           weight,
           "-s",
           "Material 1/Yield criterion=tresca",
           "-s",
           "Material 1/Cohesion=1",
           "-s",
           "Material 1/K0=0.2"});
    check("a cohesionless K0 below K_a (phi = 30, K0 = 0.2)",
          {"good.prm",
           "-s",
           k0,
           "-s",
           weight,
           "-s",
           "Material 1/Yield criterion=mohr-coulomb",
           "-s",
           "Material 1/Friction angle=30",
           "-s",
           "Material 1/K0=0.2"});
    check("the K0 procedure on ground that is not level (a vertical cut)",
          {prm + "vertical-cut.prm",
           "-s",
           k0,
           "-s",
           "Strength reduction/Materials=1",
           "-s",
           "Output/Directory=results"});
    check("the K0 procedure in 3D",
          {prm + "case1-3d.prm",
           "-s",
           k0,
           "-s",
           "Material 1/Unit weight=20",
           "-s",
           "Output/Directory=results"});
    check("gravity loading that adds up to 0.9 of the weight",
          {"good.prm",
           "-s",
           gravity,
           "-s",
           weight,
           "-s",
           "Initial state/Load increments=0.5, 0.4"});
    check("gravity loading with no weight", {"good.prm", "-s", gravity});
    check("a K0 of -1",
          {"good.prm", "-s", k0, "-s", weight, "-s", "Material 1/K0=-1"});
    check("a K0 that is a word", {"good.prm", "-s", "Material 1/K0=jaky"});
    check("a negative surcharge",
          {"good.prm", "-s", k0, "-s", "Initial state/Surcharge=-10"});
    check("an unknown procedure",
          {"good.prm", "-s", "Initial state/Procedure=excavation"});
    check("a strength reduction of an elastic material",
          {"good.prm", "-s", "Strength reduction/Materials=1"});
    check("a strength reduction of a material the mesh does not have",
          {"good.prm",
           "-s",
           "Material 1/Yield criterion=tresca",
           "-s",
           "Material 1/Cohesion=1",
           "-s",
           "Strength reduction/Materials=7"});
    check("a strength reduction of interface elements on an elastic curve",
          {prm + "case4-rough-wall-zero-thickness.prm",
           "-s",
           "Interface 6/Slip criterion=elastic",
           "-s",
           "Interface 6/Adhesion=0",
           "-s",
           "Strength reduction/Interfaces=6",
           "-s",
           "Output/Directory=results"});
    check("a strength reduction factor that falls",
          {"good.prm",
           "-s",
           "Material 1/Yield criterion=tresca",
           "-s",
           "Material 1/Cohesion=1",
           "-s",
           "Strength reduction/Materials=1",
           "-s",
           "Strength reduction/Factor increments=0.5, -0.1"});
    check(
      "a loading that applies nothing after the initial state",
      {"good.prm", "-s", k0, "-s", weight, "-s", "Boundary 2/Traction=0; 0"});
  }


  /// Further loading phases.
  void
  check_phases()
  {
    const auto phase = [](const std::string &override) {
      return std::vector<std::string>{"good.prm", "-s", override};
    };
    check("a phase that names a boundary the mesh lacks",
          phase("Phase 2/Boundary 9/Traction=0; -1"));
    check("a phase that constrains a component",
          phase("Phase 2/Boundary 2/Constrained components=x"));
    check("Phase 3 without Phase 2",
          phase("Phase 3/Boundary 2/Traction=0; -1"));
    check("a Phase 1 (the Loading section is phase 1)",
          phase("Phase 1/Boundary 2/Traction=0; -1"));
    check("a phase that applies nothing", phase("Phase 2/Load increments=1"));
    check("a phase's traction that is no function of x, y",
          phase("Phase 2/Boundary 2/Traction=0; q"));
    check("a phase's traction on a constrained component",
          phase("Phase 2/Boundary 1/Traction=1; 0"));
    check("a phase's load step of 0", phase("Phase 2/Load increments=0"));
    const std::string adaptive = "Loading/Step length=adaptive";
    check("adaptive step lengths with the programme run as given",
          {"good.prm", "-s", adaptive, "-s", "Loading/Collapse resolution=0"});
    check("adaptive step lengths on a programme that loads and unloads",
          {"good.prm",
           "-s",
           adaptive,
           "-s",
           "Loading/Load increments=0.5, 0.5, -1"});
    check("adaptive step lengths on a phase that loads and unloads",
          {"good.prm",
           "-s",
           adaptive,
           "-s",
           "Phase 2/Boundary 2/Traction=0; -1",
           "-s",
           "Phase 2/Load increments=1, -0.5"});
    const std::string work = "Loading/Control=work";
    check("work control with the programme run as given",
          {"good.prm", "-s", work, "-s", "Loading/Collapse resolution=0"});
    check("work control by the paper's method",
          {"good.prm", "-s", work, "-s", "Solver/Method=viscoplastic"});
    check("work control with a strength reduction to follow",
          {"good.prm",
           "-s",
           work,
           "-s",
           "Material 1/Yield criterion=tresca",
           "-s",
           "Material 1/Cohesion=1",
           "-s",
           "Strength reduction/Materials=1"});
    check("work control where a displacement is prescribed",
          {"good.prm", "-s", work, "-s", "Boundary 1/Displacement=0; -0.001"});
  }
} // namespace


int
main()
{
  write_valid_scene();
  check_initial_states();
  check_phases();
}
