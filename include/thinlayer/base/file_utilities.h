#ifndef thinlayer_base_file_utilities_h
#define thinlayer_base_file_utilities_h

#include <fstream>
#include <sstream>
#include <string>

namespace thinlayer
{
  /**
   * The whole text of @p file; empty if it cannot be read (callers that
   * must tell the difference check the file first, with a message that
   * names the entry it came from).
   */
  inline std::string
  read_file(const std::string &file)
  {
    std::ifstream      in(file);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
} // namespace thinlayer

#endif
