#include <deal.II/base/data_out_base.h>
#include <deal.II/grid/filtered_iterator.h>

#include <thinlayer/output/revolved_view.h>

#include <cmath>
#include <sstream>

namespace thinlayer
{
  namespace
  {
    /// The station nearest to @p angle in [0, 2 pi), mirrored into
    /// [0, pi]; and whether it was mirrored.
    std::pair<unsigned int, bool>
    nearest_station(const Kinematics &kinematics, const double angle)
    {
      const bool   mirrored = angle > numbers::PI;
      const double folded   = mirrored ? 2 * numbers::PI - angle : angle;
      unsigned int nearest  = 0;
      for (unsigned int s = 1; s < kinematics.n_stations(); ++s)
        if (std::abs(kinematics.station_angle(s) - folded) <
            std::abs(kinematics.station_angle(nearest) - folded))
          nearest = s;
      return {nearest, mirrored};
    }
  } // namespace


  RevolvedView
  revolved_view(const AnalysisView<2> &analysis,
                const CellFields      &fields,
                const ModeVectors     &modes,
                const unsigned int     slices)
  {
    const Kinematics &kinematics  = analysis.get_kinematics();
    const auto       &dof_handler = analysis.get_dof_handler();

    // Data: the displacement (3), six stress components, the equivalent
    // stress, the plastic strain, the yield ratio, the material id.
    RevolvedView view;
    view.names = {"displacement",
                  "displacement",
                  "displacement",
                  "stress_rr",
                  "stress_zz",
                  "stress_tt",
                  "stress_rz",
                  "stress_rt",
                  "stress_zt",
                  "equivalent_stress",
                  "plastic_strain",
                  "yield_ratio",
                  "material_id"};
    // The components that change sign in the mirrored half: the shear
    // stresses with theta for the symmetric series, the others for the
    // antisymmetric one.
    const bool odd_in_theta[6] = {kinematics.is_antisymmetric(),
                                  kinematics.is_antisymmetric(),
                                  kinematics.is_antisymmetric(),
                                  kinematics.is_antisymmetric(),
                                  !kinematics.is_antisymmetric(),
                                  !kinematics.is_antisymmetric()};

    std::vector<double>     angles(slices + 1);
    std::vector<ModeVector> displacement(slices + 1);
    for (unsigned int k = 0; k <= slices; ++k)
      {
        angles[k]       = 2 * numbers::PI * k / slices;
        displacement[k] = analysis.displacement_at(angles[k], modes);
      }

    std::vector<DataOutBase::Patch<3, 3>> &patches = view.patches;
    patches.reserve(std::size_t(slices) *
                    dof_handler.get_triangulation().n_active_cells());
    for (unsigned int k = 0; k < slices; ++k)
      {
        const auto [s, mirrored] =
          nearest_station(kinematics, 0.5 * (angles[k] + angles[k + 1]));
        for (const auto &cell : dof_handler.active_cell_iterators() |
                                  IteratorFilters::LocallyOwnedCell())
          {
            const unsigned int       c = cell->active_cell_index();
            DataOutBase::Patch<3, 3> patch;
            patch.reference_cell = ReferenceCells::Hexahedron;
            patch.patch_index    = patches.size();
            patch.data.reinit(view.names.size(), 8);
            // Lexicographic: the cell's vertex i + 2 j at slice edge t is
            // the patch's vertex i + 2 j + 4 t.
            for (unsigned int t = 0; t < 2; ++t)
              for (unsigned int v = 0; v < 4; ++v)
                {
                  const unsigned int p       = v + 4 * t;
                  const double       theta   = angles[k + t];
                  const ModeVector  &u       = displacement[k + t];
                  const double       r       = cell->vertex(v)[0];
                  const double       u_r     = u[cell->vertex_dof_index(v, 0)];
                  const double       u_z     = u[cell->vertex_dof_index(v, 1)];
                  const double       u_theta = u[cell->vertex_dof_index(v, 2)];
                  patch.vertices[p]          = Point<3>(r * std::cos(theta),
                                               r * std::sin(theta),
                                               cell->vertex(v)[1]);
                  patch.data(0, p) =
                    u_r * std::cos(theta) - u_theta * std::sin(theta);
                  patch.data(1, p) =
                    u_r * std::sin(theta) + u_theta * std::cos(theta);
                  patch.data(2, p) = u_z;
                  for (unsigned int i = 0; i < 6; ++i)
                    patch.data(3 + i, p) =
                      (mirrored && odd_in_theta[i] ? -1 : 1) *
                      fields.stress[s][i][c];
                  patch.data(9, p)  = fields.equivalent[s][c];
                  patch.data(10, p) = fields.plastic_strain[s][c];
                  patch.data(11, p) = fields.yield_ratio[s][c];
                  patch.data(12, p) = fields.material[c];
                }
            patches.push_back(std::move(patch));
          }
      }

    return view;
  }
} // namespace thinlayer
