#include <deal.II/base/timer.h>

#include <thinlayer/adaptivity/mesh_refinement.h>
#include <thinlayer/adaptivity/refinement_indicator.h>
#include <thinlayer/app/adaptive_run.h>
#include <thinlayer/app/run.h>
#include <thinlayer/base/interruption.h>
#include <thinlayer/base/text_format.h>
#include <thinlayer/mesh/scene.h>
#include <thinlayer/output/output_writer.h>
#include <thinlayer/parallel/mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <set>
#include <sstream>

namespace thinlayer
{
  namespace
  {
    using text_format::printf;

    /// The figures of one cycle, from its run's summary.
    CycleSummary
    cycle_of(const unsigned int cycle,
             const unsigned int refined_cells,
             const RunSummary  &s)
    {
      CycleSummary c;
      c.cycle          = cycle;
      c.refined_cells  = refined_cells;
      c.cells          = s.cells;
      c.dofs           = s.dofs;
      c.equations      = s.equations;
      c.outcome        = s.outcome;
      c.collapse_load  = s.collapse_load;
      c.relative_error = std::isfinite(s.collapse_load)
                           ? s.relative_error
                           : std::numeric_limits<double>::quiet_NaN();
      c.wall_seconds   = s.wall_seconds;
      return c;
    }


    /// adaptivity.csv: one row per cycle.
    std::string
    cycles_csv(const AdaptivitySummary &a)
    {
      std::ostringstream csv;
      csv << "cycle,refined_cells,cells,dofs,equations,outcome,collapse_load,"
             "relative_error,wall_seconds\n";
      for (const CycleSummary &c : a.cycles)
        csv << c.cycle << ',' << c.refined_cells << ',' << c.cells << ','
            << c.dofs << ',' << c.equations << ','
            << text_format::csv_field(c.outcome) << ','
            << text_format::csv_number(c.collapse_load) << ','
            << text_format::csv_number(c.relative_error) << ','
            << text_format::csv_number(c.wall_seconds) << '\n';
      return csv.str();
    }


    /// The cycles as a table on screen, and why they stopped.
    void
    print_cycles(const AdaptivitySummary &a,
                 const double             reference,
                 std::ostream            &out)
    {
      out << "  adaptive refinement (" << a.indicator << ", " << a.marking
          << "): " << a.cycles.size()
          << (a.cycles.size() == 1 ? " cycle\n" : " cycles\n")
          << "    cycle  refined    cells     DoFs  collapse load  "
             "relative error\n";
      for (const CycleSummary &c : a.cycles)
        {
          char columns[64];
          std::snprintf(columns,
                        sizeof(columns),
                        "    %5u  %7u  %7u  %7u  ",
                        c.cycle,
                        c.refined_cells,
                        c.cells,
                        c.dofs);
          out << columns;
          if (std::isfinite(c.collapse_load))
            out << printf("%13.5g", c.collapse_load);
          else
            out << std::string(13 - std::min<std::size_t>(13,
                                                          c.outcome.size() + 2),
                               ' ')
                << '(' << c.outcome << ')';
          if (std::isfinite(c.relative_error))
            out << printf("  %+14.3e", c.relative_error);
          out << '\n';
        }
      out << "  cycles stopped: " << a.stop_reason << '\n';
      if (std::isfinite(a.extrapolated_collapse_load))
        {
          out << "  extrapolated collapse load "
              << printf("%.5g", a.extrapolated_collapse_load) << " (DoFs^-"
              << printf("%.2f", a.rate)
              << "); the last cycle's estimated error "
              << printf("%.2e", a.estimated_error);
          if (std::isfinite(reference))
            out << ", the extrapolation's error against the analytic load "
                << printf("%+.3e", a.extrapolated_relative_error);
          out << '\n';
        }
      else if (a.cycles.size() >= 3)
        out << "  no extrapolation: the last three collapse loads show no "
               "rate\n";
    }


    /**
     * Why the cycles end after @p cycles (the last just run), or empty to
     * go on.
     */
    std::string
    reason_to_stop(const AdaptivityParameters      &parameters,
                   const std::vector<CycleSummary> &cycles)
    {
      const CycleSummary &last = cycles.back();
      if (last.outcome == "interrupted")
        return "cycle " + std::to_string(last.cycle) + " was interrupted";
      if (cycles.size() >= 2)
        {
          const double before = cycles[cycles.size() - 2].collapse_load;
          const double now    = last.collapse_load;
          if (std::isfinite(before) && std::isfinite(now) && before != 0 &&
              std::abs(now - before) <
                parameters.stop_tolerance * std::abs(before))
            return "the collapse load changed by " +
                   printf("%.2e", std::abs(now - before) / std::abs(before)) +
                   " from cycle " + std::to_string(last.cycle - 1) +
                   ", less than Stop tolerance " +
                   printf("%g", parameters.stop_tolerance);
        }
      if (last.cycle >= parameters.cycles)
        return "Cycles = " + std::to_string(parameters.cycles) + " reached";
      return "";
    }


    /// The collapse load the cycles of @p a tend to, where they show a
    /// rate, against the last cycle's and the @p reference load.
    void
    extrapolate(const double reference, AdaptivitySummary &a)
    {
      const auto [extrapolated, rate] = extrapolate_collapse_load(a.cycles);
      a.extrapolated_collapse_load    = extrapolated;
      a.rate                          = rate;
      if (std::isfinite(extrapolated))
        {
          a.estimated_error =
            std::abs(a.cycles.back().collapse_load - extrapolated) /
            std::abs(extrapolated);
          a.extrapolated_relative_error =
            (extrapolated - reference) / reference;
        }
    }


    /**
     * The cycles, written into the directory @p open_staging gives (called
     * by every rank once the first cycle's input has been checked).
     */
    template <int dim>
    RunSummary
    cycles(const Parameters                   &p,
           const std::function<std::string()> &open_staging,
           std::ostream                       &out)
    {
      const AdaptivityParameters &adaptivity = p.adaptivity;
      AdaptivitySummary           a;
      a.indicator =
        AdaptivityParameters::indicator_names.name(adaptivity.indicator);
      a.marking = AdaptivityParameters::marking_names.name(adaptivity.marking);

      std::set<types::boundary_id> interfaces;
      for (const auto &[id, curve] : p.interface_elements)
        interfaces.insert(id);
      const unsigned int n_components =
        (p.kinematics.fourier || dim == 3) ? 3 : 2;

      auto clock = std::make_unique<RunClock>(out);
      print_run_header(p, out);
      std::unique_ptr<Scene<dim>> scene;
      {
        TimerOutput::Scope scope(clock->timer, "mesh");
        scene = std::make_unique<Scene<dim>>(p, out);
      }

      std::string    staging;
      RunSummary     last;
      unsigned int   refined = 0;
      Vector<double> indicator;
      for (unsigned int cycle = 0;; ++cycle)
        {
          out << "  cycle " << cycle;
          if (cycle > 0)
            out << ": " << refined << " cells refined"
                << (adaptivity.marking == AdaptivityParameters::Marking::uniform
                      ? std::string(" (uniform)")
                      : " by " + a.indicator);
          out << std::endl;
          last = run_on_scene<dim>(
            p,
            *scene,
            *clock,
            [&]() {
              if (staging.empty())
                staging = open_staging();
              const std::string directory =
                staging + "/cycle-" + std::to_string(cycle);
              if (mpi::is_root())
                std::filesystem::create_directories(directory);
              return directory;
            },
            out,
            [&](const AnalysisView<dim> &analysis) {
              indicator = refinement_indicator(analysis, adaptivity.indicator);
            });
          a.cycles.push_back(cycle_of(cycle, refined, last));

          a.stop_reason = reason_to_stop(adaptivity, a.cycles);
          if (!a.stop_reason.empty() || interrupted())
            break;
          if (adaptivity.marking != AdaptivityParameters::Marking::uniform &&
              !(indicator.l1_norm() > 0))
            {
              a.stop_reason =
                "cycle " + std::to_string(cycle) +
                " ended without plastic flow in the continuum to refine toward "
                "(a mechanism of interface slip alone, or none)";
              break;
            }

          clock = std::make_unique<RunClock>(out);
          {
            TimerOutput::Scope scope(clock->timer, "mesh");
            refined = refine_mesh(scene->triangulation_to_refine(),
                                  indicator,
                                  adaptivity,
                                  interfaces,
                                  p.parameter_file);
          }
          const types::global_dof_index dofs =
            count_dofs(scene->triangulation(),
                       n_components,
                       p.discretisation.serendipity);
          if (refined == 0)
            {
              a.stop_reason =
                "no cell was marked after cycle " + std::to_string(cycle);
              break;
            }
          if (dofs > adaptivity.max_dofs)
            {
              a.stop_reason = "cycle " + std::to_string(cycle + 1) +
                              "'s mesh would have " + std::to_string(dofs) +
                              " DoFs, more than Maximum DoFs = " +
                              std::to_string(adaptivity.max_dofs);
              break;
            }
        }

      extrapolate(p.reference.analytic_load, a);
      print_cycles(a, p.reference.analytic_load, out);
      last.adaptivity = a;
      if (mpi::is_root() && !staging.empty())
        {
          write_whole_file(staging, "summary.json", last.json());
          write_whole_file(staging, "adaptivity.csv", cycles_csv(a));
        }
      return last;
    }
  } // namespace


  std::pair<double, double>
  extrapolate_collapse_load(const std::vector<CycleSummary> &cycles)
  {
    const double none = std::numeric_limits<double>::quiet_NaN();
    std::vector<std::pair<double, double>> points; // (DoFs, load)
    for (const CycleSummary &c : cycles)
      if (std::isfinite(c.collapse_load) && c.dofs > 0)
        points.emplace_back(c.dofs, c.collapse_load);
    if (points.size() < 3)
      return {none, none};
    const auto [n1, p1] = points[points.size() - 3];
    const auto [n2, p2] = points[points.size() - 2];
    const auto [n3, p3] = points[points.size() - 1];
    if (!(n1 < n2 && n2 < n3) || p2 == p3)
      return {none, none};
    // (p1 - p2) / (p2 - p3) = (a^r - 1) / (1 - b^r), a = n2/n1 > 1,
    // b = n2/n3 < 1: increasing in r, so bisection finds the rate.
    const double ratio = (p1 - p2) / (p2 - p3);
    const auto   g     = [&](const double r) {
      return (std::pow(n2 / n1, r) - 1) / (1 - std::pow(n2 / n3, r));
    };
    double low = 0.05, high = 5;
    if (!(ratio > g(low) && ratio < g(high)))
      return {none, none};
    for (unsigned int k = 0; k < 100; ++k)
      {
        const double middle              = 0.5 * (low + high);
        (g(middle) < ratio ? low : high) = middle;
      }
    const double rate = 0.5 * (low + high);
    const double c    = (p2 - p3) / (std::pow(n2, -rate) - std::pow(n3, -rate));
    return {p3 - c * std::pow(n3, -rate), rate};
  }


  RunSummary
  run_adaptive(const Parameters &p, std::ostream &out)
  {
    // Every cycle's run goes into the one output directory, written aside
    // and put in place at the end.
    return run_in_output_directory(
      p,
      [&](const std::function<std::string()> &open_staging) {
        return p.kinematics.dimension == 3 ? cycles<3>(p, open_staging, out)
                                           : cycles<2>(p, open_staging, out);
      },
      out);
  }
} // namespace thinlayer
