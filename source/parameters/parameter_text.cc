#include <deal.II/base/utilities.h>

#include <thinlayer/base/input_error.h>
#include <thinlayer/parameters/parameter_text.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace thinlayer
{
  namespace fs = std::filesystem;

  namespace
  {
    using dealii::Utilities::trim;

    /// Whether @p text starts with the word @p word (followed by a space
    /// or its end).
    bool
    starts_with_word(const std::string &text, const std::string &word)
    {
      return text.compare(0, word.size(), word) == 0 &&
             (text.size() == word.size() ||
              std::isspace(static_cast<unsigned char>(text[word.size()])));
    }


    /// The text read, with the file and line each line came from, includes
    /// followed through @p chain (the files being read, outermost first).
    void
    expand(const std::string          &text,
           const std::string          &file,
           std::vector<std::string>   &chain,
           std::vector<ParameterLine> &lines)
    {
      std::istringstream in(text);
      std::string        physical;
      for (unsigned int number = 1; std::getline(in, physical); ++number)
        {
          const unsigned int first = number;
          std::string        logical;
          // A backslash at the end continues the line, as in
          // ParameterHandler.
          while (true)
            {
              const std::string t = trim(physical);
              if (t.empty() || t.back() != '\\')
                {
                  logical += (logical.empty() ? "" : " ") + t;
                  break;
                }
              logical +=
                (logical.empty() ? "" : " ") + trim(t.substr(0, t.size() - 1));
              if (!std::getline(in, physical))
                break;
              ++number;
            }
          ParameterLine line = scan_parameter_line(logical);
          line.file          = file;
          line.line          = first;
          if (line.kind != ParameterLine::Kind::include)
            {
              lines.push_back(std::move(line));
              continue;
            }

          const std::string where = "include, line " + std::to_string(first);
          fs::path          included(line.name);
          if (included.is_relative())
            included = fs::path(file).parent_path() / included;
          std::error_code   error;
          const std::string canonical =
            fs::weakly_canonical(fs::absolute(included, error), error).string();
          for (const auto &outer : chain)
            if (outer == canonical)
              throw InputError(file,
                               where,
                               "'" + line.name +
                                 "' is a file this include is already "
                                 "inside of (an include cycle); expected "
                                 "each file included at most once along "
                                 "a chain");
          if (chain.size() >= max_include_depth)
            throw InputError(file,
                             where,
                             "includes nest more than " +
                               std::to_string(max_include_depth) +
                               " deep; expected fewer levels");
          chain.push_back(canonical);
          expand(read_parameter_file(included.string()),
                 included.string(),
                 chain,
                 lines);
          chain.pop_back();
        }
    }
  } // namespace


  std::string
  line_position(const ParameterLine &line, const std::string &file)
  {
    return "line " + std::to_string(line.line) +
           (line.file == file ? std::string() : " of '" + line.file + "'");
  }


  ParameterLine
  scan_parameter_line(const std::string &text)
  {
    ParameterLine line;
    line.text           = text;
    const std::string t = trim(text.substr(0, text.find('#')));
    if (t.empty())
      return line;
    if (t == "end")
      line.kind = ParameterLine::Kind::end;
    else if (starts_with_word(t, "subsection"))
      {
        line.kind = ParameterLine::Kind::subsection;
        line.name = trim(t.substr(10));
      }
    else if (starts_with_word(t, "set") && t.find('=') != std::string::npos)
      {
        const auto equal = t.find('=');
        line.kind        = ParameterLine::Kind::set;
        line.name        = trim(t.substr(3, equal - 3));
        line.value       = trim(t.substr(equal + 1));
      }
    else if (starts_with_word(t, "include"))
      {
        line.kind = ParameterLine::Kind::include;
        line.name = trim(t.substr(7));
      }
    else
      line.kind = ParameterLine::Kind::other;
    return line;
  }


  std::vector<ParameterLine>
  parameter_lines(const std::string &text, const std::string &file)
  {
    std::vector<ParameterLine> lines;
    std::error_code            error;
    std::vector<std::string>   chain = {
        fs::weakly_canonical(fs::absolute(file, error), error).string()};
    expand(text, file, chain, lines);
    return lines;
  }


  std::string
  read_parameter_file(const std::string &file)
  {
    std::error_code error;
    const auto      status = fs::status(file, error);
    if (error && error != std::errc::no_such_file_or_directory)
      throw InputError(file,
                       "",
                       "cannot be read: " + error.message() +
                         "; expected a parameter file");
    if (!fs::exists(status))
      throw InputError(file,
                       "",
                       "cannot open the parameter file: it does not exist");
    if (fs::is_directory(status))
      throw InputError(file, "", "is a directory; expected a parameter file");
    if (!fs::is_regular_file(status))
      throw InputError(file,
                       "",
                       "is not a regular file (a device, a pipe or a "
                       "socket); expected a parameter file");
    std::ifstream in(file, std::ios::binary);
    if (!in)
      throw InputError(file, "", "cannot open the parameter file");
    std::string text(max_parameter_file_bytes + 1, '\0');
    in.read(text.data(), text.size());
    text.resize(in.gcount());
    if (text.size() > max_parameter_file_bytes)
      throw InputError(file,
                       "",
                       "is larger than " +
                         std::to_string(max_parameter_file_bytes >> 20) +
                         " MiB; expected a parameter file (text)");
    const auto nul = text.find('\0');
    if (nul != std::string::npos)
      {
        const unsigned int line =
          1 + std::count(text.begin(), text.begin() + nul, '\n');
        throw InputError(file,
                         "",
                         "is not a text file (a NUL byte on line " +
                           std::to_string(line) +
                           "); expected a parameter file");
      }
    // A UTF-8 byte-order mark, which some editors write.
    if (text.compare(0, 3, "\xEF\xBB\xBF") == 0)
      text.erase(0, 3);
    return text;
  }


  std::string
  printable(const std::string &text_in)
  {
    // A quoted value of 100,000 characters says no more than its ends.
    std::string text = text_in;
    if (text.size() > 2000)
      text = text.substr(0, 900) + " [... " +
             std::to_string(text.size() - 1800) + " characters ...] " +
             text.substr(text.size() - 900);
    std::string result;
    for (const char c : text)
      {
        const auto u = static_cast<unsigned char>(c);
        if ((u < 0x20 && c != '\n' && c != '\t') || u == 0x7f)
          {
            char hex[8];
            std::snprintf(hex, sizeof(hex), "\\x%02x", u);
            result += hex;
          }
        else
          result += c;
      }
    return result;
  }


  std::string
  joined_text(const std::vector<ParameterLine> &lines)
  {
    std::string text;
    for (const auto &line : lines)
      text += line.text + '\n';
    return text;
  }


  std::vector<std::pair<const ParameterLine *, std::string>>
  set_entries(const std::vector<ParameterLine> &lines)
  {
    std::vector<std::pair<const ParameterLine *, std::string>> entries;
    std::vector<std::string>                                   path;
    for (const auto &line : lines)
      if (line.kind == ParameterLine::Kind::subsection)
        path.push_back(line.name);
      else if (line.kind == ParameterLine::Kind::end && !path.empty())
        path.pop_back();
      else if (line.kind == ParameterLine::Kind::set)
        {
          std::string name;
          for (const auto &p : path)
            name += p + "/";
          entries.emplace_back(&line, name + line.name);
        }
    return entries;
  }


  std::set<std::string>
  given_entries(const std::vector<ParameterLine> &lines,
                const std::vector<std::string>   &overrides)
  {
    std::set<std::string> given;
    for (const auto &[line, path] : set_entries(lines))
      given.insert(path);
    for (const auto &o : overrides)
      given.insert(entry_path(o.substr(0, o.find('='))));
    return given;
  }


  std::string
  entry_path(const std::string &key)
  {
    const auto parts = dealii::Utilities::split_string_list(key, '/');
    if (parts.size() < 2)
      return "";
    std::string path;
    for (const auto &part : parts)
      {
        if (part.empty() || part.find('=') != std::string::npos)
          return "";
        path += (path.empty() ? "" : "/") + part;
      }
    return path;
  }
} // namespace thinlayer
