#ifndef thinlayer_parameters_parameter_text_h
#define thinlayer_parameters_parameter_text_h

#include <set>
#include <string>
#include <utility>
#include <vector>

namespace thinlayer
{
  /**
   * @file
   * The text of a parameter file before deal.II's ParameterHandler sees it.
   * ParameterHandler follows `include` lines without end (a file that
   * includes itself overflows the stack), reads whatever it is given
   * (/dev/zero until memory runs out) and reports a byte-order mark as an
   * unparsable line; and the checks that ParameterHandler does not make
   * (an entry given twice, which entries a file sets) need the lines
   * anyway. So the file is read and its includes expanded here, with
   * limits and messages that name the file, and the lines are scanned by
   * hand: a regular expression over a 30,000-character line recurses
   * until the stack overflows.
   */

  /// The most bytes a parameter file (with what it includes) may have.
  constexpr std::size_t max_parameter_file_bytes = 16u << 20;

  /// How deeply `include` lines may nest.
  constexpr unsigned int max_include_depth = 16;

  /// One logical line of a parameter file (continuations joined) and where
  /// it came from.
  struct ParameterLine
  {
    enum class Kind
    {
      blank,
      subsection,
      end,
      set,
      include,
      other
    };

    Kind kind = Kind::blank;
    /// The section name (subsection), the entry (set) or the file
    /// (include), trimmed.
    std::string name;
    /// The value of a set line, trimmed.
    std::string value;
    /// The line as read, continuations joined.
    std::string text;
    /// The file and line number it starts at.
    std::string  file;
    unsigned int line = 0;
  };


  /**
   * Where @p line is, for messages about @p file: "line 7", or "line 7 of
   * 'FILE'" for a line of a file that @p file includes.
   */
  std::string
  line_position(const ParameterLine &line, const std::string &file);

  /// Classify one line of a parameter file (without its comment).
  ParameterLine
  scan_parameter_line(const std::string &text);

  /**
   * The lines of @p text (of @p file), continuations ('\' at the end of a
   * line) joined, includes expanded (relative to the including file, and
   * checked like the file itself); an InputError naming the file for an
   * include that cannot be read, a cycle of includes, or nesting deeper
   * than max_include_depth.
   */
  std::vector<ParameterLine>
  parameter_lines(const std::string &text, const std::string &file);

  /**
   * The text of the parameter file @p file, checked: it exists, is a
   * regular file (not a directory, a device or a pipe) of at most
   * max_parameter_file_bytes, and is text (no NUL byte); a UTF-8
   * byte-order mark is dropped. An InputError naming the file otherwise.
   */
  std::string
  read_parameter_file(const std::string &file);

  /**
   * @p text with its control characters (other than tab and newline)
   * written as \\xNN, so that a message quoting a binary file prints as
   * text; a message of more than 2000 characters (quoting a value of
   * 100,000) is shortened to its first and last 900.
   */
  std::string
  printable(const std::string &text);

  /// The lines as one text that ParameterHandler reads (includes expanded).
  std::string
  joined_text(const std::vector<ParameterLine> &lines);

  /// Each set line of @p lines with the path "Section/Sub/Entry" of the
  /// entry it sets.
  std::vector<std::pair<const ParameterLine *, std::string>>
  set_entries(const std::vector<ParameterLine> &lines);

  /**
   * "Section/Sub/Entry" of every entry that @p lines set, and of every
   * override ("Section/Entry=value"): the entries a user gave, which the
   * checks of entries that mean nothing in a scene ask for.
   */
  std::set<std::string>
  given_entries(const std::vector<ParameterLine> &lines,
                const std::vector<std::string>   &overrides);

  /**
   * "Section/Entry" of @p key with each part trimmed ("Solver / Tolerance"
   * gives "Solver/Tolerance"), or an empty string if @p key is no such
   * path: the form in which entries are compared.
   */
  std::string
  entry_path(const std::string &key);
} // namespace thinlayer

#endif
