// Truths checked of Loading/Control = work (the load factor found with the
// displacements, each step prescribing the work of the loads on it), by
// the default solution method (Newton throughout under work control):
// - Case 1 of the paper at 45 degrees (prm/case1-inclined-adhesive.prm, a
//   thin Tresca layer): the load reaches its plateau at the closed form
//   P / (C_w B) = 1 / (sin a cos a) = 2 within 0.5% (the collapse
//   resolution), with no attempt that failed, and in fewer iterations
//   than the same scene under load control, whose bracket of the collapse
//   the plateau lies in;
// - Prandtl's strip footing on 128 cells (prm/prandtl-strip-footing.prm):
//   the plateau within 1% of (2 + pi) c and inside the collapse bracket
//   that load control finds on the same mesh (widened by its resolution:
//   the bracket's upper end is a failed attempt, the plateau a state);
// - the same Case 1 on zero-thickness interface elements
//   (prm/case1-inclined-adhesive-zero-thickness.prm), where the whole
//   block slides on the interface and the tangent is singular at the
//   collapse: the run reports no collapse it has not found ("not
//   converged"), never a bracket from a failed step that asked for no
//   load factor.
// The same on two ranks (the bordered solve by the distributed factor).
#include <deal.II/base/mpi.h>

#include <thinlayer/parallel/mpi.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "../common/parallel_truths.h"
#include "../common/run_results.h"
#include "../common/truths.h"

namespace
{
  struct Run
  {
    std::string  outcome;
    double       collapse; // over the closed form
    double       low;      // the load factor bracket, where there is one
    double       high;
    unsigned int attempts;
    unsigned int steps;
    unsigned int iterations;
  };

  Run
  run(const std::string &prm, const std::string &control, const bool prandtl)
  {
    std::vector<std::string> settings = {
      "Solver/Method=accelerated with newton fallback",
      "Solver/Convergence criterion=default",
      "Loading/Control=" + control};
    if (prandtl)
      settings.push_back(
        "Mesh/Geometry parameters=half_width=1, width=5, depth=3, "
        "n_footing=6, n_side=10, n_depth=8, growth=1.2");
    run_results::run_prm(prm, settings);
    // Rank 0 writes the results; every rank reads them once written.
    MPI_Barrier(thinlayer::mpi::communicator());
    const auto summary = run_results::summary("results");
    const auto bracket = summary["collapse_load_factor_bracket"];
    const bool collapse =
      summary["outcome"] == "collapse" && summary["collapse_load"].is_number();
    Run r{summary["outcome"],
          collapse ? summary["collapse_load"].get<double>() /
                       summary["reference_load"].get<double>()
                   : std::nan(""),
          bracket.value("low", std::nan("")),
          bracket.value("high", std::nan("")),
          summary["attempts"],
          summary["load_steps"],
          summary["total_iterations"]};
    std::printf("%s, %s control: %s, collapse load / closed form %.4f\n",
                prm.c_str(),
                control.c_str(),
                r.outcome.c_str(),
                r.collapse);
    return r;
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi_session(argc, argv, 1);
  truths::print_on_rank_zero();
  using truths::expect;
  {
    const Run work = run("case1-inclined-adhesive.prm", "work", false);
    const Run load = run("case1-inclined-adhesive.prm", "load", false);
    expect(work.outcome == "collapse" && std::abs(work.collapse - 1) <= 0.005,
           "Case 1, work control: the plateau at 1 / (sin a cos a) within "
           "0.5%");
    expect(work.attempts == work.steps, "no attempt failed");
    expect(load.outcome == "collapse" &&
             work.collapse >= load.low * (1 - 1e-9) &&
             work.collapse <= load.high * (1 + 1e-9),
           "inside load control's bracket (to round-off: the plateau of "
           "perfect plasticity is flat to it)");
    expect(work.iterations < load.iterations,
           "fewer iterations than load control");
  }
  {
    const Run work = run("prandtl-strip-footing.prm", "work", true);
    const Run load = run("prandtl-strip-footing.prm", "load", true);
    expect(work.outcome == "collapse" && std::abs(work.collapse - 1) <= 0.01,
           "Prandtl on 128 cells, work control: the plateau within 1% of "
           "(2 + pi) c");
    expect(load.outcome == "collapse" &&
             work.collapse >= load.low * (1 - 0.005) &&
             work.collapse <= load.high * (1 + 0.005),
           "inside load control's bracket, widened by the resolution");
  }
  {
    const Run work =
      run("case1-inclined-adhesive-zero-thickness.prm", "work", false);
    expect(work.outcome == "not converged" && std::isnan(work.low),
           "Case 1 on zero-thickness elements, work control: no collapse "
           "and no bracket claimed where the tangent is singular");
  }
  return truths::conclude();
}
