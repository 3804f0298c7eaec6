#ifndef thinlayer_parameters_scene_sections_h
#define thinlayer_parameters_scene_sections_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <thinlayer/base/name_table.h>

#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace thinlayer
{
  using namespace dealii;

  // The sections of the scene: its mesh, kinematics, element, materials
  // and boundaries (source/parameters/scene_sections.cc).

  /// "Mesh": the gmsh file and the values of its geometry parameters.
  struct MeshParameters
  {
    /// The mesh or geometry file, resolved relative to the parameter file.
    std::string file;
    /// Values of the .geo file's DefineConstant[] parameters; also
    /// constants in every expression of the parameter file.
    std::map<std::string, double> geometry_parameters;
    /// The most cells a scene may have (a mistyped geometry parameter
    /// otherwise meshes until the machine runs out of memory).
    unsigned int max_cells;
    /// Whether the cells along the circles and arcs of a .geo follow them
    /// (attach_arcs()), or keep straight sides (the polygon gmsh meshes).
    bool curved_cells;
    /// Whether gmsh may run a .geo that runs programs or writes files
    /// (check_geometry_script()).
    bool trust_geometry_scripts;
    /// Seconds gmsh may take for each of its runs on a .geo.
    double meshing_time_limit;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm, const std::string &parameter_file);
  };

  /// "Kinematics": plane strain, or Fourier harmonics of an axisymmetric
  /// body.
  struct KinematicsParameters
  {
    bool fourier;
    /// The mesh's dimension: 3 for Type = 3d (components x, y, z), else 2.
    unsigned int dimension;
    /// Fourier: the harmonics, the series and the stations (radians).
    /// Plane strain: harmonic 0 and one station at 0.
    std::vector<unsigned int> harmonics;
    bool                      antisymmetric;
    std::vector<double>       station_angles;
    /// Fourier: the boundary id of the axis r = 0, or -1 if the mesh does
    /// not reach it.
    int axis_boundary_id;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm, const std::string &parameter_file);

    /// The names of the displacement components, as the parameter files
    /// write them: x, y (plane strain); r, z, theta (Fourier); x, y, z.
    std::vector<std::string>
    component_names() const;

    /// The variables of a boundary expression, as FunctionParser<3> takes
    /// them: "x,y,unused_z", "r,z,theta" or "x,y,z".
    std::string
    expression_variables() const;

  private:
    /// An InputError unless the stations are equally spaced over [0, 180]
    /// degrees and enough for the highest harmonic.
    void
    check_stations(const std::string &parameter_file,
                   const std::string &text) const;
  };

  /// "Discretisation": the element and its Gauss points.
  struct DiscretisationParameters
  {
    /// true: 8-node serendipity (constrained Q2; 20-node in 3D); false:
    /// 9-node Q2 (27-node).
    bool         serendipity;
    unsigned int gauss_points_per_direction;
    /// As the file names it (Q8, Q9, Q20 or Q27; Q8 by default, the
    /// serendipity family in 3D too).
    std::string element_name;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler           &prm,
          const std::string          &parameter_file,
          const KinematicsParameters &kinematics);
  };

  enum class YieldCriterion
  {
    elastic,
    tresca,
    von_mises,
    mohr_coulomb
  };

  /**
   * "Material <id>", one per material id (a gmsh physical surface):
   * isotropic elasticity and an elastic-perfectly plastic yield criterion.
   */
  struct MaterialParameters
  {
    std::string    name;
    double         youngs_modulus;
    double         poissons_ratio;
    YieldCriterion yield_criterion;
    /// c: adhesion C_w of an interface, undrained strength c_u of a soil.
    double cohesion;
    /// phi and psi, in degrees.
    double friction_angle;
    double dilation_angle;
    /// gamma, the weight per unit volume, acting along -y (body_loads.h).
    double unit_weight;
    /// The ratio sigma_h / sigma_v of the K0 procedure's initial stresses.
    double k0;

    static const NameTable<YieldCriterion> yield_criterion_names;

    /// The section's name: "Material <id>".
    static std::string
    section(const unsigned int id);
    static void
    declare(ParameterHandler &prm, const unsigned int id);
    void
    parse(ParameterHandler  &prm,
          const std::string &parameter_file,
          const unsigned int id);
  };

  /**
   * "Boundary <id>", one per boundary id (a gmsh physical curve).
   * Prescribed displacements, tractions and pressures are all given per
   * unit load factor, so that one load programme scales all of them
   * together.
   */
  struct BoundaryParameters
  {
    std::string name;
    /// Which components are prescribed: (x, y) in plane strain, (r, z,
    /// theta) for Fourier kinematics.
    std::vector<bool> constrained_components;
    /// Function expressions, one per component, ';'-separated: of x, y in
    /// plane strain; of r, z, theta for Fourier kinematics, where they are
    /// the Cartesian components (x, y, z) with z along the axis.
    std::string displacement;
    std::string traction;
    /// Normal pressure, positive when it pushes into the body.
    std::string pressure;

    /// The section's name: "Boundary <id>".
    static std::string
    section(const unsigned int id);
    /// With @p in_phase, as a subsection of a loading phase (`Phase <n>`).
    static void
    declare(ParameterHandler  &prm,
            const unsigned int id,
            const bool         in_phase = false);
    /// The expressions are checked against the kinematics' variables and
    /// the geometry parameters. Inside a section @p outer (as "Phase 2/",
    /// which the errors name), with the constrained components
    /// @p constrained rather than the section's own.
    void
    parse(ParameterHandler           &prm,
          const std::string          &parameter_file,
          const unsigned int          id,
          const KinematicsParameters &kinematics,
          const MeshParameters       &mesh,
          const std::string          &outer       = "",
          const std::vector<bool>    &constrained = {});

  private:
    /// An InputError for a traction or pressure on constrained components.
    void
    check_loads_where_free(const std::string          &parameter_file,
                           const std::string          &section,
                           const KinematicsParameters &kinematics) const;
  };
} // namespace thinlayer

#endif
