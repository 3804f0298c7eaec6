#include <deal.II/fe/fe_values.h>

#include <thinlayer/discretisation/strain_operator.h>

namespace thinlayer
{
  template <int dim>
  void
  StrainOperator::reinit(const DoFHandler<dim> &dof_handler,
                         const Mapping<dim>    &mapping,
                         const Quadrature<dim> &quadrature,
                         const Kinematics      &kinematics)
  {
    const auto        &fe = dof_handler.get_fe();
    const unsigned int n_cells =
      dof_handler.get_triangulation().n_active_cells();
    const unsigned int n_q     = quadrature.size();
    const unsigned int n       = fe.n_dofs_per_cell();
    const unsigned int n_modes = kinematics.n_modes();
    parts                      = kinematics.is_fourier() ? 2 : 1;
    n_cell_dofs                = n;

    dofs.resize(std::size_t(n_cells) * n);
    weights.resize(std::size_t(n_cells) * n_q);
    // Every strain part at every point, then packed (see Pattern).
    std::vector<SymmetricTensor<2, 3>> all_shape_strains(
      std::size_t(n_cells) * n_q * n_modes * n * parts);

    FEValues<dim>                        fe_values(mapping,
                            fe,
                            quadrature,
                            update_values | update_gradients |
                              update_quadrature_points | update_JxW_values);
    std::vector<types::global_dof_index> cell_dof_indices(n);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const unsigned int c = cell->active_cell_index();
        fe_values.reinit(cell);
        cell->get_dof_indices(cell_dof_indices);
        std::copy(cell_dof_indices.begin(),
                  cell_dof_indices.end(),
                  dofs.begin() + std::size_t(c) * n);

        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            const unsigned int p = c * n_q + q;
            const Point<dim>  &x = fe_values.quadrature_point(q);
            weights[p]           = kinematics.area_factor(x) * fe_values.JxW(q);
            for (unsigned int m = 0; m < n_modes; ++m)
              for (const unsigned int i : fe_values.dof_indices())
                {
                  const unsigned int component =
                    fe.system_to_component_index(i).first;
                  SymmetricTensor<2, 3> part1, part2;
                  kinematics.shape_strain(
                    m,
                    component,
                    fe_values.shape_value_component(i, q, component),
                    fe_values.shape_grad_component(i, q, component),
                    x[0],
                    part1,
                    part2);
                  const std::size_t j =
                    ((std::size_t(p) * n_modes + m) * n + i) * parts;
                  all_shape_strains[j] = part1;
                  if (parts == 2)
                    all_shape_strains[j + 1] = part2;
                }
          }
      }

    pack(all_shape_strains, n_cells * n_q, n_modes);
  }


  void
  StrainOperator::pack(
    const std::vector<SymmetricTensor<2, 3>> &all_shape_strains,
    const unsigned int                        n_points,
    const unsigned int                        n_modes)
  {
    const unsigned int n = n_cell_dofs;
    // The non-zero pattern of each mode's and part's operator, over all
    // points, grouped by component.
    const std::size_t stride = std::size_t(n_modes) * n * parts;
    patterns.resize(n_modes * parts);
    entry_dof.clear();
    std::vector<unsigned int> entry_source; // (m * n + i) * parts + part
    std::vector<unsigned int> entry_component;
    for (unsigned int m = 0; m < n_modes; ++m)
      for (unsigned int part = 0; part < parts; ++part)
        {
          Pattern &pattern = patterns[m * parts + part];
          for (unsigned int k = 0; k < 6; ++k)
            {
              pattern.component_begin[k] = entry_dof.size();
              for (unsigned int i = 0; i < n; ++i)
                {
                  const unsigned int j        = (m * n + i) * parts + part;
                  bool               non_zero = false;
                  for (unsigned int p = 0; p < n_points && !non_zero; ++p)
                    non_zero =
                      (all_shape_strains[p * stride + j].access_raw_entry(k) !=
                       0);
                  if (non_zero)
                    {
                      entry_dof.push_back(i);
                      entry_source.push_back(j);
                      entry_component.push_back(k);
                    }
                }
            }
          pattern.component_begin[6] = entry_dof.size();
        }
    entries_per_point = entry_dof.size();
    values.resize(std::size_t(n_points) * entries_per_point);
    for (unsigned int p = 0; p < n_points; ++p)
      for (unsigned int e = 0; e < entries_per_point; ++e)
        values[std::size_t(p) * entries_per_point + e] =
          all_shape_strains[p * stride + entry_source[e]].access_raw_entry(
            entry_component[e]);
  }


  template void
  StrainOperator::reinit(const DoFHandler<2> &,
                         const Mapping<2> &,
                         const Quadrature<2> &,
                         const Kinematics &);
  template void
  StrainOperator::reinit(const DoFHandler<3> &,
                         const Mapping<3> &,
                         const Quadrature<3> &,
                         const Kinematics &);
} // namespace thinlayer
