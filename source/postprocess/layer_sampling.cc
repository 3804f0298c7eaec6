#include <thinlayer/parallel/distributed_mesh.h>
#include <thinlayer/postprocess/layer_sampling.h>

#include <limits>

namespace thinlayer
{
  template <int dim>
  void
  LayerReading<dim>::place_on_ranks(const AnalysisView<dim> &analysis)
  {
    for (LayerSample<dim> &sample : samples)
      {
        sample.own = analysis.owns_whole_cell(sample.cell->active_cell_index());
        sample.cell = sample.own
                        ? cell_of(analysis.get_dof_handler(), sample.cell->id())
                        : typename DoFHandler<dim>::active_cell_iterator();
      }
  }


  template <int dim>
  std::vector<InterfaceValues>
  evaluate_layer(const AnalysisView<dim>             &analysis,
                 const std::vector<LayerSample<dim>> &samples,
                 const unsigned int                   station)
  {
    const double     theta = analysis.get_kinematics().station_angle(station);
    const ModeVector u     = analysis.displacement_at(theta);
    const ModeVector du    = analysis.displacement_at(theta, true);
    const FiniteElement<dim> &fe = analysis.get_dof_handler().get_fe();
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());

    // The face-to-face difference of @p v at a sample, 3 components.
    const auto difference = [&](const ModeVector       &v,
                                const LayerSample<dim> &s) {
      Tensor<1, 3> d;
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        {
          const unsigned int c = fe.system_to_component_index(i).first;
          d[c] += v[dofs[i]] * (fe.shape_value(i, s.unit_plus) -
                                fe.shape_value(i, s.unit_minus));
        }
      return d;
    };

    std::vector<InterfaceValues> values;
    values.reserve(samples.size());
    for (const LayerSample<dim> &s : samples)
      {
        // The points of another rank's cell: their values come from it.
        if (!s.own)
          {
            values.emplace_back();
            continue;
          }
        s.cell->get_dof_indices(dofs);
        const Tensor<1, 3> jump  = difference(u, s);
        const Tensor<1, 3> djump = difference(du, s);

        const unsigned int    cell_index = s.cell->active_cell_index();
        const MaterialLaw    &law = analysis.get_material_law(cell_index);
        SymmetricTensor<2, 3> stress;
        InterfaceValues       v;
        v.plastic            = false;
        v.mobilised_strength = 0;
        for (const unsigned int q : s.thickness_points)
          {
            const PointState &state =
              analysis.get_point_state(cell_index, q, station);
            stress += state.stress / s.thickness_points.size();
            v.plastic = v.plastic || state.yielding;
            v.mobilised_strength =
              std::max(v.mobilised_strength,
                       law.mobilised_strength(state.stress));
          }
        const Tensor<1, 3> traction   = stress * s.n;
        v.slip                        = jump * s.t1;
        v.slip_out_of_plane           = jump * s.t2;
        v.opening                     = jump * s.n;
        v.slip_increment              = djump * s.t1;
        v.opening_increment           = djump * s.n;
        v.shear_traction              = traction * s.t1;
        v.shear_traction_out_of_plane = traction * s.t2;
        v.normal_traction             = traction * s.n;
        values.push_back(v);
      }
    sum_over_ranks(values);
    return values;
  }


  template <int dim>
  std::vector<Vector<double>>
  layer_cell_averages(const AnalysisView<dim>                      &analysis,
                      const std::vector<LayerSample<dim>>          &samples,
                      const std::vector<InterfaceValues>           &values,
                      const std::vector<double InterfaceValues::*> &fields)
  {
    const unsigned int n_cells =
      analysis.get_dof_handler().get_triangulation().n_active_cells();
    std::vector<Vector<double>> averages(fields.size(),
                                         Vector<double>(n_cells));
    std::vector<unsigned int>   count(n_cells);
    for (unsigned int k = 0; k < samples.size(); ++k)
      if (samples[k].own)
        {
          const unsigned int c = samples[k].cell->active_cell_index();
          for (unsigned int f = 0; f < fields.size(); ++f)
            averages[f][c] += values[k].*fields[f];
          ++count[c];
        }
    for (auto &average : averages)
      for (unsigned int c = 0; c < n_cells; ++c)
        if (count[c] > 0)
          average[c] /= count[c];
    return averages;
  }


  template class LayerReading<2>;
  template class LayerReading<3>;
  template std::vector<InterfaceValues>
  evaluate_layer(const AnalysisView<2> &,
                 const std::vector<LayerSample<2>> &,
                 const unsigned int);
  template std::vector<InterfaceValues>
  evaluate_layer(const AnalysisView<3> &,
                 const std::vector<LayerSample<3>> &,
                 const unsigned int);
  template std::vector<Vector<double>>
  layer_cell_averages(const AnalysisView<2> &,
                      const std::vector<LayerSample<2>> &,
                      const std::vector<InterfaceValues> &,
                      const std::vector<double InterfaceValues::*> &);
  template std::vector<Vector<double>>
  layer_cell_averages(const AnalysisView<3> &,
                      const std::vector<LayerSample<3>> &,
                      const std::vector<InterfaceValues> &,
                      const std::vector<double InterfaceValues::*> &);
} // namespace thinlayer
