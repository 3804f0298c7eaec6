#include <deal.II/base/timer.h>

#include <thinlayer/analysis/analysis.h>
#include <thinlayer/app/run.h>
#include <thinlayer/base/interruption.h>
#include <thinlayer/base/text_format.h>
#include <thinlayer/mesh/scene.h>
#include <thinlayer/output/output_writer.h>
#include <thinlayer/output/reference_check.h>
#include <thinlayer/output/results_directory.h>
#include <thinlayer/postprocess/layer_profile.h>
#include <thinlayer/postprocess/monitors.h>
#include <thinlayer/stepping/load_stepping.h>
#include <thinlayer/stepping/run_outcome.h>
#include <thinlayer/stepping/step_progress.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>

namespace thinlayer
{
  namespace
  {
    using text_format::printf;

    std::string
    file_name(const std::string &path)
    {
      return std::filesystem::path(path).filename().string();
    }


    /// The model and its size, on screen. File names only: the full paths
    /// are in summary.json, and the screen output stays the same wherever
    /// the project is checked out.
    void
    print_model(const Parameters  &p,
                const Scene       &scene,
                const Analysis<2> &analysis,
                const std::string &warnings,
                std::ostream      &out)
    {
      out << "  mesh " << file_name(p.mesh.file) << ": "
          << scene.triangulation().n_active_cells() << " cells, "
          << (p.discretisation.serendipity ? "Q8" : "Q9") << ", "
          << p.discretisation.gauss_points_per_direction << 'x'
          << p.discretisation.gauss_points_per_direction << " Gauss points, "
          << analysis.n_dofs() << " DoFs (" << analysis.n_equations()
          << " equations)\n";
      if (p.kinematics.fourier)
        {
          out << "  Fourier harmonics";
          for (const auto n : p.kinematics.harmonics)
            out << ' ' << n;
          out << " ("
              << (p.kinematics.antisymmetric ? "antisymmetric" : "symmetric")
              << "), " << p.kinematics.station_angles.size() << " stations\n";
        }
      if (!warnings.empty())
        out << "  " << warnings << '\n';
      out.flush(); // progress: lines reach a file or pipe as they come
    }


    /// One line of progress on screen for an attempt, as it ends. A failed
    /// step's state is no equilibrium, and its numbers depend on rounding:
    /// they go to history.csv (where the mechanism can be seen), not here.
    void
    print_attempt(const unsigned int       step,
                  const double             load_factor,
                  const double             load,
                  const double             displacement,
                  const StepResult        &result,
                  const bool               on_mechanism,
                  const LoadStepping::Next next,
                  const bool               probe,
                  const bool               print_iterations,
                  std::ostream            &out)
    {
      out << "  step " << printf("%4.0f", step) << "  load factor "
          << printf("%10.4g", load_factor);
      if (on_mechanism)
        out << "  converged on the mechanism (secant stiffness below "
            << mechanism_knee_ratio << " of the elastic one): "
            << (next == LoadStepping::Next::retry ? "cut back"
                                                  : "not accepted");
      else if (result.converged)
        out << "  load " << printf("%12.5e", load) << "  displacement "
            << printf("%12.5e", displacement)
            << (print_iterations
                  ? "  iterations " + printf("%4.0f", result.iterations)
                  : std::string())
            << "  converged";
      else if (next == LoadStepping::Next::retry)
        out << "  failed: cut back (its state is in history.csv)";
      else if (result.non_finite)
        out << "  FAILED: not a finite number";
      else if (probe)
        out << "  probe beyond the failed step: FAILED to converge";
      else
        out << "  FAILED to converge (its state is in history.csv)";
      out << std::endl;
    }


    /**
     * The load programme, attempt by attempt (LoadStepping), each
     * attempt's row and fields written as it ends, and one line of progress
     * on screen.
     */
    class Programme
    {
    public:
      Programme(const Parameters                &p,
                Analysis<2>                     &analysis,
                const Monitors<2>               &monitors,
                const std::vector<LayerProfile> &interfaces,
                OutputWriter                    &writer,
                TimerOutput                     &timer,
                std::ostream                    &out)
        : p(p)
        , analysis(analysis)
        , monitors(monitors)
        , interfaces(interfaces)
        , writer(writer)
        , timer(timer)
        , out(out)
      {}

      ProgrammeResult
      run();

    private:
      struct Attempt
      {
        unsigned int step;
        double       load_factor;
        StepResult   result;
        double       load;
        /// Analysis::secant_stiffness_ratio() of the attempt's state.
        double stiffness_ratio;
        /// A converged attempt on the mechanism (mechanism_knee_ratio):
        /// never accepted under automatic stepping.
        bool on_mechanism;
        /// A converged attempt moving against its load: counted as failed.
        bool against_load;
      };

      /// Solve the step to @p load_factor and measure it.
      Attempt
      attempt(const unsigned int step, const double load_factor);

      /// Its row in history.csv, its fields unless it is to be retried,
      /// and its line on screen.
      void
      record(const Attempt           &a,
             const LoadStepping::Next next,
             const bool               probe = false);

      /// Take a converged attempt's figures and accept its state.
      void
      accept(const Attempt &a);

      /**
       * Automatic stepping ended at a failed step that shows no mechanism:
       * at the limit load itself a method converges slowly rather than
       * creeps. Try the same step once more beyond it, from the accepted
       * state; a mechanism there is the evidence. The probe is never
       * accepted.
       */
      void
      probe_beyond(const Attempt &failed);

      const Parameters                &p;
      Analysis<2>                     &analysis;
      const Monitors<2>               &monitors;
      const std::vector<LayerProfile> &interfaces;
      OutputWriter                    &writer;
      TimerOutput                     &timer;
      std::ostream                    &out;
      ProgrammeResult                  result;
    };


    ProgrammeResult
    Programme::run()
    {
      // An easy step: at most a quarter of the constant-stiffness
      // iteration limit (Newton's steps take a few iterations each).
      LoadStepping stepping(p.loading,
                            p.solver.continue_after_failure,
                            p.solver.max_iterations / 4);
      while (!stepping.finished())
        {
          const Attempt a = attempt(stepping.step(), stepping.target());
          // A signal stopped the step: it is neither a failure nor a
          // result, so it is not recorded; the accepted steps are the run.
          if (interrupted())
            {
              result.interrupted_by          = interruption_signal();
              result.interrupted_load_factor = a.load_factor;
              analysis.reject_step();
              break;
            }
          // A state on the mechanism is cut back like a failed one.
          StepResult reported           = a.result;
          reported.converged            = a.result.converged && !a.on_mechanism;
          const LoadStepping::Next next = stepping.report(reported);
          record(a, next);
          if (next == LoadStepping::Next::retry)
            {
              analysis.reject_step();
              continue;
            }
          ++result.steps_run;
          if (reported.converged)
            {
              accept(a);
              continue;
            }
          // Non-convergence is a result, not an error.
          if (result.converged)
            result.first_failed_load = a.load;
          result.converged = false;
          if (next == LoadStepping::Next::accept_failed)
            {
              analysis.accept_step();
              continue;
            }
          result.stopped              = true;
          result.stopped_on_mechanism = a.on_mechanism;
          result.against_load         = a.against_load;
          result.non_finite           = a.result.non_finite;
          result.failed_load_factor   = a.load_factor;
          result.bracket_resolved =
            stepping.automatic() &&
            std::abs(a.load_factor - result.last_converged_load_factor) <=
              (1 + 1e-9) * p.loading.collapse_resolution *
                std::max(std::abs(a.load_factor),
                         std::abs(p.loading.load_increments.front()));
          result.stiffness_ratio = a.stiffness_ratio;
          result.growth_ratio    = a.result.growth_ratio;
          if (stepping.automatic() && !a.result.non_finite && !a.against_load &&
              analysis.has_external_load() &&
              !shows_mechanism(a.stiffness_ratio, a.result.growth_ratio))
            probe_beyond(a);
          break;
        }
      return result;
    }


    Programme::Attempt
    Programme::attempt(const unsigned int step, const double load_factor)
    {
      Attempt a{step, load_factor, {}, 0, 0, false, false};
      {
        TimerOutput::Scope scope(timer, "load steps");
        const StepProgress progress(out,
                                    step,
                                    load_factor,
                                    p.output.progress_interval);
        a.result            = analysis.solve(load_factor);
        a.load              = monitors.load();
        result.displacement = monitors.displacement();
      }
      if (!std::isfinite(a.load) || !std::isfinite(result.displacement.mean))
        {
          a.result.non_finite = true;
          a.result.converged  = false;
        }
      result.total_iterations += a.result.iterations;
      ++result.attempts;
      a.stiffness_ratio = analysis.secant_stiffness_ratio();
      // A state that does negative work on its load increment is no
      // response of an elastic-plastic body (Drucker's stability): the
      // iterations have found a spurious equilibrium (seen with the
      // default method on Case 3's layer at aspect ratio 10000, at
      // displacements 1e9 times the elastic ones). It is a failed attempt.
      if (a.result.converged && analysis.has_external_load() &&
          a.stiffness_ratio < 0)
        {
          a.result.converged = false;
          a.against_load     = true;
        }
      a.on_mechanism = a.result.converged &&
                       p.loading.collapse_resolution > 0 &&
                       analysis.has_external_load() && a.stiffness_ratio >= 0 &&
                       a.stiffness_ratio < mechanism_knee_ratio;
      return a;
    }


    void
    Programme::record(const Attempt           &a,
                      const LoadStepping::Next next,
                      const bool               probe)
    {
      {
        TimerOutput::Scope scope(timer, "output");
        writer.write_history_row(
          {a.step,
           result.attempts,
           a.load_factor,
           a.load,
           result.displacement,
           a.result,
           !a.on_mechanism && (next == LoadStepping::Next::accept ||
                               next == LoadStepping::Next::accept_failed),
           a.stiffness_ratio});
        if (next != LoadStepping::Next::retry)
          {
            if (p.output.write_vtu)
              writer.write_fields(a.step,
                                  a.load_factor,
                                  analysis,
                                  p.monitors.displacement_angle,
                                  interfaces);
            if (p.output.write_vtu && p.output.view_slices > 0)
              writer.write_revolved_view(a.step,
                                         a.load_factor,
                                         analysis,
                                         p.output.view_slices);
            writer.write_displacements(analysis, p.monitors.displacement_angle);
            writer.write_interface_profiles(
              a.step, a.load_factor, analysis, interfaces, p.output.write_vtu);
          }
      }
      print_attempt(a.step,
                    a.load_factor,
                    a.load,
                    result.displacement.mean,
                    a.result,
                    a.on_mechanism,
                    next,
                    probe,
                    p.output.print_iterations,
                    out);
    }


    void
    Programme::accept(const Attempt &a)
    {
      const double stiffness =
        (a.load - result.last_converged_load) /
        (a.load_factor - result.last_converged_load_factor);
      if (!result.any_step_converged)
        result.first_stiffness = stiffness;
      result.last_stiffness             = stiffness;
      result.last_converged_load        = a.load;
      result.last_converged_load_factor = a.load_factor;
      result.converged_displacement     = result.displacement;
      result.converged_iterations       = result.total_iterations;
      result.any_step_converged         = true;
      if (a.result.max_yield_ratio > 10 * p.solver.tolerance)
        ++result.steps_with_drift;
      analysis.accept_step();
    }


    void
    Programme::probe_beyond(const Attempt &failed)
    {
      analysis.reject_step();
      const double probe_load_factor =
        failed.load_factor +
        (failed.load_factor - result.last_converged_load_factor);
      const Attempt probe = attempt(failed.step + 1, probe_load_factor);
      record(probe, LoadStepping::Next::stop, true);
      if ((!probe.result.converged || probe.on_mechanism) &&
          shows_mechanism(probe.stiffness_ratio, probe.result.growth_ratio))
        {
          result.stopped_on_mechanism = probe.on_mechanism;
          result.probe_load_factor    = probe_load_factor;
          result.stiffness_ratio      = probe.stiffness_ratio;
          result.growth_ratio         = probe.result.growth_ratio;
        }
    }


    /// What the failed step that ended the run shows of a mechanism.
    /// The last converged state against the reference, on screen.
    void
    print_outcome(const Parameters      &p,
                  const ProgrammeResult &run,
                  const RunSummary      &summary,
                  std::ostream          &out)
    {
      const DisplacementMeasure &u = run.converged_displacement;
      if (run.any_step_converged)
        out << "  displacement "
            << (p.monitors.displacement_measure ==
                    MonitorParameters::DisplacementMeasure::point
                  ? std::string("at the monitored point")
                  : "on boundary " +
                      std::to_string(p.monitors.displacement_boundary_id))
            << " at the last converged step: mean " << printf("%.5e", u.mean)
            << ", min " << printf("%.5e", u.min) << ", max "
            << printf("%.5e", u.max) << ", spread (max-min)/|mean| "
            << printf("%.3e", (u.max - u.min) / std::abs(u.mean)) << '\n';
      if (run.any_step_converged)
        out << "  last converged load "
            << printf("%.5g", run.last_converged_load);
      else
        out << "  no load step converged";
      if (std::isfinite(p.reference.analytic_load))
        {
          out << ", analytic " << printf("%.5g", p.reference.analytic_load);
          if (std::isfinite(summary.relative_error))
            out << ", relative error "
                << printf("%+.3e", summary.relative_error);
        }
      out << "\n  outcome: " << summary.outcome << " (" << summary.reason
          << ")\n";
      if (summary.steps_with_drift > 0)
        out << "  warning: " << summary.steps_with_drift
            << " accepted steps have stresses more than 10 TOL outside the "
               "yield surface\n";
      out.flush();
    }


    /// The model part of the summary: what ran, and its size.
    void
    describe_model(const Parameters  &p,
                   const Scene       &scene,
                   const Analysis<2> &analysis,
                   RunSummary        &s)
    {
      s.parameter_file      = p.parameter_file;
      s.mesh_file           = p.mesh.file;
      s.geometry_parameters = p.mesh.geometry_parameters;
      s.kinematics          = p.kinematics.fourier ? "fourier" : "plane strain";
      for (const auto n : p.kinematics.harmonics)
        s.harmonics += (s.harmonics.empty() ? "" : " ") + std::to_string(n);
      s.stations = p.kinematics.station_angles.size();
      s.element  = p.discretisation.serendipity ? "Q8" : "Q9";
      s.gauss_points_per_direction =
        p.discretisation.gauss_points_per_direction;
      s.cells     = scene.triangulation().n_active_cells();
      s.dofs      = analysis.n_dofs();
      s.equations = analysis.n_equations();
      s.method    = SolverParameters::method_names.name(p.solver.method);
    }
  } // namespace


  namespace
  {
    /**
     * The run itself; @p open_directory gives the directory to write into,
     * called once all input has been checked.
     */
    RunSummary
    run(const Parameters                   &p,
        const std::function<std::string()> &open_directory,
        std::ostream                       &out)
    {
      Timer       wall_clock;
      TimerOutput timer(out, TimerOutput::never, TimerOutput::wall_times);

      out << "thinlayer: " << file_name(p.parameter_file) << '\n';
      for (const std::string &warning : p.warnings)
        out << "  warning: " << warning << '\n';
      out << "  meshing " << file_name(p.mesh.file) << std::endl;
      const Scene scene = [&]() {
        TimerOutput::Scope scope(timer, "mesh");
        return Scene(p, out);
      }();

      Analysis<2> analysis(p, scene.triangulation());
      {
        TimerOutput::Scope scope(timer, "setup and factorisation");
        out << "  setting up: assembling and factorising the stiffness"
            << std::endl;
        analysis.setup();
      }
      const Monitors<2> monitors(p.monitors, analysis, p.parameter_file);
      std::vector<LayerProfile> interfaces;
      for (const types::material_id id : p.layers.material_ids)
        interfaces.emplace_back(analysis, id, p.parameter_file);

      RunSummary summary;
      describe_model(p, scene, analysis, summary);
      summary.warnings = analysis.warnings();

      // Everything the user gave us has been checked: only now write.
      OutputWriter writer(p.output, open_directory());
      writer.write_file("mesh.msh", scene.mesh_text());
      writer.write_file("parameters.prm", p.effective_parameters);
      print_model(p, scene, analysis, summary.warnings, out);

      const ProgrammeResult run =
        Programme(p, analysis, monitors, interfaces, writer, timer, out).run();

      judge_outcome(analysis, run, summary);
      summary.converged           = run.converged;
      summary.last_converged_load = run.last_converged_load;
      summary.first_failed_load   = run.first_failed_load;
      summary.reference_load      = p.reference.analytic_load;
      // A collapse load (or a plateau) is compared with the closed form,
      // and so is the final state of a run whose every step converged
      // (an elastic reference); the last converged load of a run that
      // failed or was stopped is no estimate of either.
      const double compared = std::isfinite(summary.collapse_load)
                                ? summary.collapse_load
                              : summary.outcome == "completed"
                                ? run.last_converged_load
                                : std::numeric_limits<double>::quiet_NaN();
      summary.relative_error =
        (compared - summary.reference_load) / summary.reference_load;
      summary.final_displacement     = run.displacement.mean;
      summary.final_displacement_min = run.displacement.min;
      summary.final_displacement_max = run.displacement.max;
      summary.load_steps             = run.steps_run;
      summary.attempts               = run.attempts;
      summary.steps_with_drift       = run.steps_with_drift;
      summary.total_iterations       = run.total_iterations;
      summary.converged_iterations   = run.converged_iterations;
      print_outcome(p, run, summary, out);
      if (const ReferenceCheck check = check_reference(p.reference, summary);
          check.checked)
        out << "  reference check " << check.description << '\n';
      summary.timing = timer.get_summary_data(TimerOutput::total_wall_time);
      summary.seconds_per_substitution = analysis.substitution_seconds();
      summary.seconds_per_iteration =
        run.total_iterations > 0
          ? summary.timing["load steps"] / run.total_iterations
          : 0.;
      summary.wall_seconds = wall_clock.wall_time();
      writer.write_file("summary.json", summary.json());

      if (p.output.print_timing)
        {
          out << "  wall time " << printf("%.3f", wall_clock.wall_time())
              << " s\n";
          timer.print_summary();
        }
      return summary;
    }
  } // namespace


  RunSummary
  run_scene(const Parameters &p, std::ostream &out)
  {
    std::unique_ptr<ResultsDirectory> results;
    RunSummary                        summary;
    try
      {
        summary = run(
          p,
          [&]() {
            results = std::make_unique<ResultsDirectory>(p.output.directory,
                                                         p.parameter_file);
            return results->staging();
          },
          out);
      }
    catch (const WriteError &e)
      {
        throw WriteError(std::string(e.what()) + " (Output/Directory '" +
                         p.output.directory + "')");
      }
    results->commit();
    out << "  results in " << p.output.directory << std::endl;
    return summary;
  }


  RunSummary
  run_scene_in(const Parameters  &p,
               const std::string &directory,
               std::ostream      &out)
  {
    return run(
      p,
      [&]() {
        std::filesystem::create_directories(directory);
        return directory;
      },
      out);
  }
} // namespace thinlayer
