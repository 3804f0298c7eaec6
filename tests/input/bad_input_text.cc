// Truth checked: a parameter file that is not what it should be as a file
// (it includes itself, is binary, a device, a link loop, too large, has
// lines of 30,000 characters or more, a byte-order mark) or that opens a
// per-id section with an id that is not one, gets one clear message naming
// the file (and the line or entry) and a non-zero exit, never a crash or
// an exhausted memory; the previous run and a file of the user's beside it
// survive byte for byte. Where the input is valid after all (a byte-order
// mark, a long line of valid increments) the run goes through.
#include "../common/bad_input_utilities.h"
#include <sys/stat.h>

using namespace bad_input;

namespace
{
  /// Includes that cannot be followed.
  void
  check_includes()
  {
    write("self.prm", "include self.prm\n" + scene());
    check("a parameter file that includes itself", {"self.prm"});

    write("cycle-a.prm", "include cycle-b.prm\n");
    write("cycle-b.prm", "include cycle-a.prm\n" + scene());
    check("two parameter files that include each other", {"cycle-a.prm"});

    write("include-missing.prm", scene() + "include nowhere.prm\n");
    check("an include of a file that does not exist", {"include-missing.prm"});

    for (unsigned int k = 0; k < 20; ++k)
      write("deep-" + std::to_string(k) + ".prm",
            "include deep-" + std::to_string(k + 1) + ".prm\n");
    write("deep-20.prm", scene());
    check("includes nested 20 deep", {"deep-0.prm"});

    write("included.prm", "subsection Material 2\nend\n");
    std::string outer = scene();
    outer.replace(outer.find("subsection Material 2\nend\n"),
                  26,
                  "include included.prm\n");
    write("includes.prm",
          outer + "subsection Material 2\n  set Young's modulus = 5\nend\n");
    check("a section given in the file and again in the file it includes",
          {"includes.prm"});
  }


  /// Lines and overrides tens of thousands of characters long.
  void
  check_long_lines()
  {
    std::string increments;
    for (unsigned int k = 0; k < 5000; ++k)
      increments += "0.0002, ";
    write("long-line.prm",
          scene("good.geo",
                "",
                "subsection Loading\n  set Load increments = " + increments +
                  "0.0002x\nend\n"));
    check("a set line of 40,000 characters (5000 increments, the last "
          "malformed)",
          {"long-line.prm"});

    std::string values = "height = ";
    for (unsigned int k = 0; k < 33333; ++k)
      values += "1, ";
    check("a 100,000-character override (a sweep of 33,333 values)",
          {"good.prm", "-s", "Sweep/Values=" + values + "1"});

    check("a 100,000-character override naming an unknown entry",
          {"good.prm", "-s", "Material 1/" + std::string(100000, 'x') + "=1"});
  }


  /// Files that are not parameter files.
  void
  check_not_text()
  {
    write("binary.prm",
          std::string("subsection Mesh\n\x01\x02\x7f\0\0garbage\n", 28));
    check("a binary file (NUL bytes)", {"binary.prm"});

    write("control.prm", scene("good.geo", "  \x01\x1b[2J not a line\n"));
    check("a line with control bytes (the message shows them as \\xNN)",
          {"control.prm"});

    check("/dev/zero as the parameter file", {"/dev/zero"});

    std::filesystem::remove("fifo.prm");
    mkfifo("fifo.prm", 0600);
    check("a named pipe as the parameter file", {"fifo.prm"});

    std::filesystem::remove("loop.prm");
    std::filesystem::create_symlink("loop.prm", "loop.prm");
    check("a parameter file that is a symbolic link to itself", {"loop.prm"});

    std::filesystem::remove("loop.geo");
    std::filesystem::create_symlink("loop.geo", "loop.geo");
    write("mesh-loop.prm", scene("loop.geo"));
    check("a mesh file that is a symbolic link to itself", {"mesh-loop.prm"});
    check("/dev/zero as the mesh file",
          {"good.prm", "-s", "Mesh/File=/dev/zero"});

    write("huge.prm", std::string(17u << 20, '#'));
    check("a parameter file of 17 MiB", {"huge.prm"});
    std::filesystem::remove("huge.prm");

    write("bom.prm", "\xEF\xBB\xBF" + scene());
    check("(a UTF-8 byte-order mark: read as the file without it, the run "
          "goes through)",
          {"bom.prm"});
  }


  /// Per-id sections whose id is not a whole number in range.
  void
  check_section_ids()
  {
    write("negative-id.prm",
          scene() + "subsection Material -1\n  set Young's modulus = 5\nend\n");
    check("a section 'Material -1'", {"negative-id.prm"});
    check("an override of 'Material -1/...'",
          {"good.prm", "-s", "Material -1/Young's modulus=3"});
    check("an override of 'Boundary 99999999999/...'",
          {"good.prm", "-s", "Boundary 99999999999/Traction=0; 1"});
    write("word-id.prm",
          scene() + "subsection Interface curve top\n  set Adhesion = "
                    "1\nend\n");
    check("a section 'Interface curve top'", {"word-id.prm"});
    check("a thin layer of material id 300, which the file does not describe "
          "(ids above 255 are read)",
          {"good.prm", "-s", "Layers/Material ids=300"});
    std::string padded = scene();
    padded.replace(padded.find("subsection Material 1\n"),
                   22,
                   "subsection Material 01\n");
    write("padded-id.prm", padded);
    check("a section 'Material 01' (a leading zero)", {"padded-id.prm"});
    std::string tabbed = scene();
    tabbed.replace(tabbed.find("subsection Material 1\n"),
                   22,
                   "subsection Material\t1\n");
    write("tabbed-id.prm", tabbed);
    check("a section 'Material<tab>1'", {"tabbed-id.prm"});
  }


  /// A decimal comma, which the expression parser reads as its comma
  /// operator (1,5 is 5), in every kind of expression.
  void
  check_decimal_commas()
  {
    check("a decimal comma in a traction (0; -1,5)",
          {"good.prm", "-s", "Boundary 2/Traction=0; -1,5"});
    check("a decimal comma in a pressure",
          {"good.prm",
           "-s",
           "Boundary 2/Traction=0; 0",
           "-s",
           "Boundary 2/Pressure=1,5"});
    check("a decimal comma in a prescribed displacement",
          {"good.prm",
           "-s",
           "Boundary 2/Traction=0; 0",
           "-s",
           "Boundary 2/Constrained components=y",
           "-s",
           "Boundary 2/Displacement=0; -0,001"});
    check("a decimal comma in the analytic load",
          {"good.prm", "-s", "Reference/Analytic load=2,5"});
    check("(a function of two arguments keeps its comma: run as designed)",
          {"good.prm",
           "-s",
           "Boundary 2/Traction=0; -min(1, 2)",
           "-s",
           "Output/Directory=elsewhere"});
  }


  /// Numbers a double does not hold at full precision, which
  /// ParameterHandler cannot convert.
  void
  check_numbers()
  {
    check("a Young's modulus of 1e-320 (below the smallest normal double)",
          {"good.prm", "-s", "Material 1/Young's modulus=1e-320"});
    check("a tolerance of 1e-310",
          {"good.prm", "-s", "Solver/Tolerance=1e-310"});
    check("a Poisson's ratio of 4.9e-324",
          {"good.prm", "-s", "Material 1/Poisson's ratio=4.9e-324"});
    check("a unit weight of 1e400 (beyond the largest double)",
          {"good.prm", "-s", "Material 1/Unit weight=1e400"});
    write("tiny-cohesion.prm",
          scene("good.geo",
                "  set Yield criterion = tresca\n  set Cohesion = 2e-315\n"));
    check("a cohesion of 2e-315 in the file (named with its line)",
          {"tiny-cohesion.prm"});
    check("a traction of 1e-320 in an expression",
          {"good.prm", "-s", "Boundary 2/Traction=0; -1e-320"});
    check("a load increment of 1e-320",
          {"good.prm", "-s", "Loading/Load increments=1e-320"});
    check("(a name and a directory with such digits in them: run as "
          "designed)",
          {"good.prm",
           "-s",
           "Material 1/Name=sand1e-999",
           "-s",
           "Output/Directory=run1e-999"});
  }


  /// Overrides given twice, and entries set back to their default.
  void
  check_overrides()
  {
    check("one entry overridden twice",
          {"good.prm",
           "-s",
           "Material 1/Young's modulus=5",
           "-s",
           "Material 1 / Young's modulus = 6"});
    write("fourier-only.prm",
          scene() + "subsection Kinematics\n  set Harmonics = 1, 3\nend\n");
    check("(an entry that means nothing here, set back to its default by "
          "-s: run as designed)",
          {"fourier-only.prm",
           "-s",
           "Kinematics/Harmonics=1",
           "-s",
           "Output/Directory=elsewhere"});
  }


  /// Errors inside an included file name that file and its own line.
  void
  check_included_errors()
  {
    write("inner.prm",
          "# the materials\n\nsubsection Material 2\n"
          "  set Youngs modulus = 5\nend\n");
    std::string outer = scene();
    outer.replace(outer.find("subsection Material 2\nend\n"),
                  26,
                  "include inner.prm\n");
    write("outer.prm", "# a scene\n" + outer);
    check("an unknown entry in an included file", {"outer.prm"});
    write("inner.prm",
          "# the materials\n\nsubsection Material 2\n"
          "  set Young's modulus = 0\nend\n");
    check("a value refused in an included file", {"outer.prm"});
  }
} // namespace


int
main()
{
  write_valid_scene();
  check_includes();
  check_long_lines();
  check_not_text();
  check_section_ids();
  check_decimal_commas();
  check_numbers();
  check_overrides();
  check_included_errors();
}
