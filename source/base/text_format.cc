#include <thinlayer/base/text_format.h>

#include <cmath>
#include <cstdio>

namespace thinlayer
{
  namespace text_format
  {
    std::string
    printf(const char *pattern, const double value)
    {
      char buffer[64];
      std::snprintf(buffer, sizeof(buffer), pattern, value);
      return buffer;
    }


    std::string
    csv_number(const double value)
    {
      // Never an empty field: a reader must tell "not a number" from a
      // value left out.
      if (std::isnan(value))
        return "nan";
      if (std::isinf(value))
        return value > 0 ? "inf" : "-inf";
      return printf("%.10g", value);
    }


    std::string
    csv_field(const std::string &text)
    {
      // As RFC 4180 and CSV libraries read a field: quoted where it holds
      // a separator or a quote, its quotes doubled. A line break becomes a
      // space, so that every record stays one line for line-based tools.
      if (text.find_first_of(",\"\n\r") == std::string::npos)
        return text;
      std::string quoted = "\"";
      for (const char c : text)
        quoted += (c == '"')                 ? std::string("\"\"")
                  : (c == '\n' || c == '\r') ? std::string(" ")
                                             : std::string(1, c);
      return quoted + "\"";
    }
  } // namespace text_format
} // namespace thinlayer
