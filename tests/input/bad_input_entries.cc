// Truth checked: entries that would crash the run, make it meaningless or
// mean nothing in the scene (an empty load programme, no load at all, a
// body free to rotate, Fourier entries in plane strain, a point given for
// a boundary average, a repeated component or parameter, a sweep that
// names a parameter twice, sweeps itself or has more runs than the cap,
// expectations of the run that cannot be met or mean nothing, MUMPS's
// compression asked of one rank or tuned for a solver without it,
// refinement entries without cycles or beside a sweep)
// are refused with one clear message naming the file and the entry, a
// non-zero exit, and the previous run and a file of the user's beside it
// kept byte for byte. And a truth: Reference/Variables binds the Analytic
// load to this run's entries, so that every friction angle of a sweep has
// its own closed form (to 1e-12).
#include <thinlayer/parameters/parameter_reader.h>
#include <thinlayer/parameters/parameters.h>

#include <cmath>

#include "../common/bad_input_utilities.h"
#include "../common/truths.h"

using namespace bad_input;

namespace
{
  const std::string meshes = std::string(SOURCE_DIR) + "/../../meshes/";

  /// Load programmes and loads that apply nothing.
  void
  check_loads()
  {
    check("an empty load programme (0*0.1)",
          {"good.prm", "-s", "Loading/Load increments=0*0.1"});
    check("a load programme of one step of 0",
          {"good.prm", "-s", "Loading/Load increments=0"});
    check("a step of 0 inside a programme",
          {"good.prm", "-s", "Loading/Load increments=0.5, 0, 0.5"});
    check("no load at all (a traction of 0)",
          {"good.prm", "-s", "Boundary 2/Traction=0; 0"});
    check("a load scale of 0", {"good.prm", "-s", "Monitors/Load scale=0"});
    check("a displacement scale of 0",
          {"good.prm", "-s", "Monitors/Displacement scale=0"});
  }


  /// Supports that leave a rigid-body motion free, and interface elements
  /// too soft to be factorised: each blamed on what is at fault.
  void
  check_supports()
  {
    // Tangential supports only: x along the bottom, y along the left
    // side. Both translations are held; the rotation about the corner
    // (0, 0) is not.
    write("rotation.prm",
          "subsection Mesh\n  set File = " + meshes +
            "block.geo\nend\n"
            "subsection Material 1\nend\n"
            "subsection Boundary 1\n  set Constrained components = x\nend\n"
            "subsection Boundary 4\n  set Constrained components = y\nend\n"
            "subsection Boundary 3\n  set Traction = 1; -1\nend\n"
            "subsection Monitors\n  set Displacement boundary id = 3\nend\n"
            "subsection Output\n  set Directory = results\nend\n");
    check("a body free to rotate about a corner", {"rotation.prm"});
    check("a body free to rotate about its lower right corner, shifted",
          {"rotation.prm",
           "-s",
           "Boundary 4/Constrained components=",
           "-s",
           "Boundary 2/Constrained components=y",
           "-s",
           "Mesh/Geometry parameters=x0=3"});

    write("soft-interface.prm", soft_interface_scene(meshes));
    check("an interface curve with a shear stiffness of 1e-20 E/h",
          {"soft-interface.prm"});
    check("an adhesion on an elastic interface curve",
          {"soft-interface.prm",
           "-s",
           "Interface 3/Shear stiffness=1e5",
           "-s",
           "Interface 3/Adhesion=1"});
    check("a tensile strength on an elastic interface curve",
          {"soft-interface.prm",
           "-s",
           "Interface 3/Shear stiffness=1e5",
           "-s",
           "Interface 3/Tensile strength=0"});
  }


  /// Entries that mean nothing in the scene, and values given twice.
  void
  check_meaningless_entries()
  {
    check("Fourier harmonics in plane strain",
          {"good.prm", "-s", "Kinematics/Harmonics=1, 3"});
    check("Fourier stations in plane strain",
          {"good.prm", "-s", "Kinematics/Stations=0, 90, 180"});
    check("a Fourier axis boundary id in plane strain",
          {"good.prm", "-s", "Kinematics/Axis boundary id=1"});
    check("a displacement angle in plane strain",
          {"good.prm", "-s", "Monitors/Displacement angle=90"});
    check("a point given where the measure is a boundary average",
          {"good.prm", "-s", "Monitors/Displacement point=0.5, 0.5"});
    check("a boundary id given where the measure is a point",
          {"good.prm",
           "-s",
           "Monitors/Displacement measure=point",
           "-s",
           "Monitors/Displacement point=0.5, 0.5"});
    check("a reaction's boundary id where the load measure is the load factor",
          {"good.prm", "-s", "Monitors/Load boundary id=1"});
    check("a stress component where the load measure is the load factor",
          {"good.prm", "-s", "Monitors/Load stress component=yy"});
    check("a constrained component given twice (y, y)",
          {"good.prm", "-s", "Boundary 1/Constrained components=x, y, y"});
    check("a geometry parameter given twice",
          {"good.prm", "-s", "Mesh/Geometry parameters=height=1, height=2"});
    check("an analytic load that uses x (only geometry parameters may)",
          {"good.prm", "-s", "Reference/Analytic load=2*x"});
  }


  /// The last line of @p text that contains @p what; empty if none.
  std::string
  last_line_with(const std::string &text, const std::string &what)
  {
    std::string        found;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);)
      if (line.find(what) != std::string::npos)
        found = line;
    return found;
  }


  /// What a verification scene expects of its run: malformed expectations
  /// are bad input; a run that misses a well-formed one is written (it is
  /// a result) and exits with status 4, and one that meets it with 0.
  void
  check_reference_expectations()
  {
    check("an expected outcome that is none (collapsed)",
          {"good.prm", "-s", "Reference/Expected outcome=collapsed"});
    check("an expected load range with low > high",
          {"good.prm",
           "-s",
           "Reference/Analytic load=1",
           "-s",
           "Reference/Expected load range=2, 1"});
    check("an expected load range of one number",
          {"good.prm",
           "-s",
           "Reference/Analytic load=1",
           "-s",
           "Reference/Expected load range=1"});

    // The valid scene is elastic: it completes at load factor 1.
    const auto run = [](const std::string              &what,
                        const std::vector<std::string> &expectations) {
      std::vector<std::string> arguments = {"good.prm",
                                            "-s",
                                            "Output/Directory=expectations",
                                            "-s",
                                            "Reference/Analytic load=1"};
      for (const std::string &e : expectations)
        {
          arguments.push_back("-s");
          arguments.push_back(e);
        }
      std::ostringstream out, err;
      const int status = thinlayer::run_command_line(arguments, out, err);
      const std::string check_line =
        last_line_with(out.str(), "reference check");
      std::cout << "* " << what << "\n  exit status " << status
                << ", summary written: "
                << (std::filesystem::exists("expectations/summary.json") ? "yes"
                                                                         : "no")
                << "\n"
                << check_line << "\n  " << err.str() << '\n';
      std::filesystem::remove_all("expectations");
    };
    run("a run that meets its expectations",
        {"Reference/Expected outcome=completed",
         "Reference/Expected load range=0.999999, 1.000001"});
    run("a run whose outcome misses the expected one",
        {"Reference/Expected outcome=collapse"});
    run("a run whose load misses the expected range",
        {"Reference/Expected load range=1.5, 2"});
  }


  /// Reference/Variables: the Analytic load of prm/case1-frictional-
  /// stability-map.prm, read for three friction angles of its interface (from
  /// its dilation angle, 20, up) as a sweep gives them, is each angle's closed
  /// form 1 / (cos a (sin a - cos a tan phi)); names that bind nothing a number
  /// are refused, and so is a bracket that does not hold the analytic load.
  void
  check_reference_variables()
  {
    const std::string file =
      std::string(SOURCE_DIR) + "/../../prm/case1-frictional-stability-map.prm";
    std::cout << "* Reference/Variables over a sweep of the friction angle\n";
    for (const double phi : {20., 25., 30.})
      {
        const thinlayer::Parameters p =
          thinlayer::ParameterReader().read(file,
                                            {"Material 2/Friction angle=" +
                                               std::to_string(phi),
                                             "Output/Directory=variables"});
        const double a = p.mesh.geometry_parameters.at("alpha") * M_PI / 180;
        const double closed =
          1 / (std::cos(a) *
               (std::sin(a) - std::cos(a) * std::tan(phi * M_PI / 180)));
        std::cout << "  phi " << phi << ": analytic load "
                  << p.reference.analytic_load << ", closed form " << closed
                  << '\n';
        truths::expect(std::abs(p.reference.analytic_load / closed - 1) < 1e-12,
                       "the run's own closed form");
      }
    std::cout << '\n';
    check("a variable bound to an entry that does not exist",
          {"good.prm",
           "-s",
           "Reference/Analytic load=2*c",
           "-s",
           "Reference/Variables=c = Material 1/Cohesive strength"});
    check("a variable bound to an entry that is no number",
          {"good.prm",
           "-s",
           "Reference/Analytic load=2*c",
           "-s",
           "Reference/Variables=c = Material 1/Yield criterion"});
    check("variables without an analytic load",
          {"good.prm", "-s", "Reference/Variables=c = Material 1/Cohesion"});
    check("an analytic bracket that does not hold the analytic load",
          {"good.prm",
           "-s",
           "Reference/Analytic load=1",
           "-s",
           "Reference/Analytic bracket=2, 3"});
  }


  /// A section by its former name ("Interfaces", now "Layers"), in the
  /// file and on the command line: accepted, with a warning naming where.
  /// So are "Interface curve <id>" (now "Interface <id>") and Strength
  /// reduction's "Interface curves" (now "Interfaces"): the too soft
  /// interface of soft_interface_scene() given by its former name is refused
  /// by its new one, after the warnings.
  void
  check_former_names()
  {
    std::string       curve   = soft_interface_scene(meshes);
    const std::string section = "subsection Interface 3";
    curve.replace(curve.find(section),
                  section.size(),
                  "subsection Interface curve 3");
    write("former-curve.prm",
          curve + "subsection Strength reduction\n  set Interface curves "
                  "=\nend\n");
    for (const auto &arguments :
         {std::vector<std::string>{"former-curve.prm"},
          std::vector<std::string>{"soft-interface.prm",
                                   "-s",
                                   "Interface curve 3/Shear stiffness=1e-20",
                                   "-s",
                                   "Strength reduction/Interface curves="}})
      {
        std::ostringstream out, err;
        const int status = thinlayer::run_command_line(arguments, out, err);
        std::cout << "* the former names Interface curve 3 and Strength "
                     "reduction/Interface curves, from "
                  << (arguments.size() == 1 ? "the file" : "the command line")
                  << "\n  exit status " << status << "\n";
        std::istringstream lines(out.str());
        for (std::string line; std::getline(lines, line);)
          if (line.find("warning: ") != std::string::npos)
            std::cout << line << '\n';
        std::cout << "  " << err.str() << '\n';
        std::filesystem::remove_all("results");
      }

    write("former.prm",
          scene() + "subsection Interfaces\n  set Material ids =\nend\n");
    for (const auto &arguments :
         {std::vector<std::string>{"former.prm"},
          std::vector<std::string>{"good.prm",
                                   "-s",
                                   "Interfaces/Material ids="}})
      {
        std::vector<std::string> all = arguments;
        all.insert(all.end(), {"-s", "Output/Directory=former"});
        std::ostringstream out, err;
        const int          status  = thinlayer::run_command_line(all, out, err);
        const std::string  warning = last_line_with(out.str(), "warning: ");
        std::cout << "* the former section name Interfaces, from "
                  << (arguments.size() == 1 ? "the file" : "the command line")
                  << "\n  exit status " << status << "\n"
                  << warning << "\n  " << err.str() << '\n';
        std::filesystem::remove_all("former");
      }
  }


  /// Sweeps that cannot mean what they say.
  void
  check_sweeps()
  {
    check("a sweep that names a parameter twice",
          {"good.prm", "-s", "Sweep/Values=height = 2, 3; height = 4"});
    check("a sweep that names an entry twice (spelt with spaces)",
          {"good.prm",
           "-s",
           "Sweep/Values=Solver/Tolerance = 1e-3; Solver / Tolerance = "
           "1e-4"});
    check("a sweep over Output/Directory",
          {"good.prm", "-s", "Sweep/Values=Output/Directory = a, b"});
    check("a sweep over the sweep itself",
          {"good.prm", "-s", "Sweep/Values=Sweep/Values = a, b"});
    std::string many = "Sweep/Values=height = ";
    for (unsigned int k = 1; k <= 1000; ++k)
      many += std::to_string(k) + (k < 1000 ? ", " : "");
    many += "; Solver/Tolerance = ";
    for (unsigned int k = 1; k <= 50; ++k)
      many += "1e-" + std::to_string(k % 9 + 2) + (k < 50 ? ", " : "");
    check("a sweep of 1000 x 50 runs, over the cap", {"good.prm", "-s", many});
  }


  /// Entries accepted without a word that the run could not honour.
  void
  check_silent_entries()
  {
    const std::string phases =
      "subsection Phase 2\n  set Name = unloading\n  subsection Boundary 2\n"
      "    set Traction = 0; 0.5\n  end\nend\n"
      "subsection Phase 3\n  set Name = unloading\n  subsection Boundary 2\n"
      "    set Traction = 0; -0.5\n  end\nend\n";
    write("same-names.prm", scene("good.geo", "", phases));
    check("two phases of one name", {"same-names.prm"});
    write("loading-name.prm",
          scene("good.geo",
                "",
                "subsection Phase 2\n  set Name = loading\n"
                "  subsection Boundary 2\n    set Traction = 0; 0.5\n  end\n"
                "end\n"));
    check("a phase named like the loading", {"loading-name.prm"});
    write("reduced-twice.prm",
          scene("good.geo",
                "  set Yield criterion = tresca\n  set Cohesion = 10\n",
                "subsection Strength reduction\n  set Materials = 1, 1\n"
                "end\n"));
    check("Strength reduction/Materials = 1, 1", {"reduced-twice.prm"});
    check("a reaction read off a boundary that constrains nothing",
          {"good.prm",
           "-s",
           "Monitors/Load measure=reaction",
           "-s",
           "Monitors/Load boundary id=2"});
    check("Linear solver iterations with cholmod",
          {"good.prm", "-s", "Solver/Linear solver iterations=5"});
    check("Linear solver tolerance with umfpack",
          {"good.prm",
           "-s",
           "Solver/Linear solver=umfpack",
           "-s",
           "Solver/Linear solver tolerance=1e-6"});
    check("block low-rank on one rank",
          {"good.prm", "-s", "Solver/Linear solver=block low-rank"});
    check("Block low-rank tolerance with cholmod",
          {"good.prm",
           "-s",
           "Solver/Linear solver=cholmod",
           "-s",
           "Solver/Block low-rank tolerance=1e-6"});
    check("Block low-rank tolerance of 1",
          {"good.prm", "-s", "Solver/Block low-rank tolerance=1"});
    check("an adaptivity entry without cycles",
          {"good.prm", "-s", "Adaptivity/Indicator=plastic strain"});
    check("a marking fraction of 0",
          {"good.prm",
           "-s",
           "Adaptivity/Cycles=2",
           "-s",
           "Adaptivity/Marking fraction=0"});
    check("a marking fraction with uniform refinement",
          {"good.prm",
           "-s",
           "Adaptivity/Cycles=2",
           "-s",
           "Adaptivity/Marking=uniform",
           "-s",
           "Adaptivity/Marking fraction=0.3"});
    check(
      "refinement cycles with layer profiles",
      {"good.prm", "-s", "Adaptivity/Cycles=2", "-s", "Layers/Material ids=2"});
    check("refinement cycles within a sweep",
          {"good.prm",
           "-s",
           "Adaptivity/Cycles=2",
           "-s",
           "Sweep/Values=height = 2, 3"});
    // The valid scene as the r-z plane of a Fourier body.
    write("fourier.prm",
          "subsection Mesh\n  set File = good.geo\nend\n"
          "subsection Kinematics\n  set Type = fourier\n"
          "  set Axis boundary id = 3\nend\n"
          "subsection Material 1\nend\nsubsection Material 2\nend\n"
          "subsection Boundary 1\n  set Constrained components = r, z, theta"
          "\nend\n"
          "subsection Boundary 2\n  set Traction = 1; -1; 0\nend\n"
          "subsection Monitors\n  set Displacement boundary id = 2\nend\n"
          "subsection Output\n  set Directory = results\nend\n");
    check("a Fourier body with a unit weight but no harmonic 0",
          {"fourier.prm", "-s", "Material 1/Unit weight=1"});
    check("gravity loading of a Fourier body in the antisymmetric series",
          {"fourier.prm",
           "-s",
           "Kinematics/Harmonics=0",
           "-s",
           "Kinematics/Series=antisymmetric",
           "-s",
           "Material 2/Unit weight=1",
           "-s",
           "Initial state/Procedure=gravity loading"});
  }


  /// The record of a run and the printed parameters run as given.
  void
  check_records()
  {
    const std::string valid = summary_entry("previous", "final_displacement");
    std::filesystem::copy_file(
      "previous/parameters.prm",
      "record.prm",
      std::filesystem::copy_options::overwrite_existing);
    check("(the record of the valid run, parameters.prm: run as designed, "
          "into the same directory)",
          {"record.prm"});
    std::cout << "  the same displacement as the valid run: "
              << (summary_entry("results", "final_displacement") == valid
                    ? "yes"
                    : "NO")
              << "\n\n";

    std::ostringstream printed, err;
    const int          status =
      thinlayer::run_command_line({"good.prm", "--print-parameters"},
                                  printed,
                                  err);
    write("printed.prm", printed.str());
    std::cout << "* good.prm --print-parameters: exit status " << status
              << ", entries documented: "
              << (printed.str().find("\n  # ") != std::string::npos ? "yes"
                                                                    : "NO")
              << "\n\n";
    check("(what it printed: run as designed)", {"printed.prm"});
    std::cout << "  the same displacement as the valid run: "
              << (summary_entry("results", "final_displacement") == valid
                    ? "yes"
                    : "NO")
              << "\n\n";

    std::ostringstream defaults;
    thinlayer::run_command_line({"--print-parameters"}, defaults, err);
    write("defaults.prm", defaults.str());
    check("the defaults --print-parameters prints, which name no mesh",
          {"defaults.prm"});
  }
} // namespace


int
main()
{
  write_valid_scene();
  check_loads();
  check_supports();
  check_meaningless_entries();
  check_sweeps();
  check_reference_expectations();
  check_reference_variables();
  check_former_names();
  check_silent_entries();
  check_records();
  return truths::conclude();
}
