#ifndef thinlayer_mesh_geometry_script_h
#define thinlayer_mesh_geometry_script_h

#include <string>
#include <vector>

namespace thinlayer
{
  /**
   * A gmsh .geo and every file gmsh would read as a script with it: the
   * files it includes (`Include`), the files it merges that gmsh may run as
   * scripts (`Merge` of a .geo, or of a .msh, .pos, .inp or .x3d without its
   * header), and the option file `NAME.opt` that gmsh merges after each, all
   * read as gmsh's lexer reads them (comments dropped, strings between
   * matching quotes, without escapes), never past 64 MiB and never from a
   * device or a pipe.
   *
   * A .geo runs with the rights of whoever runs thinlayer: `SystemCall
   * "..."` runs a shell command, `Printf(...) > "file"`, `Save`, `Print`,
   * `CreateDir`, `DeleteFile` and `RenameFile` touch files outside the
   * results, `OnelabRun` and the `Solver.` options start programs, and a
   * merged file of another kind (a Python script) may be run. A scene
   * shared as a parameter file plus a .geo could therefore do anything on
   * the machine of whoever runs it: check_safe() refuses such scripts.
   */
  class GeometryScript
  {
  public:
    /// Read @p geometry and what it reads; @p parameter_file for messages.
    GeometryScript(const std::string &geometry,
                   const std::string &parameter_file);

    /// Whether @p name is a word of the scripts (a parameter they define).
    bool
    has_word(const std::string &name) const;

    /**
     * An InputError naming the file, its line and the statement, for the
     * first statement that runs a program or writes a file, for a file
     * read by a name the script computes (which cannot be checked before
     * gmsh reads it), and for a file that cannot be checked (a device, a
     * pipe, one over 64 MiB, a merged file of a kind gmsh may run); the
     * message says that only the command line can trust a script
     * (Mesh/Trust geometry scripts).
     */
    void
    check_safe() const;

    /// A word, a string or a single character of a script, with its line.
    struct Token
    {
      enum class Kind
      {
        word,
        string,
        other
      };
      Kind         kind;
      std::string  text;
      unsigned int line;
    };

  private:
    /// Read @p file (unless read already), and what it reads in turn.
    void
    read(const std::string &file);

    /// Follow the Include or Merge at token @p k of the file @p file.
    void
    follow(const std::string        &file,
           const std::vector<Token> &tokens,
           const std::size_t         k);

    struct File
    {
      std::string        name;
      std::vector<Token> tokens;
    };

    /// Something in a file that cannot be checked, found while reading.
    struct Problem
    {
      std::string  file;
      unsigned int line;
      std::string  what;
    };

    [[noreturn]] void
    refuse(const std::string &file,
           const unsigned int line,
           const std::string &what) const;

    const std::string        parameter_file;
    std::vector<File>        files;
    std::vector<std::string> read_already;
    std::vector<Problem>     problems;
  };
} // namespace thinlayer

#endif
