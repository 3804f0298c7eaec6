#include <thinlayer/base/input_error.h>
#include <thinlayer/output/results_directory.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace thinlayer
{
  namespace fs = std::filesystem;

  namespace
  {
    /// The first lines of every manifest.
    constexpr const char *manifest_header =
      "# The files thinlayer wrote for this run (FNV-1a hash, bytes, name).\n"
      "# A later run replaces this directory only while it holds these "
      "files, unchanged, and no other.\n";


    /// FNV-1a, 64 bits, of a file's bytes: enough to tell a file this
    /// program wrote from one a user changed.
    std::string
    content_hash(const fs::path &file)
    {
      std::uint64_t hash = 14695981039346656037ull;
      std::ifstream in(file, std::ios::binary);
      char          buffer[1 << 16];
      while (in.read(buffer, sizeof(buffer)) || in.gcount() > 0)
        {
          for (std::streamsize i = 0; i < in.gcount(); ++i)
            {
              hash ^= static_cast<unsigned char>(buffer[i]);
              hash *= 1099511628211ull;
            }
          if (!in)
            break;
        }
      char text[20];
      std::snprintf(text,
                    sizeof(text),
                    "%016llx",
                    static_cast<unsigned long long>(hash));
      return text;
    }


    /// "hash size path" of every file under @p directory but the manifest.
    std::map<std::string, std::string>
    file_records(const fs::path &directory)
    {
      std::map<std::string, std::string> records;
      for (const auto &entry : fs::recursive_directory_iterator(directory))
        if (entry.is_regular_file() &&
            entry.path().filename() != ResultsDirectory::manifest_name)
          records[entry.path().lexically_relative(directory).string()] =
            content_hash(entry.path()) + " " +
            std::to_string(entry.file_size());
      return records;
    }


    /**
     * The entries of @p directory that this program did not write as they
     * are: every file must stand in its manifest with the same size and
     * contents, every directory must hold such files; anything else
     * (another file, a changed one, a link, an empty directory) is
     * foreign. Without a manifest, every entry is.
     */
    std::vector<std::string>
    foreign_entries(const fs::path &directory)
    {
      // A manifest is one only if it is ours to the letter: our header,
      // then "hash size name" lines; a file of the user's that happens to
      // have the name lists nothing.
      std::map<std::string, std::string> written;
      {
        std::ifstream manifest(directory / ResultsDirectory::manifest_name);
        std::string   line;
        bool          valid =
          std::getline(manifest, line) &&
          line + '\n' ==
            std::string(manifest_header)
              .substr(0, std::string(manifest_header).find('\n') + 1);
        std::getline(manifest, line); // the header's second line
        while (valid && std::getline(manifest, line))
          {
            const auto first  = line.find(' ');
            const auto second = line.find(' ', first + 1);
            valid             = first == 16 && second != std::string::npos &&
                    second > first + 1 &&
                    line.find_first_not_of("0123456789abcdef") == 16 &&
                    line.find_first_not_of("0123456789", first + 1) == second &&
                    second + 1 < line.size();
            if (valid)
              written[line.substr(second + 1)] = line.substr(0, second);
          }
        if (!valid)
          written.clear();
      }
      std::vector<std::string> foreign;
      std::error_code          error;
      const bool               has_manifest = !written.empty();
      for (auto entry = fs::recursive_directory_iterator(directory, error);
           entry != fs::recursive_directory_iterator();
           entry.increment(error))
        {
          const std::string name =
            entry->path().lexically_relative(directory).string();
          if (!has_manifest && name == ResultsDirectory::manifest_name)
            {
              foreign.push_back(name + " (not a manifest of this program)");
              continue;
            }
          if (name == ResultsDirectory::manifest_name)
            continue;
          if (entry->is_symlink())
            foreign.push_back(name + " (a link)");
          else if (entry->is_directory())
            {
              const auto below = written.lower_bound(name + "/");
              if (below == written.end() ||
                  below->first.compare(0, name.size() + 1, name + "/") != 0)
                foreign.push_back(name + "/");
            }
          else if (written.count(name) == 0)
            foreign.push_back(name);
          else if (!entry->is_regular_file() ||
                   written[name] != content_hash(entry->path()) + " " +
                                      std::to_string(entry->file_size()))
            foreign.push_back(name + " (changed since it was written)");
        }
      std::sort(foreign.begin(), foreign.end());
      return foreign;
    }


    /// "a, b, c (and 4 more)".
    std::string
    list_of(const std::vector<std::string> &names)
    {
      std::string text;
      for (unsigned int i = 0; i < names.size() && i < 5; ++i)
        text += (i ? ", " : "") + names[i];
      if (names.size() > 5)
        text += " (and " + std::to_string(names.size() - 5) + " more)";
      return text;
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
    // "out/run/", as a shell's completion writes it, names out/run.
    std::string name = directory;
    while (name.size() > 1 && name.back() == '/')
      name.pop_back();
    std::error_code error;
    final_path = fs::weakly_canonical(fs::absolute(name, error), error);
    if (error || final_path.filename().empty() || final_path == "/")
      refuse("is not a directory the results can go to" +
             (error ? " (" + error.message() + ")" : std::string()));
    const fs::path parent = final_path.parent_path();
    fs::create_directories(parent, error);
    if (error)
      refuse("cannot be created: " + error.message());
    lock.take(final_path, parameter_file);
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
        const auto foreign = foreign_entries(final_path);
        if (!foreign.empty())
          refuse("holds files that thinlayer did not write (" +
                 list_of(foreign) +
                 "), and a run replaces its whole directory; name a new "
                 "directory, or one that holds an earlier run only (its " +
                 manifest_name + " lists that run's files)");
      }

    clear_stale_staging(parent, final_path.filename().string());

    static std::atomic<unsigned int> counter{0};
    staging_path =
      parent / ("." + final_path.filename().string() + ".partial-" +
                std::to_string(getpid()) + "-" + std::to_string(counter++));
    fs::create_directory(staging_path, error);
    if (error)
      refuse("cannot be written: " + error.message());
  }


  void
  ResultsDirectory::Lock::take(const fs::path    &directory,
                               const std::string &parameter_file)
  {
    const auto refuse = [&](const std::string &why) {
      throw InputError(parameter_file,
                       "Output/Directory",
                       "'" + directory.string() + "' " + why);
    };
    const fs::path lock_path =
      directory.parent_path() / ("." + directory.filename().string() + ".lock");
    const std::string ours = "thinlayer run, process ";
    // A file of that name that is not ours is the user's: never taken.
    {
      std::ifstream existing(lock_path);
      std::string   text;
      std::getline(existing, text);
      if (existing && !text.empty() && text.rfind(ours, 0) != 0)
        refuse("cannot be locked: " + lock_path.string() +
               " exists and is not a lock of thinlayer's; move it");
    }
    // The holder removes the file as it lets go; a lock taken on a file
    // that was removed meanwhile guards nothing, so it is taken again.
    for (unsigned int attempt = 0; attempt < 100; ++attempt)
      {
        // Not inherited by gmsh, which outlives a killed run for a while.
        const int fd = ::open(lock_path.c_str(),
                              O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW,
                              0644);
        if (fd < 0)
          refuse("cannot be locked: " + std::string(std::strerror(errno)));
        if (::flock(fd, LOCK_EX | LOCK_NB) != 0)
          {
            char      holder[64] = {};
            const int n          = ::pread(fd, holder, sizeof(holder) - 1, 0);
            ::close(fd);
            std::string who(holder, std::max(n, 0));
            while (!who.empty() && (who.back() == '\n' || who.back() == ' '))
              who.pop_back();
            refuse("is being written by another run (" +
                   (who.rfind(ours, 0) == 0 ? "a " + who
                                            : std::string("a thinlayer run")) +
                   ", which holds " + lock_path.string() +
                   "); expected one run at a time in a directory: wait for it "
                   "to end, or name another directory");
          }
        struct stat opened, named;
        if (::fstat(fd, &opened) == 0 &&
            ::stat(lock_path.c_str(), &named) == 0 &&
            opened.st_ino == named.st_ino && opened.st_dev == named.st_dev)
          {
            // The holder's process id, for the message a second run gets;
            // the lock holds without it.
            const std::string text    = ours + std::to_string(getpid()) + "\n";
            const bool        written = ::ftruncate(fd, 0) == 0 &&
                                 ::pwrite(fd, text.data(), text.size(), 0) ==
                                   static_cast<ssize_t>(text.size());
            (void)written;
            path       = lock_path;
            descriptor = fd;
            return;
          }
        ::close(fd);
      }
    refuse("cannot be locked: " + lock_path.string() + " keeps being replaced");
  }


  ResultsDirectory::Lock::~Lock()
  {
    if (descriptor >= 0)
      {
        // Removed while held: no other run can have taken it.
        ::unlink(path.c_str());
        ::close(descriptor);
      }
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
    {
      std::ofstream manifest(staging_path / manifest_name);
      manifest << manifest_header;
      for (const auto &[name, record] : file_records(staging_path))
        manifest << record << ' ' << name << '\n';
      manifest.close();
      if (!manifest)
        fail(std::string("writing ") + manifest_name);
    }
    // Files a user put there while the run went on are not ours to remove:
    // the run is left beside them.
    if (fs::is_directory(final_path, error))
      if (const auto foreign = foreign_entries(final_path); !foreign.empty())
        {
          const fs::path aside =
            final_path.string() + ".new-" + std::to_string(getpid());
          if (::rename(staging_path.c_str(), aside.c_str()) == 0)
            committed = true;
          throw WriteError("Output/Directory " + final_path.string() +
                           " gained files that thinlayer did not write (" +
                           list_of(foreign) + ") during the run; " +
                           (committed
                              ? "this run's results are in " + aside.string()
                              : std::string("this run was not kept")));
        }
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
