#include <thinlayer/text_format.h>

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
    json_number(const double value)
    {
      return std::isfinite(value) ? printf("%.10g", value) : "null";
    }


    std::string
    json_string(const std::string &text)
    {
      std::string out = "\"";
      for (const char c : text)
        if (c == '"' || c == '\\')
          out += std::string("\\") + c;
        else if (c == '\n')
          out += "\\n";
        else if (static_cast<unsigned char>(c) < 0x20)
          {
            char code[8];
            std::snprintf(code,
                          sizeof(code),
                          "\\u%04x",
                          static_cast<unsigned int>(c));
            out += code;
          }
        else
          out += c;
      return out + "\"";
    }


    std::string
    csv_number(const double value)
    {
      return std::isfinite(value) ? printf("%.10g", value) : "";
    }


    std::string
    csv_field(const std::string &text)
    {
      if (text.find_first_of(",\"\n") == std::string::npos)
        return text;
      std::string quoted = "\"";
      for (const char c : text)
        quoted += (c == '"')    ? std::string("\"\"")
                  : (c == '\n') ? std::string(" ")
                                : std::string(1, c);
      return quoted + "\"";
    }
  } // namespace text_format
} // namespace thinlayer
