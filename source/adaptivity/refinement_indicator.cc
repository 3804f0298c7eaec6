#include <thinlayer/adaptivity/refinement_indicator.h>
#include <thinlayer/elements/continuum_cells.h>
#include <thinlayer/parallel/mpi.h>

#include <algorithm>
#include <cmath>

namespace thinlayer
{
  template <int dim>
  Vector<double>
  refinement_indicator(const AnalysisView<dim>              &analysis,
                       const AdaptivityParameters::Indicator indicator)
  {
    const Triangulation<dim> &whole = analysis.get_whole_mesh();
    const Triangulation<dim> &own =
      analysis.get_dof_handler().get_triangulation();
    const ContinuumCells<dim> &cells = analysis.get_cells();
    const auto                &B     = cells.get_strain_operator();
    const unsigned int         n_q   = analysis.n_quadrature_points();
    const unsigned int         n_s   = analysis.get_kinematics().n_stations();

    Vector<double> values(whole.n_active_cells());
    for (const auto &cell : own.active_cell_iterators())
      {
        const unsigned int c = cell->active_cell_index();
        if (!cells.owns(c))
          continue;
        double value = 0;
        for (unsigned int q = 0; q < n_q; ++q)
          for (unsigned int s = 0; s < n_s; ++s)
            {
              const PointState &state = analysis.get_point_state(c, q, s);
              const SymmetricTensor<2, 3> &strain = state.plastic_strain;
              const double                 at_point =
                indicator == AdaptivityParameters::Indicator::plastic_work
                                  ? state.converged_stress * strain
                                  : std::sqrt(2. / 3. * (strain * strain));
              value += std::max(0., at_point) * B.point_weight(c * n_q + q);
            }
        // The same cell in the whole mesh: by its id, which the mesh split
        // over the ranks keeps.
        const unsigned int whole_index =
          mpi::n_ranks() > 1
            ? whole.create_cell_iterator(cell->id())->active_cell_index()
            : c;
        values[whole_index] = value / n_s;
      }
    mpi::sum(values);
    return values;
  }


  template Vector<double>
  refinement_indicator(const AnalysisView<2> &,
                       const AdaptivityParameters::Indicator);
  template Vector<double>
  refinement_indicator(const AnalysisView<3> &,
                       const AdaptivityParameters::Indicator);
} // namespace thinlayer
