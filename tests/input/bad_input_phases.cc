// Truth checked: a further loading phase (Phase <n>) the scene cannot have
// is refused with one clear message naming the file and the entry, a
// non-zero exit, and the previous run and a file of the user's beside it
// kept byte for byte: a phase that names a boundary the mesh lacks, one
// that changes which components are constrained, a gap in the phases'
// numbers or a Phase 1, a phase that applies nothing, an expression that is no
// function, a traction on a constrained component, and a load step of 0.
#include "../common/bad_input_utilities.h"

using namespace bad_input;

int
main()
{
  write_valid_scene();
  const auto phase = [](const std::string &override) {
    return std::vector<std::string>{"good.prm", "-s", override};
  };
  check("a phase that names a boundary the mesh lacks",
        phase("Phase 2/Boundary 9/Traction=0; -1"));
  check("a phase that constrains a component",
        phase("Phase 2/Boundary 2/Constrained components=x"));
  check("Phase 3 without Phase 2", phase("Phase 3/Boundary 2/Traction=0; -1"));
  check("a Phase 1 (the Loading section is phase 1)",
        phase("Phase 1/Boundary 2/Traction=0; -1"));
  check("a phase that applies nothing", phase("Phase 2/Load increments=1"));
  check("a phase's traction that is no function of x, y",
        phase("Phase 2/Boundary 2/Traction=0; q"));
  check("a phase's traction on a constrained component",
        phase("Phase 2/Boundary 1/Traction=1; 0"));
  check("a phase's load step of 0", phase("Phase 2/Load increments=0"));
  return 0;
}
