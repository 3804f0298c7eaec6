#include <deal.II/base/timer.h>

#include <thinlayer/analysis.h>
#include <thinlayer/monitors.h>
#include <thinlayer/output_writer.h>
#include <thinlayer/run.h>
#include <thinlayer/scene.h>
#include <thinlayer/text_format.h>

#include <cmath>
#include <filesystem>
#include <limits>

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


    /// What the load programme leaves behind.
    struct ProgrammeResult
    {
      bool         converged           = true;
      bool         any_step_converged  = false;
      double       last_converged_load = 0;
      double       first_failed_load = std::numeric_limits<double>::quiet_NaN();
      unsigned int total_iterations  = 0;
      unsigned int converged_iterations = 0;
      unsigned int steps_run            = 0;
      DisplacementMeasure displacement{0, 0, 0};
      DisplacementMeasure converged_displacement{0, 0, 0};
    };


    /// The model and its size, on screen. File names only: the full paths
    /// are in summary.json, and the screen output stays the same wherever
    /// the project is checked out.
    void
    print_model(const Parameters  &p,
                const Scene       &scene,
                const Analysis<2> &analysis,
                const std::string &station_warning,
                std::ostream      &out)
    {
      out << "thinlayer: " << file_name(p.parameter_file) << '\n'
          << "  mesh " << file_name(p.mesh.file) << ": "
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
      if (!station_warning.empty())
        out << "  " << station_warning << '\n';
    }


    /// The load programme, step by step, each step's row and fields
    /// written as it ends, and one line of progress on screen.
    ProgrammeResult
    run_load_programme(const Parameters  &p,
                       Analysis<2>       &analysis,
                       const Monitors<2> &monitors,
                       OutputWriter      &writer,
                       TimerOutput       &timer,
                       std::ostream      &out)
    {
      ProgrammeResult run;
      double          load_factor = 0;
      for (unsigned int step = 1; step <= p.loading.load_increments.size();
           ++step)
        {
          load_factor += p.loading.load_increments[step - 1];

          StepResult result;
          double     load;
          {
            TimerOutput::Scope scope(timer, "load steps");
            result           = analysis.solve(load_factor);
            load             = monitors.load();
            run.displacement = monitors.displacement();
          }
          run.total_iterations += result.iterations;
          ++run.steps_run;

          {
            TimerOutput::Scope scope(timer, "output");
            writer.write_history_row(
              {step, load_factor, load, run.displacement, result});
            if (p.output.write_vtu)
              writer.write_fields(step,
                                  load_factor,
                                  analysis,
                                  p.monitors.displacement_angle);
            writer.write_displacements(analysis, p.monitors.displacement_angle);
          }

          // Progress: one line per step, as it ends. A failed step's state
          // is no equilibrium, and its numbers depend on rounding: they go
          // to history.csv (where the mechanism can be seen), not here.
          out << "  step " << printf("%4.0f", step) << "  load factor "
              << printf("%10.4g", load_factor);
          if (result.converged)
            out << "  load " << printf("%12.5e", load) << "  displacement "
                << printf("%12.5e", run.displacement.mean) << "  iterations "
                << printf("%4.0f", result.iterations) << "  converged";
          else
            out << "  FAILED to converge (its state is in history.csv)";
          out << std::endl;

          if (result.converged)
            {
              run.last_converged_load    = load;
              run.converged_displacement = run.displacement;
              run.converged_iterations   = run.total_iterations;
              run.any_step_converged     = true;
            }
          else
            {
              // Non-convergence is a result (collapse), not an error.
              if (run.converged)
                run.first_failed_load = load;
              run.converged = false;
              if (!p.solver.continue_after_failure)
                break;
            }
        }
      return run;
    }


    /// The last converged state against the reference, on screen.
    void
    print_outcome(const Parameters      &p,
                  const ProgrammeResult &run,
                  const double           relative_error,
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
      out << "  last converged load "
          << printf("%.5g", run.last_converged_load);
      if (std::isfinite(p.reference.analytic_load))
        out << ", analytic " << printf("%.5g", p.reference.analytic_load)
            << ", relative error " << printf("%+.3e", relative_error);
      out << '\n';
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


  RunSummary
  run_scene(const Parameters &p, std::ostream &out)
  {
    Timer       wall_clock;
    TimerOutput timer(out, TimerOutput::never, TimerOutput::wall_times);

    const Scene scene = [&]() {
      TimerOutput::Scope scope(timer, "mesh");
      return Scene(p);
    }();

    Analysis<2> analysis(p, scene.triangulation());
    {
      TimerOutput::Scope scope(timer, "setup and factorisation");
      analysis.setup();
    }
    const Monitors<2> monitors(p.monitors, analysis);

    RunSummary summary;
    describe_model(p, scene, analysis, summary);
    summary.warnings = analysis.get_kinematics().station_warning();

    // Everything the user gave us has been checked: only now write.
    OutputWriter writer(p.output);
    writer.write_file("mesh.msh", scene.mesh_text());
    writer.write_file("parameters.prm", p.effective_parameters);
    print_model(p, scene, analysis, summary.warnings, out);

    const ProgrammeResult run =
      run_load_programme(p, analysis, monitors, writer, timer, out);

    summary.converged           = run.converged;
    summary.last_converged_load = run.last_converged_load;
    summary.first_failed_load   = run.first_failed_load;
    summary.reference_load      = p.reference.analytic_load;
    summary.relative_error =
      (run.last_converged_load - summary.reference_load) /
      summary.reference_load;
    print_outcome(p, run, summary.relative_error, out);

    summary.final_displacement     = run.displacement.mean;
    summary.final_displacement_min = run.displacement.min;
    summary.final_displacement_max = run.displacement.max;
    summary.load_steps             = run.steps_run;
    summary.total_iterations       = run.total_iterations;
    summary.converged_iterations   = run.converged_iterations;
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
    out << "  results in " << writer.get_directory() << '\n';
    return summary;
  }
} // namespace thinlayer
