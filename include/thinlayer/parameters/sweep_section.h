#ifndef thinlayer_parameters_sweep_section_h
#define thinlayer_parameters_sweep_section_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <thinlayer/base/name_table.h>

#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /**
   * "Sweep": the runs are the cartesian product of these value lists. A
   * name with a '/' is an entry ("Solver/Tolerance"), any other name a
   * geometry parameter. Empty: a single run.
   */
  struct SweepParameters
  {
    /// The most runs a sweep may have: checking each takes milliseconds
    /// and running each seconds, so more is a mistyped list.
    static constexpr std::size_t max_runs = 10000;

    std::vector<std::pair<std::string, std::vector<std::string>>> values;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm, const std::string &parameter_file);
  };
} // namespace thinlayer

#endif
