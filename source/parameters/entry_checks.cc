#include <deal.II/base/utilities.h>

#include <thinlayer/base/input_error.h>
#include <thinlayer/parameters/entry_checks.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>

namespace thinlayer
{
  namespace
  {
    /// The entries whose values are free text, never read as numbers.
    bool
    is_free_text(const std::string &entry)
    {
      const std::string name = entry.substr(entry.rfind('/') + 1);
      return name == "Name" || name == "File" || name == "Directory";
    }


    /**
     * The first number written in @p value that a double cannot hold at
     * full precision (see check_numbers_representable()), or an empty
     * string. A number starts where no letter, digit, '_' or '.' precedes
     * it, so that names such as "x1e999" are no numbers.
     */
    std::string
    unrepresentable_number(const std::string &value)
    {
      const auto is_word = [](const char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' ||
               c == '.';
      };
      for (std::size_t i = 0; i < value.size(); ++i)
        {
          const bool digit_start =
            std::isdigit(static_cast<unsigned char>(value[i])) ||
            (value[i] == '.' && i + 1 < value.size() &&
             std::isdigit(static_cast<unsigned char>(value[i + 1])));
          if (!digit_start || (i > 0 && is_word(value[i - 1])))
            continue;
          const char *begin = value.c_str() + i;
          char       *end   = nullptr;
          errno             = 0;
          const double x    = std::strtod(begin, &end);
          const bool   lost =
            errno == ERANGE ||
            (x != 0 && std::abs(x) < std::numeric_limits<double>::min()) ||
            std::isinf(x);
          const std::size_t length = std::max<std::size_t>(1, end - begin);
          if (lost)
            return value.substr(i, length);
          i += length - 1;
          while (i + 1 < value.size() && is_word(value[i + 1]))
            ++i;
        }
      return "";
    }


    /// "Section/Entry" and value of an override "Section/Entry=value".
    std::pair<std::string, std::string>
    split_override(const std::string &o)
    {
      const auto equal = o.find('=');
      if (equal == std::string::npos)
        return {"", ""};
      return {entry_path(o.substr(0, equal)),
              Utilities::trim(o.substr(equal + 1))};
    }


    /// The value of @p entry ("Section/Sub/Entry") in @p prm.
    std::string
    value_of(ParameterHandler &prm, const std::string &entry)
    {
      const auto   parts   = Utilities::split_string_list(entry, '/');
      unsigned int entered = 0;
      std::string  value;
      try
        {
          for (; entered + 1 < parts.size(); ++entered)
            prm.enter_subsection(parts[entered]);
          value = prm.get(parts.back());
        }
      catch (...)
        {
          // prm stays at its top level, whatever failed.
          for (; entered > 0; --entered)
            prm.leave_subsection();
          throw;
        }
      for (; entered > 0; --entered)
        prm.leave_subsection();
      std::string compact;
      for (const char c : value)
        if (!std::isspace(static_cast<unsigned char>(c)))
          compact += c;
      return compact;
    }


  } // namespace


  void
  check_nothing_given_twice(const std::vector<ParameterLine> &lines,
                            const std::string                &file,
                            const std::vector<std::string>   &overrides)
  {
    std::vector<std::string>             path;
    std::map<std::string, ParameterLine> first;
    for (const auto &line : lines)
      {
        std::string key;
        std::string name;
        for (const auto &p : path)
          name += p + "/";
        if (line.kind == ParameterLine::Kind::subsection)
          {
            path.push_back(line.name);
            key = "subsection ";
            name += line.name;
          }
        else if (line.kind == ParameterLine::Kind::end)
          {
            if (!path.empty())
              path.pop_back();
            continue;
          }
        else if (line.kind == ParameterLine::Kind::set)
          {
            key = "entry ";
            name += line.name;
          }
        else
          continue;
        const auto [it, inserted] = first.emplace(key + name, line);
        if (!inserted)
          throw InputError(file,
                           name,
                           "given twice, at " +
                             line_position(it->second, file) + " and " +
                             line_position(line, file) +
                             " (the later would silently win); expected "
                             "each " +
                             (key == "entry " ? "entry" : "subsection") +
                             " once");
      }

    std::map<std::string, std::string> overridden;
    for (const auto &o : overrides)
      {
        const std::string entry = split_override(o).first;
        if (entry.empty())
          continue;
        const auto [it, inserted] = overridden.emplace(entry, o);
        if (!inserted)
          throw InputError("command line",
                           entry,
                           "overridden twice, by -s \"" + it->second +
                             "\" and -s \"" + o +
                             "\" (the later would silently win); expected "
                             "each entry overridden once");
      }
  }


  void
  check_numbers_representable(const std::vector<ParameterLine> &lines,
                              const std::vector<std::string>   &overrides)
  {
    const auto refuse = [](const std::string &where,
                           const std::string &entry,
                           const std::string &number,
                           const std::string &at) {
      throw InputError(
        where,
        entry,
        at + "the number " + number +
          " is beyond what a double holds at full precision (magnitudes "
          "from 2.2e-308 to 1.8e308, or 0); expected 0 or a number in "
          "that range");
    };
    for (const auto &[line, entry] : set_entries(lines))
      if (!is_free_text(entry))
        if (const std::string n = unrepresentable_number(line->value);
            !n.empty())
          refuse(line->file, entry, n, line_position(*line, line->file) + ": ");
    for (const auto &o : overrides)
      {
        const auto [entry, value] = split_override(o);
        if (entry.empty() || is_free_text(entry))
          continue;
        const std::string n = unrepresentable_number(value);
        if (!n.empty())
          refuse("command line", entry, n, "");
      }
  }


  void
  check_trust_given_on_command_line(const std::vector<ParameterLine> &lines)
  {
    for (const auto &[line, entry] : set_entries(lines))
      if (entry == "Mesh/Trust geometry scripts" && line->value != "false" &&
          line->value != "no")
        throw InputError(
          line->file,
          entry,
          line_position(*line, line->file) +
            ": a parameter file cannot trust its own geometry script (a "
            "shared scene could run anything); expected it unset here, and "
            "-s \"Mesh/Trust geometry scripts=true\" on the command line of "
            "whoever trusts the script");
  }


  std::set<std::string>
  entries_off_default(const std::set<std::string> &given,
                      ParameterHandler            &prm,
                      ParameterHandler            &defaults)
  {
    std::set<std::string> off;
    for (const auto &entry : given)
      {
        try
          {
            if (value_of(prm, entry) != value_of(defaults, entry))
              off.insert(entry);
          }
        catch (const ExceptionBase &)
          {
            // Not an entry of this scene (ParameterHandler has refused it
            // before this is asked): given, whatever its value.
            off.insert(entry);
          }
      }
    return off;
  }


  EntrySource
  source_of(const std::string                &entry,
            const std::vector<ParameterLine> &lines,
            const std::vector<std::string>   &overrides)
  {
    for (const auto &o : overrides)
      if (split_override(o).first == entry)
        return {"command line", ""};
    EntrySource source;
    for (const auto &[line, path] : set_entries(lines))
      if (path == entry)
        source = {line->file, line_position(*line, line->file)};
    return source;
  }
} // namespace thinlayer
