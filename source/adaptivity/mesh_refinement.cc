#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_refinement.h>
#include <deal.II/lac/affine_constraints.h>

#include <thinlayer/adaptivity/mesh_refinement.h>
#include <thinlayer/discretisation/serendipity_constraints.h>
#include <thinlayer/mesh/interface_pairing.h>

namespace thinlayer
{
  namespace
  {
    /// Flag the partner of every flagged cell of an interface element;
    /// returns whether any flag was added.
    template <int dim>
    bool
    refine_partners(const std::vector<FacingSides<dim>> &pairs)
    {
      bool added = false;
      for (const FacingSides<dim> &pair : pairs)
        if (pair.plus_cell->refine_flag_set() !=
            pair.minus_cell->refine_flag_set())
          {
            pair.plus_cell->set_refine_flag();
            pair.minus_cell->set_refine_flag();
            added = true;
          }
      return added;
    }
  } // namespace


  template <int dim>
  unsigned int
  refine_mesh(Triangulation<dim>                 &tria,
              const Vector<double>               &indicator,
              const AdaptivityParameters         &parameters,
              const std::set<types::boundary_id> &interfaces,
              const std::string                  &parameter_file)
  {
    AssertDimension(indicator.size(), tria.n_active_cells());
    for (const auto &cell : tria.active_cell_iterators())
      cell->clear_refine_flag();

    using Marking = AdaptivityParameters::Marking;
    switch (parameters.marking)
      {
        case Marking::uniform:
          for (const auto &cell : tria.active_cell_iterators())
            cell->set_refine_flag();
          break;
        case Marking::bulk:
          // L1: the indicators are integrals (work), and their sum is the
          // whole mechanism's.
          GridRefinement::refine_and_coarsen_fixed_fraction(tria,
                                                            indicator,
                                                            parameters.fraction,
                                                            0.);
          break;
        case Marking::fixed_number:
          GridRefinement::refine_and_coarsen_fixed_number(tria,
                                                          indicator,
                                                          parameters.fraction,
                                                          0.);
          break;
      }
    // Cells without any indicator are never refined by it: a fraction of
    // nothing marks ties at zero otherwise.
    if (parameters.marking != Marking::uniform)
      for (const auto &cell : tria.active_cell_iterators())
        if (!(indicator[cell->active_cell_index()] > 0))
          cell->clear_refine_flag();

    // The 2:1 rule may flag neighbours, and an interface element's partner
    // cell may need its own neighbours flagged in turn: repeat until both
    // hold. Flags are only ever added, so this ends.
    const DoFHandler<dim>               cells(tria);
    const std::vector<FacingSides<dim>> pairs =
      interfaces.empty() ? std::vector<FacingSides<dim>>()
                         : pair_facing_sides(cells, interfaces, parameter_file);
    bool changed = true;
    while (changed)
      {
        changed = refine_partners(pairs);
        changed = tria.prepare_coarsening_and_refinement() || changed;
      }

    unsigned int flagged = 0;
    for (const auto &cell : tria.active_cell_iterators())
      flagged += cell->refine_flag_set() ? 1 : 0;
    if (flagged > 0)
      tria.execute_coarsening_and_refinement();
    return flagged;
  }


  template <int dim>
  types::global_dof_index
  count_dofs(const Triangulation<dim> &tria,
             const unsigned int        n_components,
             const bool                serendipity)
  {
    DoFHandler<dim> dof_handler(tria);
    dof_handler.distribute_dofs(FESystem<dim>(FE_Q<dim>(2), n_components));
    AffineConstraints<double> constraints;
    make_element_constraints(dof_handler, serendipity, constraints);
    return dof_handler.n_dofs() - constraints.n_constraints();
  }


  template unsigned int
  refine_mesh(Triangulation<2> &,
              const Vector<double> &,
              const AdaptivityParameters &,
              const std::set<types::boundary_id> &,
              const std::string &);
  template unsigned int
  refine_mesh(Triangulation<3> &,
              const Vector<double> &,
              const AdaptivityParameters &,
              const std::set<types::boundary_id> &,
              const std::string &);
  template types::global_dof_index
  count_dofs(const Triangulation<2> &, const unsigned int, const bool);
  template types::global_dof_index
  count_dofs(const Triangulation<3> &, const unsigned int, const bool);
} // namespace thinlayer
