#include <deal.II/base/utilities.h>

#include <thinlayer/base/input_error.h>
#include <thinlayer/parallel/mpi.h>
#include <thinlayer/parameters/parameter_checks.h>
#include <thinlayer/parameters/parameters.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

// The sections that describe a run of the model: solver, monitors and
// output (the loading and the initial state have loading_sections.cc, the
// reference reference_section.cc, the sweep sweep_section.cc).

namespace thinlayer
{
  const NameTable<SolverParameters::Method> SolverParameters::method_names = {
    {Method::viscoplastic, "viscoplastic"},
    {Method::initial_stress, "initial stress"},
    {Method::accelerated_initial_stress, "accelerated initial stress"},
    {Method::newton, "newton"},
    {Method::accelerated_with_newton_fallback,
     "accelerated with newton fallback"}};

  const NameTable<SolverParameters::NewtonCorrections>
    SolverParameters::newton_corrections_names = {
      {NewtonCorrections::factorised, "factorised"},
      {NewtonCorrections::krylov, "krylov"}};

  namespace
  {
    /// The Solver entry @p name, a value in (0, 1): @p meaning says what
    /// fraction it is.
    double
    fraction(const ParameterHandler &prm,
             const std::string      &name,
             const std::string      &file,
             const std::string      &meaning)
    {
      const double value = positive(prm, name, file, "Solver");
      if (!(value < 1))
        throw InputError(file,
                         "Solver/" + name,
                         "expected a value in (0, 1), " + meaning + "; got " +
                           prm.get(name));
      return value;
    }
  } // namespace


  const NameTable<SolverParameters::ConvergenceCriterion>
    SolverParameters::criterion_names = {
      {ConvergenceCriterion::body_loads, "body loads"},
      {ConvergenceCriterion::displacements, "displacements"},
      {ConvergenceCriterion::residual, "residual"}};

  const NameTable<SolverParameters::LinearSolver>
    SolverParameters::linear_solver_names = {
      {LinearSolver::automatic, "automatic"},
      {LinearSolver::cholmod, "cholmod"},
      {LinearSolver::umfpack, "umfpack"},
      {LinearSolver::block_low_rank, "block low-rank"},
      {LinearSolver::amg_cg, "amg cg"}};


  void
  SolverParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    prm.declare_entry(
      "Method",
      "accelerated with newton fallback",
      Patterns::Selection(method_names.pattern()),
      "viscoplastic: the paper's constant-stiffness viscoplastic strain "
      "iterations; initial stress: constant stiffness, each point "
      "return-mapped, the stress excess as body loads; accelerated initial "
      "stress: the same with Anderson acceleration, still one factorisation; "
      "newton: the consistent tangent (its corrections as Newton "
      "corrections says), with a line search and load-step cut-back; "
      "accelerated with newton "
      "fallback (the default, the one the benchmarks find reliable on every "
      "scene): accelerated initial stress within a budget of iterations "
      "set by what a Newton step costs, and Newton for a step it cannot "
      "converge within it.");
    prm.declare_entry("Anderson depth",
                      "5",
                      Patterns::Integer(1, 50),
                      "Accelerated initial stress: how many previous "
                      "iterates the Anderson update combines.");
    prm.declare_entry("Maximum cut-backs",
                      "4",
                      Patterns::Integer(0, 20),
                      "Newton with the load programme as given "
                      "(Loading/Collapse resolution = 0): how often a load "
                      "step that does not converge is halved before it "
                      "counts as failed. Automatic stepping halves failed "
                      "steps itself, and this entry is then not used.");
    prm.declare_entry("Maximum Newton iterations",
                      "25",
                      Patterns::Integer(1),
                      "Newton: iterations per attempt at a load step before "
                      "it is cut back (Maximum iterations applies to the "
                      "constant-stiffness methods).");
    prm.declare_entry(
      "Newton corrections",
      "factorised",
      Patterns::Selection(newton_corrections_names.pattern()),
      "How Newton solves K_t du = r: factorised (the default: the "
      "tangent assembled and factorised at every iteration); or krylov "
      "(GMRES on the assembled tangent, preconditioned by a factor kept "
      "from an earlier iteration, or by the elastic factors before any "
      "tangent has been factorised, to the inexact-Newton forcing term of "
      "Eisenstat and Walker; the tangent is factorised, and kept, only "
      "when GMRES needs more than Krylov iterations). benchmarks/"
      "performance.py compares the two (the manual's page on running a "
      "scene).");
    prm.declare_entry("Krylov iterations",
                      "20",
                      Patterns::Integer(1, 500),
                      "Newton corrections = krylov: the GMRES iterations a "
                      "correction may take with the kept factor before "
                      "the tangent is factorised instead; a correction "
                      "that took more than half of them has the next "
                      "iteration's tangent factorised. A factorisation "
                      "costs some fifteen (2D) to some twenty-five (3D) "
                      "substitutions.");
    prm.declare_entry(
      "Convergence criterion",
      "default",
      Patterns::Selection("default|" + criterion_names.pattern()),
      "default: body loads for the viscoplastic method, residual for "
      "the others; body loads: the paper's test, no body load "
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
    prm.declare_entry(
      "Linear solver",
      "automatic",
      Patterns::Selection(linear_solver_names.pattern()),
      "The solver of the elastic stiffness and of Newton's tangents. "
      "automatic (the default): cholmod on one rank; on several, block "
      "low-rank for a 3D mesh and MUMPS uncompressed for a plane one "
      "(benchmarks/linear_solvers.py measures why); cholmod "
      "(sparse Cholesky, the stiffness being symmetric positive definite) "
      "or umfpack (LU), factorised once per analysis; on several ranks "
      "both mean MUMPS without compression; block low-rank: MUMPS with its "
      "block low-rank compression (several ranks only), which shortens a "
      "3D factorisation and its substitutions; amg cg (conjugate gradients "
      "preconditioned by PETSc's algebraic multigrid, GAMG, with the "
      "rigid-body motions), for a scene whose factors do not fit in "
      "memory: every solve then iterates, slowly where a thin layer is "
      "much stiffer than the soil (the manual's page on running a scene), "
      "and Newton's tangent is still factorised. The run reports its "
      "choice (summary.json's linear_solver).");
    prm.declare_entry("Block low-rank tolerance",
                      "1e-8",
                      Patterns::Double(0),
                      "Block low-rank compression: blocks of the factor are "
                      "stored as products of low rank up to this fraction "
                      "of the matrix's norm (MUMPS's CNTL(7)). A solve "
                      "then errs by about this tolerance times the matrix's "
                      "condition number, which the iterations correct, as "
                      "they test the true out-of-balance force; larger "
                      "values compress more, and the factor becomes a "
                      "preconditioner that the iterations correct.");
    prm.declare_entry("Linear solver tolerance",
                      "1e-10",
                      Patterns::Double(0),
                      "amg cg: a solve stops at a residual this fraction of "
                      "its right-hand side's.");
    prm.declare_entry("Linear solver iterations",
                      "2000",
                      Patterns::Integer(1),
                      "amg cg: the iteration limit of a solve; a solve that "
                      "reaches it ends the run with an error.");
    prm.declare_entry("Spread harmonics over ranks",
                      "true",
                      Patterns::Bool(),
                      "On several ranks, a Fourier scene with at least as "
                      "many harmonics as ranks: each rank factorises its "
                      "harmonics' elastic stiffness whole (the m-th on rank "
                      "m mod ranks) and substitutes them at the same time "
                      "as the others (true; faster, some 20% more memory "
                      "per rank), or every harmonic is split over all ranks "
                      "by MUMPS (false). Fewer harmonics than ranks are "
                      "always split.");
    prm.declare_entry("Continue after failure",
                      "false",
                      Patterns::Bool(),
                      "Go on with the next load step after a failed one "
                      "(true), or stop the analysis there (false). Only "
                      "with Loading/Collapse resolution = 0 (the programme "
                      "as given); automatic stepping always ends the run "
                      "at the bracketed collapse.");
    prm.declare_entry("Single precision",
                      "false",
                      Patterns::Bool(),
                      "An experiment on why the paper's thinner layers "
                      "needed tighter tolerances (viscoplastic method "
                      "only): the step's displacement increments and body "
                      "loads rounded to 32-bit reals at every iteration, "
                      "as codes of the paper's time held them; the "
                      "factorisation and the point rules stay in double "
                      "precision. Not for results.");
    prm.leave_subsection();
  }


  void
  SolverParameters::parse(ParameterHandler &prm, const std::string &file)
  {
    prm.enter_subsection("Solver");
    method                = method_names.value(prm.get("Method"));
    anderson_depth        = prm.get_integer("Anderson depth");
    max_cut_backs         = prm.get_integer("Maximum cut-backs");
    max_newton_iterations = prm.get_integer("Maximum Newton iterations");
    newton_corrections =
      newton_corrections_names.value(prm.get("Newton corrections"));
    krylov_iterations           = prm.get_integer("Krylov iterations");
    const std::string criterion = prm.get("Convergence criterion");
    convergence_criterion =
      criterion != "default"           ? criterion_names.value(criterion)
      : method == Method::viscoplastic ? ConvergenceCriterion::body_loads
                                       : ConvergenceCriterion::residual;
    if (method == Method::viscoplastic &&
        convergence_criterion == ConvergenceCriterion::residual)
      throw InputError(file,
                       "Solver/Convergence criterion",
                       "'body loads' or 'displacements' for the "
                       "viscoplastic method, whose stresses are in "
                       "equilibrium at every iteration (its out-of-balance "
                       "is the change of the body loads), not 'residual'");
    if ((method == Method::newton ||
         method == Method::accelerated_with_newton_fallback) &&
        convergence_criterion == ConvergenceCriterion::body_loads)
      throw InputError(file,
                       "Solver/Convergence criterion",
                       "'residual' or 'displacements' for Newton, not "
                       "'body loads': past collapse the stress excess "
                       "grows without bound and that test would pass");
    tolerance = positive(prm, "Tolerance", file, "Solver");
    if (!(tolerance < 1))
      throw InputError(file,
                       "Solver/Tolerance",
                       "expected a value in (0, 1): it is measured against "
                       "the largest force (or body load), so 1 or more "
                       "accepts any state; got " +
                         prm.get("Tolerance"));
    max_iterations         = prm.get_integer("Maximum iterations");
    continue_after_failure = prm.get_bool("Continue after failure");
    single_precision       = prm.get_bool("Single precision");
    if (single_precision && method != Method::viscoplastic)
      throw InputError(file,
                       "Solver/Single precision",
                       "false unless Solver/Method is viscoplastic (the "
                       "experiment rounds that method's displacements and "
                       "body loads)");
    linear_solver = linear_solver_names.value(prm.get("Linear solver"));
    if (linear_solver == LinearSolver::block_low_rank && mpi::n_ranks() == 1)
      throw InputError(file,
                       "Solver/Linear solver",
                       "block low-rank is MUMPS's, which thinlayer runs on "
                       "several ranks (mpirun); on one rank expected "
                       "automatic, cholmod, umfpack or amg cg");
    block_low_rank_tolerance = fraction(prm,
                                        "Block low-rank tolerance",
                                        file,
                                        "a fraction of the matrix's norm");
    linear_solver_tolerance =
      fraction(prm,
               "Linear solver tolerance",
               file,
               "the fraction of the right-hand side's residual a solve "
               "reaches");
    linear_solver_iterations = prm.get_integer("Linear solver iterations");
    spread_harmonics         = prm.get_bool("Spread harmonics over ranks");
    prm.leave_subsection();
  }


  const NameTable<MonitorParameters::LoadMeasure>
    MonitorParameters::load_measure_names = {
      {LoadMeasure::load_factor, "load factor"},
      {LoadMeasure::reaction, "reaction"},
      {LoadMeasure::stress_average, "stress average"}};

  const NameTable<MonitorParameters::LoadComponent>
    MonitorParameters::load_component_names = {
      {LoadComponent::x, "x"},
      {LoadComponent::y, "y"},
      {LoadComponent::z, "z"},
      {LoadComponent::moment, "moment"},
      {LoadComponent::torque, "torque"}};

  const NameTable<MonitorParameters::DisplacementMeasure>
    MonitorParameters::displacement_measure_names = {
      {DisplacementMeasure::boundary_average, "boundary average"},
      {DisplacementMeasure::point, "point"}};


  void
  MonitorParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Monitors");
    prm.declare_entry("Load measure",
                      "load factor",
                      Patterns::Selection(load_measure_names.pattern()),
                      "What the 'load' column reports: the load factor; "
                      "the resultant of the reactions on 'Load boundary "
                      "id' ('Load component'); or the average of 'Load "
                      "stress component' over 'Load material id' (Fourier: "
                      "over its r-z section at theta = 0, weighted by r). "
                      "Each is multiplied by 'Load scale' (e.g. a "
                      "length).");
    prm.declare_entry("Load scale",
                      "1",
                      Patterns::Double(),
                      "Factor applied to the load measure (e.g. the area a "
                      "unit traction acts on, or -1 for a sign).");
    prm.declare_entry("Load boundary id",
                      "0",
                      Patterns::Integer(0),
                      "Boundary id whose reactions are summed.");
    prm.declare_entry(
      "Load component",
      "y",
      Patterns::Selection(load_component_names.pattern()),
      "The resultant of the reactions. Plane strain (per unit length): x, "
      "y, or the moment about the out-of-plane axis through the origin. "
      "3d: x, y, z, moment about the z axis and torque about the y axis, "
      "both through the origin. "
      "Fourier (the whole body): y the axial force (harmonic 0), x the "
      "force in the direction theta = 0 (harmonic 1), moment the "
      "overturning moment about the horizontal axis through the origin "
      "normal to theta = 0 (harmonic 1), torque the moment about the axis "
      "(the antisymmetric harmonic 0).");
    prm.declare_entry("Load material id",
                      "0",
                      Patterns::Integer(0),
                      "Material id over which a stress is averaged.");
    prm.declare_entry("Load stress component",
                      "xx",
                      Patterns::Selection("xx|yy|zz|xy|xz|yz"),
                      "The averaged stress component (tension positive).");
    prm.declare_entry("Displacement measure",
                      "boundary average",
                      Patterns::Selection(displacement_measure_names.pattern()),
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
                      Patterns::List(Patterns::Double(), 2, 3),
                      "The point x, y (x, y, z in 3d) for the point "
                      "measure.");
    prm.declare_entry("Displacement boundary id",
                      "0",
                      Patterns::Integer(0),
                      "Boundary id over which the displacement is "
                      "averaged (length-weighted); min and max over its "
                      "nodes are reported too.");
    prm.declare_entry("Displacement component",
                      "y",
                      Patterns::Selection("x|y|z"),
                      "Component of the monitored displacement (z in 3d "
                      "only).");
    prm.declare_entry("Displacement scale",
                      "1",
                      Patterns::Double(),
                      "Factor applied to the monitored displacement (e.g. "
                      "-1 to report settlement as positive).");
    prm.leave_subsection();
  }


  void
  MonitorParameters::check_load_component(
    const std::string          &file,
    const KinematicsParameters &kinematics) const
  {
    const std::string component = load_component_names.name(load_component);
    if (kinematics.dimension == 3)
      return;
    if (!kinematics.fourier)
      {
        if (load_component == LoadComponent::torque ||
            load_component == LoadComponent::z)
          throw InputError(file,
                           "Monitors/Load component",
                           "a " + component +
                             " resultant needs Fourier or 3d kinematics; "
                             "in plane strain expected x, y or moment");
        return;
      }
    if (load_component == LoadComponent::z)
      throw InputError(file,
                       "Monitors/Load component",
                       "a Fourier body's resultants are x, y, moment and "
                       "torque; z is for 3d kinematics");
    // The resultant comes from one harmonic of one series: without it the
    // body carries no such resultant, which is not what was meant.
    const unsigned int n      = (load_component == LoadComponent::y ||
                            load_component == LoadComponent::torque)
                                  ? 0
                                  : 1;
    const bool  antisymmetric = (load_component == LoadComponent::torque);
    const auto &h             = kinematics.harmonics;
    if (kinematics.antisymmetric != antisymmetric ||
        std::find(h.begin(), h.end(), n) == h.end())
      throw InputError(file,
                       "Monitors/Load component",
                       "the " + component +
                         " resultant of Fourier reactions "
                         "comes from harmonic " +
                         std::to_string(n) + " of the " +
                         (antisymmetric ? "antisymmetric" : "symmetric") +
                         " series, which Kinematics does not have");
  }


  void
  MonitorParameters::parse(ParameterHandler           &prm,
                           const std::string          &file,
                           const KinematicsParameters &kinematics)
  {
    prm.enter_subsection("Monitors");
    load_measure     = load_measure_names.value(prm.get("Load measure"));
    load_material_id = prm.get_integer("Load material id");
    const std::string component = prm.get("Load stress component");
    load_stress_component       = {component[0] == 'x' ? 0u : 1u,
                             component[1] == 'x'   ? 0u
                                   : component[1] == 'y' ? 1u
                                                         : 2u};
    if (component == "zz")
      load_stress_component = {2u, 2u};
    displacement_angle =
      prm.get_double("Displacement angle") * numbers::PI / 180;
    load_component = load_component_names.value(prm.get("Load component"));
    if (load_measure == LoadMeasure::reaction)
      check_load_component(file, kinematics);
    displacement_measure =
      displacement_measure_names.value(prm.get("Displacement measure"));
    displacement_point.clear();
    for (const auto &x :
         Utilities::split_string_list(prm.get("Displacement point")))
      displacement_point.push_back(std::stod(x));
    load_scale         = prm.get_double("Load scale");
    displacement_scale = prm.get_double("Displacement scale");
    for (const auto &[name, value] :
         {std::pair<const char *, double>{"Load scale", load_scale},
          {"Displacement scale", displacement_scale}})
      if (value == 0)
        throw InputError(file,
                         std::string("Monitors/") + name,
                         "expected a non-zero factor: 0 reports every "
                         "state as 0");
    load_boundary_id         = prm.get_integer("Load boundary id");
    displacement_boundary_id = prm.get_integer("Displacement boundary id");
    const std::string displacement = prm.get("Displacement component");
    displacement_component         = displacement == "x"   ? 0
                                     : displacement == "y" ? 1
                                                           : 2;
    if (displacement_component == 2 && kinematics.dimension != 3)
      throw InputError(file,
                       "Monitors/Displacement component",
                       "z is a component of 3d kinematics; expected x or y");
    if (displacement_measure == DisplacementMeasure::point &&
        displacement_point.size() != kinematics.dimension)
      throw InputError(file,
                       "Monitors/Displacement point",
                       "expected " + std::to_string(kinematics.dimension) +
                         " coordinates, got '" + prm.get("Displacement point") +
                         "'");
    prm.leave_subsection();
  }


  void
  OutputParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry("Directory",
                      "output",
                      Patterns::Anything(),
                      "Where results go, relative to the working "
                      "directory; created if missing.");
    prm.declare_entry("Write VTU",
                      "true",
                      Patterns::Bool(),
                      "Write VTU/PVD fields for ParaView (which steps: "
                      "Fields interval).");
    prm.declare_entry("Fields interval",
                      "1",
                      Patterns::Integer(0),
                      "With Write VTU: the fields of every n-th accepted "
                      "step (fields.pvd), and always those of the last "
                      "accepted state of each phase and of the failed "
                      "attempt that ends a run, the collapse mechanism "
                      "(attempts.pvd); 0 for those alone. Writing the "
                      "fields is the largest cost after the solver on a "
                      "fine mesh.");
    prm.declare_entry("Fields of cut-back attempts",
                      "false",
                      Patterns::Bool(),
                      "With Write VTU: also the fields of every attempt "
                      "that was cut back and tried again with a smaller "
                      "step (attempts.pvd), for studying a failure.");
    prm.declare_entry("VTU subdivisions",
                      "2",
                      Patterns::Integer(1, 8),
                      "Patches per cell edge in VTU output (2 shows the "
                      "quadratic fields).");
    prm.declare_entry("3D view slices",
                      "0",
                      Patterns::Integer(0, 360),
                      "Fourier: with Write VTU, also write the body "
                      "revolved about its axis, swept through this many "
                      "equal angles over the circle, as revolved-NNNN.vtu "
                      "(revolved.pvd) for ParaView: the summed displacement "
                      "and the stations' stresses. 0 for none.");
    prm.declare_entry("Progress interval",
                      "5",
                      Patterns::Double(0),
                      "Seconds between the lines a long load step prints "
                      "while it iterates (its iteration and convergence "
                      "measure); 0 for none, which makes the screen output "
                      "independent of the machine's speed (the tests).");
    prm.declare_entry("Gauss-point profiles",
                      "false",
                      Patterns::Bool(),
                      "Also write each interface's profile with the raw "
                      "tractions at its integration points, as "
                      "NAME-gauss-NNNN.csv (and .vtu with Write VTU) beside "
                      "NAME-NNNN.csv, whose tractions are recovered at the "
                      "nodes from the interface's nodal forces. Once the "
                      "soil flows the raw ones can oscillate from point to "
                      "point; they are there for studying that.");
    prm.declare_entry("Print timing",
                      "true",
                      Patterns::Bool(),
                      "Print wall time and the timer table on screen "
                      "(timings always go to summary.json).");
    prm.declare_entry("Print iterations",
                      "true",
                      Patterns::Bool(),
                      "Print each load step's iteration count on screen "
                      "(history.csv always has it). The tests turn it off "
                      "where the count is not their truth: it can change by "
                      "one with the BLAS's rounding.");
    prm.leave_subsection();
  }


  void
  OutputParameters::parse(ParameterHandler &prm, const std::string &file)
  {
    prm.enter_subsection("Output");
    directory = prm.get("Directory");
    if (directory.empty())
      throw InputError(file, "Output/Directory", "expected a directory");
    write_vtu            = prm.get_bool("Write VTU");
    fields_interval      = prm.get_integer("Fields interval");
    fields_of_cut_backs  = prm.get_bool("Fields of cut-back attempts");
    vtu_subdivisions     = prm.get_integer("VTU subdivisions");
    view_slices          = prm.get_integer("3D view slices");
    print_timing         = prm.get_bool("Print timing");
    print_iterations     = prm.get_bool("Print iterations");
    progress_interval    = prm.get_double("Progress interval");
    gauss_point_profiles = prm.get_bool("Gauss-point profiles");
    prm.leave_subsection();
  }
} // namespace thinlayer
