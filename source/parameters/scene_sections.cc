#include <deal.II/base/utilities.h>

#include <thinlayer/base/input_error.h>
#include <thinlayer/parameters/parameter_checks.h>
#include <thinlayer/parameters/parameters.h>

#include <algorithm>
#include <cmath>

// The sections that describe the model: mesh, kinematics, discretisation,
// materials and boundaries.

namespace thinlayer
{
  namespace
  {
    std::string
    directory_of(const std::string &file)
    {
      const auto slash = file.find_last_of('/');
      return slash == std::string::npos ? std::string(".")
                                        : file.substr(0, slash);
    }

    /// Parse 'name=value, name=value' (the geometry parameters).
    std::map<std::string, double>
    parse_geometry_parameters(const std::string &text, const std::string &file)
    {
      const std::string             entry = "Mesh/Geometry parameters";
      std::map<std::string, double> result;
      for (const auto &pair : Utilities::split_string_list(text, ','))
        {
          const auto equal = pair.find('=');
          if (equal == std::string::npos)
            throw InputError(file,
                             entry,
                             "expected 'name=value' pairs, got '" + pair + "'");
          const std::string name  = Utilities::trim(pair.substr(0, equal));
          const std::string value = Utilities::trim(pair.substr(equal + 1));
          if (!is_identifier(name))
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
          if (result.count(name) != 0)
            throw InputError(file,
                             entry,
                             "'" + name +
                               "' is given twice; expected each parameter "
                               "once");
          if (!to_number(value, result[name]))
            throw InputError(file,
                             entry,
                             "expected a number for '" + name + "', got '" +
                               value + "'");
        }
      return result;
    }


    std::vector<bool>
    parse_components(const std::string              &text,
                     const std::vector<std::string> &names,
                     const std::string              &file,
                     const std::string              &entry)
    {
      std::string listed;
      for (const auto &name : names)
        listed += (listed.empty() ? "" : ", ") + name;
      std::vector<bool> result(names.size(), false);
      for (const auto &c : Utilities::split_string_list(text, ','))
        {
          const auto k = std::find(names.begin(), names.end(), c);
          if (k == names.end())
            throw InputError(file,
                             entry,
                             "expected a comma-separated list of " + listed +
                               ", got '" + c + "'");
          if (result[k - names.begin()])
            throw InputError(file,
                             entry,
                             "'" + c +
                               "' is given twice; expected each "
                               "component once");
          result[k - names.begin()] = true;
        }
      return result;
    }
  } // namespace


  void
  MeshParameters::declare(ParameterHandler &prm)
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
    prm.declare_entry("Maximum cells",
                      "1000000",
                      Patterns::Integer(1),
                      "The most cells the mesh may have. gmsh is stopped "
                      "once its memory shows it making far more (a "
                      "mistyped geometry parameter), and a larger mesh is "
                      "refused.");
    prm.declare_entry(
      "Curved cells",
      "true",
      Patterns::Bool(),
      "true: the cell sides a .geo's circles and arcs run along (its "
      "Circle(n) = {start, centre, end} curves, boundaries and curves "
      "inside the body alike, in 3D the cylinders an extruded arc sweeps) "
      "follow the circle, through the quadratic mapping, so that a body "
      "slides on the circle, not on the polygon of its nodes. false: every "
      "cell keeps straight sides, as does a .msh file always (it carries "
      "no geometry).");
    prm.declare_entry(
      "Trust geometry scripts",
      "false",
      Patterns::Bool(),
      "gmsh runs a .geo with your rights, and a .geo can run shell commands "
      "(SystemCall, OnelabRun) and write or delete files (Printf > file, "
      "Save, Print, DeleteFile, ...). false: a .geo (or a file it includes) "
      "with such a statement is refused, naming its line. true: gmsh runs "
      "the script as it is; only for scripts you trust.");
    prm.declare_entry("Meshing time limit",
                      "600",
                      Patterns::Double(0),
                      "Seconds gmsh may take to mesh the .geo (each of its "
                      "runs); it is stopped beyond them (a loop without "
                      "end, or a mesh far finer than meant).");
    prm.leave_subsection();
  }


  void
  MeshParameters::parse(ParameterHandler  &prm,
                        const std::string &parameter_file)
  {
    prm.enter_subsection("Mesh");
    const std::string mesh = prm.get("File");
    if (mesh.empty())
      throw InputError(parameter_file,
                       "Mesh/File",
                       "expected a .geo or .msh file");
    file =
      (mesh.front() == '/') ? mesh : directory_of(parameter_file) + "/" + mesh;
    geometry_parameters =
      parse_geometry_parameters(prm.get("Geometry parameters"), parameter_file);
    max_cells              = prm.get_integer("Maximum cells");
    curved_cells           = prm.get_bool("Curved cells");
    trust_geometry_scripts = prm.get_bool("Trust geometry scripts");
    meshing_time_limit =
      positive(prm, "Meshing time limit", parameter_file, "Mesh");
    prm.leave_subsection();
  }


  void
  KinematicsParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Kinematics");
    prm.declare_entry("Type",
                      "plane strain",
                      Patterns::Selection("plane strain|fourier|3d"),
                      "plane strain: the mesh is a cross-section, "
                      "components x, y. fourier: the mesh is the r-z plane "
                      "of an axisymmetric body (x = r >= 0, y = z the "
                      "axis) and the load need not be axisymmetric: the "
                      "displacement is a sum of Fourier harmonics, "
                      "components r, z, theta. 3d: the mesh is the body "
                      "itself, of hexahedra, components x, y, z.");
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
                      Patterns::List(Patterns::Double(0, 180), 1),
                      "Fourier: the angles (degrees, equally spaced from 0 "
                      "to 180, at least n + 2 of them for harmonics up to "
                      "n, so that the projection is exact) at which the "
                      "material is evaluated. For harmonic 0 alone (an "
                      "axisymmetric state) one station is enough.");
    prm.declare_entry("Axis boundary id",
                      "-1",
                      Patterns::Integer(-1),
                      "Fourier: the boundary id on the axis r = 0, where "
                      "each harmonic gets the conditions that keep the "
                      "field single-valued; -1 if the mesh does not reach "
                      "the axis.");
    prm.leave_subsection();
  }


  void
  KinematicsParameters::check_stations(const std::string &file,
                                       const std::string &text) const
  {
    // The stations are a trapezoidal rule over the circle: with S equally
    // spaced ones over [0, 180] degrees (2 (S - 1) over the circle) it
    // integrates trigonometric polynomials of degree below 2 (S - 1)
    // exactly, and the projections onto the harmonics need degree 2 n_max.
    // Too few, or unequally spaced, stations alias the harmonics: the body
    // loads no longer balance, and the run ends in values that are not
    // numbers or in a collapse load a few per cent off.
    const unsigned int S = station_angles.size();
    const unsigned int n_max =
      *std::max_element(harmonics.begin(), harmonics.end());
    if (S == 1)
      {
        if (n_max > 0)
          throw InputError(file,
                           "Kinematics/Stations",
                           "one station serves harmonic 0 alone (an "
                           "axisymmetric state); for harmonics up to " +
                             std::to_string(n_max) + " expected at least " +
                             std::to_string(n_max + 2) +
                             " equally spaced stations from 0 to 180 degrees");
        return;
      }
    for (unsigned int s = 0; s < S; ++s)
      if (std::abs(station_angles[s] - s * numbers::PI / (S - 1)) > 1e-9)
        throw InputError(file,
                         "Kinematics/Stations",
                         "expected equally spaced angles from 0 to 180 "
                         "degrees (the projection onto the harmonics is "
                         "exact only then), got " +
                           text);
    if (S < n_max + 2)
      throw InputError(file,
                       "Kinematics/Stations",
                       std::to_string(S) +
                         " stations are too few for harmonic " +
                         std::to_string(n_max) + ": expected at least " +
                         std::to_string(n_max + 2) +
                         ", so that 2 (stations - 1) >= 2 n + 1 over the "
                         "circle");
  }


  void
  KinematicsParameters::parse(ParameterHandler  &prm,
                              const std::string &parameter_file)
  {
    const std::string &file = parameter_file;
    prm.enter_subsection("Kinematics");
    fourier   = (prm.get("Type") == "fourier");
    dimension = (prm.get("Type") == "3d") ? 3 : 2;
    harmonics.clear();
    for (const auto &n : Utilities::split_string_list(prm.get("Harmonics")))
      {
        const unsigned int h = std::stoul(n);
        if (std::find(harmonics.begin(), harmonics.end(), h) != harmonics.end())
          throw InputError(file,
                           "Kinematics/Harmonics",
                           "expected each harmonic once, got " + n + " twice");
        harmonics.push_back(h);
      }
    antisymmetric = (prm.get("Series") == "antisymmetric");
    station_angles.clear();
    for (const auto &a : Utilities::split_string_list(prm.get("Stations")))
      station_angles.push_back(std::stod(a) * numbers::PI / 180);
    for (unsigned int s = 1; s < station_angles.size(); ++s)
      if (!(station_angles[s] > station_angles[s - 1]))
        throw InputError(file,
                         "Kinematics/Stations",
                         "expected increasing angles, got " +
                           prm.get("Stations"));
    if (station_angles.size() > 1 &&
        (std::abs(station_angles.front()) > 1e-12 ||
         std::abs(station_angles.back() - numbers::PI) > 1e-12))
      throw InputError(file,
                       "Kinematics/Stations",
                       "expected angles from 0 to 180 degrees, got " +
                         prm.get("Stations"));
    if (fourier)
      check_stations(file, prm.get("Stations"));
    axis_boundary_id = prm.get_integer("Axis boundary id");
    if (!fourier)
      {
        harmonics      = {0};
        station_angles = {0};
      }
    prm.leave_subsection();
  }


  std::vector<std::string>
  KinematicsParameters::component_names() const
  {
    return fourier          ? std::vector<std::string>{"r", "z", "theta"}
           : dimension == 3 ? std::vector<std::string>{"x", "y", "z"}
                            : std::vector<std::string>{"x", "y"};
  }


  std::string
  KinematicsParameters::expression_variables() const
  {
    return fourier ? "r,z,theta" : dimension == 3 ? "x,y,z" : "x,y,unused_z";
  }


  void
  DiscretisationParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Discretisation");
    prm.declare_entry("Element",
                      "Q8",
                      Patterns::Selection("Q8|Q9|Q20|Q27"),
                      "Q8: 8-node serendipity quadrilateral (a Q2 element "
                      "whose centre node is constrained), the paper's; Q9: "
                      "Lagrangian 9-node quadrilateral, a refinement level "
                      "ahead of Q8 on rigid circular footings but, with 2x2 "
                      "points, singular on meshes of few cells (spurious "
                      "zero-energy modes). In 3d: Q20, the 20-node "
                      "serendipity hexahedron (a Q2 element whose face and "
                      "body centres are constrained; the default there), or "
                      "Q27, the Lagrangian 27-node one.");
    prm.declare_entry("Gauss points per direction",
                      "2",
                      Patterns::Integer(2, 3),
                      "2: reduced 2x2 integration (2x2x2 in 3d), as in the "
                      "paper; 3: full 3x3 (3x3x3) integration.");
    prm.leave_subsection();
  }


  void
  DiscretisationParameters::parse(ParameterHandler           &prm,
                                  const std::string          &file,
                                  const KinematicsParameters &kinematics)
  {
    prm.enter_subsection("Discretisation");
    element_name          = prm.get("Element");
    serendipity           = (element_name == "Q8" || element_name == "Q20");
    const bool hexahedron = (element_name == "Q20" || element_name == "Q27");
    if (hexahedron != (kinematics.dimension == 3) &&
        !(element_name == "Q8" && kinematics.dimension == 3))
      throw InputError(file,
                       "Discretisation/Element",
                       element_name + " is a " +
                         (hexahedron ? "hexahedron" : "quadrilateral") +
                         "; expected " +
                         (kinematics.dimension == 3 ? "Q20 or Q27 in 3d"
                                                    : "Q8 or Q9 on a 2D mesh"));
    gauss_points_per_direction = prm.get_integer("Gauss points per direction");
    prm.leave_subsection();
  }


  const NameTable<YieldCriterion> MaterialParameters::yield_criterion_names = {
    {YieldCriterion::elastic, "elastic"},
    {YieldCriterion::tresca, "tresca"},
    {YieldCriterion::von_mises, "von mises"},
    {YieldCriterion::mohr_coulomb, "mohr-coulomb"}};


  std::string
  MaterialParameters::section(const unsigned int id)
  {
    return "Material " + std::to_string(id);
  }


  void
  MaterialParameters::declare(ParameterHandler &prm, const unsigned int id)
  {
    prm.enter_subsection(section(id));
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
                      Patterns::Selection(yield_criterion_names.pattern()),
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
    prm.declare_entry("Unit weight",
                      "0",
                      Patterns::Double(),
                      "Weight per unit volume gamma (>= 0), acting along -y "
                      "(every mesh has y up: the vertical of a plane-strain "
                      "section, the axis of a Fourier or 3D body), "
                      "proportional to the load factor like every load: a "
                      "load programme of the weight alone is gravity "
                      "loading. Drained analysis in total stresses: no pore "
                      "pressures.");
    prm.declare_entry("K0",
                      "1 - sin(phi)",
                      Patterns::Anything(),
                      "The coefficient of earth pressure at rest, "
                      "sigma_h / sigma_v, of Initial state/Procedure = K0 "
                      "procedure: a number > 0, or '1 - sin(phi)' (Jaky's, "
                      "1 without friction).");
    prm.leave_subsection();
  }


  void
  MaterialParameters::parse(ParameterHandler  &prm,
                            const std::string &file,
                            const unsigned int id)
  {
    const std::string section = MaterialParameters::section(id);
    prm.enter_subsection(section);
    name = prm.get("Name");
    // Above 1e30, products in the stiffness and the stresses overflow.
    youngs_modulus = positive(prm, "Young's modulus", file, section, 1e30);
    poissons_ratio = prm.get_double("Poisson's ratio");
    if (!(poissons_ratio > -1 && poissons_ratio < 0.5))
      throw InputError(file,
                       section + "/Poisson's ratio",
                       "expected a value in (-1, 0.5), got " +
                         prm.get("Poisson's ratio"));
    const std::string criterion = prm.get("Yield criterion");
    yield_criterion             = yield_criterion_names.value(criterion);
    cohesion                    = prm.get_double("Cohesion");
    friction_angle              = prm.get_double("Friction angle");
    dilation_angle              = prm.get_double("Dilation angle");
    unit_weight                 = prm.get_double("Unit weight");
    if (!(unit_weight >= 0) || !std::isfinite(unit_weight))
      throw InputError(file,
                       section + "/Unit weight",
                       "expected a weight per unit volume >= 0 (it acts "
                       "along -y), got " +
                         prm.get("Unit weight"));
    if ((yield_criterion == YieldCriterion::tresca ||
         yield_criterion == YieldCriterion::von_mises) &&
        !(cohesion > 0))
      throw InputError(file,
                       section + "/Cohesion",
                       "expected a value > 0 for the " + criterion +
                         " criterion, got " + prm.get("Cohesion"));
    if (yield_criterion == YieldCriterion::mohr_coulomb &&
        !(cohesion > 0 || friction_angle > 0))
      throw InputError(file,
                       section + "/Friction angle",
                       "expected a friction angle > 0 where the "
                       "cohesion is 0 (the material would have no "
                       "strength)");
    if (yield_criterion != YieldCriterion::mohr_coulomb &&
        (friction_angle > 0 || dilation_angle > 0))
      throw InputError(file,
                       section + (friction_angle > 0 ? "/Friction angle"
                                                     : "/Dilation angle"),
                       "the " + criterion +
                         " criterion has no friction or dilation angle; "
                         "expected 0, or Yield criterion = mohr-coulomb");
    if (yield_criterion == YieldCriterion::elastic && cohesion > 0)
      throw InputError(file,
                       section + "/Cohesion",
                       "an elastic material has no cohesion; expected 0, or "
                       "a yield criterion");
    check_dilation_angle(prm, file, section);
    const std::string k0_text = prm.get("K0");
    std::string       compact;
    for (const char c : k0_text)
      if (c != ' ')
        compact += c;
    if (compact == "1-sin(phi)")
      k0 = 1 - std::sin(friction_angle * numbers::PI / 180);
    else if (!to_number(k0_text, k0) || !(k0 > 0) || !std::isfinite(k0))
      throw InputError(file,
                       section + "/K0",
                       "expected a number > 0 or '1 - sin(phi)', got '" +
                         k0_text + "'");
    prm.leave_subsection();
  }


  std::string
  BoundaryParameters::section(const unsigned int id)
  {
    return "Boundary " + std::to_string(id);
  }


  void
  BoundaryParameters::declare(ParameterHandler  &prm,
                              const unsigned int id,
                              const bool         in_phase)
  {
    prm.enter_subsection(section(id));
    prm.declare_entry("Name",
                      "",
                      Patterns::Anything(),
                      "A name for this boundary id (the gmsh physical curve "
                      "with the same number), used in output.");
    prm.declare_entry(
      "Constrained components",
      "",
      Patterns::Anything(),
      in_phase ? "Not to be set in a phase: the Boundary sections' "
                 "constraints hold throughout the run (the stiffness is "
                 "factorised once), and a phase's Displacement applies "
                 "to the components they constrain."
               : "Comma-separated components whose displacement is "
                 "prescribed here: any of x, y in plane strain; of r, z, "
                 "theta for Fourier kinematics (every harmonic); of x, y, "
                 "z in 3d; empty for none.");
    prm.declare_entry(
      "Displacement",
      "0",
      Patterns::Anything(),
      "Prescribed displacement per unit load factor of the constrained "
      "components: one function expression of x, y (x, y, z in 3d; and "
      "the geometry parameters) per component, separated by ';', or one "
      "expression "
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
                      "Fourier kinematics; x, y, z in 3d).");
    prm.leave_subsection();
  }


  void
  BoundaryParameters::check_loads_where_free(
    const std::string          &file,
    const std::string          &section,
    const KinematicsParameters &kinematics) const
  {
    const bool fourier = kinematics.fourier;
    const auto names   = kinematics.component_names();
    // A load on a constrained component goes into the reaction and is
    // lost: say so rather than ignore it. Fourier tractions are Cartesian
    // and the constraints cylindrical, so there only a boundary
    // constrained in every component is checked.
    const auto is_zero = [](const std::string &e) {
      try
        {
          std::size_t end;
          return std::stod(e, &end) == 0 && end == e.size();
        }
      catch (const std::exception &)
        {
          return false;
        }
    };
    const unsigned int n             = constrained_components.size();
    unsigned int       n_constrained = 0;
    for (const bool c : constrained_components)
      n_constrained += c ? 1 : 0;
    auto parts = Utilities::split_string_list(traction, ';');
    if (parts.size() == 1)
      parts.assign(names.size(), parts[0]);
    for (unsigned int c = 0; c < n; ++c)
      if (constrained_components[c] && (!fourier || n_constrained == n) &&
          !is_zero(parts[std::min<std::size_t>(c, parts.size() - 1)]))
        throw InputError(file,
                         section + "/Traction",
                         "a traction on the constrained component " + names[c] +
                           " would go into the reaction; expected 0 there, "
                           "or the component free");
    if (n_constrained == n && !is_zero(pressure))
      throw InputError(file,
                       section + "/Pressure",
                       "a pressure on a boundary constrained in every "
                       "component would go into the reaction; expected 0");
  }


  void
  BoundaryParameters::parse(ParameterHandler           &prm,
                            const std::string          &file,
                            const unsigned int          id,
                            const KinematicsParameters &kinematics,
                            const MeshParameters       &mesh,
                            const std::string          &outer,
                            const std::vector<bool>    &constrained)
  {
    const std::string section   = outer + BoundaryParameters::section(id);
    const std::string variables = kinematics.expression_variables();
    prm.enter_subsection(BoundaryParameters::section(id));
    name = prm.get("Name");
    constrained_components =
      outer.empty() ? parse_components(prm.get("Constrained components"),
                                       kinematics.component_names(),
                                       file,
                                       section + "/Constrained components")
                    : constrained;
    displacement                 = prm.get("Displacement");
    traction                     = prm.get("Traction");
    pressure                     = prm.get("Pressure");
    const unsigned int n_vector  = kinematics.component_names().size();
    const auto        &constants = mesh.geometry_parameters;
    check_expressions(displacement,
                      n_vector,
                      variables,
                      constants,
                      file,
                      section + "/Displacement");
    check_expressions(
      traction, n_vector, variables, constants, file, section + "/Traction");
    check_expressions(
      pressure, 1, variables, constants, file, section + "/Pressure");
    if (Utilities::split_string_list(pressure, ';').size() != 1)
      throw InputError(file,
                       section + "/Pressure",
                       "expected a single expression");
    check_loads_where_free(file, section, kinematics);
    prm.leave_subsection();
  }
} // namespace thinlayer
