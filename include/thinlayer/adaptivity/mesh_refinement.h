#ifndef thinlayer_adaptivity_mesh_refinement_h
#define thinlayer_adaptivity_mesh_refinement_h

#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>

#include <thinlayer/parameters/adaptivity_section.h>

#include <set>
#include <string>

namespace thinlayer
{
  using namespace dealii;

  /**
   * Refine @p tria where @p indicator (one value per active cell) marks it,
   * by the Marking of @p parameters, keeping what the analysis needs of a
   * refined mesh:
   * - the two cells of every interface element (the facing sides on the
   *   boundaries @p interfaces, which the mesh was split along) are refined
   *   together, so that their children's sides face each other and pair
   *   into child elements with the parent's law;
   * - at most one hanging node per cell side (deal.II's 2:1 rule, which may
   *   refine neighbours; those carry their interface partners along);
   * - new vertices on curved sides lie on their manifolds, and children
   *   keep their parent's material id, so a thin layer's children are
   *   still the layer, its thickness now spanned by two rows of cells of
   *   its aspect ratio.
   * Every rank refines its copy of the whole mesh alike (the indicator is
   * the same on every rank).
   *
   * @return the number of cells flagged (0: the mesh is unchanged).
   */
  template <int dim>
  unsigned int
  refine_mesh(Triangulation<dim>                 &tria,
              const Vector<double>               &indicator,
              const AdaptivityParameters         &parameters,
              const std::set<types::boundary_id> &interfaces,
              const std::string                  &parameter_file);

  /**
   * The DoFs an analysis of @p tria has with @p n_components displacement
   * components (2 in plane strain, 3 in Fourier and 3D): the Q2 nodes less
   * the hanging ones and, where @p serendipity, the centres the serendipity
   * element eliminates (as AnalysisView::n_dofs() counts them). For
   * checking a refined mesh against a budget before it is set up.
   */
  template <int dim>
  types::global_dof_index
  count_dofs(const Triangulation<dim> &tria,
             const unsigned int        n_components,
             const bool                serendipity);
} // namespace thinlayer

#endif
