#include <thinlayer/base/file_utilities.h>
#include <thinlayer/base/input_error.h>
#include <thinlayer/base/interruption.h>
#include <thinlayer/mesh/gmsh_process.h>

#include <chrono>
#include <filesystem>
#include <sstream>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

namespace thinlayer
{
  namespace
  {
    /// A temporary directory, removed with everything in it on every way
    /// out of its scope.
    class TemporaryDirectory
    {
    public:
      TemporaryDirectory()
      {
        // The process id in the name tells whose it is.
        std::string name =
          "/tmp/thinlayer-gmsh-" + std::to_string(getpid()) + "-XXXXXX";
        if (mkdtemp(name.data()) == nullptr)
          throw std::runtime_error(
            "cannot create a temporary directory in /tmp");
        path = name;
      }
      ~TemporaryDirectory()
      {
        std::error_code error;
        std::filesystem::remove_all(path, error);
      }
      std::string path;
    };


    /// A child process in its own process group, killed (the group) and
    /// reaped unless it was waited for.
    class ChildProcess
    {
    public:
      ChildProcess(const std::vector<std::string> &arguments,
                   const std::string              &log_file)
      {
        std::vector<char *> argv;
        for (const auto &a : arguments)
          argv.push_back(const_cast<char *>(a.c_str()));
        argv.push_back(nullptr);
        pid = fork();
        if (pid < 0)
          throw std::runtime_error("cannot start gmsh (fork failed)");
        if (pid == 0)
          {
            // The child: only async-signal-safe calls until exec.
            setpgid(0, 0);
            const int log =
              open(log_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
            const int nothing = open("/dev/null", O_RDONLY);
            if (log >= 0)
              {
                dup2(log, STDOUT_FILENO);
                dup2(log, STDERR_FILENO);
              }
            if (nothing >= 0)
              dup2(nothing, STDIN_FILENO);
            execv(argv[0], argv.data());
            _exit(127);
          }
        setpgid(pid, pid); // also here: whichever runs first
      }

      ~ChildProcess()
      {
        if (pid > 0)
          kill_and_reap();
      }

      /// The exit status once the child has ended, or -1 while it runs.
      int
      poll()
      {
        int status = 0;
        if (waitpid(pid, &status, WNOHANG) != pid)
          return -1;
        pid = 0;
        return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
      }

      /// Resident memory in bytes (0 if it cannot be read).
      std::size_t
      resident_bytes() const
      {
        std::ifstream statm("/proc/" + std::to_string(pid) + "/statm");
        std::size_t   size = 0, resident = 0;
        statm >> size >> resident;
        return resident * static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
      }

      void
      kill_and_reap()
      {
        kill(-pid, SIGKILL);
        kill(pid, SIGKILL); // had it no group of its own yet
        int status;
        waitpid(pid, &status, 0);
        pid = 0;
      }

    private:
      pid_t pid = 0;
    };


    /// The lines of gmsh's log that report errors.
    std::string
    errors_in(const std::string &log_file)
    {
      std::istringstream log(read_file(log_file));
      std::string        errors, line;
      while (std::getline(log, line))
        if (line.rfind("Error", 0) == 0)
          errors += "\n  " + line;
      return errors;
    }
  } // namespace


  namespace
  {
    /**
     * Run gmsh on @p job with @p options before the parameters and
     * "-o @p output", as run_gmsh() describes, and return what it wrote
     * there.
     */
    std::string
    run_gmsh_to(const GmshJob                  &job,
                const std::vector<std::string> &options,
                const std::string              &output,
                std::ostream                   &progress)
    {
      const TemporaryDirectory directory;
      const std::string        out_file = directory.path + "/" + output;
      const std::string        log_file = directory.path + "/gmsh.log";

      std::vector<std::string> arguments = {THINLAYER_GMSH_EXECUTABLE};
      arguments.insert(arguments.end(), options.begin(), options.end());
      for (const auto &[name, value] : job.parameters)
        {
          std::ostringstream text;
          text.precision(17);
          text << value;
          arguments.insert(arguments.end(), {"-setnumber", name, text.str()});
        }
      arguments.insert(arguments.end(), {"-o", out_file, job.geometry});

      const std::size_t budget =
        (100u << 20) + std::size_t(job.max_cells) * 1024;
      const auto   start       = std::chrono::steady_clock::now();
      auto         next_report = start + std::chrono::seconds(5);
      ChildProcess gmsh(arguments, log_file);
      int          status;
      while ((status = gmsh.poll()) < 0)
        {
          if (local_interruption_signal() != 0)
            {
              gmsh.kill_and_reap();
              throw Interrupted("while gmsh was meshing " + job.geometry);
            }
          if (gmsh.resident_bytes() > budget)
            {
              gmsh.kill_and_reap();
              throw InputError(
                job.parameter_file,
                "Mesh/Geometry parameters",
                "gmsh used more than " + std::to_string(budget >> 20) +
                  " MB meshing " + job.geometry +
                  " and was stopped: these parameters ask for far more than "
                  "Mesh/Maximum cells = " +
                  std::to_string(job.max_cells) +
                  " cells; check them, or raise that limit");
            }
          const auto now = std::chrono::steady_clock::now();
          if (std::chrono::duration<double>(now - start).count() >
              job.time_limit)
            {
              gmsh.kill_and_reap();
              std::ostringstream limit;
              limit << job.time_limit;
              throw InputError(job.parameter_file,
                               "Mesh/Meshing time limit",
                               "gmsh ran for more than " + limit.str() +
                                 " s on " + job.geometry +
                                 " and was stopped: the script loops without "
                                 "end, or asks for a far finer mesh than "
                                 "meant; check it, or raise the limit");
            }
          if (now >= next_report)
            {
              progress << "  meshing: gmsh has run for "
                       << std::chrono::duration_cast<std::chrono::seconds>(
                            now - start)
                            .count()
                       << " s, " << (gmsh.resident_bytes() >> 20) << " MB"
                       << std::endl;
              next_report += std::chrono::seconds(5);
            }
          std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }

      const std::string errors = errors_in(log_file);
      if (status != 0 || !errors.empty())
        throw InputError(job.geometry,
                         "",
                         "gmsh could not mesh this geometry:" +
                           (errors.empty() ? std::string(" exit status ") +
                                               std::to_string(status)
                                           : errors));
      return read_file(out_file);
    }
  } // namespace


  std::string
  run_gmsh(const GmshJob &job, std::ostream &progress)
  {
    return run_gmsh_to(
      job,
      {job.dimension == 3 ? "-3" : "-2", "-format", "msh22", "-nt", "1"},
      "mesh.msh",
      progress);
  }


  std::string
  unrolled_geometry(const GmshJob &job, std::ostream &progress)
  {
    return run_gmsh_to(job,
                       {"-0", "-nt", "1"},
                       "geometry.geo_unrolled",
                       progress);
  }
} // namespace thinlayer
