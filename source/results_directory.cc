#include <thinlayer/input_error.h>
#include <thinlayer/results_directory.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>

#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <unistd.h>

namespace thinlayer
{
  namespace fs = std::filesystem;

  namespace
  {
    /// The files by which a directory is recognised as a thinlayer run or
    /// sweep (summary.json is written last, so history.csv counts too).
    bool
    holds_a_run_or_nothing(const fs::path &directory)
    {
      if (fs::is_empty(directory))
        return true;
      for (const char *name : {"summary.json", "history.csv", "sweep.csv"})
        if (fs::exists(directory / name))
          return true;
      return false;
    }


    /// Staging directories (".NAME.partial-PID-K") of processes that are gone.
    void
    clear_stale_staging(const fs::path &parent, const std::string &name)
    {
      const std::string prefix = "." + name + ".partial-";
      std::error_code   error;
      for (const auto &entry : fs::directory_iterator(parent, error))
        {
          const std::string file = entry.path().filename().string();
          if (file.rfind(prefix, 0) != 0)
            continue;
          const pid_t pid = std::atoi(file.c_str() + prefix.size());
          if (pid > 0 && kill(pid, 0) != 0 && errno == ESRCH)
            fs::remove_all(entry.path(), error);
        }
    }


    /// Swap two directories in one step where the kernel and file system
    /// can; false where they cannot (the caller then renames twice).
    bool
    exchange(const fs::path &a, const fs::path &b)
    {
#ifdef RENAME_EXCHANGE
      return renameat2(
               AT_FDCWD, a.c_str(), AT_FDCWD, b.c_str(), RENAME_EXCHANGE) == 0;
#else
      (void)a;
      (void)b;
      return false;
#endif
    }
  } // namespace


  ResultsDirectory::ResultsDirectory(const std::string &directory,
                                     const std::string &parameter_file)
  {
    const auto refuse = [&](const std::string &why) {
      throw InputError(parameter_file,
                       "Output/Directory",
                       "'" + directory + "' " + why);
    };
    if (directory.empty())
      refuse("is empty; name the directory the results go to");
    std::error_code error;
    final_path = fs::weakly_canonical(fs::absolute(directory, error), error);
    if (error || final_path.filename().empty() || final_path == "/")
      refuse("is not a directory the results can go to" +
             (error ? " (" + error.message() + ")" : std::string()));
    if (fs::exists(fs::symlink_status(final_path, error)) &&
        !fs::is_directory(final_path, error))
      refuse("exists and is not a directory");
    if (fs::is_directory(final_path, error))
      {
        const fs::path prm =
          fs::weakly_canonical(fs::absolute(parameter_file), error);
        for (fs::path p = prm.parent_path(); !p.empty() && p != p.root_path();
             p          = p.parent_path())
          if (p == final_path)
            refuse("contains the parameter file, and a run replaces its "
                            "whole directory");
        if (!holds_a_run_or_nothing(final_path))
          refuse("holds files that are not a thinlayer run, and a run "
                 "replaces its whole directory; name a new directory or "
                 "one an earlier run wrote");
      }

    const fs::path parent = final_path.parent_path();
    fs::create_directories(parent, error);
    if (error)
      refuse("cannot be created: " + error.message());
    clear_stale_staging(parent, final_path.filename().string());

    static std::atomic<unsigned int> counter{0};
    staging_path =
      parent / ("." + final_path.filename().string() + ".partial-" +
                std::to_string(getpid()) + "-" + std::to_string(counter++));
    fs::create_directory(staging_path, error);
    if (error)
      refuse("cannot be written: " + error.message());
  }


  ResultsDirectory::~ResultsDirectory()
  {
    if (!committed)
      {
        std::error_code error;
        fs::remove_all(staging_path, error);
      }
  }


  std::string
  ResultsDirectory::staging() const
  {
    return staging_path.string();
  }


  void
  ResultsDirectory::commit()
  {
    const auto fail = [&](const std::string &what) {
      throw WriteError("cannot put the results in place: " + what + ": " +
                       std::strerror(errno) + " (Output/Directory " +
                       final_path.string() + ")");
    };
    std::error_code error;
    if (!fs::exists(final_path, error))
      {
        if (::rename(staging_path.c_str(), final_path.c_str()) != 0)
          fail("renaming " + staging_path.string());
      }
    else if (exchange(staging_path, final_path))
      fs::remove_all(staging_path, error); // now the previous run
    else
      {
        const fs::path previous = staging_path.string() + "-previous";
        if (::rename(final_path.c_str(), previous.c_str()) != 0)
          fail("moving the previous run aside");
        if (::rename(staging_path.c_str(), final_path.c_str()) != 0)
          {
            const int saved = errno;
            ::rename(previous.c_str(), final_path.c_str());
            errno = saved;
            fail("renaming " + staging_path.string());
          }
        fs::remove_all(previous, error);
      }
    committed = true;
  }
} // namespace thinlayer
