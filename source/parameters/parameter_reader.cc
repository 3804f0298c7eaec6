#include <deal.II/base/utilities.h>

#include <thinlayer/base/input_error.h>
#include <thinlayer/parameters/entry_checks.h>
#include <thinlayer/parameters/parameter_checks.h>
#include <thinlayer/parameters/parameter_reader.h>
#include <thinlayer/parameters/parameter_text.h>
#include <thinlayer/parameters/parameters.h>
#include <thinlayer/parameters/scene_checks.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace thinlayer
{
  namespace
  {
    /**
     * Throw ParameterHandler's @p message about the joined lines (includes
     * expanded) as an InputError naming the file and line the text came
     * from: ParameterHandler counts the lines of the whole text, "Line <N>
     * of file <F>".
     */
    [[noreturn]] void
    throw_at_line(const std::string                &message,
                  const std::vector<ParameterLine> &lines,
                  const std::string                &file)
    {
      const std::string prefix = "Line <";
      const auto        begin  = message.find(prefix);
      const auto        close  = message.find('>', begin);
      const auto        colon  = message.find(": ", close);
      if (begin == 0 && close != std::string::npos &&
          colon != std::string::npos)
        {
          const std::string number =
            message.substr(prefix.size(), close - prefix.size());
          double n = 0;
          if (to_number(number, n) && n >= 1 && n <= lines.size())
            {
              const ParameterLine &line =
                lines[static_cast<unsigned int>(n) - 1];
              throw InputError(line.file,
                               "",
                               line_position(line, line.file) +
                                 (line.file == file
                                    ? std::string()
                                    : " (included by '" + file + "')") +
                                 ": " + message.substr(colon + 2));
            }
        }
      throw InputError(file, "", message);
    }


    /// The largest id a per-id section may have: gmsh's physical tags are
    /// ints.
    constexpr unsigned long max_section_id = 2147483647ul;

    /**
     * The id of the per-id section @p name ("Material 3") of @p kind, or
     * -1 if @p name is no such section; an InputError naming @p where if
     * it is one whose id is not a whole number in range ("Material -1").
     */
    long
    section_id(const std::string &name,
               const std::string &kind,
               const std::string &where,
               const std::string &entry)
    {
      if (name.compare(0, kind.size(), kind) != 0 ||
          (name.size() > kind.size() &&
           !std::isspace(static_cast<unsigned char>(name[kind.size()]))))
        return -1;
      // One form of each id, so that a section is found where it is
      // declared: "Material 01" would be a section no id declares, and a
      // tab (which ParameterHandler reads as a space) no form at all.
      const bool spaced = name.size() > kind.size() && name[kind.size()] == ' ';
      const std::string id = spaced ? name.substr(kind.size() + 1) : "";
      if (spaced && !id.empty() && id.size() <= 10 &&
          id.find_first_not_of("0123456789") == std::string::npos &&
          (id == "0" || id[0] != '0') && std::stoul(id) <= max_section_id)
        return static_cast<long>(std::stoul(id));
      std::string shown;
      for (const char c : name)
        shown += c == '\t' ? std::string("\\t") : std::string(1, c);
      throw InputError(where,
                       entry,
                       "expected '" + kind +
                         " <id>', one space before <id>, a whole "
                         "number from 0 to " +
                         std::to_string(max_section_id) +
                         " without leading zeros or spaces (a physical group "
                         "of the mesh), got '" +
                         shown + "'");
    }


    /**
     * The ids of the per-id sections ("Material 3") that the parameter
     * lines open, and that the overrides address ("Material 3/...").
     */
    std::set<types::global_dof_index>
    ids_of_sections(const std::vector<ParameterLine> &lines,
                    const std::string                &file,
                    const std::vector<std::string>   &overrides,
                    const std::string                &kind)
    {
      std::set<types::global_dof_index> ids;
      unsigned int                      depth = 0;
      for (const auto &line : lines)
        if (line.kind == ParameterLine::Kind::subsection)
          {
            if (depth++ == 0)
              if (const long id =
                    section_id(line.name,
                               kind,
                               file,
                               "subsection, " + line_position(line, file));
                  id >= 0)
                ids.insert(id);
          }
        else if (line.kind == ParameterLine::Kind::end && depth > 0)
          --depth;

      for (const auto &o : overrides)
        {
          const auto slash = o.find('/');
          if (slash != std::string::npos && slash < o.find('='))
            if (const long id = section_id(Utilities::trim(o.substr(0, slash)),
                                           kind,
                                           "command line",
                                           o.substr(0, o.find('=')));
                id >= 0)
              ids.insert(id);
        }
      return ids;
    }


    /**
     * The ids of the per-id sections of @p inner_kind ("Boundary 3") that
     * the parameter lines open inside each section of @p outer_kind
     * ("Phase 2"), and that the overrides address ("Phase 2/Boundary
     * 3/..."), by the outer section's id.
     */
    std::map<long, std::set<types::global_dof_index>>
    nested_section_ids(const std::vector<ParameterLine> &lines,
                       const std::string                &file,
                       const std::vector<std::string>   &overrides,
                       const std::string                &outer_kind,
                       const std::string                &inner_kind)
    {
      std::map<long, std::set<types::global_dof_index>> ids;
      unsigned int                                      depth = 0;
      long                                              outer = -1;
      for (const auto &line : lines)
        if (line.kind == ParameterLine::Kind::subsection)
          {
            const std::string where =
              "subsection, " + line_position(line, file);
            if (depth == 0)
              {
                outer = section_id(line.name, outer_kind, file, where);
                if (outer >= 0)
                  ids[outer];
              }
            else if (depth == 1 && outer >= 0)
              if (const long id =
                    section_id(line.name, inner_kind, file, where);
                  id >= 0)
                ids[outer].insert(id);
            ++depth;
          }
        else if (line.kind == ParameterLine::Kind::end && depth > 0)
          --depth;

      for (const auto &o : overrides)
        {
          const std::string path  = o.substr(0, o.find('='));
          const auto        parts = Utilities::split_string_list(path, '/');
          if (parts.size() < 2)
            continue;
          const long n = section_id(parts[0], outer_kind, "command line", path);
          if (n < 0)
            continue;
          ids[n];
          if (parts.size() > 2)
            if (const long id =
                  section_id(parts[1], inner_kind, "command line", path);
                id >= 0)
              ids[n].insert(id);
        }
      return ids;
    }


    /// Sections renamed, by their former name: a file that uses one still
    /// runs for one release, with a warning.
    const std::map<std::string, std::string> former_section_names = {
      {"Interfaces", "Layers"}};

    /// Per-id sections renamed, by the former name of their kind: "Interface
    /// curve 3" is now "Interface 3" (it names a surface in 3d).
    const std::map<std::string, std::string> former_section_kinds = {
      {"Interface curve", "Interface"}};

    /// Entries renamed, by their section and former name.
    const std::map<std::pair<std::string, std::string>, std::string>
      former_entry_names = {
        {{"Strength reduction", "Interface curves"}, "Interfaces"}};


    /**
     * The name @p name of a top-level section has now, and whether it is a
     * former one.
     */
    std::pair<std::string, bool>
    current_section_name(const std::string &name)
    {
      if (const auto renamed = former_section_names.find(name);
          renamed != former_section_names.end())
        return {renamed->second, true};
      // Only a former name with its id ("Interface curve 3") is renamed:
      // any other text is reported as written.
      for (const auto &[former, kind] : former_section_kinds)
        if (name.size() > former.size() + 1 &&
            name.compare(0, former.size() + 1, former + " ") == 0 &&
            name.find_first_not_of("0123456789", former.size() + 1) ==
              std::string::npos)
          return {kind + name.substr(former.size()), true};
      return {name, false};
    }


    /**
     * The former names of sections and entries in @p lines and
     * @p overrides replaced by their names; returns a warning for each.
     */
    std::vector<std::string>
    rename_former_sections(std::vector<ParameterLine> &lines,
                           std::vector<std::string>   &overrides,
                           const std::string          &file)
    {
      std::vector<std::string> warnings;
      const auto               warn = [&](const std::string &where,
                            const std::string &what,
                            const std::string &former,
                            const std::string &name) {
        warnings.push_back(where + ": " + what + " '" + former +
                           "' is now called '" + name +
                           "'; the former name is accepted until the next "
                                         "release");
      };
      std::vector<std::string> open;
      for (ParameterLine &line : lines)
        if (line.kind == ParameterLine::Kind::subsection)
          {
            if (open.empty())
              if (const auto [name, renamed] = current_section_name(line.name);
                  renamed)
                {
                  warn("'" + file + "', " + line_position(line, file),
                       "section",
                       line.name,
                       name);
                  line.text = "subsection " + name;
                  line.name = name;
                }
            open.push_back(line.name);
          }
        else if (line.kind == ParameterLine::Kind::end && !open.empty())
          open.pop_back();
        else if (line.kind == ParameterLine::Kind::set && open.size() == 1)
          if (const auto renamed =
                former_entry_names.find({open.back(), line.name});
              renamed != former_entry_names.end())
            {
              warn("'" + file + "', " + line_position(line, file),
                   "entry",
                   open.back() + "/" + line.name,
                   open.back() + "/" + renamed->second);
              line.text = "set " + renamed->second + " = " + line.value;
              line.name = renamed->second;
            }
      for (std::string &o : overrides)
        {
          const auto slash = o.find('/');
          if (slash == std::string::npos || slash > o.find('='))
            continue;
          const std::string section = Utilities::trim(o.substr(0, slash));
          if (const auto [name, renamed] = current_section_name(section);
              renamed)
            {
              warn("command line '" + o + "'", "section", section, name);
              o = name + o.substr(slash);
            }
          const auto equal = o.find('=');
          if (equal == std::string::npos)
            continue; // apply_override() refuses it
          const auto        slash_now = o.find('/');
          const std::string owner     = Utilities::trim(o.substr(0, slash_now));
          const std::string entry =
            Utilities::trim(o.substr(slash_now + 1, equal - slash_now - 1));
          if (const auto renamed = former_entry_names.find({owner, entry});
              renamed != former_entry_names.end())
            {
              warn("command line '" + o + "'",
                   "entry",
                   owner + "/" + entry,
                   owner + "/" + renamed->second);
              o =
                o.substr(0, slash_now + 1) + renamed->second + o.substr(equal);
            }
        }
      return warnings;
    }


    void
    apply_override(ParameterHandler &prm, const std::string &override_text)
    {
      const auto equal = override_text.find('=');
      if (equal == std::string::npos)
        throw InputError("command line",
                         override_text,
                         "expected -s \"Section/Entry=value\"");
      const std::string path = Utilities::trim(override_text.substr(0, equal));
      const std::string value =
        Utilities::trim(override_text.substr(equal + 1));
      const auto parts = Utilities::split_string_list(path, '/');
      if (parts.size() < 2)
        throw InputError("command line",
                         path,
                         "expected a path 'Section/Entry'");
      for (unsigned int i = 0; i + 1 < parts.size(); ++i)
        prm.enter_subsection(parts[i]);
      try
        {
          prm.set(parts.back(), value);
        }
      catch (const ExceptionBase &e)
        {
          for (unsigned int i = 0; i + 1 < parts.size(); ++i)
            prm.leave_subsection();
          throw InputError("command line", path, message_of(e));
        }
      for (unsigned int i = 0; i + 1 < parts.size(); ++i)
        prm.leave_subsection();
    }


    /// The sections every file has, in the order --print-parameters shows
    /// them, and the per-id sections the file opens.
    void
    declare_sections(
      ParameterHandler                                        &prm,
      const std::set<types::global_dof_index>                 &material_ids,
      const std::set<types::global_dof_index>                 &boundary_ids,
      const std::set<types::global_dof_index>                 &curve_ids,
      const std::map<long, std::set<types::global_dof_index>> &phases)
    {
      MeshParameters::declare(prm);
      KinematicsParameters::declare(prm);
      DiscretisationParameters::declare(prm);
      LayerParameters::declare(prm);
      InitialStateParameters::declare(prm);
      LoadingParameters::declare(prm);
      StrengthReductionParameters::declare(prm);
      SolverParameters::declare(prm);
      MonitorParameters::declare(prm);
      ReferenceParameters::declare(prm);
      SweepParameters::declare(prm);
      AdaptivityParameters::declare(prm);
      OutputParameters::declare(prm);
      for (const auto id : material_ids)
        MaterialParameters::declare(prm, id);
      for (const auto id : boundary_ids)
        BoundaryParameters::declare(prm, id);
      for (const auto id : curve_ids)
        InterfaceElementParameters::declare(prm, id);
      for (const auto &[n, ids] : phases)
        LoadingPhaseParameters::declare(prm, n, ids);
    }


    /// Every section, in an order in which each finds the sections it
    /// depends on already read.
    Parameters
    parse_sections(
      ParameterHandler                                        &prm,
      const std::string                                       &file,
      const std::set<types::global_dof_index>                 &material_ids,
      const std::set<types::global_dof_index>                 &boundary_ids,
      const std::set<types::global_dof_index>                 &curve_ids,
      const std::map<long, std::set<types::global_dof_index>> &phases)
    {
      Parameters p;
      p.parameter_file = file;
      p.mesh.parse(prm, file);
      p.kinematics.parse(prm, file);
      p.discretisation.parse(prm, file, p.kinematics);
      if (material_ids.empty())
        throw InputError(file,
                         "Material <id>",
                         "expected at least one 'subsection Material <id>' "
                         "for the physical surfaces of the mesh");
      std::set<types::material_id> materials;
      for (const auto id : material_ids)
        {
          p.materials[id].parse(prm, file, id);
          materials.insert(id);
        }
      p.layers.parse(prm, file, materials);
      for (const auto id : boundary_ids)
        p.boundaries[id].parse(prm, file, id, p.kinematics, p.mesh);
      for (const auto id : curve_ids)
        {
          if (boundary_ids.count(id) != 0)
            throw InputError(file,
                             InterfaceElementParameters::section(id),
                             "a physical curve either of boundary conditions "
                             "or of interface elements; 'Boundary " +
                               std::to_string(id) + "' names it too");
          p.interface_elements[id].parse(prm, file, id);
        }
      p.initial_state.parse(prm, file);
      check_initial_state(p);
      p.loading.parse(prm, file);
      // Phase 2, 3, ... without gaps: Loading is phase 1.
      long expected = 2;
      for (const auto &[n, ids] : phases)
        {
          if (n != expected)
            throw InputError(file,
                             LoadingPhaseParameters::section(n),
                             "expected the phases numbered 2, 3, ... without "
                             "a gap (the Loading section is phase 1), but " +
                               (n < 2 ? std::string("got 'Phase ") +
                                          std::to_string(n) + "'"
                                      : "there is no 'Phase " +
                                          std::to_string(expected) + "'"));
          p.loading_phases.emplace_back();
          p.loading_phases.back().parse(
            prm, file, n, ids, p.boundaries, p.loading, p.kinematics, p.mesh);
          ++expected;
        }
      {
        std::map<types::material_id, bool> can_yield;
        for (const auto &[id, material] : p.materials)
          can_yield[id] = material.yield_criterion != YieldCriterion::elastic;
        std::map<types::boundary_id, bool> can_slip;
        for (const auto &[id, curve] : p.interface_elements)
          can_slip[id] =
            curve.criterion != InterfaceElementParameters::Criterion::elastic;
        p.strength_reduction.parse(prm, file, can_yield, can_slip);
      }
      p.solver.parse(prm, file);
      // With automatic stepping the load stepping halves a failed step and
      // records each attempt; cut-backs inside Newton would repeat that
      // work unrecorded (up to 5 x 25 factorisations per failed attempt).
      if (p.loading.collapse_resolution > 0)
        p.solver.max_cut_backs = 0;
      using Method = SolverParameters::Method;
      if (p.loading.control == LoadingParameters::Control::work &&
          p.solver.method != Method::newton &&
          p.solver.method != Method::accelerated_with_newton_fallback)
        throw InputError(
          file,
          "Loading/Control",
          "'work' finds the load factor with Newton's "
          "tangent; expected Solver/Method = newton or the "
          "default (accelerated with newton fallback), got '" +
            SolverParameters::method_names.name(p.solver.method) + "'");
      if (p.loading.control == LoadingParameters::Control::work &&
          p.strength_reduction.active())
        throw InputError(file,
                         "Loading/Control",
                         "expected 'load' with a strength reduction (its "
                         "phase raises a factor, not a load)");
      p.monitors.parse(prm, file, p.kinematics);
      check_monitors_and_phases(p);
      p.reference.parse(prm, file, p.mesh);
      p.sweep.parse(prm, file);
      p.adaptivity.parse(prm, file);
      check_adaptivity(p);
      p.output.parse(prm, file);
      if (p.output.view_slices > 0 && !p.kinematics.fourier)
        throw InputError(file,
                         "Output/3D view slices",
                         "a revolved view needs Fourier kinematics; expected "
                         "0 in plane strain");
      return p;
    }
  } // namespace


  Parameters
  ParameterReader::read(const std::string              &file,
                        const std::vector<std::string> &overrides,
                        std::ostream                   *documented) const
  {
    return read_from_string(read_parameter_file(file),
                            file,
                            overrides,
                            documented);
  }


  Parameters
  ParameterReader::read_from_string(
    const std::string              &text,
    const std::string              &file,
    const std::vector<std::string> &given_overrides,
    std::ostream                   *documented) const
  {
    std::vector<ParameterLine>     lines     = parameter_lines(text, file);
    std::vector<std::string>       overrides = given_overrides;
    const std::vector<std::string> warnings =
      rename_former_sections(lines, overrides, file);
    check_nothing_given_twice(lines, file, overrides);
    check_numbers_representable(lines, overrides);
    check_trust_given_on_command_line(lines);
    const auto material_ids =
      ids_of_sections(lines, file, overrides, "Material");
    const auto boundary_ids =
      ids_of_sections(lines, file, overrides, "Boundary");
    const auto curve_ids = ids_of_sections(lines, file, overrides, "Interface");
    const auto phases =
      nested_section_ids(lines, file, overrides, "Phase", "Boundary");

    ParameterHandler prm;
    declare_sections(prm, material_ids, boundary_ids, curve_ids, phases);
    try
      {
        std::istringstream in(joined_text(lines));
        prm.parse_input(in, file);
      }
    catch (const ExceptionBase &e)
      {
        throw_at_line(message_of(e), lines, file);
      }
    for (const auto &o : overrides)
      apply_override(prm, o);

    Parameters parameters;
    try
      {
        parameters = parse_sections(
          prm, file, material_ids, boundary_ids, curve_ids, phases);
        ParameterHandler defaults;
        declare_sections(
          defaults, material_ids, boundary_ids, curve_ids, phases);
        const std::set<std::string> written = given_entries(lines, overrides);
        check_entries_mean_something(
          parameters, entries_off_default(written, prm, defaults), written);
      }
    catch (const InputError &e)
      {
        // The message names where the entry was set: the line of this
        // file or of a file it includes, or the command line.
        const EntrySource source = source_of(e.entry, lines, overrides);
        if (e.file != file || source.file.empty())
          throw;
        throw InputError(source.file,
                         e.entry,
                         e.expected + (source.line.empty()
                                         ? std::string()
                                         : " (" + source.line + ")"));
      }
    // Q8 stands for Q20 in 3D; the record names the element itself, so
    // that it runs again as given.
    if (parameters.kinematics.dimension == 3 &&
        parameters.discretisation.element_name == "Q8")
      {
        prm.enter_subsection("Discretisation");
        prm.set("Element", "Q20");
        prm.leave_subsection();
      }
    // The record names the mesh by its absolute path, so that it can be
    // run again from anywhere; it trusts no script (only a command line
    // can).
    prm.enter_subsection("Mesh");
    prm.set("Trust geometry scripts", false);
    prm.set("File",
            std::filesystem::absolute(parameters.mesh.file)
              .lexically_normal()
              .string());
    prm.leave_subsection();
    std::ostringstream effective;
    effective << "# The parameters of this run: " << file;
    for (const auto &o : overrides)
      effective << " -s \"" << o << '"';
    effective << '\n';
    if (documented != nullptr)
      {
        *documented << effective.str();
        prm.print_parameters(*documented, ParameterHandler::PRM);
      }
    prm.print_parameters(effective, ParameterHandler::ShortPRM);
    parameters.effective_parameters = effective.str();
    parameters.warnings             = warnings;
    return parameters;
  }


  void
  ParameterReader::print_parameters(std::ostream &out) const
  {
    ParameterHandler prm;
    declare_sections(prm, {1}, {1}, {1}, {{2, {1}}});
    out
      << "# thinlayer parameters. 'Material <id>' and 'Boundary <id>' may be\n"
      << "# repeated for every physical surface and curve id of the mesh,\n"
      << "# 'Interface <id>' for every physical curve (a physical "
         "surface\n"
      << "# in 3d) of zero-thickness interface elements, 'Phase <n>' for\n"
      << "# every further loading phase (n = 2, 3, ...), with a 'Boundary "
         "<id>'\n"
      << "# for every boundary it loads.\n";
    prm.print_parameters(out, ParameterHandler::PRM);
  }
} // namespace thinlayer
