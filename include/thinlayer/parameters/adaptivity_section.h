#ifndef thinlayer_parameters_adaptivity_section_h
#define thinlayer_parameters_adaptivity_section_h

#include <deal.II/base/parameter_handler.h>

#include <thinlayer/base/name_table.h>

#include <string>

namespace thinlayer
{
  using namespace dealii;

  /**
   * "Adaptivity": refine the mesh toward the collapse mechanism and run the
   * load path again, cycle after cycle. A collapse load depends on how well
   * the mesh resolves the mechanism, which lives in a small part of the
   * body; refining where the plastic flow is, rather than everywhere, buys
   * the same accuracy with fewer equations. Each cycle re-solves the whole
   * path on the refined mesh (no state is transferred), so that every
   * cycle's collapse load is an independent, comparable result.
   */
  struct AdaptivityParameters
  {
    /// What marks a cell for refinement, from the last converged state.
    enum class Indicator
    {
      /// The plastic work sigma : eps_p integrated over the cell: where
      /// the mechanism dissipates.
      plastic_work,
      /// The equivalent plastic strain integrated over the cell: where it
      /// flows, whatever the stress.
      plastic_strain
    };

    /// Which cells are refined.
    enum class Marking
    {
      /// Doerfler's bulk criterion: the fewest cells whose indicators add
      /// up to the fraction of the total.
      bulk,
      /// The fraction of the cells with the largest indicators.
      fixed_number,
      /// Every cell: uniform refinement, the series adaptivity is measured
      /// against.
      uniform
    };

    static const NameTable<Indicator> indicator_names;
    static const NameTable<Marking>   marking_names;

    /// Refinements after the first run; 0: none (a single run).
    unsigned int cycles = 0;
    Indicator    indicator;
    Marking      marking;
    double       fraction;
    /// Stop when the collapse load changes by less than this, relative,
    /// between two cycles.
    double stop_tolerance;
    /// Stop before running a mesh with more DoFs than this.
    unsigned int max_dofs;

    bool
    active() const
    {
      return cycles > 0;
    }

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm, const std::string &parameter_file);
  };
} // namespace thinlayer

#endif
