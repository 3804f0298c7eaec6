#ifndef thinlayer_parameters_parameter_reader_h
#define thinlayer_parameters_parameter_reader_h

#include <thinlayer/parameters/parameters.h>

#include <iosfwd>
#include <string>
#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /**
   * Reads parameter files into Parameters. Per-id sections ("Material 3",
   * "Boundary 2") cannot be declared in advance because the ids come from the
   * user's mesh, so the reader first scans the file and the overrides for
   * such section names and declares exactly those.
   */
  class ParameterReader
  {
  public:
    /**
     * Read @p file, then apply @p overrides of the form
     * "Section/Subsection/Entry=value". Throws InputError naming the file
     * (or the override) and the entry on any problem.
     */
    Parameters
    read(const std::string              &file,
         const std::vector<std::string> &overrides  = {},
         std::ostream                   *documented = nullptr) const;

    /**
     * Same as read(), from the text of a parameter file; @p file_name is
     * used in messages and to resolve the mesh path. Where @p documented is
     * given, every entry as used, each with its documentation, is written
     * there (what --print-parameters prints for a scene: a file that runs
     * as given).
     */
    Parameters
    read_from_string(const std::string              &text,
                     const std::string              &file_name,
                     const std::vector<std::string> &overrides = {},
                     std::ostream *documented                  = nullptr) const;

    /**
     * Every entry with its documentation and default, with one example
     * material and boundary section.
     */
    void
    print_parameters(std::ostream &out) const;
  };
} // namespace thinlayer

#endif
