#ifndef thinlayer_base_text_format_h
#define thinlayer_base_text_format_h

#include <string>

namespace thinlayer
{
  /**
   * How numbers and text are written into results, in one place so that
   * every writer of text (screen, history.csv, sweep.csv) quotes and rounds
   * the same way; summary.json is written by nlohmann's JSON library.
   */
  namespace text_format
  {
    /// @p value formatted by the printf pattern @p pattern (one number).
    std::string
    printf(const char *pattern, const double value);

    /// Ten significant digits (%.10g); nan, inf or -inf where not finite
    /// (also for a figure a run does not have), never an empty field.
    std::string
    csv_number(const double value);

    /// A CSV field, quoted where it holds a comma, a quote or a line break
    /// (RFC 4180, as CSV libraries read it); a line break becomes a space.
    std::string
    csv_field(const std::string &text);
  } // namespace text_format
} // namespace thinlayer

#endif
