#include <thinlayer/materials/elasticity.h>
#include <thinlayer/postprocess/cell_fields.h>

#include <cmath>
#include <limits>

namespace thinlayer
{
  template <int dim>
  CellFields::CellFields(const AnalysisView<dim> &analysis)
  {
    const auto        &tria    = analysis.get_dof_handler().get_triangulation();
    const unsigned int n_q     = analysis.n_quadrature_points();
    const unsigned int n_cells = tria.n_active_cells();
    const unsigned int n_s     = analysis.get_kinematics().n_stations();
    n_components = analysis.get_kinematics().n_components() == 3 ? 6 : 4;
    stress.assign(n_s,
                  std::vector<Vector<double>>(n_components,
                                              Vector<double>(n_cells)));
    equivalent.assign(n_s, Vector<double>(n_cells));
    plastic_strain.assign(n_s, Vector<double>(n_cells));
    yield_ratio.assign(n_s, Vector<double>(n_cells));
    material.reinit(n_cells);
    for (const auto &cell : tria.active_cell_iterators())
      {
        const unsigned int c = cell->active_cell_index();
        material[c]          = cell->material_id();
        // Another rank's points: it writes their cell.
        if (!analysis.get_cells().owns(c))
          continue;
        const MaterialLaw &law = analysis.get_material_law(c);
        for (unsigned int s = 0; s < n_s; ++s)
          {
            yield_ratio[s][c] = law.can_yield()
                                  ? std::numeric_limits<double>::lowest()
                                  : std::numeric_limits<double>::quiet_NaN();
            for (unsigned int q = 0; q < n_q; ++q)
              {
                const PointState &state = analysis.get_point_state(c, q, s);
                for (unsigned int k = 0; k < n_components; ++k)
                  stress[s][k][c] +=
                    state.stress[components[k][0]][components[k][1]] / n_q;
                equivalent[s][c] += equivalent_stress(state.stress) / n_q;
                // Equivalent plastic strain sqrt(2/3 e:e) of the state as
                // it stands: with the step's own when the step is pending
                // (the fields of a step are written before it is
                // accepted), as ContinuumCells::accept() will add it.
                const SymmetricTensor<2, 3> total =
                  state.plastic_strain + state.step_plastic_strain -
                  state.pending_plastic_strain;
                plastic_strain[s][c] +=
                  std::sqrt(2. / 3. * (total * total)) / n_q;
                if (law.can_yield())
                  yield_ratio[s][c] =
                    std::max(yield_ratio[s][c], law.yield_ratio(state.stress));
              }
          }
      }
  }


  template CellFields::CellFields(const AnalysisView<2> &);
  template CellFields::CellFields(const AnalysisView<3> &);
} // namespace thinlayer
