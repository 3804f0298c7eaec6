#include <deal.II/base/utilities.h>

#include <thinlayer/base/input_error.h>
#include <thinlayer/parameters/parameter_checks.h>
#include <thinlayer/parameters/parameter_reader.h>
#include <thinlayer/parameters/parameter_text.h>
#include <thinlayer/parameters/parameters.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace thinlayer
{
  namespace
  {
    /// Where @p line is, for messages: "line 7", or "line 7 of FILE" for a
    /// line of an included file.
    std::string
    position(const ParameterLine &line, const std::string &file)
    {
      return "line " + std::to_string(line.line) +
             (line.file == file ? std::string() : " of '" + line.file + "'");
    }


    /// What Initial state/Procedure needs of the rest of the scene.
    void
    check_initial_state(const Parameters &p)
    {
      using Procedure           = InitialStateParameters::Procedure;
      const Procedure procedure = p.initial_state.procedure;
      if (procedure == Procedure::none)
        return;
      const std::string name =
        InitialStateParameters::procedure_names.name(procedure);
      const std::string entry  = "Initial state/Procedure";
      bool              weight = p.initial_state.surcharge > 0;
      for (const auto &[id, material] : p.materials)
        weight = weight || material.unit_weight > 0;
      if (!weight)
        throw InputError(p.parameter_file,
                         entry,
                         "expected a Material <id>/Unit weight > 0 or an "
                         "Initial state/Surcharge > 0 for the " +
                           name +
                           ": without them the initial state is "
                           "free of stress");
      if (procedure != Procedure::k0)
        return;
      if (p.kinematics.dimension == 3)
        throw InputError(p.parameter_file,
                         entry,
                         "the K0 procedure is built for 2D meshes (plane "
                         "strain, Fourier); expected 'gravity loading' in "
                         "3D");
      if (p.kinematics.fourier &&
          (p.kinematics.antisymmetric ||
           std::find(p.kinematics.harmonics.begin(),
                     p.kinematics.harmonics.end(),
                     0u) == p.kinematics.harmonics.end()))
        throw InputError(p.parameter_file,
                         entry,
                         "the K0 stresses are the same at every angle: "
                         "expected Kinematics/Harmonics to include 0 "
                         "(symmetric)");
    }


    /**
     * A section opened twice, or an entry set twice in one section:
     * ParameterHandler lets the later win, silently.
     */
    void
    check_nothing_given_twice(const std::vector<ParameterLine> &lines,
                              const std::string                &file)
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
                             "given twice, at " + position(it->second, file) +
                               " and " + position(line, file) +
                               " (the later would silently win); expected "
                               "each " +
                               (key == "entry " ? "entry" : "subsection") +
                               " once");
        }
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
          (name.size() > kind.size() && name[kind.size()] != ' '))
        return -1;
      const std::string id = Utilities::trim(name.substr(kind.size()));
      if (!id.empty() && id.size() <= 10 &&
          id.find_first_not_of("0123456789") == std::string::npos &&
          std::stoul(id) <= max_section_id)
        return static_cast<long>(std::stoul(id));
      throw InputError(where,
                       entry,
                       "expected '" + kind +
                         " <id>' with <id> a whole "
                         "number from 0 to " +
                         std::to_string(max_section_id) +
                         " (a physical group of the mesh), got '" + name + "'");
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
                               "subsection, " + position(line, file));
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
            const std::string where = "subsection, " + position(line, file);
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


    /**
     * Entries the user gave that mean nothing in this scene: accepted
     * silently, they would let a user believe they had an effect.
     */
    void
    check_entries_mean_something(const Parameters            &p,
                                 const std::set<std::string> &given)
    {
      const auto refuse_if_given = [&](const std::string &entry,
                                       const std::string &why) {
        if (given.count(entry) != 0)
          throw InputError(p.parameter_file,
                           entry,
                           "means nothing " + why + "; expected it unset");
      };
      if (!p.kinematics.fourier)
        for (const char *entry : {"Kinematics/Harmonics",
                                  "Kinematics/Series",
                                  "Kinematics/Stations",
                                  "Kinematics/Axis boundary id",
                                  "Monitors/Displacement angle"})
          refuse_if_given(entry,
                          "in plane strain or 3d (it is for "
                          "Kinematics/Type = fourier)");
      // Q8 is the default in 3D too, where it stands for Q20: written out,
      // it is a mistake.
      if (p.kinematics.dimension == 3 &&
          p.discretisation.element_name == "Q8" &&
          given.count("Discretisation/Element") != 0)
        throw InputError(p.parameter_file,
                         "Discretisation/Element",
                         "Q8 is a quadrilateral; expected Q20 or Q27 in 3d");
      using Measure = MonitorParameters::DisplacementMeasure;
      if (p.monitors.displacement_measure == Measure::boundary_average)
        refuse_if_given("Monitors/Displacement point",
                        "with Displacement measure = boundary average "
                        "(it is for the point measure)");
      else
        refuse_if_given("Monitors/Displacement boundary id",
                        "with Displacement measure = point (it is for the "
                        "boundary average)");
      using Load = MonitorParameters::LoadMeasure;
      if (p.monitors.load_measure != Load::reaction)
        for (const char *entry :
             {"Monitors/Load boundary id", "Monitors/Load component"})
          refuse_if_given(entry,
                          "unless Load measure = reaction (it is for the "
                          "reactions' resultant)");
      if (p.monitors.load_measure != Load::stress_average)
        for (const char *entry :
             {"Monitors/Load material id", "Monitors/Load stress component"})
          refuse_if_given(entry,
                          "unless Load measure = stress average (it is for "
                          "the averaged stress)");
    }


    /// Sections renamed, by their former name: a file that uses one still
    /// runs for one release, with a warning.
    const std::map<std::string, std::string> former_section_names = {
      {"Interfaces", "Layers"}};


    /**
     * The former names of sections in @p lines and @p overrides replaced by
     * their names; returns a warning for each.
     */
    std::vector<std::string>
    rename_former_sections(std::vector<ParameterLine> &lines,
                           std::vector<std::string>   &overrides,
                           const std::string          &file)
    {
      std::vector<std::string> warnings;
      const auto               warn = [&](const std::string &where,
                            const std::string &former,
                            const std::string &name) {
        warnings.push_back(where + ": section '" + former +
                           "' is now called '" + name +
                           "'; the former name is accepted until the next "
                                         "release");
      };
      unsigned int depth = 0;
      for (ParameterLine &line : lines)
        if (line.kind == ParameterLine::Kind::subsection)
          {
            const auto renamed = former_section_names.find(line.name);
            if (depth == 0 && renamed != former_section_names.end())
              {
                warn("'" + file + "', " + position(line, file),
                     line.name,
                     renamed->second);
                line.text = "subsection " + renamed->second;
                line.name = renamed->second;
              }
            ++depth;
          }
        else if (line.kind == ParameterLine::Kind::end && depth > 0)
          --depth;
      for (std::string &o : overrides)
        for (const auto &[former, name] : former_section_names)
          if (o.rfind(former + "/", 0) == 0)
            {
              warn("command line '" + o + "'", former, name);
              o = name + o.substr(former.size());
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
      p.monitors.parse(prm, file, p.kinematics);
      p.reference.parse(prm, file, p.mesh);
      p.sweep.parse(prm, file);
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
                        const std::vector<std::string> &overrides) const
  {
    return read_from_string(read_parameter_file(file), file, overrides);
  }


  Parameters
  ParameterReader::read_from_string(
    const std::string              &text,
    const std::string              &file,
    const std::vector<std::string> &given_overrides) const
  {
    std::vector<ParameterLine>     lines     = parameter_lines(text, file);
    std::vector<std::string>       overrides = given_overrides;
    const std::vector<std::string> warnings =
      rename_former_sections(lines, overrides, file);
    check_nothing_given_twice(lines, file);
    const auto material_ids =
      ids_of_sections(lines, file, overrides, "Material");
    const auto boundary_ids =
      ids_of_sections(lines, file, overrides, "Boundary");
    const auto curve_ids =
      ids_of_sections(lines, file, overrides, "Interface curve");
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
        throw InputError(file, "", message_of(e));
      }
    for (const auto &o : overrides)
      apply_override(prm, o);

    Parameters parameters =
      parse_sections(prm, file, material_ids, boundary_ids, curve_ids, phases);
    check_entries_mean_something(parameters, given_entries(lines, overrides));
    // The record names the mesh by its absolute path, so that it can be
    // run again from anywhere.
    prm.enter_subsection("Mesh");
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
      << "# 'Interface curve <id>' for every physical curve (a physical "
         "surface\n"
      << "# in 3d) of zero-thickness interface elements, 'Phase <n>' for\n"
      << "# every further loading phase (n = 2, 3, ...), with a 'Boundary "
         "<id>'\n"
      << "# for every boundary it loads.\n";
    prm.print_parameters(out, ParameterHandler::PRM);
  }
} // namespace thinlayer
