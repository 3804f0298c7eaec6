#include <deal.II/base/function_parser.h>
#include <deal.II/base/utilities.h>

#include <thinlayer/input_error.h>
#include <thinlayer/parameters.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <regex>
#include <set>
#include <sstream>

namespace thinlayer
{
  namespace
  {
    /**
     * The message part of a deal.II exception, without the source location
     * that means nothing to a user.
     */
    std::string
    message_of(const ExceptionBase &exception)
    {
      std::ostringstream out;
      exception.print_info(out);
      // deal.II lays its messages out over indented lines; one line reads
      // better after our "error in 'file', entry '...':" prefix.
      std::string text;
      for (const char c : out.str())
        if (!std::isspace(static_cast<unsigned char>(c)))
          text += c;
        else if (!text.empty() && text.back() != ' ')
          text += ' ';
      while (!text.empty() && text.back() == ' ')
        text.pop_back();
      return text;
    }

    /**
     * Silences std::cerr while alive: muparser's diagnostics go there, and
     * we report the error ourselves, once, naming the entry.
     */
    class SilencedErrorStream
    {
    public:
      SilencedErrorStream()
        : saved(std::cerr.rdbuf(sink.rdbuf()))
      {}
      ~SilencedErrorStream()
      {
        std::cerr.rdbuf(saved);
      }

    private:
      std::ostringstream sink;
      std::streambuf    *saved;
    };

    std::string
    directory_of(const std::string &file)
    {
      const auto slash = file.find_last_of('/');
      return slash == std::string::npos ? std::string(".")
                                        : file.substr(0, slash);
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
    declare_material(ParameterHandler &prm, const unsigned int id)
    {
      prm.enter_subsection("Material " + std::to_string(id));
      prm.declare_entry("Name",
                        "",
                        Patterns::Anything(),
                        "A name for this material id (the gmsh physical "
                        "surface with the same number), used in output.");
      prm.declare_entry("Young's modulus",
                        "1e5",
                        Patterns::Double(),
                        "Young's modulus E (> 0).");
      prm.declare_entry("Poisson's ratio",
                        "0.3",
                        Patterns::Double(),
                        "Poisson's ratio nu, in (-1, 0.5).");
      prm.declare_entry("Yield criterion",
                        "elastic",
                        Patterns::Selection(
                          "elastic|tresca|von mises|mohr-coulomb"),
                        "elastic: never yields; tresca: (sigma_1 - sigma_3)/2 "
                        "= c; von mises: sqrt(3 J2) = sqrt(3) c (matched to "
                        "Tresca in plane strain); mohr-coulomb: c, friction "
                        "and dilation angles. Perfectly plastic.");
      prm.declare_entry("Cohesion",
                        "0",
                        Patterns::Double(0),
                        "Shear strength c: the adhesion C_w of an interface, "
                        "the undrained strength c_u of a Tresca soil.");
      prm.declare_entry("Friction angle",
                        "0",
                        Patterns::Double(0, 89),
                        "Mohr-Coulomb friction angle phi in degrees.");
      prm.declare_entry("Dilation angle",
                        "0",
                        Patterns::Double(0, 89),
                        "Mohr-Coulomb dilation angle psi in degrees, at most "
                        "phi (psi = phi is associated flow).");
      prm.leave_subsection();
    }

    void
    declare_boundary(ParameterHandler &prm, const unsigned int id)
    {
      prm.enter_subsection("Boundary " + std::to_string(id));
      prm.declare_entry("Name",
                        "",
                        Patterns::Anything(),
                        "A name for this boundary id (the gmsh physical curve "
                        "with the same number), used in output.");
      prm.declare_entry("Constrained components",
                        "",
                        Patterns::Anything(),
                        "Comma-separated components whose displacement is "
                        "prescribed here: any of x, y in plane strain; of r, "
                        "z, theta for Fourier kinematics (every harmonic); "
                        "empty for none.");
      prm.declare_entry(
        "Displacement",
        "0",
        Patterns::Anything(),
        "Prescribed displacement per unit load factor of the constrained "
        "components: one function expression of x, y (and the geometry "
        "parameters) per component, separated by ';', or one expression "
        "for all components. For Fourier kinematics: the Cartesian "
        "components x; y; z (z along the axis) as expressions of r, z, "
        "theta, decomposed into the harmonics. Where boundary ids share a "
        "node, the lowest "
        "id's value wins.");
      prm.declare_entry("Traction",
                        "0",
                        Patterns::Anything(),
                        "Cartesian traction per unit load factor: expressions "
                        "as for the displacement (for Fourier kinematics "
                        "decomposed into the harmonics; a uniform horizontal "
                        "traction on a disc loads harmonic 1 only).");
      prm.declare_entry("Pressure",
                        "0",
                        Patterns::Anything(),
                        "Normal pressure per unit load factor, positive into "
                        "the body: one expression of x, y (r, z, theta for "
                        "Fourier kinematics).");
      prm.leave_subsection();
    }

    void
    declare_fixed_sections(ParameterHandler &prm)
    {
      prm.enter_subsection("Mesh");
      prm.declare_entry("File",
                        "",
                        Patterns::Anything(),
                        "A gmsh geometry (.geo, meshed with gmsh) or mesh "
                        "(.msh), relative to this parameter file. Physical "
                        "surfaces become material ids, physical curves "
                        "boundary ids; cells must be quadrilaterals.");
      prm.declare_entry(
        "Geometry parameters",
        "",
        Patterns::Anything(),
        "Values for the DefineConstant[] parameters of the .geo file, as "
        "'name=value, name=value'. They are also constants in every "
        "expression of this file.");
      prm.leave_subsection();

      prm.enter_subsection("Kinematics");
      prm.declare_entry("Type",
                        "plane strain",
                        Patterns::Selection("plane strain|fourier"),
                        "plane strain: the mesh is a cross-section, "
                        "components x, y. fourier: the mesh is the r-z plane "
                        "of an axisymmetric body (x = r >= 0, y = z the "
                        "axis) and the load need not be axisymmetric: the "
                        "displacement is a sum of Fourier harmonics, "
                        "components r, z, theta.");
      prm.declare_entry("Harmonics",
                        "1",
                        Patterns::List(Patterns::Integer(0), 1),
                        "Fourier: the harmonics n in the series (a lateral "
                        "load on a disc is n = 1; 1, 3 as in the paper).");
      prm.declare_entry("Series",
                        "symmetric",
                        Patterns::Selection("symmetric|antisymmetric"),
                        "Fourier: symmetric about theta = 0 (u_r, u_z with "
                        "cos n theta, u_theta with sin n theta), or "
                        "antisymmetric (cos and sin swapped; n = 0 is "
                        "torsion).");
      prm.declare_entry("Stations",
                        "0, 45, 90, 135, 180",
                        Patterns::List(Patterns::Double(0, 180), 2),
                        "Fourier: the angles (degrees, from 0 to 180, "
                        "equally spaced for an exact projection) at which "
                        "the material is evaluated.");
      prm.declare_entry("Axis boundary id",
                        "-1",
                        Patterns::Integer(-1),
                        "Fourier: the boundary id on the axis r = 0, where "
                        "each harmonic gets the conditions that keep the "
                        "field single-valued; -1 if the mesh does not reach "
                        "the axis.");
      prm.leave_subsection();

      prm.enter_subsection("Discretisation");
      prm.declare_entry("Element",
                        "Q8",
                        Patterns::Selection("Q8|Q9"),
                        "Q8: 8-node serendipity quadrilateral (a Q2 element "
                        "whose centre node is constrained); Q9: Lagrangian "
                        "9-node quadrilateral.");
      prm.declare_entry("Gauss points per direction",
                        "2",
                        Patterns::Integer(2, 3),
                        "2: reduced 2x2 integration, as in the paper; 3: full "
                        "3x3 integration.");
      prm.leave_subsection();

      prm.enter_subsection("Loading");
      prm.declare_entry(
        "Load increments",
        "1",
        Patterns::Anything(),
        "Increments of the load factor, one per load step, comma-separated; "
        "'n*d' repeats the increment d n times (e.g. '0.5, 10*0.05'). All "
        "tractions, pressures and prescribed displacements scale with the "
        "load factor.");
      prm.leave_subsection();

      prm.enter_subsection("Solver");
      prm.declare_entry(
        "Method",
        "viscoplastic",
        Patterns::Selection(
          "viscoplastic|initial stress|accelerated initial stress|newton"),
        "viscoplastic: the paper's constant-stiffness viscoplastic strain "
        "iterations; initial stress: constant stiffness, each point "
        "return-mapped, the stress excess as body loads; accelerated initial "
        "stress: the same with Anderson acceleration, still one factorisation; "
        "newton: the consistent tangent, refactorised every iteration, with "
        "a line search and load-step cut-back.");
      prm.declare_entry("Anderson depth",
                        "5",
                        Patterns::Integer(1, 50),
                        "Accelerated initial stress: how many previous "
                        "iterates the Anderson update combines.");
      prm.declare_entry("Maximum cut-backs",
                        "4",
                        Patterns::Integer(0, 20),
                        "Newton: how often a load step that does not "
                        "converge is halved before it counts as failed "
                        "(collapse).");
      prm.declare_entry("Maximum Newton iterations",
                        "25",
                        Patterns::Integer(1),
                        "Newton: iterations per attempt at a load step before "
                        "it is cut back (Maximum iterations applies to the "
                        "constant-stiffness methods).");
      prm.declare_entry("Convergence criterion",
                        "body loads",
                        Patterns::Selection(
                          "body loads|displacements|residual"),
                        "body loads: the paper's test, no body load "
                        "(divided by the largest) changes by more than the "
                        "tolerance between two iterations; for the "
                        "return-mapping methods that change is the "
                        "out-of-balance force and the body loads the stress "
                        "excess int B^T (trial stress - stress); "
                        "displacements: the same test on the step's "
                        "displacement increment (its last correction "
                        "against its size); residual (return-mapping methods "
                        "only): max |out-of-balance force| against the "
                        "largest external or internal force, reactions "
                        "included. Newton needs residual or displacements: "
                        "past collapse its stress excess grows without bound "
                        "and the body-load test would pass.");
      prm.declare_entry("Tolerance",
                        "1e-4",
                        Patterns::Double(0),
                        "TOL of the convergence criterion. Thin interfaces "
                        "need tight values (the paper's main finding).");
      prm.declare_entry("Maximum iterations",
                        "250",
                        Patterns::Integer(1),
                        "Iterations per load step; a step that reaches the "
                        "limit has failed (collapse).");
      prm.declare_entry("Linear solver",
                        "cholmod",
                        Patterns::Selection("cholmod|umfpack"),
                        "The direct solver of the stiffness, factorised once "
                        "per analysis: cholmod (sparse Cholesky, the stiffness "
                        "being symmetric positive definite) or umfpack (LU).");
      prm.declare_entry("Continue after failure",
                        "false",
                        Patterns::Bool(),
                        "Go on with the next load step after a failed one "
                        "(true), or stop the analysis there (false).");
      prm.leave_subsection();

      prm.enter_subsection("Monitors");
      prm.declare_entry("Load measure",
                        "load factor",
                        Patterns::Selection(
                          "load factor|reaction|stress average"),
                        "What the 'load' column reports: the load factor; "
                        "the sum of reactions on 'Load boundary id' in "
                        "'Load component'; or the average of 'Load stress "
                        "component' over 'Load material id'. Each is "
                        "multiplied by 'Load scale' (e.g. a length).");
      prm.declare_entry("Load scale",
                        "1",
                        Patterns::Double(),
                        "Factor applied to the load measure (e.g. the area a "
                        "unit traction acts on, or -1 for a sign).");
      prm.declare_entry("Load boundary id",
                        "0",
                        Patterns::Integer(0),
                        "Boundary id whose reactions are summed.");
      prm.declare_entry("Load component",
                        "y",
                        Patterns::Selection("x|y"),
                        "Direction of the summed reactions.");
      prm.declare_entry("Load material id",
                        "0",
                        Patterns::Integer(0),
                        "Material id over which a stress is averaged.");
      prm.declare_entry("Load stress component",
                        "xx",
                        Patterns::Selection("xx|yy|zz|xy"),
                        "The averaged stress component (tension positive).");
      prm.declare_entry("Displacement measure",
                        "boundary average",
                        Patterns::Selection("boundary average|point"),
                        "What the 'displacement' column reports: the "
                        "average over 'Displacement boundary id', or the "
                        "value at 'Displacement point'.");
      prm.declare_entry("Displacement angle",
                        "0",
                        Patterns::Double(0, 360),
                        "Fourier: the angle (degrees) at which the "
                        "displacement is monitored; x is then the Cartesian "
                        "component in the direction theta = 0, y the one "
                        "along the axis.");
      prm.declare_entry("Displacement point",
                        "0, 0",
                        Patterns::List(Patterns::Double(), 2, 2),
                        "The point x, y for the point measure.");
      prm.declare_entry("Displacement boundary id",
                        "0",
                        Patterns::Integer(0),
                        "Boundary id over which the displacement is "
                        "averaged (length-weighted); min and max over its "
                        "nodes are reported too.");
      prm.declare_entry("Displacement component",
                        "y",
                        Patterns::Selection("x|y"),
                        "Component of the monitored displacement.");
      prm.declare_entry("Displacement scale",
                        "1",
                        Patterns::Double(),
                        "Factor applied to the monitored displacement (e.g. "
                        "-1 to report settlement as positive).");
      prm.leave_subsection();

      prm.enter_subsection("Reference");
      prm.declare_entry(
        "Analytic load",
        "",
        Patterns::Anything(),
        "Closed-form value the final load is compared with, as an "
        "expression of the geometry parameters (e.g. "
        "'1/(sin(alpha*pi/180)*cos(alpha*pi/180))'); empty for none.");
      prm.leave_subsection();

      prm.enter_subsection("Sweep");
      prm.declare_entry(
        "Values",
        "",
        Patterns::Anything(),
        "Rerun the scene for every combination of values: "
        "'name = v1, v2, ...; name = ...'. A name with a '/' is an entry "
        "('Solver/Tolerance = 1e-3, 1e-6'), any other a geometry parameter "
        "('alpha = 10, 20, 30'). Braces group a value that is a list "
        "('Kinematics/Harmonics = {1}, {1, 3}'). Each run writes into run-NNN "
        "of the output "
        "directory, and sweep.csv there gets one row per run. Empty: one "
        "run.");
      prm.leave_subsection();

      prm.enter_subsection("Output");
      prm.declare_entry("Directory",
                        "output",
                        Patterns::Anything(),
                        "Where results go, relative to the working "
                        "directory; created if missing.");
      prm.declare_entry("Write VTU",
                        "true",
                        Patterns::Bool(),
                        "Write VTU/PVD fields for ParaView at every step.");
      prm.declare_entry("VTU subdivisions",
                        "2",
                        Patterns::Integer(1, 8),
                        "Patches per cell edge in VTU output (2 shows the "
                        "quadratic fields).");
      prm.declare_entry("Print timing",
                        "true",
                        Patterns::Bool(),
                        "Print wall time and the timer table on screen "
                        "(timings always go to summary.json).");
      prm.leave_subsection();
    }

    /// Parse 'name=value, name=value' (the geometry parameters).
    std::map<std::string, double>
    parse_geometry_parameters(const std::string &text, const std::string &file)
    {
      const std::string             entry = "Mesh/Geometry parameters";
      std::map<std::string, double> result;
      const std::regex              identifier("[A-Za-z_][A-Za-z0-9_]*");
      for (const auto &pair : Utilities::split_string_list(text, ','))
        {
          const auto equal = pair.find('=');
          if (equal == std::string::npos)
            throw InputError(file,
                             entry,
                             "expected 'name=value' pairs, got '" + pair + "'");
          const std::string name  = Utilities::trim(pair.substr(0, equal));
          const std::string value = Utilities::trim(pair.substr(equal + 1));
          if (!std::regex_match(name, identifier))
            throw InputError(file,
                             entry,
                             "expected a parameter name (letters, digits, "
                             "'_'), got '" +
                               name + "'");
          if (name == "x" || name == "y" || name == "z" || name == "pi")
            throw InputError(file,
                             entry,
                             "'" + name +
                               "' is reserved for expressions; choose "
                               "another parameter name");
          try
            {
              std::size_t used = 0;
              result[name]     = std::stod(value, &used);
              if (used != value.size())
                throw std::invalid_argument(value);
            }
          catch (const std::exception &)
            {
              throw InputError(file,
                               entry,
                               "expected a number for '" + name + "', got '" +
                                 value + "'");
            }
        }
      return result;
    }

    /// Parse '0.5, 10*0.05' into a list of increments.
    std::vector<double>
    parse_increments(const std::string &text, const std::string &file)
    {
      const std::string   entry = "Loading/Load increments";
      std::vector<double> result;
      const std::regex    repeated(
        "\\s*([0-9]+)\\s*\\*\\s*([-+0-9.eE]+)\\s*|\\s*([-+0-9.eE]+)\\s*");
      for (const auto &item : Utilities::split_string_list(text, ','))
        {
          std::smatch match;
          if (!std::regex_match(item, match, repeated))
            throw InputError(file,
                             entry,
                             "expected a number or 'n*number', got '" + item +
                               "'");
          try
            {
              if (match[1].matched)
                result.insert(result.end(),
                              std::stoul(match[1]),
                              std::stod(match[2]));
              else
                result.push_back(std::stod(match[3]));
            }
          catch (const std::exception &)
            {
              throw InputError(file,
                               entry,
                               "expected a number or 'n*number', got '" + item +
                                 "'");
            }
        }
      if (result.empty())
        throw InputError(file, entry, "expected at least one increment");
      return result;
    }

    /// Parse 'name = v1, v2; name = w1, w2'.
    std::vector<std::pair<std::string, std::vector<std::string>>>
    parse_sweep(const std::string &text, const std::string &file)
    {
      std::vector<std::pair<std::string, std::vector<std::string>>> sweep;
      const std::regex name("[A-Za-z_][A-Za-z0-9_]*|[^/=]+(/[^/=]+)+");
      for (const auto &item : Utilities::split_string_list(text, ';'))
        {
          const auto        equal = item.find('=');
          const std::string key =
            Utilities::trim(item.substr(0, std::min(equal, item.size())));
          if (equal == std::string::npos || !std::regex_match(key, name))
            throw InputError(file,
                             "Sweep/Values",
                             "expected 'name = v1, v2, ...' (a geometry "
                             "parameter or Section/Entry), got '" +
                               item + "'");
          // Values are comma-separated; braces group a value that is a
          // list itself ("Kinematics/Harmonics = {1}, {1, 3}").
          std::vector<std::string> values;
          std::string              current;
          int                      depth = 0;
          for (const char ch : item.substr(equal + 1) + ",")
            {
              if (ch == '{')
                ++depth;
              else if (ch == '}')
                --depth;
              else if (ch == ',' && depth == 0)
                {
                  if (!Utilities::trim(current).empty())
                    values.push_back(Utilities::trim(current));
                  current.clear();
                }
              else
                current += ch;
            }
          if (depth != 0)
            throw InputError(file,
                             "Sweep/Values",
                             "unbalanced braces in '" + item + "'");
          if (values.empty())
            throw InputError(file,
                             "Sweep/Values",
                             "expected at least one value for '" + key + "'");
          if (key.find('/') == std::string::npos)
            for (const auto &v : values)
              {
                std::size_t used = 0;
                try
                  {
                    std::stod(v, &used);
                  }
                catch (const std::exception &)
                  {}
                if (used == 0 || used != v.size())
                  throw InputError(file,
                                   "Sweep/Values",
                                   "expected numbers for the geometry "
                                   "parameter '" +
                                     key + "', got '" + v + "'");
              }
          sweep.emplace_back(key, values);
        }
      return sweep;
    }

    std::vector<bool>
    parse_components(const std::string &text,
                     const bool         fourier,
                     const std::string &file,
                     const std::string &entry)
    {
      const std::vector<std::string> names =
        fourier ? std::vector<std::string>{"r", "z", "theta"}
                : std::vector<std::string>{"x", "y"};
      std::vector<bool> result(names.size(), false);
      for (const auto &c : Utilities::split_string_list(text, ','))
        {
          const auto k = std::find(names.begin(), names.end(), c);
          if (k == names.end())
            throw InputError(
              file,
              entry,
              std::string("expected a comma-separated list of ") +
                (fourier ? "r, z, theta" : "x, y") + ", got '" + c + "'");
          result[k - names.begin()] = true;
        }
      return result;
    }

    /// Checks that an expression list parses, for messages at read time.
    void
    check_expressions(const std::string                   &expressions,
                      const unsigned int                   n_components,
                      const bool                           fourier,
                      const std::map<std::string, double> &constants,
                      const std::string                   &file,
                      const std::string                   &entry)
    {
      const auto parts = Utilities::split_string_list(expressions, ';');
      if (parts.size() != 1 && parts.size() != n_components)
        throw InputError(file,
                         entry,
                         "expected " + std::to_string(n_components) +
                           " expressions separated by ';' (or one for all), "
                           "got " +
                           std::to_string(parts.size()));
      const SilencedErrorStream silence;
      try
        {
          FunctionParser<3> f(1);
          auto              all_constants = constants;
          all_constants["pi"]             = numbers::PI;
          for (const auto &p : parts)
            {
              f.initialize(fourier ? "r,z,theta" : "x,y,unused_z",
                           p,
                           all_constants);
              (void)f.value(Point<3>(1, 0, 0));
            }
        }
      catch (const ExceptionBase &e)
        {
          throw InputError(file,
                           entry,
                           std::string("expected function expressions of ") +
                             (fourier ? "r, z, theta" : "x, y") +
                             " and the geometry parameters: " + message_of(e));
        }
    }

    double
    positive(const ParameterHandler &prm,
             const std::string      &name,
             const std::string      &file,
             const std::string      &section)
    {
      const double value = prm.get_double(name);
      if (!(value > 0))
        throw InputError(file,
                         section + "/" + name,
                         "expected a value > 0, got " + prm.get(name));
      return value;
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

    Parameters
    extract(ParameterHandler                        &prm,
            const std::string                       &file,
            const std::set<types::global_dof_index> &material_ids,
            const std::set<types::global_dof_index> &boundary_ids)
    {
      Parameters p;
      p.parameter_file = file;

      prm.enter_subsection("Mesh");
      const std::string mesh = prm.get("File");
      if (mesh.empty())
        throw InputError(file, "Mesh/File", "expected a .geo or .msh file");
      p.mesh_file =
        (mesh.front() == '/') ? mesh : directory_of(file) + "/" + mesh;
      p.geometry_parameters =
        parse_geometry_parameters(prm.get("Geometry parameters"), file);
      prm.leave_subsection();

      prm.enter_subsection("Kinematics");
      p.fourier = (prm.get("Type") == "fourier");
      for (const auto &n : Utilities::split_string_list(prm.get("Harmonics")))
        {
          const unsigned int h = std::stoul(n);
          if (std::find(p.harmonics.begin(), p.harmonics.end(), h) !=
              p.harmonics.end())
            throw InputError(file,
                             "Kinematics/Harmonics",
                             "expected each harmonic once, got " + n +
                               " twice");
          p.harmonics.push_back(h);
        }
      p.antisymmetric = (prm.get("Series") == "antisymmetric");
      for (const auto &a : Utilities::split_string_list(prm.get("Stations")))
        p.station_angles.push_back(std::stod(a) * numbers::PI / 180);
      for (unsigned int s = 1; s < p.station_angles.size(); ++s)
        if (!(p.station_angles[s] > p.station_angles[s - 1]))
          throw InputError(file,
                           "Kinematics/Stations",
                           "expected increasing angles, got " +
                             prm.get("Stations"));
      if (std::abs(p.station_angles.front()) > 1e-12 ||
          std::abs(p.station_angles.back() - numbers::PI) > 1e-12)
        throw InputError(file,
                         "Kinematics/Stations",
                         "expected angles from 0 to 180 degrees, got " +
                           prm.get("Stations"));
      p.axis_boundary_id = prm.get_integer("Axis boundary id");
      if (!p.fourier)
        {
          p.harmonics      = {0};
          p.station_angles = {0};
        }
      prm.leave_subsection();

      prm.enter_subsection("Discretisation");
      p.serendipity = (prm.get("Element") == "Q8");
      p.gauss_points_per_direction =
        prm.get_integer("Gauss points per direction");
      prm.leave_subsection();

      if (material_ids.empty())
        throw InputError(file,
                         "Material <id>",
                         "expected at least one 'subsection Material <id>' "
                         "for the physical surfaces of the mesh");
      for (const auto id : material_ids)
        {
          const std::string section = "Material " + std::to_string(id);
          prm.enter_subsection(section);
          MaterialParameters m;
          m.name           = prm.get("Name");
          m.youngs_modulus = positive(prm, "Young's modulus", file, section);
          m.poissons_ratio = prm.get_double("Poisson's ratio");
          if (!(m.poissons_ratio > -1 && m.poissons_ratio < 0.5))
            throw InputError(file,
                             section + "/Poisson's ratio",
                             "expected a value in (-1, 0.5), got " +
                               prm.get("Poisson's ratio"));
          const std::string criterion = prm.get("Yield criterion");
          m.yield_criterion =
            (criterion == "tresca")         ? YieldCriterion::tresca
            : (criterion == "von mises")    ? YieldCriterion::von_mises
            : (criterion == "mohr-coulomb") ? YieldCriterion::mohr_coulomb
                                            : YieldCriterion::elastic;
          m.cohesion       = prm.get_double("Cohesion");
          m.friction_angle = prm.get_double("Friction angle");
          m.dilation_angle = prm.get_double("Dilation angle");
          if ((m.yield_criterion == YieldCriterion::tresca ||
               m.yield_criterion == YieldCriterion::von_mises) &&
              !(m.cohesion > 0))
            throw InputError(file,
                             section + "/Cohesion",
                             "expected a value > 0 for the " + criterion +
                               " criterion, got " + prm.get("Cohesion"));
          if (m.yield_criterion == YieldCriterion::mohr_coulomb &&
              !(m.cohesion > 0 || m.friction_angle > 0))
            throw InputError(file,
                             section + "/Friction angle",
                             "expected a friction angle > 0 where the "
                             "cohesion is 0 (the material would have no "
                             "strength)");
          if (m.dilation_angle > m.friction_angle)
            throw InputError(file,
                             section + "/Dilation angle",
                             "expected at most the friction angle (" +
                               prm.get("Friction angle") + "), got " +
                               prm.get("Dilation angle"));
          prm.leave_subsection();
          p.materials[id] = m;
        }

      for (const auto id : boundary_ids)
        {
          const std::string section = "Boundary " + std::to_string(id);
          prm.enter_subsection(section);
          BoundaryParameters b;
          b.name = prm.get("Name");
          b.constrained_components =
            parse_components(prm.get("Constrained components"),
                             p.fourier,
                             file,
                             section + "/Constrained components");
          b.displacement              = prm.get("Displacement");
          b.traction                  = prm.get("Traction");
          b.pressure                  = prm.get("Pressure");
          const unsigned int n_vector = p.fourier ? 3 : 2;
          check_expressions(b.displacement,
                            n_vector,
                            p.fourier,
                            p.geometry_parameters,
                            file,
                            section + "/Displacement");
          check_expressions(b.traction,
                            n_vector,
                            p.fourier,
                            p.geometry_parameters,
                            file,
                            section + "/Traction");
          check_expressions(b.pressure,
                            1,
                            p.fourier,
                            p.geometry_parameters,
                            file,
                            section + "/Pressure");
          if (Utilities::split_string_list(b.pressure, ';').size() != 1)
            throw InputError(file,
                             section + "/Pressure",
                             "expected a single expression");
          prm.leave_subsection();
          p.boundaries[id] = b;
        }

      prm.enter_subsection("Loading");
      p.load_increments = parse_increments(prm.get("Load increments"), file);
      prm.leave_subsection();

      prm.enter_subsection("Solver");
      {
        const std::string method = prm.get("Method");
        p.method = (method == "initial stress") ? SolutionMethod::initial_stress
                   : (method == "accelerated initial stress")
                     ? SolutionMethod::accelerated_initial_stress
                   : (method == "newton") ? SolutionMethod::newton
                                          : SolutionMethod::viscoplastic;
      }
      p.anderson_depth        = prm.get_integer("Anderson depth");
      p.max_cut_backs         = prm.get_integer("Maximum cut-backs");
      p.max_newton_iterations = prm.get_integer("Maximum Newton iterations");
      {
        const std::string criterion = prm.get("Convergence criterion");
        p.convergence_criterion =
          (criterion == "displacements") ? ConvergenceCriterion::displacements
          : (criterion == "residual")    ? ConvergenceCriterion::residual
                                         : ConvergenceCriterion::body_loads;
        if (p.method == SolutionMethod::viscoplastic &&
            p.convergence_criterion == ConvergenceCriterion::residual)
          throw InputError(file,
                           "Solver/Convergence criterion",
                           "'body loads' or 'displacements' for the "
                           "viscoplastic method, whose stresses are in "
                           "equilibrium at every iteration (its out-of-balance "
                           "is the change of the body loads), not 'residual'");
        if (p.method == SolutionMethod::newton &&
            p.convergence_criterion == ConvergenceCriterion::body_loads)
          throw InputError(file,
                           "Solver/Convergence criterion",
                           "'residual' or 'displacements' for Newton, not "
                           "'body loads': past collapse the stress excess "
                           "grows without bound and that test would pass");
      }
      p.tolerance              = positive(prm, "Tolerance", file, "Solver");
      p.max_iterations         = prm.get_integer("Maximum iterations");
      p.continue_after_failure = prm.get_bool("Continue after failure");
      p.linear_solver          = (prm.get("Linear solver") == "umfpack")
                                   ? LinearSolver::umfpack
                                   : LinearSolver::cholmod;
      prm.leave_subsection();

      prm.enter_subsection("Monitors");
      const std::string measure = prm.get("Load measure");
      p.load_measure     = (measure == "reaction") ? LoadMeasure::reaction
                           : (measure == "stress average")
                             ? LoadMeasure::stress_average
                             : LoadMeasure::load_factor;
      p.load_material_id = prm.get_integer("Load material id");
      const std::string component = prm.get("Load stress component");
      p.load_stress_component     = {component[0] == 'x' ? 0u : 1u,
                                 component[1] == 'x'   ? 0u
                                     : component[1] == 'y' ? 1u
                                                           : 2u};
      if (component == "zz")
        p.load_stress_component = {2u, 2u};
      p.displacement_angle =
        prm.get_double("Displacement angle") * numbers::PI / 180;
      if (p.fourier && p.load_measure != LoadMeasure::load_factor)
        throw InputError(file,
                         "Monitors/Load measure",
                         "expected 'load factor' with Fourier kinematics "
                         "(reactions and stress averages are plane-strain "
                         "measures so far)");
      p.displacement_measure = (prm.get("Displacement measure") == "point")
                                 ? DisplacementMeasureType::point
                                 : DisplacementMeasureType::boundary_average;
      for (const auto &x :
           Utilities::split_string_list(prm.get("Displacement point")))
        p.displacement_point.push_back(std::stod(x));
      p.load_scale               = prm.get_double("Load scale");
      p.load_boundary_id         = prm.get_integer("Load boundary id");
      p.load_component           = (prm.get("Load component") == "x") ? 0 : 1;
      p.displacement_boundary_id = prm.get_integer("Displacement boundary id");
      p.displacement_component =
        (prm.get("Displacement component") == "x") ? 0 : 1;
      p.displacement_scale = prm.get_double("Displacement scale");
      prm.leave_subsection();

      prm.enter_subsection("Reference");
      const std::string reference = prm.get("Analytic load");
      p.reference_load            = std::numeric_limits<double>::quiet_NaN();
      if (!Utilities::trim(reference).empty())
        {
          check_expressions(reference,
                            1,
                            false,
                            p.geometry_parameters,
                            file,
                            "Reference/Analytic load");
          FunctionParser<2> f(1);
          auto              constants = p.geometry_parameters;
          constants["pi"]             = numbers::PI;
          f.initialize("x,y", reference, constants);
          p.reference_load = f.value(Point<2>());
          if (!std::isfinite(p.reference_load) || p.reference_load == 0)
            throw InputError(file,
                             "Reference/Analytic load",
                             "expected a finite, non-zero value, got " +
                               std::to_string(p.reference_load));
        }
      prm.leave_subsection();

      prm.enter_subsection("Sweep");
      p.sweep = parse_sweep(prm.get("Values"), file);
      prm.leave_subsection();

      prm.enter_subsection("Output");
      p.output_directory = prm.get("Directory");
      if (p.output_directory.empty())
        throw InputError(file, "Output/Directory", "expected a directory");
      p.write_vtu        = prm.get_bool("Write VTU");
      p.vtu_subdivisions = prm.get_integer("VTU subdivisions");
      p.print_timing     = prm.get_bool("Print timing");
      prm.leave_subsection();

      return p;
    }
  } // namespace


  Parameters
  ParameterReader::read(const std::string              &file,
                        const std::vector<std::string> &overrides) const
  {
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
    const auto material_ids = ids_of_sections(text, overrides, "Material");
    const auto boundary_ids = ids_of_sections(text, overrides, "Boundary");

    ParameterHandler prm;
    declare_fixed_sections(prm);
    for (const auto id : material_ids)
      declare_material(prm, id);
    for (const auto id : boundary_ids)
      declare_boundary(prm, id);

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

    Parameters parameters = extract(prm, file, material_ids, boundary_ids);
    // The record names the mesh by its absolute path, so that it can be
    // run again from anywhere.
    prm.enter_subsection("Mesh");
    prm.set("File",
            std::filesystem::absolute(parameters.mesh_file)
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
    declare_fixed_sections(prm);
    declare_material(prm, 1);
    declare_boundary(prm, 1);
    out
      << "# thinlayer parameters. 'Material <id>' and 'Boundary <id>' may be\n"
      << "# repeated for every physical surface and curve id of the mesh.\n";
    prm.print_parameters(out, ParameterHandler::PRM);
  }
} // namespace thinlayer
