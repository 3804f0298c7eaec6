#ifndef thinlayer_base_name_table_h
#define thinlayer_base_name_table_h

#include <deal.II/base/exceptions.h>

#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace thinlayer
{
  /**
   * The names of the values of an enumeration as they appear in parameter
   * files and in results. One table per enumeration feeds the
   * Patterns::Selection of its entry, the parsing of that entry and the
   * name written to summary.json, so that the three can never disagree: a
   * new value is one line in its table.
   */
  template <typename Enum>
  class NameTable
  {
  public:
    NameTable(std::initializer_list<std::pair<Enum, const char *>> entries)
      : entries(entries.begin(), entries.end())
    {}

    /// "a|b|c", for Patterns::Selection.
    std::string
    pattern() const
    {
      std::string text;
      for (const auto &[value, name] : entries)
        text += (text.empty() ? "" : "|") + std::string(name);
      return text;
    }

    /// The value named @p name; the entry's pattern has already checked it.
    Enum
    value(const std::string &name) const
    {
      for (const auto &[value, entry_name] : entries)
        if (name == entry_name)
          return value;
      AssertThrow(false,
                  dealii::ExcMessage("'" + name + "' is not one of " +
                                     pattern()));
      return entries.front().first;
    }

    /// The name of @p value.
    std::string
    name(const Enum value) const
    {
      for (const auto &[entry_value, name] : entries)
        if (entry_value == value)
          return name;
      AssertThrow(false, dealii::ExcInternalError());
      return "";
    }

  private:
    std::vector<std::pair<Enum, const char *>> entries;
  };
} // namespace thinlayer

#endif
