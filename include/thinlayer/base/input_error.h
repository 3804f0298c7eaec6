#ifndef thinlayer_base_input_error_h
#define thinlayer_base_input_error_h

#include <stdexcept>
#include <string>

namespace thinlayer
{
  /**
   * An error in what the user gave us: a parameter file, a command-line
   * override, a mesh. It carries the file, the entry (or id) and what was
   * expected, because a researcher fixing a parameter file needs all three
   * to find the line; the command line turns it into one message and a
   * non-zero exit before any result is written.
   */
  class InputError : public std::runtime_error
  {
  public:
    /**
     * @param file     the file at fault (parameter file, mesh, .geo).
     * @param entry    the entry, as "Section/Entry", or an id such as
     *                 "material id 3"; may be empty for whole-file errors.
     * @param expected what was expected, and what was found where useful.
     */
    InputError(const std::string &file,
               const std::string &entry,
               const std::string &expected)
      : std::runtime_error(compose(file, entry, expected))
      , file(file)
      , entry(entry)
      , expected(expected)
    {}

    const std::string file;
    const std::string entry;
    const std::string expected;

  private:
    static std::string
    compose(const std::string &file,
            const std::string &entry,
            const std::string &expected)
    {
      std::string message = "error in '" + file + "'";
      if (!entry.empty())
        message += ", entry '" + entry + "'";
      return message + ": " + expected;
    }
  };
} // namespace thinlayer

#endif
