#include <deal.II/base/utilities.h>

#include <thinlayer/input_error.h>
#include <thinlayer/parameter_checks.h>
#include <thinlayer/parameters.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

namespace thinlayer
{
  namespace
  {
    /**
     * A section opened twice, or an entry set twice in one section:
     * ParameterHandler lets the later win, silently. Line numbers are the
     * file's.
     */
    void
    check_nothing_given_twice(const std::string &text, const std::string &file)
    {
      const std::regex         opens("^\\s*subsection\\s+(.*?)\\s*(#.*)?$");
      const std::regex         closes("^\\s*end\\s*(#.*)?$");
      const std::regex         sets("^\\s*set\\s+([^=]*?)\\s*=.*$");
      std::vector<std::string> path;
      std::map<std::string, unsigned int> first_line;
      std::istringstream                  lines(text);
      std::string                         line;
      std::smatch                         match;
      for (unsigned int number = 1; std::getline(lines, line); ++number)
        {
          std::string key;
          if (std::regex_match(line, match, opens))
            {
              path.push_back(match[1]);
              key = "subsection ";
            }
          else if (std::regex_match(line, match, closes))
            {
              if (!path.empty())
                path.pop_back();
              continue;
            }
          else if (std::regex_match(line, match, sets))
            key = "entry ";
          else
            continue;
          std::string name;
          for (unsigned int i = 0; i + (key == "entry " ? 0 : 1) < path.size();
               ++i)
            name += path[i] + "/";
          name += key == "entry " ? std::string(match[1]) : path.back();
          const auto [it, inserted] = first_line.emplace(key + name, number);
          if (!inserted)
            throw InputError(file,
                             name,
                             "given twice, at lines " +
                               std::to_string(it->second) + " and " +
                               std::to_string(number) +
                               " (the later would silently win); expected "
                               "each " +
                               (key == "entry " ? "entry" : "subsection") +
                               " once");
        }
    }


    /**
     * The names of per-id sections ("Material 3") that the parameter text
     * opens, and that the overrides address ("Material 3/...").
     */
    std::set<types::global_dof_index>
    ids_of_sections(const std::string              &text,
                    const std::vector<std::string> &overrides,
                    const std::string              &kind)
    {
      std::set<types::global_dof_index> ids;
      const std::regex                  in_file("^\\s*subsection\\s+" + kind +
                               "\\s+([0-9]+)\\s*(#.*)?$");
      std::istringstream                lines(text);
      std::string                       line;
      std::smatch                       match;
      while (std::getline(lines, line))
        if (std::regex_match(line, match, in_file))
          ids.insert(std::stoul(match[1]));

      const std::regex in_override("^\\s*" + kind + "\\s+([0-9]+)\\s*/.*");
      for (const auto &o : overrides)
        if (std::regex_match(o, match, in_override))
          ids.insert(std::stoul(match[1]));
      return ids;
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
    declare_sections(ParameterHandler                        &prm,
                     const std::set<types::global_dof_index> &material_ids,
                     const std::set<types::global_dof_index> &boundary_ids,
                     const std::set<types::global_dof_index> &curve_ids)
    {
      MeshParameters::declare(prm);
      KinematicsParameters::declare(prm);
      DiscretisationParameters::declare(prm);
      InterfaceParameters::declare(prm);
      LoadingParameters::declare(prm);
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
        InterfaceCurveParameters::declare(prm, id);
    }


    /// Every section, in an order in which each finds the sections it
    /// depends on already read.
    Parameters
    parse_sections(ParameterHandler                        &prm,
                   const std::string                       &file,
                   const std::set<types::global_dof_index> &material_ids,
                   const std::set<types::global_dof_index> &boundary_ids,
                   const std::set<types::global_dof_index> &curve_ids)
    {
      Parameters p;
      p.parameter_file = file;
      p.mesh.parse(prm, file);
      p.kinematics.parse(prm, file);
      p.discretisation.parse(prm);
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
      p.interfaces.parse(prm, file, materials);
      for (const auto id : boundary_ids)
        p.boundaries[id].parse(prm, file, id, p.kinematics, p.mesh);
      for (const auto id : curve_ids)
        {
          if (boundary_ids.count(id) != 0)
            throw InputError(file,
                             InterfaceCurveParameters::section(id),
                             "a physical curve either of boundary conditions "
                             "or of interface elements; 'Boundary " +
                               std::to_string(id) + "' names it too");
          p.interface_curves[id].parse(prm, file, id);
        }
      p.loading.parse(prm, file);
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
    if (std::filesystem::is_directory(file))
      throw InputError(file, "", "is a directory; expected a parameter file");
    std::ifstream in(file);
    if (!in)
      throw InputError(file, "", "cannot open the parameter file");
    std::stringstream text;
    text << in.rdbuf();
    return read_from_string(text.str(), file, overrides);
  }


  Parameters
  ParameterReader::read_from_string(
    const std::string              &text,
    const std::string              &file,
    const std::vector<std::string> &overrides) const
  {
    check_nothing_given_twice(text, file);
    const auto material_ids = ids_of_sections(text, overrides, "Material");
    const auto boundary_ids = ids_of_sections(text, overrides, "Boundary");
    const auto curve_ids = ids_of_sections(text, overrides, "Interface curve");

    ParameterHandler prm;
    declare_sections(prm, material_ids, boundary_ids, curve_ids);
    try
      {
        std::istringstream in(text);
        prm.parse_input(in, file);
      }
    catch (const ExceptionBase &e)
      {
        throw InputError(file, "", message_of(e));
      }
    for (const auto &o : overrides)
      apply_override(prm, o);

    Parameters parameters =
      parse_sections(prm, file, material_ids, boundary_ids, curve_ids);
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
    return parameters;
  }


  void
  ParameterReader::print_parameters(std::ostream &out) const
  {
    ParameterHandler prm;
    declare_sections(prm, {1}, {1}, {1});
    out
      << "# thinlayer parameters. 'Material <id>' and 'Boundary <id>' may be\n"
      << "# repeated for every physical surface and curve id of the mesh,\n"
      << "# 'Interface curve <id>' for every physical curve of zero-thickness\n"
      << "# interface elements.\n";
    prm.print_parameters(out, ParameterHandler::PRM);
  }
} // namespace thinlayer
