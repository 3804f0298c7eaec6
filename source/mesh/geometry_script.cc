#include <thinlayer/base/file_utilities.h>
#include <thinlayer/base/input_error.h>
#include <thinlayer/mesh/geometry_script.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <set>

namespace thinlayer
{
  namespace
  {
    namespace fs = std::filesystem;
    using Token  = GeometryScript::Token;

    /// The most bytes of a file read as a script.
    constexpr std::uintmax_t max_script_bytes = 64u << 20;


    /**
     * The tokens of @p text as gmsh's lexer reads them: comments (// and
     * / * * /) dropped; a string runs from a quote (" or ') to the next
     * of the same kind, with no escapes; a word is a letter or '_' and
     * what letters, digits and '_' follow; anything else is a character of
     * its own (so "Solver . Executable0" is three tokens, as for gmsh).
     */
    std::vector<Token>
    tokens_of(const std::string &text)
    {
      std::vector<Token> tokens;
      unsigned int       line = 1;
      const auto         word = [](const char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
      };
      for (std::size_t i = 0; i < text.size();)
        {
          const char c = text[i];
          if (c == '\n')
            {
              ++line;
              ++i;
            }
          else if (std::isspace(static_cast<unsigned char>(c)))
            ++i;
          else if (text.compare(i, 2, "//") == 0)
            i = std::min(text.find('\n', i), text.size());
          else if (text.compare(i, 2, "/*") == 0)
            {
              const std::size_t end =
                std::min(text.find("*/", i + 2), text.size());
              line += std::count(text.begin() + i, text.begin() + end, '\n');
              i = std::min(end + 2, text.size());
            }
          else if (c == '"' || c == '\'')
            {
              const std::size_t end =
                std::min(text.find(c, i + 1), text.size());
              tokens.push_back(
                {Token::Kind::string, text.substr(i + 1, end - i - 1), line});
              line += std::count(text.begin() + i, text.begin() + end, '\n');
              i = std::min(end + 1, text.size());
            }
          else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_')
            {
              std::size_t end = i;
              while (end < text.size() && word(text[end]))
                ++end;
              tokens.push_back(
                {Token::Kind::word, text.substr(i, end - i), line});
              i = end;
            }
          else
            {
              tokens.push_back({Token::Kind::other, std::string(1, c), line});
              ++i;
            }
        }
      return tokens;
    }


    /// The text of token @p k, or "" past the end.
    const std::string &
    text_at(const std::vector<Token> &tokens, const std::size_t k)
    {
      static const std::string none;
      return k < tokens.size() ? tokens[k].text : none;
    }


    /// The token after a bracketed index "[...]" at @p k (or @p k itself).
    std::size_t
    after_index(const std::vector<Token> &tokens, std::size_t k)
    {
      if (text_at(tokens, k) != "[")
        return k;
      for (int depth = 0; k < tokens.size(); ++k)
        if (tokens[k].text == "[")
          ++depth;
        else if (tokens[k].text == "]" && --depth == 0)
          return k + 1;
      return k;
    }


    /// The statements that run a program or write a file, as gmsh 4 spells
    /// them, with what each does. As an option's name ("Print.Width")
    /// they are none.
    const std::vector<std::pair<std::string, std::string>> &
    refused_commands()
    {
      static const std::vector<std::pair<std::string, std::string>> commands = {
        {"SystemCall", "runs a shell command"},
        {"NonBlockingSystemCall", "runs a shell command"},
        {"System", "runs a shell command"},
        {"OnelabRun", "runs a program"},
        {"SendToServer", "talks to another program"},
        {"CreateDir", "creates a directory"},
        {"DeleteFile", "deletes a file"},
        {"RenameFile", "renames a file"},
        {"Save", "writes a file"},
        {"Print", "writes a file"}};
      return commands;
    }


    /// The lower-case extension of @p name.
    std::string
    extension_of(const std::string &name)
    {
      std::string extension = fs::path(name).extension().string();
      std::transform(extension.begin(),
                     extension.end(),
                     extension.begin(),
                     [](const unsigned char c) { return std::tolower(c); });
      return extension;
    }


    /// Files gmsh may run as scripts when it merges them: a .geo, its
    /// options, and the text formats it runs as a script where their
    /// header is missing.
    bool
    is_script(const std::string &name)
    {
      static const std::set<std::string> scripts = {
        ".geo", ".opt", ".msh", ".pos", ".inp", ".x3d"};
      return scripts.count(extension_of(name)) != 0;
    }


    /// Geometry and mesh formats gmsh reads by their extension and never
    /// runs.
    bool
    is_data(const std::string &name)
    {
      static const std::set<std::string> data = {".brep",
                                                 ".step",
                                                 ".stp",
                                                 ".iges",
                                                 ".igs",
                                                 ".stl",
                                                 ".med",
                                                 ".xao",
                                                 ".unv",
                                                 ".vtk",
                                                 ".bdf",
                                                 ".nas",
                                                 ".mesh",
                                                 ".ply",
                                                 ".off",
                                                 ".cgns"};
      return data.count(extension_of(name)) != 0;
    }
  } // namespace


  GeometryScript::GeometryScript(const std::string &geometry,
                                 const std::string &parameter_file)
    : parameter_file(parameter_file)
  {
    read(geometry);
  }


  void
  GeometryScript::read(const std::string &file)
  {
    std::error_code   error;
    const std::string canonical =
      fs::weakly_canonical(fs::absolute(file, error), error).string();
    if (std::find(read_already.begin(), read_already.end(), canonical) !=
        read_already.end())
      return;
    read_already.push_back(canonical);
    if (read_already.size() > 64)
      {
        problems.push_back({file, 0, "is one of more than 64 files read"});
        return;
      }
    const auto status = fs::status(file, error);
    // A file that is not there is gmsh's to report; it runs nothing.
    if (!fs::exists(status))
      return;
    if (!fs::is_regular_file(status))
      {
        problems.push_back(
          {file, 0, "is not a regular file (a device or a pipe)"});
        return;
      }
    const std::uintmax_t size = fs::file_size(file, error);
    if (error || size > max_script_bytes)
      {
        problems.push_back({file, 0, "is larger than 64 MiB"});
        return;
      }
    files.push_back({file, tokens_of(read_file(file))});
    const std::vector<Token> tokens = files.back().tokens;
    for (std::size_t k = 0; k < tokens.size(); ++k)
      if (tokens[k].kind == Token::Kind::word &&
          (tokens[k].text == "Include" || tokens[k].text == "Merge" ||
           tokens[k].text == "MergeWithBoundingBox"))
        follow(file, tokens, k);
    // gmsh merges FILE.opt, where it exists, after each file it opens.
    read(file + ".opt");
  }


  void
  GeometryScript::follow(const std::string        &file,
                         const std::vector<Token> &tokens,
                         const std::size_t         k)
  {
    const Token &t = tokens[k];
    if (k + 2 >= tokens.size() || tokens[k + 1].kind != Token::Kind::string ||
        tokens[k + 2].text != ";")
      {
        problems.push_back({file,
                            t.line,
                            "'" + t.text +
                              "' of a file name the script computes, which "
                              "cannot be checked before gmsh reads it"});
        return;
      }
    const std::string &name = tokens[k + 1].text;
    fs::path           path(name);
    if (path.is_relative())
      path = fs::path(file).parent_path() / path;
    if (t.text == "Include" || is_script(name))
      read(path.string());
    else if (!is_data(name))
      problems.push_back({file,
                          t.line,
                          "'" + t.text + " \"" + name +
                            "\"' hands gmsh a file that is no geometry or "
                            "mesh, which it may run"});
  }


  bool
  GeometryScript::has_word(const std::string &name) const
  {
    for (const File &f : files)
      for (const Token &t : f.tokens)
        if (t.kind == Token::Kind::word && t.text == name)
          return true;
    return false;
  }


  void
  GeometryScript::check_safe() const
  {
    for (const File &f : files)
      {
        const std::vector<Token> &tokens = f.tokens;
        for (std::size_t k = 0; k < tokens.size(); ++k)
          {
            const Token &t = tokens[k];
            if (t.kind != Token::Kind::word)
              continue;
            const std::string &next   = text_at(tokens, k + 1);
            const bool         option = next == "." || next == "[";
            for (const auto &[command, what] : refused_commands())
              if (t.text == command && !option)
                refuse(f.name, t.line, "'" + command + "' " + what);
            if (t.text == "Printf")
              {
                // Printf(...) > "file" and >> "file".
                std::size_t j     = k + 1;
                int         depth = 0;
                for (; j < tokens.size(); ++j)
                  if (tokens[j].kind != Token::Kind::other)
                    continue;
                  else if (tokens[j].text == "(")
                    ++depth;
                  else if (tokens[j].text == ")" && --depth <= 0)
                    break;
                  else if (tokens[j].text == ";")
                    break;
                if (text_at(tokens, j) == ")" && text_at(tokens, j + 1) == ">")
                  refuse(f.name, t.line, "'Printf(...) >' writes a file");
              }
            if (t.text == "Solver" && option)
              refuse(f.name,
                     t.line,
                     "a 'Solver.' option sets up a program for gmsh to run");
            if (t.text == "General" && option)
              {
                const std::size_t dot = after_index(tokens, k + 1);
                const std::string name =
                  text_at(tokens, dot) == "." ? text_at(tokens, dot + 1) : "";
                if (name.find("FileName") != std::string::npos ||
                    name.rfind("Save", 0) == 0)
                  refuse(f.name,
                         t.line,
                         "'General." + name + "' makes gmsh write a file");
              }
          }
      }
    if (!problems.empty())
      refuse(problems[0].file, problems[0].line, problems[0].what);
  }


  void
  GeometryScript::refuse(const std::string &file,
                         const unsigned int line,
                         const std::string &what) const
  {
    throw InputError(
      file,
      "",
      (line > 0 ? "line " + std::to_string(line) + ": " : std::string()) +
        what +
        ". gmsh runs a .geo with your rights, so thinlayer meshes only "
        "geometry scripts that neither run programs nor write files; remove "
        "the statement, or, if you trust this script, run " +
        parameter_file +
        " with -s \"Mesh/Trust geometry scripts=true\" (only the command "
        "line can trust a script)");
  }
} // namespace thinlayer
