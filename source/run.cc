#include <deal.II/base/timer.h>

#include <thinlayer/analysis.h>
#include <thinlayer/run.h>
#include <thinlayer/scene.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

namespace thinlayer
{
  namespace
  {
    std::string
    format(const char *pattern, const double value)
    {
      char buffer[64];
      std::snprintf(buffer, sizeof(buffer), pattern, value);
      return buffer;
    }

    std::string
    file_name(const std::string &path)
    {
      return std::filesystem::path(path).filename().string();
    }

    std::string
    method_name(const SolutionMethod method)
    {
      switch (method)
        {
          case SolutionMethod::viscoplastic:
            return "viscoplastic";
          case SolutionMethod::initial_stress:
            return "initial stress";
          case SolutionMethod::accelerated_initial_stress:
            return "accelerated initial stress";
          case SolutionMethod::newton:
            return "newton";
        }
      return "";
    }
  } // namespace


  RunSummary
  run_scene(const Parameters &p, std::ostream &out)
  {
    Timer       wall_clock;
    TimerOutput timer(out, TimerOutput::never, TimerOutput::wall_times);

    timer.enter_subsection("mesh");
    const Scene scene(p);
    timer.leave_subsection();

    timer.enter_subsection("setup and factorisation");
    Analysis<2> analysis(p, scene.triangulation());
    analysis.setup();
    timer.leave_subsection();

    const std::string station_warning =
      analysis.get_kinematics().station_warning();

    // Everything the user gave us has been checked: only now write.
    OutputWriter writer(p.output_directory);
    writer.write_file("mesh.msh", scene.mesh_text());
    writer.write_file("parameters.prm", p.effective_parameters);

    // File names only: the full paths are in summary.json, and the screen
    // output stays the same wherever the project is checked out.
    out << "thinlayer: " << file_name(p.parameter_file) << '\n'
        << "  mesh " << file_name(p.mesh_file) << ": "
        << scene.triangulation().n_active_cells() << " cells, "
        << (p.serendipity ? "Q8" : "Q9") << ", " << p.gauss_points_per_direction
        << 'x' << p.gauss_points_per_direction << " Gauss points, "
        << analysis.n_dofs() << " DoFs (" << analysis.n_equations()
        << " equations)\n";
    if (p.fourier)
      {
        out << "  Fourier harmonics";
        for (const auto n : p.harmonics)
          out << ' ' << n;
        out << " (" << (p.antisymmetric ? "antisymmetric" : "symmetric")
            << "), " << p.station_angles.size() << " stations\n";
      }
    if (!station_warning.empty())
      out << "  " << station_warning << '\n';

    double       load_factor = 0, last_converged_load = 0;
    double       first_failed_load = std::numeric_limits<double>::quiet_NaN();
    unsigned int total_iterations  = 0;
    unsigned int converged_iterations = 0;
    unsigned int steps_run            = 0;
    bool         converged            = true;
    bool         any_step_converged   = false;
    DisplacementMeasure displacement{0, 0, 0};
    DisplacementMeasure converged_displacement{0, 0, 0};

    for (unsigned int step = 1; step <= p.load_increments.size(); ++step)
      {
        load_factor += p.load_increments[step - 1];

        timer.enter_subsection("load steps");
        const StepResult result = analysis.solve(load_factor);
        const double     load   = analysis.load();
        displacement            = analysis.displacement();
        timer.leave_subsection();
        total_iterations += result.iterations;
        ++steps_run;

        timer.enter_subsection("output");
        writer.write_history_row(
          {step, load_factor, load, displacement, result});
        if (p.write_vtu)
          writer.write_fields(step, load_factor, analysis, p);
        writer.write_displacements(analysis, p.displacement_angle);
        timer.leave_subsection();

        // Progress: one line per step, as it ends. A failed step's state
        // is no equilibrium, and its numbers depend on rounding: they go to
        // history.csv (where the mechanism can be seen), not here.
        out << "  step " << format("%4.0f", step) << "  load factor "
            << format("%10.4g", load_factor);
        if (result.converged)
          out << "  load " << format("%12.5e", load) << "  displacement "
              << format("%12.5e", displacement.mean) << "  iterations "
              << format("%4.0f", result.iterations) << "  converged";
        else
          out << "  FAILED to converge (its state is in history.csv)";
        out << std::endl;

        if (result.converged)
          {
            last_converged_load    = load;
            converged_displacement = displacement;
            converged_iterations   = total_iterations;
            any_step_converged     = true;
          }
        else
          {
            // Non-convergence is a result (collapse), not an error.
            if (converged)
              first_failed_load = load;
            converged = false;
            if (!p.continue_after_failure)
              break;
          }
      }

    const double relative_error =
      (last_converged_load - p.reference_load) / p.reference_load;
    if (any_step_converged)
      out << "  displacement "
          << (p.displacement_measure == DisplacementMeasureType::point
                ? std::string("at the monitored point")
                : "on boundary " + std::to_string(p.displacement_boundary_id))
          << " at the last converged step: mean "
          << format("%.5e", converged_displacement.mean) << ", min "
          << format("%.5e", converged_displacement.min) << ", max "
          << format("%.5e", converged_displacement.max)
          << ", spread (max-min)/|mean| "
          << format("%.3e",
                    (converged_displacement.max - converged_displacement.min) /
                      std::abs(converged_displacement.mean))
          << '\n';
    out << "  last converged load " << format("%.5g", last_converged_load);
    if (std::isfinite(p.reference_load))
      out << ", analytic " << format("%.5g", p.reference_load)
          << ", relative error " << format("%+.3e", relative_error);
    out << '\n';

    JsonObject geometry;
    for (const auto &[name, value] : p.geometry_parameters)
      geometry.add(name, value);
    std::string harmonics;
    for (const auto n : p.harmonics)
      harmonics += (harmonics.empty() ? "" : " ") + std::to_string(n);
    JsonObject timing;
    for (const auto &[section, seconds] :
         timer.get_summary_data(TimerOutput::total_wall_time))
      timing.add(section, seconds);

    JsonObject summary;
    summary.add("parameter_file", p.parameter_file)
      .add("mesh_file", p.mesh_file)
      .add("geometry_parameters", geometry)
      .add("kinematics", std::string(p.fourier ? "fourier" : "plane strain"))
      .add("harmonics", harmonics)
      .add_integer("stations", p.station_angles.size())
      .add("element", std::string(p.serendipity ? "Q8" : "Q9"))
      .add_integer("gauss_points_per_direction", p.gauss_points_per_direction)
      .add_integer("cells", scene.triangulation().n_active_cells())
      .add_integer("dofs", analysis.n_dofs())
      .add_integer("equations", analysis.n_equations())
      .add("converged", converged)
      .add("last_converged_load", last_converged_load)
      .add("first_failed_load", first_failed_load)
      .add("reference_load", p.reference_load)
      .add("relative_error", relative_error)
      .add("final_displacement", displacement.mean)
      .add("final_displacement_min", displacement.min)
      .add("final_displacement_max", displacement.max)
      .add_integer("load_steps", steps_run)
      .add_integer("total_iterations", total_iterations)
      .add_integer("iterations_to_last_converged_step", converged_iterations)
      .add("method", method_name(p.method))
      .add("seconds_per_substitution", analysis.substitution_seconds())
      .add("seconds_per_iteration",
           total_iterations > 0
             ? timer.get_summary_data(
                 TimerOutput::total_wall_time)["load steps"] /
                 total_iterations
             : 0.)
      .add("wall_seconds", wall_clock.wall_time())
      .add("warnings", station_warning)
      .add("timing", timing);
    writer.write_summary(summary);

    if (p.print_timing)
      {
        out << "  wall time " << format("%.3f", wall_clock.wall_time())
            << " s\n";
        timer.print_summary();
      }
    out << "  results in " << writer.get_directory() << '\n';
    return {converged,
            last_converged_load,
            first_failed_load,
            p.reference_load,
            relative_error,
            scene.triangulation().n_active_cells(),
            static_cast<unsigned int>(analysis.n_dofs()),
            static_cast<unsigned int>(analysis.n_equations()),
            steps_run,
            total_iterations,
            converged_iterations,
            wall_clock.wall_time(),
            station_warning};
  }
} // namespace thinlayer
