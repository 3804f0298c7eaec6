#ifndef thinlayer_parameters_run_sections_h
#define thinlayer_parameters_run_sections_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <thinlayer/base/name_table.h>

#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace thinlayer
{
  using namespace dealii;

  struct KinematicsParameters;
  struct MeshParameters;

  // The sections of the run: its solver, monitors, reference and output
  // (source/parameters/run_sections.cc).

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

    /// The solver of the constant stiffness: direct on one rank (MUMPS on
    /// several), or iterative; automatic chooses by the ranks
    /// (choose_linear_solver()).
    enum class LinearSolver
    {
      automatic,
      cholmod,
      umfpack,
      block_low_rank,
      amg_cg
    };

    /// How Newton solves its corrections.
    enum class NewtonCorrections
    {
      /// The tangent factorised at every iteration.
      factorised,
      /// GMRES preconditioned by a factor kept from an earlier tangent
      /// (or the elastic stiffness), refactorised only when GMRES needs
      /// more than Krylov iterations to reach its forcing term.
      krylov
    };

    static const NameTable<Method>               method_names;
    static const NameTable<NewtonCorrections>    newton_corrections_names;
    static const NameTable<ConvergenceCriterion> criterion_names;
    static const NameTable<LinearSolver>         linear_solver_names;

    Method            method;
    unsigned int      anderson_depth;
    unsigned int      max_cut_backs;
    unsigned int      max_newton_iterations;
    NewtonCorrections newton_corrections;
    /// Krylov: GMRES iterations a correction may take with the kept
    /// factor before the tangent is factorised.
    unsigned int         krylov_iterations;
    ConvergenceCriterion convergence_criterion;
    double               tolerance;
    unsigned int         max_iterations;
    bool                 continue_after_failure;
    /// The viscoplastic method's displacements and body loads rounded to
    /// 32-bit reals at every iteration (an experiment on the paper's
    /// stability finding).
    bool         single_precision;
    LinearSolver linear_solver;
    /// MUMPS's block low-rank compression: its blocks' dropping threshold.
    double block_low_rank_tolerance;
    /// AMG-CG: the residual reduction of a solve, and its iteration limit.
    double       linear_solver_tolerance;
    unsigned int linear_solver_iterations;
    /// On several ranks: each Fourier harmonic factorised whole on one
    /// rank (rather than split over all).
    bool spread_harmonics;

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
      /// 3D: along z.
      z,
      /// Plane strain and 3D: about the z axis through the origin.
      /// Fourier: about the horizontal axis through the origin normal to
      /// theta = 0 (overturning, from harmonic 1), the same axis for a
      /// body whose axis is y and theta = 0 along x.
      moment,
      /// Fourier: about the axis (torsion, the antisymmetric harmonic 0).
      /// 3D: about the y axis through the origin.
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

  /// "Output": where results go and which.
  struct OutputParameters
  {
    std::string directory;
    bool        write_vtu;
    /// The VTU fields of every n-th accepted step (and always of the last
    /// one, and of the failure that ends a run); 0: only those.
    unsigned int fields_interval;
    /// Whether the fields of attempts that were cut back are written too.
    bool         fields_of_cut_backs;
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
    /// Whether the interfaces' profiles are also written with the raw
    /// values at their integration points (NAME-gauss-NNNN.csv).
    bool gauss_point_profiles;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm, const std::string &parameter_file);
  };
} // namespace thinlayer

#endif
