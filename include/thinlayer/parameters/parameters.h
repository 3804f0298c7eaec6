#ifndef thinlayer_parameters_parameters_h
#define thinlayer_parameters_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <thinlayer/base/name_table.h>

#include <cmath>
#include <iosfwd>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /**
   * @file
   * The parameter file, one struct per section in the style of deal.II's
   * step-44: each declares its entries (declare()) and reads them back
   * (parse()) side by side, and checks them while reading, so that code
   * that receives a section can trust it. Every check names the file, the
   * entry and what was expected (InputError). Each component of the code
   * receives only the sections it needs.
   *
   * Enumerations have one NameTable each, which gives the entry's
   * Patterns::Selection, its parsing and the name written into results.
   */

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
    /// true: 8-node serendipity (constrained Q2); false: 9-node Q2.
    bool         serendipity;
    unsigned int gauss_points_per_direction;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm);
  };


  /// "Layers" (called "Interfaces" before, which is still accepted, with a
  /// warning): the thin layers whose profile a run reports.
  struct LayerParameters
  {
    /// Material ids of thin layers (one cell thick).
    std::vector<types::material_id> material_ids;

    static void
    declare(ParameterHandler &prm);
    /// Every id must have its Material section (@p materials).
    void
    parse(ParameterHandler                   &prm,
          const std::string                  &parameter_file,
          const std::set<types::material_id> &materials);
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
   * "Interface curve <id>", one per gmsh physical curve that carries
   * zero-thickness (Goodman-type) interface elements: the mesh is split
   * along the curve when read, and each pair of facing cell sides is
   * coupled by an InterfaceLaw.
   */
  struct InterfaceElementParameters
  {
    enum class Criterion
    {
      elastic,
      tresca,
      mohr_coulomb
    };
    enum class Integration
    {
      gauss,
      lobatto
    };
    static const NameTable<Criterion>   criterion_names;
    static const NameTable<Integration> integration_names;

    std::string name;
    /// k_n and k_s, traction per unit relative displacement.
    double    normal_stiffness;
    double    shear_stiffness;
    Criterion criterion;
    /// c (adhesion), phi and psi (degrees), and the tension cut-off T
    /// (infinity for none).
    double      adhesion;
    double      friction_angle;
    double      dilation_angle;
    double      tensile_strength;
    Integration integration;
    /// Points per cell side: Gauss 2 or 3; Lobatto 3 (the side's nodes).
    unsigned int points;

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
    static void
    declare(ParameterHandler &prm, const unsigned int id);
    /// The expressions are checked against the kinematics' variables and
    /// the geometry parameters.
    void
    parse(ParameterHandler           &prm,
          const std::string          &parameter_file,
          const unsigned int          id,
          const KinematicsParameters &kinematics,
          const MeshParameters       &mesh);

  private:
    /// An InputError for a traction or pressure on constrained components.
    void
    check_loads_where_free(const std::string &parameter_file,
                           const std::string &section,
                           const bool         fourier) const;
  };


  /// "Loading": the load programme.
  struct LoadingParameters
  {
    /// Increments of the load factor, one per load step: the programme.
    std::vector<double> load_increments;
    /// Automatic stepping: a failed step is halved and retried until the
    /// collapse load is bracketed to this fraction of the load factor; 0
    /// runs the programme as given (LoadStepping).
    double collapse_resolution;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm, const std::string &parameter_file);
  };


  /// "Solver": how the elasto-plastic equations of a load step are solved.
  struct SolverParameters
  {
    /// The solution methods; each is a class of its own (see
    /// create_solution_method()).
    enum class Method
    {
      /// The paper's: constant stiffness, viscoplastic strain iterations.
      viscoplastic,
      /// Constant stiffness, return mapping, the stress excess as body
      /// loads.
      initial_stress,
      /// Initial stress with Anderson acceleration on the same factor.
      accelerated_initial_stress,
      /// Consistent tangent, line search, load-step cut-back.
      newton,
      /// Accelerated initial stress; Newton where it fails a step.
      accelerated_with_newton_fallback
    };

    /// When the iterations of a load step have converged.
    enum class ConvergenceCriterion
    {
      /// The paper's: no body load, divided by the largest, changed by
      /// more than the tolerance between two iterations.
      body_loads,
      /// The same test on the displacement increment of the step.
      displacements,
      /// Return-mapping methods: the out-of-balance force against the
      /// largest external or internal force (reactions included).
      residual
    };

    /// The direct solver of the constant stiffness.
    enum class LinearSolver
    {
      cholmod,
      umfpack
    };

    static const NameTable<Method>               method_names;
    static const NameTable<ConvergenceCriterion> criterion_names;
    static const NameTable<LinearSolver>         linear_solver_names;

    Method               method;
    unsigned int         anderson_depth;
    unsigned int         max_cut_backs;
    unsigned int         max_newton_iterations;
    ConvergenceCriterion convergence_criterion;
    double               tolerance;
    unsigned int         max_iterations;
    bool                 continue_after_failure;
    LinearSolver         linear_solver;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm, const std::string &parameter_file);
  };


  /// "Monitors": what the load and displacement columns of history.csv
  /// measure.
  struct MonitorParameters
  {
    enum class LoadMeasure
    {
      /// The load factor times a scale (e.g. a traction times an area).
      load_factor,
      /// The sum of reactions on a boundary id in one direction.
      reaction,
      /// The average of a stress component over a material id.
      stress_average
    };

    enum class DisplacementMeasure
    {
      /// Length-weighted average over a boundary id.
      boundary_average,
      /// The value at a point.
      point
    };

    /// The resultant of the reactions that the reaction measure reports.
    enum class LoadComponent
    {
      /// Along x (Fourier: the direction theta = 0, from harmonic 1).
      x,
      /// Along y (Fourier: the axis, from harmonic 0).
      y,
      /// Plane strain: about the out-of-plane axis through the origin.
      /// Fourier: about the horizontal axis through the origin normal to
      /// theta = 0 (overturning, from harmonic 1).
      moment,
      /// Fourier: about the axis (torsion, the antisymmetric harmonic 0).
      torque
    };

    static const NameTable<LoadMeasure>         load_measure_names;
    static const NameTable<LoadComponent>       load_component_names;
    static const NameTable<DisplacementMeasure> displacement_measure_names;

    LoadMeasure        load_measure;
    double             load_scale;
    types::boundary_id load_boundary_id;
    LoadComponent      load_component;
    types::material_id load_material_id;
    /// (i, j) of the averaged stress component.
    std::pair<unsigned int, unsigned int> load_stress_component;
    DisplacementMeasure                   displacement_measure;
    /// Fourier: the angle (radians) at which displacements are monitored.
    double              displacement_angle;
    std::vector<double> displacement_point;
    types::boundary_id  displacement_boundary_id;
    unsigned int        displacement_component;
    double              displacement_scale;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler           &prm,
          const std::string          &parameter_file,
          const KinematicsParameters &kinematics);

  private:
    /// An InputError for a reaction component the kinematics cannot give.
    void
    check_load_component(const std::string          &parameter_file,
                         const KinematicsParameters &kinematics) const;
  };


  /**
   * "Reference": the analytic value of the load the run is compared with,
   * and what a scene that verifies a closed form expects of its run: the
   * outcome and the range, as multiples of the analytic load, its load must
   * end in. A run that misses them is reported and exits non-zero, so a
   * verification scene fails on its own truth, whatever its screen output.
   */
  struct ReferenceParameters
  {
    /// Evaluated from the geometry parameters; NaN where none is declared.
    double analytic_load;
    /// The outcome the run must end in; empty for any.
    std::string expected_outcome;
    /// The range, as multiples of analytic_load (in load units where there
    /// is none), the run's load (its collapse load where it has one, else
    /// its last converged load) must lie in; NaN for no check.
    double expected_low  = std::numeric_limits<double>::quiet_NaN();
    double expected_high = std::numeric_limits<double>::quiet_NaN();

    /// Whether the parameter file expects anything of the run.
    bool
    expects_something() const
    {
      return !expected_outcome.empty() || std::isfinite(expected_low);
    }

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler     &prm,
          const std::string    &parameter_file,
          const MeshParameters &mesh);
  };


  /**
   * "Sweep": the runs are the cartesian product of these value lists. A
   * name with a '/' is an entry ("Solver/Tolerance"), any other name a
   * geometry parameter. Empty: a single run.
   */
  struct SweepParameters
  {
    /// The most runs a sweep may have: checking each takes milliseconds
    /// and running each seconds, so more is a mistyped list.
    static constexpr std::size_t max_runs = 10000;

    std::vector<std::pair<std::string, std::vector<std::string>>> values;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm, const std::string &parameter_file);
  };


  /// "Output": where results go and which.
  struct OutputParameters
  {
    std::string  directory;
    bool         write_vtu;
    unsigned int vtu_subdivisions;
    /// Fourier: slices of the revolved 3D view over the circle; 0 for none.
    unsigned int view_slices;
    bool         print_timing;
    /// Whether the screen shows iteration counts (history.csv always has
    /// them): a count can change with rounding, which the tests' compared
    /// screen output must not depend on.
    bool print_iterations;
    /// Seconds between a long step's progress lines; 0 for none.
    double progress_interval;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm, const std::string &parameter_file);
  };


  /**
   * Everything one analysis needs, read from a parameter file (plus
   * command-line overrides) by ParameterReader: one member per section.
   */
  struct Parameters
  {
    /// The parameter file, as given on the command line (for messages).
    std::string parameter_file;

    /// Every entry as used, overrides applied, in parameter-file format:
    /// the record of what ran.
    std::string effective_parameters;
    /// What the file asks of that is accepted but should change (a
    /// section's former name): one line each, shown when the run starts.
    std::vector<std::string> warnings;

    MeshParameters                                   mesh;
    KinematicsParameters                             kinematics;
    DiscretisationParameters                         discretisation;
    LayerParameters                                  layers;
    std::map<types::material_id, MaterialParameters> materials;
    std::map<types::boundary_id, BoundaryParameters> boundaries;
    /// Physical curves of zero-thickness interface elements.
    std::map<types::boundary_id, InterfaceElementParameters> interface_elements;
    LoadingParameters                                        loading;
    SolverParameters                                         solver;
    MonitorParameters                                        monitors;
    ReferenceParameters                                      reference;
    SweepParameters                                          sweep;
    OutputParameters                                         output;
  };


  /**
   * Reads parameter files into Parameters. Per-id sections ("Material 3",
   * "Boundary 2") cannot be declared in advance because the ids come from the
   * user's mesh, so the reader first scans the file and the overrides for
   * such section names and declares exactly those.
   */
  class ParameterReader
  {
  public:
    /**
     * Read @p file, then apply @p overrides of the form
     * "Section/Subsection/Entry=value". Throws InputError naming the file
     * (or the override) and the entry on any problem.
     */
    Parameters
    read(const std::string              &file,
         const std::vector<std::string> &overrides = {}) const;

    /**
     * Same as read(), from the text of a parameter file; @p file_name is
     * used in messages and to resolve the mesh path.
     */
    Parameters
    read_from_string(const std::string              &text,
                     const std::string              &file_name,
                     const std::vector<std::string> &overrides = {}) const;

    /**
     * Every entry with its documentation and default, with one example
     * material and boundary section.
     */
    void
    print_parameters(std::ostream &out) const;
  };
} // namespace thinlayer

#endif
