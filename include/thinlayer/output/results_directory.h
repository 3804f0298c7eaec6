#ifndef thinlayer_output_results_directory_h
#define thinlayer_output_results_directory_h

#include <filesystem>
#include <stdexcept>
#include <string>

namespace thinlayer
{
  /**
   * A file of the results could not be written (a full disk, a quota, a
   * file size limit): the run stops with this message, which names the
   * file, and the results directory keeps the run it held before.
   */
  class WriteError : public std::runtime_error
  {
  public:
    explicit WriteError(const std::string &message)
      : std::runtime_error(message)
    {}
  };


  /**
   * The output directory of one run (or one sweep), which always holds
   * exactly one complete run.
   *
   * A run writes into a staging directory beside the one it names
   * (`.NAME.partial-PID-K`, on the same file system). commit() puts it in
   * place in one step (the kernel's atomic exchange where the file system
   * has it), and only then is the previous run removed. A run that ends in
   * an error, or is killed, leaves the previous run as it was; a later run
   * into the same parent clears staging directories whose process is gone.
   * Two runs into one directory each write their own staging directory, and
   * the directory holds whichever finished last, whole.
   *
   * Because commit() replaces the whole directory, it writes a manifest
   * (manifest.txt: every file with its size and a hash of its bytes), and
   * a directory is replaced only while it holds what its manifest lists,
   * unchanged, and nothing else (or nothing at all). A directory with any
   * other entry (a thesis, raw data, notes added to a run, a directory an
   * older version wrote without a manifest) is refused with their names,
   * and so is one that contains the parameter file. Files that appear
   * during the run leave the directory as it is and the run beside it.
   *
   * Two runs into one directory at once would each take the other's
   * results, manifest and all, for an earlier run of its own and replace
   * them. So a run holds a lock on its directory (an advisory lock on
   * `.NAME.lock` beside it, which the kernel releases if the run is
   * killed) from this check to the end, and a second run into it is
   * refused while the first holds it.
   */
  class ResultsDirectory
  {
  public:
    /// The manifest's name, in every directory a run or sweep writes.
    static constexpr const char *manifest_name = "manifest.txt";

    /**
     * Check @p directory (Output/Directory of @p parameter_file) and create
     * the staging directory: an InputError naming the entry if it cannot be
     * used.
     */
    ResultsDirectory(const std::string &directory,
                     const std::string &parameter_file);

    /// Removes the staging directory unless it was committed.
    ~ResultsDirectory();

    ResultsDirectory(const ResultsDirectory &) = delete;
    ResultsDirectory &
    operator=(const ResultsDirectory &) = delete;

    /// Where this run writes.
    std::string
    staging() const;

    /// Put the run in place of the previous one.
    void
    commit();

  private:
    /// The lock on a results directory, let go (its file removed) when
    /// destroyed, also when the constructor of its owner throws.
    class Lock
    {
    public:
      Lock() = default;
      ~Lock();
      Lock(const Lock &) = delete;
      Lock &
      operator=(const Lock &) = delete;
      /// Take the lock on @p directory, or refuse (InputError naming
      /// Output/Directory of @p parameter_file) while another run holds it.
      void
      take(const std::filesystem::path &directory,
           const std::string           &parameter_file);

    private:
      std::filesystem::path path;
      /// The open lock file (-1: none).
      int descriptor = -1;
    };

    Lock                  lock;
    std::filesystem::path final_path;
    std::filesystem::path staging_path;
    bool                  committed = false;
  };
} // namespace thinlayer

#endif
