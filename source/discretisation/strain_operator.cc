#include <deal.II/fe/fe_values.h>

#include <thinlayer/discretisation/strain_operator.h>

#include <numeric>

namespace thinlayer
{
  template <int dim, typename Function>
  void
  StrainOperator::for_each_point(const DoFHandler<dim> &dof_handler,
                                 const Mapping<dim>    &mapping,
                                 const Quadrature<dim> &quadrature,
                                 const Function        &f) const
  {
    FEValues<dim> fe_values(mapping,
                            dof_handler.get_fe(),
                            quadrature,
                            update_values | update_gradients |
                              update_quadrature_points | update_JxW_values);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const unsigned int slot = cell_slot[cell->active_cell_index()];
        if (slot == numbers::invalid_unsigned_int)
          continue;
        fe_values.reinit(cell);
        for (const unsigned int q : fe_values.quadrature_point_indices())
          f(slot * n_q + q, q, fe_values);
      }
  }


  template <int dim>
  void
  StrainOperator::reinit(const DoFHandler<dim> &dof_handler,
                         const Mapping<dim>    &mapping,
                         const Quadrature<dim> &quadrature,
                         const Kinematics      &kinematics)
  {
    std::vector<unsigned int> all(
      dof_handler.get_triangulation().n_active_cells());
    std::iota(all.begin(), all.end(), 0U);
    reinit(dof_handler, mapping, quadrature, kinematics, all);
    cell_slot.clear();
  }


  template <int dim>
  void
  StrainOperator::reinit(const DoFHandler<dim>           &dof_handler,
                         const Mapping<dim>              &mapping,
                         const Quadrature<dim>           &quadrature,
                         const Kinematics                &kinematics,
                         const std::vector<unsigned int> &cells)
  {
    const auto        &fe = dof_handler.get_fe();
    const unsigned int n_cells =
      dof_handler.get_triangulation().n_active_cells();
    const unsigned int n       = fe.n_dofs_per_cell();
    const unsigned int n_modes = kinematics.n_modes();
    parts                      = kinematics.is_fourier() ? 2 : 1;
    n_cell_dofs                = n;
    n_q                        = quadrature.size();

    cell_slot.assign(n_cells, numbers::invalid_unsigned_int);
    for (unsigned int k = 0; k < cells.size(); ++k)
      cell_slot[cells[k]] = k;
    dofs.resize(std::size_t(cells.size()) * n);
    std::vector<types::global_dof_index> cell_dof_indices(n);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const unsigned int slot = cell_slot[cell->active_cell_index()];
        if (slot == numbers::invalid_unsigned_int)
          continue;
        cell->get_dof_indices(cell_dof_indices);
        std::copy(cell_dof_indices.begin(),
                  cell_dof_indices.end(),
                  dofs.begin() + std::size_t(slot) * n);
      }

    // The strain parts of every shape function in every mode at one point,
    // [(m * n + i) * parts + part].
    std::vector<SymmetricTensor<2, 3>> point_strains(n_modes * n * parts);
    const auto                         compute = [&](const unsigned int   q,
                             const FEValues<dim> &fe_values) {
      const Point<dim> &x = fe_values.quadrature_point(q);
      for (unsigned int m = 0; m < n_modes; ++m)
        for (const unsigned int i : fe_values.dof_indices())
          {
            const unsigned int component =
              fe.system_to_component_index(i).first;
            SymmetricTensor<2, 3> part2;
            kinematics.shape_strain(
              m,
              component,
              fe_values.shape_value_component(i, q, component),
              fe_values.shape_grad_component(i, q, component),
              x[0],
              point_strains[(m * n + i) * parts],
              part2);
            if (parts == 2)
              point_strains[(m * n + i) * parts + 1] = part2;
          }
    };

    // Two passes over the points, so that the strains of every shape
    // function at every point are never held at once (they are several
    // times the packed operator): the first finds where the operator is
    // not zero anywhere (see Pattern), the second keeps its values there.
    std::vector<unsigned char> non_zero(n_modes * n * parts * 6, 0);
    for_each_point(dof_handler,
                   mapping,
                   quadrature,
                   [&](const unsigned int,
                       const unsigned int   q,
                       const FEValues<dim> &fe_values) {
                     compute(q, fe_values);
                     for (unsigned int j = 0; j < point_strains.size(); ++j)
                       for (unsigned int k = 0; k < 6; ++k)
                         non_zero[j * 6 + k] |=
                           (point_strains[j].access_raw_entry(k) != 0);
                   });

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
                  const unsigned int j = (m * n + i) * parts + part;
                  if (non_zero[j * 6 + k])
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

    const std::size_t n_points = std::size_t(cells.size()) * n_q;
    weights.assign(n_points, 0.);
    values.assign(n_points * entries_per_point, 0.);
    values.shrink_to_fit();
    weights.shrink_to_fit();
    for_each_point(dof_handler,
                   mapping,
                   quadrature,
                   [&](const unsigned int   p,
                       const unsigned int   q,
                       const FEValues<dim> &fe_values) {
                     compute(q, fe_values);
                     weights[p] =
                       kinematics.area_factor(fe_values.quadrature_point(q)) *
                       fe_values.JxW(q);
                     for (unsigned int e = 0; e < entries_per_point; ++e)
                       values[p * entries_per_point + e] =
                         point_strains[entry_source[e]].access_raw_entry(
                           entry_component[e]);
                   });
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
  template void
  StrainOperator::reinit(const DoFHandler<2> &,
                         const Mapping<2> &,
                         const Quadrature<2> &,
                         const Kinematics &,
                         const std::vector<unsigned int> &);
  template void
  StrainOperator::reinit(const DoFHandler<3> &,
                         const Mapping<3> &,
                         const Quadrature<3> &,
                         const Kinematics &,
                         const std::vector<unsigned int> &);
} // namespace thinlayer
