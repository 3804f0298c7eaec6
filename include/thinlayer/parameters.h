#ifndef thinlayer_parameters_h
#define thinlayer_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <iosfwd>
#include <map>
#include <string>
#include <vector>

namespace thinlayer
{
  using namespace dealii;

  enum class YieldCriterion
  {
    elastic,
    tresca,
    von_mises,
    mohr_coulomb
  };

  /**
   * One material id (a gmsh physical surface): isotropic elasticity and an
   * elastic-perfectly plastic yield criterion.
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
  };

  /// The direct solver of the constant stiffness.
  enum class LinearSolver
  {
    cholmod,
    umfpack
  };

  /**
   * How the elasto-plastic equations of a load step are solved.
   */
  enum class SolutionMethod
  {
    /// The paper's: constant stiffness, viscoplastic strain iterations.
    viscoplastic,
    /// Constant stiffness, return mapping, the stress excess as body loads.
    initial_stress,
    /// Initial stress with Anderson acceleration on the same factor.
    accelerated_initial_stress,
    /// Consistent tangent, line search, load-step cut-back.
    newton
  };

  /**
   * When an iteration of the constant-stiffness method has converged.
   */
  enum class ConvergenceCriterion
  {
    /// The paper's: no body load, divided by the largest, changed by more
    /// than the tolerance between two iterations.
    body_loads,
    /// The same test on the displacement increment of the step.
    displacements,
    /// Return-mapping methods: the out-of-balance force against the
    /// largest external or internal force (reactions included).
    residual
  };

  /**
   * Conditions on one boundary id (a gmsh physical curve). Prescribed
   * displacements, tractions and pressures are all given per unit load
   * factor, so that one load programme scales all of them together.
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
  };

  /**
   * How the "load" column of history.csv is measured.
   */
  enum class LoadMeasure
  {
    /// The load factor times a scale (e.g. a traction times an area).
    load_factor,
    /// The sum of reactions on a boundary id in one direction.
    reaction,
    /// The average of a stress component over a material id.
    stress_average
  };

  /**
   * How the "displacement" column of history.csv is measured.
   */
  enum class DisplacementMeasureType
  {
    /// Length-weighted average over a boundary id.
    boundary_average,
    /// The value at a point.
    point
  };

  /**
   * Everything one analysis needs, read from a parameter file (plus
   * command-line overrides) by ParameterReader. Plain data: validation
   * happens while reading, so code that receives a Parameters object can
   * trust it.
   */
  struct Parameters
  {
    /// The parameter file, as given on the command line (for messages).
    std::string parameter_file;

    /// Every entry as used, overrides applied, in parameter-file format:
    /// the record of what ran.
    std::string effective_parameters;

    // Mesh
    /// The mesh or geometry file, resolved relative to the parameter file.
    std::string                   mesh_file;
    std::map<std::string, double> geometry_parameters;

    // Kinematics
    bool fourier;
    /// Fourier: the harmonics, the series and the stations (radians).
    std::vector<unsigned int> harmonics;
    bool                      antisymmetric;
    std::vector<double>       station_angles;
    /// Fourier: the boundary id of the axis r = 0, or -1 if the mesh does
    /// not reach it.
    int axis_boundary_id;

    // Discretisation
    /// true: 8-node serendipity (constrained Q2); false: 9-node Q2.
    bool         serendipity;
    unsigned int gauss_points_per_direction;

    // Materials and boundaries, by id
    std::map<types::material_id, MaterialParameters> materials;
    std::map<types::boundary_id, BoundaryParameters> boundaries;

    // Loading: increments of the load factor, one per load step.
    std::vector<double> load_increments;

    // Solver
    SolutionMethod       method;
    unsigned int         anderson_depth;
    unsigned int         max_cut_backs;
    unsigned int         max_newton_iterations;
    ConvergenceCriterion convergence_criterion;
    double               tolerance;
    unsigned int         max_iterations;
    bool                 continue_after_failure;
    LinearSolver         linear_solver;

    // Monitors
    LoadMeasure        load_measure;
    double             load_scale;
    types::boundary_id load_boundary_id;
    unsigned int       load_component;
    types::material_id load_material_id;
    /// (i, j) of the averaged stress component.
    std::pair<unsigned int, unsigned int> load_stress_component;
    DisplacementMeasureType               displacement_measure;
    /// Fourier: the angle (radians) at which displacements are monitored.
    double              displacement_angle;
    std::vector<double> displacement_point;
    types::boundary_id  displacement_boundary_id;
    unsigned int        displacement_component;
    double              displacement_scale;

    // Reference: the analytic value of the load the run is compared with,
    // evaluated from the geometry parameters; NaN where none is declared.
    double reference_load;

    /**
     * Sweep: the runs are the cartesian product of these value lists. A
     * name with a '/' is an entry ("Solver/Tolerance"), any other name a
     * geometry parameter. Empty: a single run.
     */
    std::vector<std::pair<std::string, std::vector<std::string>>> sweep;

    // Output
    std::string  output_directory;
    bool         write_vtu;
    unsigned int vtu_subdivisions;
    bool         print_timing;
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
