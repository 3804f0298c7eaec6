#ifndef thinlayer_output_run_summary_h
#define thinlayer_output_run_summary_h

#include <limits>
#include <map>
#include <string>
#include <vector>

namespace thinlayer
{
  /**
   * How one phase of a run ended (the initial state, the loading, each
   * further loading phase, the strength reduction): the outcomes apply per
   * phase, and a phase that does not complete ends the run, so only the
   * last of these can be other than "completed" or "set".
   */
  struct PhaseSummary
  {
    std::string  name;
    std::string  outcome;
    std::string  reason;
    unsigned int load_steps = 0;
    /// The phase's collapse load (or plateau), NaN where it has none.
    double collapse_load       = std::numeric_limits<double>::quiet_NaN();
    double last_converged_load = std::numeric_limits<double>::quiet_NaN();
    /// The monitored displacement at the phase's last converged state
    /// (mean).
    double final_displacement = std::numeric_limits<double>::quiet_NaN();
  };


  /**
   * One cycle of an adaptive run: its mesh and what the load path gave on
   * it.
   */
  struct CycleSummary
  {
    unsigned int cycle = 0;
    /// The cells flagged to make this cycle's mesh from the last one (0
    /// for the mesh as given).
    unsigned int refined_cells = 0;
    unsigned int cells         = 0;
    unsigned int dofs          = 0;
    unsigned int equations     = 0;
    std::string  outcome;
    double       collapse_load  = std::numeric_limits<double>::quiet_NaN();
    double       relative_error = std::numeric_limits<double>::quiet_NaN();
    double       wall_seconds   = std::numeric_limits<double>::quiet_NaN();
  };


  /**
   * The cycles of an adaptive run (Adaptivity section) and where they lead:
   * the collapse load extrapolated from the last three cycles where their
   * changes show a rate, P = P_inf + C DoFs^(-rate).
   */
  struct AdaptivitySummary
  {
    std::string               indicator;
    std::string               marking;
    std::vector<CycleSummary> cycles;
    /// Why no further cycle ran.
    std::string stop_reason;
    double      extrapolated_collapse_load =
      std::numeric_limits<double>::quiet_NaN();
    /// The extrapolated load against the reference load.
    double extrapolated_relative_error =
      std::numeric_limits<double>::quiet_NaN();
    /// The last cycle's collapse load against the extrapolated one: its
    /// estimated discretisation error.
    double estimated_error = std::numeric_limits<double>::quiet_NaN();
    double rate            = std::numeric_limits<double>::quiet_NaN();
  };


  /**
   * The figures of one run: what it was (model, discretisation, size), how
   * it ended (collapse load against the reference, iterations) and what it
   * cost. This is the one list of them: summary.json and the rows of
   * sweep.csv are both written from visit(), so a new figure is a member
   * here, one line in visit(), and its value set in run_scene().
   */
  struct RunSummary
  {
    std::string                   parameter_file;
    std::string                   mesh_file;
    std::map<std::string, double> geometry_parameters;
    std::string                   kinematics;
    /// The harmonics, space-separated ("0" in plane strain).
    std::string  harmonics;
    unsigned int stations = 0;
    std::string  element;
    unsigned int gauss_points_per_direction = 0;
    unsigned int cells                      = 0;
    unsigned int dofs                       = 0;
    unsigned int equations                  = 0;

    /**
     * How the run ended: "completed" (every load step converged),
     * "collapse" (under load, the stepping reached a mechanism: a step
     * that failed with one as evidence, or one that converged on it)
     * or "not converged" (anything else; the reason says what).
     */
    std::string outcome;
    std::string reason;
    /// The phase the outcome and the figures of the load steps are of:
    /// "loading", or "initial state" where gravity loading did not
    /// complete and the loading was not run.
    std::string phase;
    /// Every phase that ran, in order, with its own outcome.
    std::vector<PhaseSummary> phases;
    /// Initial state/Procedure, and how it ended: "set" (K0 procedure),
    /// gravity loading's outcome, or empty (none); its reason, and the
    /// load steps of gravity loading.
    std::string  initial_state;
    std::string  initial_state_outcome;
    std::string  initial_state_reason;
    unsigned int initial_state_steps = 0;
    /// The K0 procedure's out-of-balance force against the weight it
    /// carries (StepAccess::set_initial_stresses()); NaN otherwise.
    double initial_out_of_balance = std::numeric_limits<double>::quiet_NaN();
    /// The monitored load and displacement the loading starts from (after
    /// an initial state; 0 without): where its load-displacement curve
    /// begins.
    double initial_load         = 0;
    double initial_displacement = 0;
    /// The collapse load: the last accepted load where the outcome is a
    /// collapse; under prescribed displacement, the load's plateau if the
    /// last step reached one; NaN otherwise.
    double collapse_load;
    /// A strength reduction's safety factor: the factor F at its collapse
    /// (its collapse_load, F being that phase's load); NaN for every other
    /// run.
    double safety_factor;
    /// The bracket a collapse by mechanism lies in, as its reason states
    /// it: "low" the last converged load factor, "high" the failed one (or
    /// the probe's), both as the history's load column counts a strength
    /// reduction's F. Empty for every other outcome.
    std::map<std::string, double> collapse_load_factor_bracket;
    /// The knee of the load-displacement curve (mechanism_knee_ratio),
    /// a serviceability figure beside the collapse load; NaN where the
    /// curve's secant stiffness never fell below it on an accepted step.
    double knee_load;
    /// Whether every load step converged.
    bool   converged = false;
    double last_converged_load;
    double first_failed_load;
    double reference_load;
    /// Reference/Analytic bracket: {"low", "high"}, empty for none.
    std::map<std::string, double> reference_bracket;
    double                        relative_error;
    /// The displacement measure at the last converged state, where the
    /// collapse load is read (not at a failed step or a probe beyond it,
    /// whose displacements run away); NaN where no state converged.
    double       final_displacement;
    double       final_displacement_min;
    double       final_displacement_max;
    unsigned int load_steps = 0;
    /// Attempts at load steps: load_steps and the cut-back ones.
    unsigned int attempts = 0;
    /// Accepted steps whose largest yield ratio exceeds 10 TOL: stresses
    /// that drifted out of the yield surface (the viscoplastic method's
    /// criterion does not bound it).
    unsigned int steps_with_drift = 0;
    unsigned int total_iterations = 0;
    /// The iterations of the steps up to the last converged one (those of
    /// a failed step depend on rounding).
    unsigned int converged_iterations = 0;
    /// The work of the load programme: factorisations and substitutions of
    /// the direct solvers, and sweeps over the points (WorkCounts).
    unsigned int factorisations = 0;
    unsigned int substitutions  = 0;
    unsigned int sweeps         = 0;
    /// Newton's GMRES iterations on kept factors (each also one of the
    /// substitutions).
    unsigned int krylov_iterations = 0;
    /// The mean wall time of those factorisations (NaN: none).
    double      seconds_per_factorisation;
    std::string method;
    /// The linear algebra used, and why (LinearSolverChoice).
    std::string linear_solver;
    double      seconds_per_substitution;
    /// With an iterative linear solver, its mean iterations per solve
    /// (NaN with factors).
    double linear_iterations_per_solve;
    double seconds_per_iteration;
    double wall_seconds;
    /// The MPI ranks the run ran on, and the largest peak resident memory
    /// of any of them (VmHWM), in MB.
    unsigned int ranks = 1;
    double       peak_memory_mb;
    /// The largest resident memory of any rank before the mesh was read,
    /// in MB: the loaded program (in a sweep, with what the runs before
    /// this one left).
    double program_memory_mb;
    /// Warnings about the model (e.g. too few stations); empty if none.
    std::string warnings;
    /// Wall seconds per timer section.
    std::map<std::string, double> timing;
    /// The cycles of an adaptive run (none for a single run).
    AdaptivitySummary adaptivity;

    RunSummary();

    /// summary.json: every figure, nested ones as objects; NaN as null.
    std::string
    json() const;

    /// The names of the figures that are single values, comma-separated:
    /// the columns sweep.csv has for every run.
    static std::string
    csv_header();

    /// The values of those figures, comma-separated; NaN as empty.
    std::string
    csv_row() const;

    /// The row of a run that stopped with an error before it had figures:
    /// "converged" 0, every other field empty.
    static std::string
    csv_error_row();

    /**
     * Calls @p visitor(name, value) for every figure in order, value being
     * a double, an unsigned int, a bool, a std::string, a map of names
     * to doubles, the list of phases or the adaptive cycles.
     */
    template <typename Visitor>
    void
    visit(Visitor &visitor) const
    {
      visitor("parameter_file", parameter_file);
      visitor("mesh_file", mesh_file);
      visitor("geometry_parameters", geometry_parameters);
      visitor("kinematics", kinematics);
      visitor("harmonics", harmonics);
      visitor("stations", stations);
      visitor("element", element);
      visitor("gauss_points_per_direction", gauss_points_per_direction);
      visitor("cells", cells);
      visitor("dofs", dofs);
      visitor("equations", equations);
      visitor("outcome", outcome);
      visitor("reason", reason);
      visitor("phase", phase);
      visitor("initial_state", initial_state);
      visitor("initial_state_outcome", initial_state_outcome);
      visitor("initial_state_reason", initial_state_reason);
      visitor("initial_state_steps", initial_state_steps);
      visitor("initial_out_of_balance", initial_out_of_balance);
      visitor("initial_load", initial_load);
      visitor("initial_displacement", initial_displacement);
      visitor("collapse_load", collapse_load);
      visitor("safety_factor", safety_factor);
      visitor("collapse_load_factor_bracket", collapse_load_factor_bracket);
      visitor("knee_load", knee_load);
      visitor("converged", converged);
      visitor("last_converged_load", last_converged_load);
      visitor("first_failed_load", first_failed_load);
      visitor("reference_load", reference_load);
      visitor("reference_bracket", reference_bracket);
      visitor("relative_error", relative_error);
      visitor("final_displacement", final_displacement);
      visitor("final_displacement_min", final_displacement_min);
      visitor("final_displacement_max", final_displacement_max);
      visitor("load_steps", load_steps);
      visitor("attempts", attempts);
      visitor("steps_with_drift", steps_with_drift);
      visitor("total_iterations", total_iterations);
      visitor("iterations_to_last_converged_step", converged_iterations);
      visitor("factorisations", factorisations);
      visitor("substitutions", substitutions);
      visitor("sweeps", sweeps);
      visitor("krylov_iterations", krylov_iterations);
      visitor("seconds_per_factorisation", seconds_per_factorisation);
      visitor("method", method);
      visitor("linear_solver", linear_solver);
      visitor("seconds_per_substitution", seconds_per_substitution);
      visitor("linear_iterations_per_solve", linear_iterations_per_solve);
      visitor("seconds_per_iteration", seconds_per_iteration);
      visitor("wall_seconds", wall_seconds);
      visitor("ranks", ranks);
      visitor("peak_memory_mb_per_rank", peak_memory_mb);
      visitor("program_memory_mb_per_rank", program_memory_mb);
      visitor("warnings", warnings);
      visitor("timing", timing);
      // Last, so that the run's own figures come first.
      visitor("phases", phases);
      visitor("adaptivity", adaptivity);
    }
  };
} // namespace thinlayer

#endif
