// Truth checked: a .geo is a script gmsh runs with the user's rights, and
// thinlayer meshes none that would run a program or write a file unless the
// parameter file trusts it (Mesh/Trust geometry scripts): each statement
// that runs a shell command (SystemCall, System, NonBlockingSystemCall,
// OnelabRun, the Solver. options), writes, moves or deletes a file
// (Printf > and >>, Save, Print, CreateDir, DeleteFile, RenameFile,
// General.Save...), in the .geo, a file it includes or merges or the
// options file gmsh merges beside it, however it is spelt for gmsh (spaces
// in an option's name, a string ended where gmsh ends it), or hands gmsh a
// script (Merge of a .py) or a file name computed at run time, is refused
// naming the file, its line and the statement, with a non-zero exit; the
// command has not run (its mark file does not exist), no file was written,
// and the previous run and a file of the user's survive byte for byte. The
// same words in a comment or a string are no statements, a parameter file
// cannot trust its own script, and a script trusted on the command line
// runs. gmsh is stopped after Mesh/Meshing time limit (a loop
// without end), and DEAL_II_NUM_THREADS that is no number of threads is
// refused before deal.II reads it (it aborted the program).
#include <cstdlib>

#include "../common/bad_input_utilities.h"
#include <sys/wait.h>

using namespace bad_input;

namespace
{
  /// A valid one-surface geometry after @p statements.
  std::string
  script(const std::string &statements)
  {
    return statements + "\n" + good_geo;
  }

  /// Whether the file @p name exists, for the report.
  std::string
  exists(const std::string &name)
  {
    return std::filesystem::exists(name) ? "YES" : "no";
  }

  /// Check the scene on @p geo (written from @p text): the command's mark
  /// and the files a statement would write must not exist afterwards.
  void
  check_script(const std::string              &what,
               const std::string              &geo,
               const std::string              &text,
               const std::vector<std::string> &overrides = {})
  {
    std::filesystem::remove("mark");
    std::filesystem::remove("written.txt");
    write(geo, text);
    write("script.prm", scene(geo));
    std::vector<std::string> arguments = {"script.prm"};
    arguments.insert(arguments.end(), overrides.begin(), overrides.end());
    check(what, arguments);
    std::cout << "  command run: " << exists("mark")
              << ", file written: " << exists("written.txt") << "\n\n";
  }


  /// Statements that run a program.
  void
  check_commands()
  {
    check_script("SystemCall",
                 "system-call.geo",
                 script("SystemCall \"touch mark\";"));
    check_script("NonBlockingSystemCall",
                 "non-blocking.geo",
                 script("NonBlockingSystemCall \"touch mark\";"));
    check_script("System, the older spelling",
                 "system.geo",
                 script("System \"touch mark\";"));
    check_script("OnelabRun",
                 "onelab.geo",
                 script("OnelabRun(\"client\", \"touch mark\");"));
    check_script("a solver for gmsh to run (Solver.Executable0)",
                 "solver.geo",
                 script("Solver.Executable0 = \"/bin/sh\";"));
    check_script("a shell command on a line of its own, after comments",
                 "late.geo",
                 good_geo + "// the mesh is done\n/* now\n the payload */\n"
                            "  SystemCall StrCat(\"touch \", \"mark\");\n");
  }


  /// Statements that write, move or delete files.
  void
  check_file_statements()
  {
    check_script("Printf into a file",
                 "printf.geo",
                 script("Printf(\"%g\", 1) > \"written.txt\";"));
    check_script("Printf appended to a file",
                 "append.geo",
                 script("Printf(\"%g, %g\", 1, 2) >> \"written.txt\";"));
    check_script("Save", "save.geo", script("Save \"written.txt\";"));
    check_script("Print", "print.geo", script("Print \"written.txt\";"));
    check_script("CreateDir", "mkdir.geo", script("CreateDir \"made\";"));
    check_script("DeleteFile of the user's file",
                 "delete.geo",
                 script("DeleteFile \"thesis.tex\";"));
    check_script("RenameFile of the user's file",
                 "rename.geo",
                 script("RenameFile \"thesis.tex\", \"moved.tex\";"));
    check_script("an option that makes gmsh save its options",
                 "options.geo",
                 script("General.SaveOptions = 1;"));
  }


  /// Files a script reads in.
  void
  check_included_files()
  {
    write("payload.geo", "x = 1;\nSystemCall \"touch mark\";\n");
    check_script("an Include of a file that runs a command (named with its "
                 "line)",
                 "includes.geo",
                 script("Include \"payload.geo\";"));
    write("run.py", "open('mark', 'w')\n");
    check_script("a Merge of a Python script",
                 "merge.geo",
                 script("Merge \"run.py\";"));
    check_script("an Include of a file name computed by the script",
                 "computed.geo",
                 script("Include StrCat(\"pay\", \"load.geo\");"));
  }


  /// Ways to hide a statement from a reader that is not gmsh's: a string
  /// that ends where gmsh ends it (no escapes), an option name spread over
  /// tokens, a merged file gmsh runs as a script, the options file gmsh
  /// merges by itself.
  void
  check_hidden_statements()
  {
    check_script("a 'string' whose backslash gmsh does not read as an escape",
                 "escape.geo",
                 script("s = \"\\\"; SystemCall \"touch mark\"; t = "
                        "\"\\\";"));
    check_script("an option name with spaces ('Solver . Executable0')",
                 "spaced.geo",
                 script("Solver . Executable0 = \"/bin/sh\";"));
    write("payload.GEO", "SystemCall \"touch mark\";\n");
    check_script("a Merge of a .GEO (upper case)",
                 "upper.geo",
                 script("Merge \"payload.GEO\";"));
    write("data.msh", "SystemCall \"touch mark\";\n");
    check_script("a Merge of a .msh without its header, which gmsh runs as "
                 "a script",
                 "merge-msh.geo",
                 script("Merge \"data.msh\";"));
    write("options.geo.opt", "SystemCall \"touch mark\";\n");
    check_script("an options file beside the .geo (gmsh merges NAME.opt)",
                 "options.geo",
                 script(""));
    std::filesystem::remove("options.geo.opt");
    write("trusting.prm",
          scene("good.geo") +
            "subsection Sweep\n  set Values = Mesh/Trust geometry scripts = "
            "true\nend\n");
    check("a parameter file that sweeps the trust of its script",
          {"trusting.prm"});
    std::string trusting = scene("good.geo");
    trusting.replace(trusting.find("end\n"),
                     4,
                     "  set Trust geometry scripts = true\nend\n");
    write("trusting.prm", trusting);
    check("a parameter file that trusts its own script", {"trusting.prm"});
  }


  /// What is allowed: the words as comments and strings, a plain Include,
  /// and a script the parameter file trusts.
  void
  check_allowed()
  {
    write("helper.geo", "lc = 1;\n");
    check_script("(the words in a comment, a string and an option name, and "
                 "a plain Include: meshed as designed)",
                 "harmless.geo",
                 script("// SystemCall \"touch mark\"; Save \"x\";\n"
                        "Printf(\"SystemCall Save Print\");\n"
                        "Print.Width = 800;\nInclude \"helper.geo\";"),
                 {"-s", "Output/Directory=harmless"});
    std::cout << "  summary written: "
              << (summary_entry("harmless", "outcome") != "(none)" ? "yes"
                                                                   : "no")
              << "\n\n";


    write("trusted.geo", script("Printf(\"%g\", 1) > \"written.txt\";"));
    write("trusted.prm", scene("trusted.geo"));
    std::filesystem::remove("written.txt");
    std::ostringstream out, err;
    const int          status =
      thinlayer::run_command_line({"trusted.prm",
                                   "-s",
                                   "Mesh/Trust geometry scripts=true",
                                   "-s",
                                   "Output/Directory=trusted"},
                                  out,
                                  err);
    std::cout << "* (a script the parameter file trusts: run as designed)\n"
              << "  exit status " << status
              << ", file written: " << exists("written.txt") << "\n\n";
  }


  /// gmsh is stopped after the time limit.
  void
  check_time_limit()
  {
    write("forever.geo",
          script("n = 0;\nFor i In {1:1e12}\n  n = n + 1;\nEndFor"));
    write("forever.prm", scene("forever.geo"));
    check("a loop without end in the script, the limit 2 s",
          {"forever.prm", "-s", "Mesh/Meshing time limit=2"});
  }


  /// DEAL_II_NUM_THREADS, read by deal.II as it is loaded: checked before.
  void
  check_environment()
  {
    for (const std::string value : {"abc", "0", "-5", "1e3", "99999", ""})
      {
        const std::string command = "DEAL_II_NUM_THREADS='" + value + "' " +
                                    THINLAYER_EXECUTABLE +
                                    " --help > env.out 2> env.err";
        const int status = std::system(command.c_str());
        std::cout << "* DEAL_II_NUM_THREADS='" << value << "'\n  exit status "
                  << (WIFEXITED(status) ? WEXITSTATUS(status) : -1) << "\n  "
                  << read_text("env.err") << '\n';
      }
    const std::string command = std::string("DEAL_II_NUM_THREADS=1 ") +
                                THINLAYER_EXECUTABLE +
                                " --help > env.out 2> env.err";
    const int status = std::system(command.c_str());
    std::cout << "* (DEAL_II_NUM_THREADS=1: runs as designed)\n  exit status "
              << (WIFEXITED(status) ? WEXITSTATUS(status) : -1) << "\n\n";
  }
} // namespace


int
main()
{
  // This test's own directories, from a run before, start empty.
  for (const char *directory : {"harmless", "trusted"})
    std::filesystem::remove_all(directory);
  write_valid_scene();
  check_commands();
  check_file_statements();
  check_included_files();
  check_hidden_statements();
  check_allowed();
  check_time_limit();
  check_environment();
  std::cout << "thesis.tex kept: "
            << (read_text("thesis.tex") == "\\chapter{}\n" ? "yes" : "NO")
            << ", moved.tex or made/ exist: "
            << ((std::filesystem::exists("moved.tex") ||
                 std::filesystem::exists("made"))
                  ? "YES"
                  : "no")
            << '\n';
}
