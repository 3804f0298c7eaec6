// Truth checked: the output path never loses or mixes results. An output
// directory that cannot be used is refused with a message naming
// Output/Directory; a write that fails (a file size limit standing in for a
// full disk) names the file and exits 1 with the previous run intact, byte
// for byte; SIGINT and SIGTERM end the run with `outcome: interrupted` in
// place of the previous run and exit 128 + the signal; a rerun leaves no
// file of an earlier one; a staging directory of a process that is gone is
// cleared; a sweep with a run that ended in an error exits 1; a standard
// output that cannot be written exits 1. The program runs in-process
// through run_command_line().
#include <thinlayer/app/command_line.h>
#include <thinlayer/output/results_directory.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>
#include <thread>

#include "../common/bad_input_utilities.h"
#include <sys/resource.h>
#include <unistd.h>

namespace fs = std::filesystem;
using bad_input::summary_entry;

namespace
{
  void
  write(const std::string &name, const std::string &text)
  {
    std::ofstream(name) << text;
  }

  std::string
  read(const std::string &name)
  {
    std::ostringstream text;
    text << std::ifstream(name).rdbuf();
    return text.str();
  }

  /// Every file under @p directory with its contents.
  std::map<std::string, std::string>
  contents(const std::string &directory)
  {
    std::map<std::string, std::string> files;
    if (fs::exists(directory))
      for (const auto &entry : fs::recursive_directory_iterator(directory))
        files[entry.path().lexically_relative(directory).string()] =
          entry.is_regular_file() ? read(entry.path()) : "";
    return files;
  }

  /// @p message with this directory's absolute path and this process's id
  /// in it made the same on every machine and run.
  std::string
  portable(std::string message)
  {
    for (const auto &[from, to] :
         {std::pair<std::string, std::string>{fs::current_path().string(), "."},
          {"new-" + std::to_string(getpid()), "new-PID"},
          {"process " + std::to_string(getpid()), "process PID"}})
      for (auto at = message.find(from); at != std::string::npos;
           at      = message.find(from, at + to.size()))
        message.replace(at, from.size(), to);
    return message;
  }

  /// The valid run's results, which the checks start from.
  std::map<std::string, std::string> previous_run;

  /// Staging directories (".NAME.partial-...") left in the current one.
  unsigned int
  staging_left()
  {
    unsigned int n = 0;
    for (const auto &entry : fs::directory_iterator("."))
      if (entry.path().filename().string().find(".partial-") !=
          std::string::npos)
        ++n;
    return n;
  }

  const std::string geo = R"(
DefineConstant[ height = {1, Name "Parameters/height"} ];
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0};
Point(3) = {1, height, 0}; Point(4) = {0, height, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{:} = 3; Transfinite Surface{1}; Recombine Surface{1};
Physical Surface("block", 1) = {1};
Physical Curve("bottom", 1) = {1}; Physical Curve("top", 2) = {3};
)";

  std::string
  scene(const std::string &directory, const std::string &extra = "")
  {
    return "subsection Mesh\n  set File = block.geo\nend\n"
           "subsection Material 1\nend\n"
           "subsection Boundary 1\n  set Constrained components = x, y\nend\n"
           "subsection Boundary 2\n  set Traction = 0; -1\nend\n"
           "subsection Monitors\n  set Displacement boundary id = 2\nend\n"
           "subsection Loading\n  set Load increments = 3*0.1\nend\n"
           "subsection Output\n  set Directory = " +
           directory + "\n  set Print timing = false\nend\n" + extra;
  }

  struct Result
  {
    int         status;
    std::string error;
  };

  Result
  run(const std::vector<std::string> &arguments)
  {
    std::ostringstream out, err;
    const int status = thinlayer::run_command_line(arguments, out, err);
    return {status, err.str()};
  }

  /// Start @p name from a copy of the valid run.
  void
  restore(const std::string &name)
  {
    fs::remove_all(name);
    fs::copy("previous", name, fs::copy_options::recursive);
  }

  void
  report(const std::string &what, const Result &r, const bool kept)
  {
    std::cout << "* " << what << "\n  exit status " << r.status
              << ", previous run kept: " << (kept ? "yes" : "NO")
              << ", staging left behind: " << staging_left() << "\n  "
              << r.error << '\n';
  }

  /// Send @p signal to this process (none if 0: only wait) once the run
  /// has written @p rows rows of history.csv into its staging directory.
  void
  signal_after_rows(const int signal, const unsigned int rows)
  {
    for (unsigned int wait = 0; wait < 600000; ++wait)
      {
        for (const auto &entry : fs::directory_iterator("."))
          if (entry.path().filename().string().find(".results.partial-") == 0)
            {
              std::ifstream history(entry.path() / "history.csv");
              unsigned int  n = 0;
              for (std::string line; std::getline(history, line);)
                ++n;
              if (n > rows)
                {
                  if (signal != 0)
                    kill(getpid(), signal);
                  return;
                }
            }
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      }
  }
  /// Temporary gmsh directories of this process, and whether a gmsh child runs.
  std::string
  gmsh_left()
  {
    unsigned int n = 0;
    for (const auto &entry : fs::directory_iterator("/tmp"))
      if (entry.path().filename().string().find(
            "thinlayer-gmsh-" + std::to_string(getpid()) + "-") == 0)
        ++n;
    const bool running = std::system(("pgrep -P " + std::to_string(getpid()) +
                                      " -x gmsh > /dev/null")
                                       .c_str()) == 0;
    return std::to_string(n) + " temporary directories, gmsh " +
           (running ? "STILL RUNNING" : "not running");
  }
} // namespace


namespace
{
  /// The valid scene, whose results the checks start from.
  void
  run_valid_scene()
  {
    write("block.geo", geo);
    write("good.prm", scene("results"));
    {
      const Result r = run({"good.prm"});
      std::cout << "* the valid scene: exit status " << r.status << "\n\n";
      fs::remove_all("previous");
      fs::rename("results", "previous");
    }
    previous_run = contents("previous");
  }


  /// Output directories that cannot hold a run.
  void
  check_directories()
  {
    write("a-file", "not a directory\n");
    report("Output/Directory is a file",
           run({"good.prm", "-s", "Output/Directory=a-file"}),
           read("a-file") == "not a directory\n");
    fs::create_directories("notes");
    write("notes/thesis.tex", "\\chapter{}\n");
    report("Output/Directory holds files that are not a run",
           run({"good.prm", "-s", "Output/Directory=notes"}),
           read("notes/thesis.tex") == "\\chapter{}\n");
    fs::create_directories("project");
    write("project/scene.prm", scene("."));
    write("project/block.geo", geo);
    report("Output/Directory contains the parameter file",
           run({"project/scene.prm"}),
           contents("project").size() == 2);
    report("Output/Directory is empty",
           run({"good.prm", "-s", "Output/Directory="}),
           true);
    fs::remove("loop");
    fs::create_symlink("loop", "loop");
    report("Output/Directory is a symbolic link to itself",
           run({"good.prm", "-s", "Output/Directory=loop/results"}),
           true);
    report("Output/Directory lies under a file",
           run({"good.prm", "-s", "Output/Directory=a-file/results"}),
           read("a-file") == "not a directory\n");
  }


  /// Directories that hold an earlier run and something else: refused
  /// with the names of what is foreign, nothing of either lost.
  void
  check_foreign_files()
  {
    const auto try_with = [](const std::string           &what,
                             const std::function<void()> &change) {
      restore("results");
      change();
      const auto   before = contents("results");
      const Result r      = run({"good.prm"});
      report(what, r, contents("results") == before);
    };
    try_with("a run's directory with a thesis added to it",
             []() { write("results/thesis.tex", "\\chapter{}\n"); });
    try_with("a run's directory with a folder of raw data added", []() {
      fs::create_directories("results/raw");
      write("results/raw/data.csv", "1,2\n");
    });
    try_with("a run's directory with an empty folder added",
             []() { fs::create_directories("results/figures"); });
    try_with("a run's directory whose history.csv has notes appended", []() {
      std::ofstream("results/history.csv", std::ios::app) << "# checked\n";
    });
    try_with("a run's directory without its manifest (an older version's)",
             []() { fs::remove("results/manifest.txt"); });
    try_with("a directory with a file named manifest.txt that lists nothing",
             []() {
               fs::remove_all("results");
               fs::create_directories("results");
               write("results/manifest.txt", "my shopping list\n");
             });
  }


  /// A file put into the results directory while a run goes on: the run
  /// is left beside it, the directory as the user left it.
  void
  check_file_added_during_run()
  {
    restore("results");
    std::thread  writer([]() {
      signal_after_rows(0, 2);
      write("results/notes.txt", "added during the run\n");
    });
    const Result r = run({"good.prm",
                          "-s",
                          "Loading/Load increments=3000*0.0001",
                          "-s",
                          "Output/Write VTU=false"});
    writer.join();
    const std::string aside = "results.new-" + std::to_string(getpid());
    auto              kept  = contents("results");
    kept.erase("notes.txt");
    std::cout << "* a file put into Output/Directory during the run\n"
              << "  exit status " << r.status << ", previous run kept: "
              << (kept == previous_run ? "yes" : "NO")
              << ", the user's file kept: "
              << (read("results/notes.txt") == "added during the run\n" ? "yes"
                                                                        : "NO")
              << ", this run beside it: "
              << (fs::exists(aside + "/summary.json") ? "yes" : "NO") << "\n  "
              << portable(r.error) << '\n';
    fs::remove_all(aside);
  }


  /// A write that fails: a file size limit of 5000 bytes, so that
  /// history.csv, the mesh and the parameters (2.6 kB) fit but a VTU with
  /// eight subdivisions (7.4 kB) does not: the write fails in the middle of
  /// the run. The limit is lifted again after.
  void
  check_failed_write()
  {
    {
      restore("results");
      // The limit holds for this test's own output too, which is longer
      // than it: nothing of it may wait in a buffer meanwhile.
      std::cout.flush();
      rlimit saved;
      getrlimit(RLIMIT_FSIZE, &saved);
      rlimit limit   = saved;
      limit.rlim_cur = 5000;
      setrlimit(RLIMIT_FSIZE, &limit);
      const Result r = run({"good.prm", "-s", "Output/VTU subdivisions=8"});
      setrlimit(RLIMIT_FSIZE, &saved);
      report("a write that fails (file size limit, as on a full disk)",
             r,
             contents("results") == previous_run);
    }
  }


  /// Signals: the run stops at the next iteration and is written as
  /// interrupted, in place of the previous run.
  void
  check_signals()
  {
    for (const int signal : {SIGINT, SIGTERM})
      {
        restore("results");
        std::thread  sender(signal_after_rows, signal, 2);
        const Result r = run({"good.prm",
                              "-s",
                              "Loading/Load increments=100000*0.00001",
                              "-s",
                              "Output/Write VTU=false"});
        sender.join();
        const std::string reason = summary_entry("results", "reason");
        std::cout << "* " << (signal == SIGINT ? "SIGINT" : "SIGTERM")
                  << " during a run\n  exit status " << r.status << ", outcome "
                  << summary_entry("results", "outcome") << ", reason "
                  << reason.substr(0, reason.find(" at "))
                  << ", history of this run only: "
                  << (read("results/history.csv").find(",1e-05,") !=
                          std::string::npos
                        ? "yes"
                        : "NO")
                  << ", staging left behind: " << staging_left() << "\n  "
                  << r.error << '\n';
      }
  }


  /// A rerun with fewer steps and no VTU: nothing of the earlier run stays.
  void
  check_rerun()
  {
    {
      restore("results");
      const Result r = run({"good.prm",
                            "-s",
                            "Loading/Load increments=0.1",
                            "-s",
                            "Output/Write VTU=false"});
      std::cout << "* a rerun with fewer steps and without VTU\n  exit status "
                << r.status << ", files:";
      for (const auto &[name, text] : contents("results"))
        std::cout << ' ' << name;
      std::cout << "\n\n";
    }
  }


  /// A staging directory of a process that is gone is cleared by the next run
  /// into the same parent; that of a live one (this process) is not.
  void
  check_stale_staging()
  {
    {
      fs::create_directories(".results.partial-999999999-0");
      fs::create_directories(".results.partial-" + std::to_string(getpid()) +
                             "-99");
      const Result r = run({"good.prm"});
      std::cout << "* staging directories of a process that is gone, and of "
                   "this one\n  exit status "
                << r.status << ", gone one cleared: "
                << (fs::exists(".results.partial-999999999-0") ? "NO" : "yes")
                << ", live one kept: "
                << (fs::exists(".results.partial-" + std::to_string(getpid()) +
                               "-99")
                      ? "yes"
                      : "NO")
                << "\n\n";
      fs::remove_all(".results.partial-" + std::to_string(getpid()) + "-99");
    }
  }


  /// A sweep whose second run cannot be meshed into valid cells (height 0
  /// makes them flat): a row with the error, and a non-zero exit.
  void
  check_sweep_with_error()
  {
    write("sweep.prm",
          scene("sweep-results",
                "subsection Sweep\n  set Values = height = 1, 0\nend\n"));
    {
      const Result r = run({"sweep.prm"});
      std::cout << "* a sweep with a run that ended in an error\n  exit status "
                << r.status << ", run-001 written: "
                << (fs::exists("sweep-results/run-001/summary.json") ? "yes"
                                                                     : "no")
                << ", run-002 written: "
                << (fs::exists("sweep-results/run-002") ? "yes" : "no")
                << "\n  " << r.error << '\n';
    }
  }


  /// gmsh: a geometry parameter that asks for 10^8 cells is stopped by its
  /// memory within seconds; a signal while gmsh meshes stops it too. Either
  /// way no gmsh process and no temporary directory of this process stay.
  void
  check_gmsh()
  {
    {
      write("huge.geo", R"(
  DefineConstant[ n = {2, Name "Parameters/n"} ];
  Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0};
  Point(4) = {0, 1, 0};
  Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
  Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
  Transfinite Curve{:} = n + 1; Transfinite Surface{1}; Recombine Surface{1};
  Physical Surface("block", 1) = {1};
  Physical Curve("bottom", 1) = {1}; Physical Curve("top", 2) = {3};
  )");
      std::string huge = read("good.prm");
      huge.replace(huge.find("block.geo"), 9, "huge.geo");
      write("huge.prm", huge);
      restore("results");
      const Result stopped =
        run({"huge.prm", "-s", "Mesh/Geometry parameters=n=1e8"});
      report("a geometry parameter that asks for 10^8 cells",
             stopped,
             contents("results") == previous_run);
      std::cout << "  afterwards: " << gmsh_left() << "\n\n";

      restore("results");
      std::thread  sender([]() {
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
        kill(getpid(), SIGINT);
      });
      const Result interrupted = run({"huge.prm",
                                      "-s",
                                      "Mesh/Geometry parameters=n=1e8",
                                      "-s",
                                      "Mesh/Maximum cells=1000000000"});
      sender.join();
      report("SIGINT while gmsh meshes",
             interrupted,
             contents("results") == previous_run);
      std::cout << "  afterwards: " << gmsh_left() << "\n\n";
    }
  }


  /// Signals during a sweep: while its runs are checked (10,000 of them,
  /// a minute's work) the sweep stops at once and writes nothing; while
  /// gmsh meshes its second run, the first run and its row are kept and
  /// the second's row says it was interrupted.
  void
  check_sweep_interrupted()
  {
    {
      std::string values = "Sweep/Values=height = ";
      for (unsigned int k = 1; k <= 10000; ++k)
        values += std::to_string(k) + (k < 10000 ? ", " : "");
      const auto   before = contents("sweep-results");
      std::thread  sender([]() {
        std::this_thread::sleep_for(std::chrono::milliseconds(1000));
        kill(getpid(), SIGINT);
      });
      const Result r = run({"sweep.prm", "-s", values});
      sender.join();
      report("SIGINT while a sweep of 10,000 runs is checked",
             r,
             contents("sweep-results") == before);
    }
    {
      fs::remove_all("sweep-results");
      std::string huge = read("sweep.prm");
      huge.replace(huge.find("block.geo"), 9, "huge.geo");
      write("huge-sweep.prm", huge);
      std::thread  sender([]() {
        for (unsigned int wait = 0; wait < 600000; ++wait)
          {
            for (const auto &entry : fs::directory_iterator("."))
              if (entry.path().filename().string().find(
                    ".sweep-results.partial-") == 0 &&
                  fs::exists(entry.path() / "run-001/summary.json"))
                {
                  std::this_thread::sleep_for(std::chrono::milliseconds(500));
                  kill(getpid(), SIGINT);
                  return;
                }
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
          }
      });
      const Result r = run({"huge-sweep.prm",
                            "-s",
                            "Sweep/Values=n = 2, 1e8",
                            "-s",
                            "Mesh/Maximum cells=1000000000"});
      sender.join();
      std::istringstream csv(read("sweep-results/sweep.csv"));
      std::string        line, rows;
      for (unsigned int k = 0; std::getline(csv, line); ++k)
        if (k > 0)
          rows += "\n    row " + line.substr(0, line.find(',')) + ": " +
                  (line.find(",interrupted while gmsh was meshing") !=
                       std::string::npos
                     ? "interrupted while gmsh was meshing (its error)"
                   : line.find(",completed,") != std::string::npos
                     ? "completed"
                     : "OTHER: " + line);
      std::cout << "* SIGINT while gmsh meshes the second run of a sweep\n"
                << "  exit status " << r.status << ", run-001 kept: "
                << (fs::exists("sweep-results/run-001/summary.json") ? "yes"
                                                                     : "NO")
                << ", run-002 written: "
                << (fs::exists("sweep-results/run-002") ? "YES" : "no")
                << ", sweep.csv rows:" << rows
                << "\n  afterwards: " << gmsh_left() << "\n\n";
    }
  }


  /// Standard output that cannot be written.
  void
  check_standard_output()
  {
    {
      restore("results");
      std::ostream       broken(nullptr);
      std::ostringstream err;
      const int status = thinlayer::run_command_line({"good.prm"}, broken, err);
      std::cout << "* standard output cannot be written\n  exit status "
                << status << "\n  " << err.str() << '\n';
    }
    {
      // mpirun, sent SIGTERM, passes it on to the ranks and stops
      // forwarding their standard output: the signal is what ended the run.
      restore("results");
      std::thread        sender(signal_after_rows, SIGTERM, 2);
      std::ostream       broken(nullptr);
      std::ostringstream err;
      const int          status =
        thinlayer::run_command_line({"good.prm",
                                     "-s",
                                     "Loading/Load increments=100000*0.00001",
                                     "-s",
                                     "Output/Write VTU=false"},
                                    broken,
                                    err);
      sender.join();
      std::cout << "* SIGTERM during a run whose standard output cannot be "
                   "written (as under mpirun)\n  exit status "
                << status << ", outcome " << summary_entry("results", "outcome")
                << "\n  " << err.str() << '\n';
    }
  }


  /// A second run into a directory that a run is writing: refused while
  /// the first holds its lock, the first's results then put in place.
  void
  check_concurrent_runs()
  {
    restore("results");
    Result second;
    bool   kept;
    {
      const thinlayer::ResultsDirectory first("results", "good.prm");
      second = run({"good.prm"});
      kept   = contents("results") == previous_run;
    }
    // Reported once the first run (here: its directory) has ended, so
    // that its staging directory is gone.
    second.error = portable(second.error);
    report("a second run into a directory that a run is writing", second, kept);
    std::cout << "  lock left behind: "
              << (fs::exists(".results.lock") ? "YES" : "no") << "\n\n";
    const Result after = run({"good.prm"});
    std::cout << "* (the same run once the first has ended: run as "
                 "designed)\n  exit status "
              << after.status << "\n\n";
  }


  /// Output/Directory as a shell's completion writes it.
  void
  check_trailing_slash()
  {
    fs::remove_all("slashed");
    const Result r = run({"good.prm", "-s", "Output/Directory=slashed/run/"});
    std::cout << "* (Output/Directory with a trailing slash: run as "
                 "designed)\n  exit status "
              << r.status << ", results in slashed/run: "
              << (fs::exists("slashed/run/summary.json") ? "yes" : "NO")
              << "\n\n";
  }


  /// history.csv's phase names with commas, quotes and line breaks, quoted
  /// as a CSV library reads them: every row keeps its 19 fields.
  void
  check_csv_fields()
  {
    fs::remove_all("quoted");
    const Result  r = run({"good.prm",
                           "-s",
                           "Output/Directory=quoted",
                           "-s",
                           "Loading/Load increments=0.1",
                           "-s",
                           "Phase 2/Name=unload, \"gently\"",
                           "-s",
                           "Phase 2/Boundary 2/Traction=0; 0.1"});
    std::ifstream history("quoted/history.csv");
    std::string   text((std::istreambuf_iterator<char>(history)),
                     std::istreambuf_iterator<char>());
    // Fields of each record, a quoted field read whole.
    std::vector<unsigned int> fields(1, 1);
    bool                      quoted = false;
    for (const char c : text)
      if (c == '"')
        quoted = !quoted;
      else if (c == ',' && !quoted)
        ++fields.back();
      else if (c == '\n' && !quoted)
        fields.push_back(1);
    fields.pop_back();
    std::cout << "* (a phase name with a comma and quotes: written as "
                 "designed)\n  exit status "
              << r.status << ", rows " << fields.size() << ", fields per row:";
    for (const unsigned int n : fields)
      std::cout << ' ' << n;
    std::cout << ", the name quoted: "
              << (text.find(",\"unload, \"\"gently\"\"\"") != std::string::npos
                    ? "yes"
                    : "NO")
              << "\n\n";
  }
} // namespace


int
main()
{
  run_valid_scene();
  check_directories();
  check_foreign_files();
  check_file_added_during_run();
  check_failed_write();
  check_signals();
  check_rerun();
  check_stale_staging();
  check_sweep_with_error();
  check_gmsh();
  check_sweep_interrupted();
  check_standard_output();
  check_concurrent_runs();
  check_trailing_slash();
  check_csv_fields();
}
