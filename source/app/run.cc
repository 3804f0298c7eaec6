#include <deal.II/base/timer.h>

#include <thinlayer/analysis/analysis.h>
#include <thinlayer/app/run.h>
#include <thinlayer/base/interruption.h>
#include <thinlayer/base/text_format.h>
#include <thinlayer/base/work_counts.h>
#include <thinlayer/mesh/scene.h>
#include <thinlayer/output/output_writer.h>
#include <thinlayer/output/reference_check.h>
#include <thinlayer/output/results_directory.h>
#include <thinlayer/parallel/mpi.h>
#include <thinlayer/postprocess/layer_profile.h>
#include <thinlayer/postprocess/monitors.h>
#include <thinlayer/stepping/phases.h>
#include <thinlayer/stepping/run_outcome.h>
#include <thinlayer/stepping/step_solver.h>

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
    /// The element's name: Q8 or Q9 in 2D, Q20 or Q27 in 3D.
    std::string
    element_name(const Parameters &p)
    {
      const bool serendipity = p.discretisation.serendipity;
      if (p.kinematics.dimension == 3)
        return serendipity ? "Q20" : "Q27";
      return serendipity ? "Q8" : "Q9";
    }


    /// The Gauss rule's name: 2x2, 3x3x3 and so on.
    std::string
    gauss_rule_name(const Parameters &p)
    {
      const std::string n =
        std::to_string(p.discretisation.gauss_points_per_direction);
      std::string rule = n;
      for (unsigned int d = 1; d < p.kinematics.dimension; ++d)
        rule += 'x' + n;
      return rule;
    }


    template <int dim>
    void
    print_model(const Parameters    &p,
                const Scene<dim>    &scene,
                const Analysis<dim> &analysis,
                const std::string   &warnings,
                std::ostream        &out)
    {
      out << "  mesh " << file_name(p.mesh.file) << ": "
          << scene.triangulation().n_active_cells() << " cells, "
          << element_name(p) << ", " << gauss_rule_name(p) << " Gauss points, "
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
      // The linear algebra where it is not one rank's plain choice.
      const LinearSolverChoice &linear_solver = analysis.get_linear_solver();
      if (mpi::n_ranks() > 1 ||
          linear_solver.kind != LinearSolverChoice::Kind::cholmod)
        {
          out << "  ";
          if (mpi::n_ranks() > 1)
            out << mpi::n_ranks() << " MPI ranks; ";
          out << "linear solver: " << linear_solver.description << '\n';
        }
      if (!warnings.empty())
        out << "  " << warnings << '\n';
      out.flush(); // progress: lines reach a file or pipe as they come
    }


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
            << (u.mean != 0 ? printf("%.3e", (u.max - u.min) / std::abs(u.mean))
                            : std::string("- (the mean is 0)"))
            << '\n';
      if (run.any_step_converged)
        out << "  last converged load "
            << printf("%.5g", run.last_converged_load);
      else
        out << "  no load step converged";
      // The figure the error belongs to, where it is not the last
      // converged load (a plateau).
      if (std::isfinite(summary.collapse_load) &&
          summary.collapse_load != run.last_converged_load)
        out << ", collapse load " << printf("%.5g", summary.collapse_load);
      if (std::isfinite(summary.safety_factor))
        out << ", safety factor " << printf("%.5g", summary.safety_factor);
      if (std::isfinite(p.reference.analytic_load))
        {
          out << ", analytic " << printf("%.5g", p.reference.analytic_load);
          if (!p.reference.analytic_bracket.empty())
            out << " (bracket "
                << printf("%.5g", p.reference.analytic_bracket.at("low"))
                << " - "
                << printf("%.5g", p.reference.analytic_bracket.at("high"))
                << ")";
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
    template <int dim>
    void
    describe_model(const Parameters    &p,
                   const Scene<dim>    &scene,
                   const Analysis<dim> &analysis,
                   RunSummary          &s)
    {
      s.parameter_file      = p.parameter_file;
      s.mesh_file           = p.mesh.file;
      s.geometry_parameters = p.mesh.geometry_parameters;
      s.kinematics          = p.kinematics.fourier          ? "fourier"
                              : p.kinematics.dimension == 3 ? "3d"
                                                            : "plane strain";
      for (const auto n : p.kinematics.harmonics)
        s.harmonics += (s.harmonics.empty() ? "" : " ") + std::to_string(n);
      s.stations = p.kinematics.station_angles.size();
      s.element  = element_name(p);
      s.gauss_points_per_direction =
        p.discretisation.gauss_points_per_direction;
      s.cells         = scene.triangulation().n_active_cells();
      s.dofs          = analysis.n_dofs();
      s.equations     = analysis.n_equations();
      s.method        = SolverParameters::method_names.name(p.solver.method);
      s.linear_solver = analysis.get_linear_solver().description;
    }


    /// How the load programme ended, and its work, in the summary.
    void
    record_run(const Parameters      &p,
               const ProgrammeResult &run,
               const WorkCounts      &work,
               RunSummary            &summary)
    {
      summary.converged           = run.converged;
      summary.last_converged_load = run.last_converged_load;
      summary.first_failed_load   = run.first_failed_load;
      summary.reference_load      = p.reference.analytic_load;
      summary.reference_bracket   = p.reference.analytic_bracket;
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
      const double none = std::numeric_limits<double>::quiet_NaN();
      const DisplacementMeasure &last = run.converged_displacement;
      summary.final_displacement = run.any_step_converged ? last.mean : none;
      summary.final_displacement_min = run.any_step_converged ? last.min : none;
      summary.final_displacement_max = run.any_step_converged ? last.max : none;
      summary.load_steps             = run.steps_run;
      summary.attempts               = run.attempts;
      summary.steps_with_drift       = run.steps_with_drift;
      summary.total_iterations       = run.total_iterations;
      summary.converged_iterations   = run.converged_iterations;
      summary.factorisations         = work.factorisations;
      summary.substitutions          = work.substitutions;
      summary.sweeps                 = work.sweeps;
      summary.krylov_iterations      = work.krylov_iterations;
      if (work.factorisations > 0)
        summary.seconds_per_factorisation =
          work.factorisation_seconds / work.factorisations;
    }
  } // namespace


  void
  print_run_header(const Parameters &p, std::ostream &out)
  {
    out << "thinlayer: " << file_name(p.parameter_file) << '\n';
    for (const std::string &warning : p.warnings)
      out << "  warning: " << warning << '\n';
    out << "  meshing " << file_name(p.mesh.file) << std::endl;
  }


  RunClock::RunClock(std::ostream &out)
    : timer(out, TimerOutput::never, TimerOutput::wall_times)
    , program_memory_mb(mpi::resident_memory_mb())
  {}


  template <int dim>
  RunSummary
  run_on_scene(const Parameters                   &p,
               const Scene<dim>                   &scene,
               RunClock                           &clock,
               const std::function<std::string()> &open_directory,
               std::ostream                       &out,
               const std::function<void(const AnalysisView<dim> &)> &read)
  {
    TimerOutput  &timer = clock.timer;
    Analysis<dim> analysis(p, scene.triangulation());
    {
      TimerOutput::Scope scope(timer, "setup and factorisation");
      out << "  setting up: assembling and factorising the stiffness"
          << std::endl;
      analysis.setup();
    }
    // The stepping owns the solution method; Newton's sparsity and its
    // cells' elastic matrices are set up here.
    std::unique_ptr<StepSolver<dim>> solver;
    {
      TimerOutput::Scope scope(timer, "setup and factorisation");
      solver = std::make_unique<StepSolver<dim>>(p.solver, analysis);
    }
    const Monitors<dim> monitors(p.monitors, analysis, p.parameter_file);
    std::vector<LayerProfile<dim>> layers;
    for (const types::material_id id : p.layers.material_ids)
      layers.emplace_back(analysis, id, p.parameter_file);

    RunSummary summary;
    describe_model(p, scene, analysis, summary);
    summary.warnings = analysis.warnings();

    // The initial state is checked (and set) before anything is written.
    Phases<dim> phases(p, analysis, *solver, monitors, layers, timer, out);
    phases.prepare(summary);

    // Everything the user gave us has been checked: only now write.
    OutputWriter writer(p.output, open_directory());
    writer.write_file("mesh.msh", scene.mesh_text());
    writer.write_file("parameters.prm", p.effective_parameters);
    print_model(p, scene, analysis, summary.warnings, out);

    const WorkCounts      work_before = work_counts();
    const ProgrammeResult run         = phases.run(writer, summary);
    {
      // The fields still being written are part of the run's time.
      TimerOutput::Scope scope(timer, "output");
      writer.finish();
    }
    if (read)
      read(analysis);

    record_run(p, run, work_counts().since(work_before), summary);
    print_outcome(p, run, summary, out);
    if (const ReferenceCheck check = check_reference(p.reference, summary);
        check.checked)
      out << "  reference check " << check.description << '\n';
    summary.timing = timer.get_summary_data(TimerOutput::total_wall_time);
    summary.seconds_per_substitution = analysis.substitution_seconds();
    summary.linear_iterations_per_solve =
      analysis.linear_iterations_per_solve();
    summary.seconds_per_iteration =
      run.total_iterations > 0
        ? summary.timing["load steps"] / run.total_iterations
        : 0.;
    summary.wall_seconds      = clock.wall_clock.wall_time();
    summary.ranks             = mpi::n_ranks();
    summary.peak_memory_mb    = mpi::peak_memory_mb();
    summary.program_memory_mb = clock.program_memory_mb;
    writer.write_file("summary.json", summary.json());

    if (p.output.print_timing)
      {
        out << "  wall time " << printf("%.3f", clock.wall_clock.wall_time())
            << " s\n";
        timer.print_summary();
      }
    return summary;
  }


  namespace
  {
    /**
     * The run itself; @p open_directory gives the directory to write into,
     * called once all input has been checked.
     */
    template <int dim>
    RunSummary
    run(const Parameters                   &p,
        const std::function<std::string()> &open_directory,
        std::ostream                       &out)
    {
      RunClock clock(out);
      print_run_header(p, out);
      const Scene<dim> scene = [&]() {
        TimerOutput::Scope scope(clock.timer, "mesh");
        return Scene<dim>(p, out);
      }();
      return run_on_scene(p, scene, clock, open_directory, out, {});
    }


    /// run() on the mesh's dimension.
    RunSummary
    run_in_dimension(const Parameters                   &p,
                     const std::function<std::string()> &open_directory,
                     std::ostream                       &out)
    {
      return p.kinematics.dimension == 3 ? run<3>(p, open_directory, out)
                                         : run<2>(p, open_directory, out);
    }
  } // namespace


  RunSummary
  run_in_output_directory(
    const Parameters                                                      &p,
    const std::function<RunSummary(const std::function<std::string()> &)> &work,
    std::ostream                                                          &out)
  {
    std::unique_ptr<ResultsDirectory> results;
    RunSummary                        summary;
    try
      {
        // Rank 0 writes every file (OutputWriter), so only it has a
        // results directory.
        summary = work([&]() {
          return mpi::on_root([&]() {
            results = std::make_unique<ResultsDirectory>(p.output.directory,
                                                         p.parameter_file);
            return results->staging();
          });
        });
      }
    catch (const WriteError &e)
      {
        throw WriteError(std::string(e.what()) + " (Output/Directory '" +
                         p.output.directory + "')");
      }
    if (results)
      results->commit();
    out << "  results in " << p.output.directory << std::endl;
    return summary;
  }


  RunSummary
  run_scene(const Parameters &p, std::ostream &out)
  {
    return run_in_output_directory(
      p,
      [&](const std::function<std::string()> &open_directory) {
        return run_in_dimension(p, open_directory, out);
      },
      out);
  }


  template RunSummary
  run_on_scene(const Parameters &,
               const Scene<2> &,
               RunClock &,
               const std::function<std::string()> &,
               std::ostream &,
               const std::function<void(const AnalysisView<2> &)> &);
  template RunSummary
  run_on_scene(const Parameters &,
               const Scene<3> &,
               RunClock &,
               const std::function<std::string()> &,
               std::ostream &,
               const std::function<void(const AnalysisView<3> &)> &);


  RunSummary
  run_scene_in(const Parameters  &p,
               const std::string &directory,
               std::ostream      &out)
  {
    return run_in_dimension(
      p,
      [&]() {
        if (mpi::is_root())
          std::filesystem::create_directories(directory);
        return directory;
      },
      out);
  }
} // namespace thinlayer
