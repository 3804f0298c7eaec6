#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>

#include <thinlayer/elements/continuum_cells.h>
#include <thinlayer/parameters/parameters.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace thinlayer
{
  template <int dim>
  ContinuumCells<dim>::ContinuumCells(
    const DoFHandler<dim>                                  &dof_handler,
    const Mapping<dim>                                     &mapping,
    const Quadrature<dim>                                  &quadrature,
    const Kinematics                                       &kinematics,
    const std::map<types::material_id, MaterialParameters> &materials,
    const CellPartition                                    &partition)
    : dof_handler(dof_handler)
    , mapping(mapping)
    , quadrature(quadrature)
    , kinematics(kinematics)
    , n_q(quadrature.size())
    , materials(materials)
    , time_step(std::numeric_limits<double>::infinity())
    , all_cells(partition.owner.empty())
  {
    for (const auto &[id, material] : materials)
      {
        laws[id]  = create_material_law(material);
        time_step = std::min(time_step, laws[id]->viscoplastic_time_step());
      }

    const Triangulation<dim> &tria = dof_handler.get_triangulation();
    cell_law.resize(tria.n_active_cells());
    for (const auto &cell : tria.active_cell_iterators())
      if (!cell->is_artificial())
        cell_law[cell->active_cell_index()] =
          laws.at(cell->material_id()).get();

    std::vector<unsigned int> cells;
    if (all_cells)
      {
        cells.resize(tria.n_active_cells());
        for (unsigned int c = 0; c < cells.size(); ++c)
          cells[c] = c;
        strain_operator.reinit(dof_handler, mapping, quadrature, kinematics);
      }
    else
      {
        // Only this rank's points: their operator and their states.
        cells = partition.owned_cells();
        cell_position.assign(tria.n_active_cells(),
                             numbers::invalid_unsigned_int);
        for (unsigned int i = 0; i < cells.size(); ++i)
          cell_position[cells[i]] = i;
        strain_operator.reinit(
          dof_handler, mapping, quadrature, kinematics, cells);
      }
    states.assign(std::size_t(cells.size()) * n_q * kinematics.n_stations(),
                  PointState());
    point_loop.reinit(
      strain_operator, kinematics, n_q, cell_law, cells, states);
  }


  template <int dim>
  void
  ContinuumCells<dim>::add_dofs(
    std::vector<types::global_dof_index> &dofs) const
  {
    for (const unsigned int c : point_loop.get_cells())
      dofs.insert(dofs.end(),
                  strain_operator.cell_dofs(c),
                  strain_operator.cell_dofs(c) +
                    strain_operator.dofs_per_cell());
  }


  template <int dim>
  void
  ContinuumCells<dim>::add_sparsity(
    DynamicSparsityPattern          &dsp,
    const AffineConstraints<double> &constraints) const
  {
    if (all_cells)
      DoFTools::make_sparsity_pattern(dof_handler,
                                      dsp,
                                      constraints,
                                      /*keep_constrained_dofs=*/true);
    else
      {
        std::vector<types::global_dof_index> dofs(
          strain_operator.dofs_per_cell());
        for (const unsigned int c : point_loop.get_cells())
          {
            std::copy(strain_operator.cell_dofs(c),
                      strain_operator.cell_dofs(c) + dofs.size(),
                      dofs.begin());
            constraints.add_entries_local_to_global(dofs,
                                                    dsp,
                                                    /*keep_constrained=*/true);
          }
      }
  }


  template <int dim>
  void
  ContinuumCells<dim>::assemble_elastic(const unsigned int    m,
                                        const CellMatrixSink &add) const
  {
    const unsigned int                   n = strain_operator.dofs_per_cell();
    FullMatrix<double>                   cell_matrix(n, n);
    std::vector<types::global_dof_index> dofs(n);
    std::vector<SymmetricTensor<2, 3>>   strain(n), stress(n);

    for (const unsigned int c : point_loop.get_cells())
      {
        cell_matrix                    = 0;
        const SymmetricTensor<4, 3> &D = cell_law[c]->elasticity();
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const unsigned int p = c * n_q + q;
            for (unsigned int part = 0; part < strain_operator.n_parts();
                 ++part)
              {
                const double weight =
                  (part == 0 ? kinematics.c1(m) : kinematics.c2(m)) *
                  strain_operator.point_weight(p);
                if (weight == 0)
                  continue;
                strain_operator.shape_strains(p, m, part, strain.data());
                for (unsigned int i = 0; i < n; ++i)
                  stress[i] = D * strain[i];
                for (unsigned int i = 0; i < n; ++i)
                  for (unsigned int j = 0; j < n; ++j)
                    cell_matrix(i, j) += (strain[i] * stress[j]) * weight;
              }
          }
        std::copy(strain_operator.cell_dofs(c),
                  strain_operator.cell_dofs(c) + n,
                  dofs.begin());
        add(dofs, cell_matrix);
      }
  }


  template <int dim>
  bool
  ContinuumCells<dim>::all_associated() const
  {
    for (const auto &[id, law] : laws)
      if (!law->is_associated())
        return false;
    return true;
  }


  template <int dim>
  unsigned int
  ContinuumCells<dim>::viscoplastic_update(const ModeVectors &step_increment,
                                           ModeVectors       &body_load_change)
  {
    return point_loop.viscoplastic_update(time_step,
                                          step_increment,
                                          body_load_change);
  }


  template <int dim>
  unsigned int
  ContinuumCells<dim>::return_mapping_update(const ModeVectors &step_increment,
                                             const bool         with_tangents,
                                             ModeVectors       &internal_forces,
                                             ModeVectors       &stress_excess)
  {
    Assert(!with_tangents ||
             tangents.size() ==
               point_loop.point_index(point_loop.get_cells().size(), 0, 0),
           ExcMessage("Tangents are kept only after add_coupled_sparsity(), "
                      "for the point loop's cells at that time."));
    return point_loop.return_mapping_update(step_increment,
                                            with_tangents ? &tangents : nullptr,
                                            internal_forces,
                                            stress_excess);
  }


  template <int dim>
  void
  ContinuumCells<dim>::add_internal_forces(ModeVectors &internal_forces) const
  {
    point_loop.add_internal_forces(internal_forces);
  }


  template <int dim>
  void
  ContinuumCells<dim>::accept()
  {
    for (PointState &state : states)
      {
        state.converged_stress = state.stress;
        state.plastic_strain +=
          state.step_plastic_strain - state.pending_plastic_strain;
        state.step_plastic_strain    = 0;
        state.pending_plastic_strain = 0;
      }
  }


  template <int dim>
  void
  ContinuumCells<dim>::set_initial_stresses(
    const std::function<SymmetricTensor<2, 3>(const Point<dim> &,
                                              types::material_id)> &initial)
  {
    FEValues<dim> fe_values(mapping,
                            dof_handler.get_fe(),
                            quadrature,
                            update_quadrature_points);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const unsigned int c = cell->active_cell_index();
        if (!cell->is_locally_owned() || !owns(c))
          continue;
        fe_values.reinit(cell);
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const SymmetricTensor<2, 3> stress =
              initial(fe_values.quadrature_point(q), cell->material_id());
            for (unsigned int s = 0; s < kinematics.n_stations(); ++s)
              {
                PointState &state      = states[point_loop.point_index(
                  all_cells ? c : cell_position[c], q, s)];
                state.stress           = stress;
                state.converged_stress = stress;
              }
          }
      }
  }


  template <int dim>
  void
  ContinuumCells<dim>::reduce_strength(
    const StrengthReductionParameters &reduced,
    const double                       factor)
  {
    for (const types::material_id id : reduced.materials)
      {
        MaterialParameters m = materials.at(id);
        const auto         r = StrengthReductionParameters::reduce(m.cohesion,
                                                           m.friction_angle,
                                                           m.dilation_angle,
                                                           factor);
        m.cohesion           = r.cohesion;
        m.friction_angle     = r.friction_angle;
        m.dilation_angle     = r.dilation_angle;
        laws[id]             = create_material_law(m);
      }
    time_step = std::numeric_limits<double>::infinity();
    for (const auto &[id, law] : laws)
      time_step = std::min(time_step, law->viscoplastic_time_step());
    // The point loop reads the laws through cell_law.
    for (const auto &cell :
         dof_handler.get_triangulation().active_cell_iterators())
      if (!cell->is_artificial())
        cell_law[cell->active_cell_index()] =
          laws.at(cell->material_id()).get();
  }


  template <int dim>
  void
  ContinuumCells<dim>::reject()
  {
    for (PointState &state : states)
      {
        state.stress                 = state.converged_stress;
        state.step_plastic_strain    = 0;
        state.pending_plastic_strain = 0;
      }
  }


  template <int dim>
  void
  ContinuumCells<dim>::check_state(StateCheck &check) const
  {
    // Overflow anywhere is no state: stresses whose invariants overflow
    // make the yield tests meaningless (NaN compares false, and a point
    // would count as elastic).
    const std::vector<unsigned int> &cells = point_loop.get_cells();
    for (unsigned int i = 0; i < cells.size(); ++i)
      {
        const MaterialLaw &law = *cell_law[cells[i]];
        for (std::size_t p = point_loop.point_index(i, 0, 0);
             p < point_loop.point_index(i + 1, 0, 0);
             ++p)
          {
            const PointState &state = states[p];
            for (unsigned int k = 0;
                 k < SymmetricTensor<2, 3>::n_independent_components;
                 ++k)
              check.finite =
                check.finite && std::isfinite(state.stress.access_raw_entry(k));
            if (!law.can_yield())
              continue;
            const double ratio = law.yield_ratio(state.stress);
            check.finite       = check.finite && std::isfinite(ratio);
            check.add_yield_ratio(ratio);
          }
      }
  }


  template <int dim>
  void
  ContinuumCells<dim>::coupled_cell_dofs(
    const unsigned int                    c,
    std::vector<types::global_dof_index> &dofs) const
  {
    const unsigned int n      = dof_handler.n_dofs();
    const unsigned int n_cell = strain_operator.dofs_per_cell();
    for (unsigned int m = 0; m < kinematics.n_modes(); ++m)
      for (unsigned int i = 0; i < n_cell; ++i)
        dofs[m * n_cell + i] = m * n + strain_operator.cell_dofs(c)[i];
  }


  template <int dim>
  void
  ContinuumCells<dim>::add_coupled_sparsity(const DofSink &add)
  {
    const unsigned int n_local =
      kinematics.n_modes() * strain_operator.dofs_per_cell();
    const std::vector<unsigned int>     &cells = point_loop.get_cells();
    std::vector<types::global_dof_index> dofs(n_local);
    for (const unsigned int c : cells)
      {
        coupled_cell_dofs(c, dofs);
        add(dofs);
      }
    // Matrices and tangents only for this rank's cells.
    cell_matrices.assign(cells.size(), FullMatrix<double>(n_local, n_local));

    TangentScratch scratch;
    scratch.strain.resize(n_local);
    scratch.stress.resize(n_local);
    scratch.part2.resize(strain_operator.dofs_per_cell());
    scratch.strain_rows.resize(6 * n_local);
    scratch.stress_rows.resize(6 * n_local);
    tangent_scratch.assign(point_loop.n_chunks(), scratch);

    // Each cell's matrix with elastic tangents: a cell whose points are
    // all elastic takes it as it is in every factorisation.
    const unsigned int n_stations = kinematics.n_stations();
    tangents.resize(cells.size() * n_q * n_stations);
    for (unsigned int i = 0; i < cells.size(); ++i)
      for (unsigned int q = 0; q < n_q; ++q)
        for (unsigned int s = 0; s < n_stations; ++s)
          tangents[point_loop.point_index(i, q, s)] =
            cell_law[cells[i]]->elasticity();
    point_loop.for_each_chunk([this](const unsigned int begin,
                                     const unsigned int end,
                                     const unsigned int chunk) {
      for (unsigned int i = begin; i < end; ++i)
        compute_cell_tangent(i, tangent_scratch[chunk]);
    });
    holds_elastic_matrix.assign(cells.size(), 1);
  }


  template <int dim>
  bool
  ContinuumCells<dim>::elastic_tangents(const unsigned int i) const
  {
    const SymmetricTensor<4, 3> &elasticity =
      cell_law[point_loop.get_cells()[i]]->elasticity();
    for (std::size_t k = point_loop.point_index(i, 0, 0);
         k < point_loop.point_index(i + 1, 0, 0);
         ++k)
      if (!(tangents[k] == elasticity))
        return false;
    return true;
  }


  template <int dim>
  void
  ContinuumCells<dim>::compute_cell_tangent(const unsigned int i,
                                            TangentScratch    &scratch)
  {
    const unsigned int    c          = point_loop.get_cells()[i];
    const StrainOperator &B          = strain_operator;
    const unsigned int    n_cell     = B.dofs_per_cell();
    const unsigned int    n_modes    = kinematics.n_modes();
    const unsigned int    n_stations = kinematics.n_stations();
    const unsigned int    n_local    = n_modes * n_cell;
    const bool            two_parts  = (B.n_parts() == 2);
    // Per mode: the strain of each shape function at a station (T1 B1 +
    // T2 B2) and the tangent applied to it; then both as 6 rows of raw
    // components, the strains' shear rows doubled and weighted, so that
    // the cell matrix takes a rank-6 update with contiguous rows.
    auto &strain      = scratch.strain;
    auto &stress      = scratch.stress;
    auto &part2       = scratch.part2;
    auto &strain_rows = scratch.strain_rows;
    auto &stress_rows = scratch.stress_rows;

    {
      FullMatrix<double> &cell_matrix = cell_matrices[i];
      cell_matrix                     = 0;
      for (unsigned int q = 0; q < n_q; ++q)
        {
          const unsigned int p = c * n_q + q;
          for (unsigned int s = 0; s < n_stations; ++s)
            {
              const SymmetricTensor<4, 3> &C =
                tangents[point_loop.point_index(i, q, s)];
              const double weight =
                kinematics.station_weight(s) * B.point_weight(p);
              for (unsigned int m = 0; m < n_modes; ++m)
                {
                  SymmetricTensor<2, 3> *e = &strain[m * n_cell];
                  B.shape_strains(p, m, 0, e);
                  if (two_parts)
                    B.shape_strains(p, m, 1, part2.data());
                  for (unsigned int i = 0; i < n_cell; ++i)
                    {
                      e[i] *= kinematics.T1(m, s);
                      if (two_parts)
                        e[i] += kinematics.T2(m, s) * part2[i];
                      stress[m * n_cell + i] = C * e[i];
                    }
                }
              // Every pair of modes: the station sum of
              // (T1 B1 + T2 B2)_m^T C_t (T1 B1 + T2 B2)_m'.
              for (unsigned int k = 0; k < 6; ++k)
                for (unsigned int i = 0; i < n_local; ++i)
                  {
                    strain_rows[k * n_local + i] =
                      (k < 3 ? weight : 2 * weight) *
                      strain[i].access_raw_entry(k);
                    stress_rows[k * n_local + i] =
                      stress[i].access_raw_entry(k);
                  }
              for (unsigned int i = 0; i < n_local; ++i)
                {
                  double *row = &cell_matrix(i, 0);
                  for (unsigned int k = 0; k < 6; ++k)
                    {
                      const double  a = strain_rows[k * n_local + i];
                      const double *b = &stress_rows[k * n_local];
                      if (a != 0)
                        for (unsigned int j = 0; j < n_local; ++j)
                          row[j] += a * b[j];
                    }
                }
            }
        }
    }
  }


  template <int dim>
  void
  ContinuumCells<dim>::add_coupled_tangent(const CellMatrixSink &add)
  {
    // The matrices of the cells with a plastic point in parallel (the
    // return mappings give the elastic tangent itself at an elastic point,
    // so the test is exact), and of those elastic again, whose matrix is
    // still the last plastic one; then all added in cell order (the same
    // sums on any number of threads).
    point_loop.for_each_chunk([this](const unsigned int begin,
                                     const unsigned int end,
                                     const unsigned int chunk) {
      for (unsigned int i = begin; i < end; ++i)
        {
          const bool elastic = elastic_tangents(i);
          if (!elastic || !holds_elastic_matrix[i])
            compute_cell_tangent(i, tangent_scratch[chunk]);
          holds_elastic_matrix[i] = elastic;
        }
    });

    const std::vector<unsigned int>     &cells = point_loop.get_cells();
    std::vector<types::global_dof_index> dofs(kinematics.n_modes() *
                                              strain_operator.dofs_per_cell());
    for (unsigned int i = 0; i < cells.size(); ++i)
      {
        coupled_cell_dofs(cells[i], dofs);
        add(dofs, cell_matrices[i]);
      }
  }


  template class ContinuumCells<2>;
  template class ContinuumCells<3>;
} // namespace thinlayer
