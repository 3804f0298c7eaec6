#ifndef thinlayer_parameters_entry_checks_h
#define thinlayer_parameters_entry_checks_h

#include <deal.II/base/parameter_handler.h>

#include <thinlayer/parameters/parameter_text.h>

#include <set>
#include <string>
#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /**
   * @file
   * Checks of the entries as a user wrote them, in the file's lines and on
   * the command line, that ParameterHandler does not make: it lets the
   * later of two values win, converts a number it cannot hold into an
   * internal error, and cannot tell an entry written at its default from
   * one left out.
   */

  /**
   * A section opened twice, an entry set twice in one section, or one entry
   * overridden twice on the command line: ParameterHandler lets the later
   * win, silently. (An override of an entry the file sets is what -s is
   * for.)
   */
  void
  check_nothing_given_twice(const std::vector<ParameterLine> &lines,
                            const std::string                &file,
                            const std::vector<std::string>   &overrides);

  /**
   * Every number written in a value (an entry's value, a list, an
   * expression) is one a double holds at full precision: a magnitude
   * beyond 1.8e308 or, other than 0, below 2.2e-308 (where doubles lose
   * digits and ParameterHandler cannot convert them) is refused, naming the
   * entry, its file and line (or the override) and the number. Free text
   * (names, files, the results directory) is not read as numbers.
   */
  void
  check_numbers_representable(const std::vector<ParameterLine> &lines,
                              const std::vector<std::string>   &overrides);

  /**
   * Mesh/Trust geometry scripts, which lets gmsh run a .geo that runs
   * programs or writes files, is taken from the command line only: a
   * parameter file that sets it true would let a shared scene trust
   * itself. Refused where a line of the file (or one it includes) sets it.
   */
  void
  check_trust_given_on_command_line(const std::vector<ParameterLine> &lines);

  /**
   * Of the @p given entries ("Section/Entry"), those whose value in
   * @p prm differs from their default in @p defaults (declared alike and
   * never read): an entry written at its default is as if left out, so that
   * the record of a run (parameters.prm, every entry written) and the
   * output of --print-parameters run as given. Values are compared without
   * their spaces.
   */
  std::set<std::string>
  entries_off_default(const std::set<std::string> &given,
                      ParameterHandler            &prm,
                      ParameterHandler            &defaults);

  /// Where an entry got its value.
  struct EntrySource
  {
    /// The file of the line that sets it, or "command line" for an
    /// override; empty if neither sets it.
    std::string file;
    /// "line N" in that file (empty for an override).
    std::string line;
  };

  /// Where @p entry ("Section/Entry") got its value: an override wins.
  EntrySource
  source_of(const std::string                &entry,
            const std::vector<ParameterLine> &lines,
            const std::vector<std::string>   &overrides);
} // namespace thinlayer

#endif
