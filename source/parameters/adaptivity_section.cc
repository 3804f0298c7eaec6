#include <thinlayer/base/input_error.h>
#include <thinlayer/base/text_format.h>
#include <thinlayer/parameters/adaptivity_section.h>

// The Adaptivity section: the refinement cycles, checked as they are read.

namespace thinlayer
{
  const NameTable<AdaptivityParameters::Indicator>
    AdaptivityParameters::indicator_names = {
      {Indicator::plastic_work, "plastic work"},
      {Indicator::plastic_strain, "plastic strain"}};

  const NameTable<AdaptivityParameters::Marking>
    AdaptivityParameters::marking_names = {{Marking::bulk, "bulk"},
                                           {Marking::fixed_number,
                                            "fixed number"},
                                           {Marking::uniform, "uniform"}};


  void
  AdaptivityParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Adaptivity");
    prm.declare_entry(
      "Cycles",
      "0",
      Patterns::Integer(0, 20),
      "How many times the mesh is refined toward the collapse mechanism "
      "and the load path run again on it; 0: one run on the mesh as "
      "given. Each cycle writes its run into cycle-N of the output "
      "directory; summary.json there is the last cycle's, with every "
      "cycle's cells, DoFs and collapse load, and adaptivity.csv lists "
      "them.");
    prm.declare_entry(
      "Indicator",
      "plastic work",
      Patterns::Selection(indicator_names.pattern()),
      "What marks a cell, at the last converged state: 'plastic work' "
      "integrates sigma : eps_p over the cell (where the mechanism "
      "dissipates); 'plastic strain' integrates the equivalent plastic "
      "strain (where the soil flows, whatever its strength).");
    prm.declare_entry(
      "Marking",
      "bulk",
      Patterns::Selection(marking_names.pattern()),
      "Which cells are refined: 'bulk' (Doerfler) the fewest cells whose "
      "indicators add up to Marking fraction of the total; 'fixed number' "
      "that fraction of the cells, those with the largest indicators; "
      "'uniform' every cell (the series adaptive refinement is measured "
      "against). The two cells of an interface element are refined "
      "together, and a cell's neighbours as far as one hanging node per "
      "side needs.");
    prm.declare_entry("Marking fraction",
                      "0.5",
                      Patterns::Double(0, 1),
                      "The fraction of the indicator's total (bulk) or of "
                      "the cells (fixed number) refined; above 0, at most "
                      "1.");
    prm.declare_entry(
      "Stop tolerance",
      "0.005",
      Patterns::Double(0),
      "The cycles stop when the collapse load changes by less than this, "
      "relative, from one cycle to the next; 0: they run to Cycles.");
    prm.declare_entry("Maximum DoFs",
                      "2000000",
                      Patterns::Integer(1),
                      "The cycles stop before a refined mesh with more DoFs "
                      "than this would be run.");
    prm.leave_subsection();
  }


  void
  AdaptivityParameters::parse(ParameterHandler &prm, const std::string &file)
  {
    prm.enter_subsection("Adaptivity");
    cycles         = prm.get_integer("Cycles");
    indicator      = indicator_names.value(prm.get("Indicator"));
    marking        = marking_names.value(prm.get("Marking"));
    fraction       = prm.get_double("Marking fraction");
    stop_tolerance = prm.get_double("Stop tolerance");
    max_dofs       = prm.get_integer("Maximum DoFs");
    prm.leave_subsection();
    if (!(fraction > 0))
      throw InputError(file,
                       "Adaptivity/Marking fraction",
                       "expected a fraction above 0 and at most 1, got " +
                         text_format::printf("%g", fraction));
  }
} // namespace thinlayer
