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
}
