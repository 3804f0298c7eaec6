#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <thinlayer/solution_methods/newton.h>

namespace thinlayer
{
  template <int dim>
  void
  NewtonMethod<dim>::initialize()
  {
    ReturnMappingMethod<dim>::initialize();
    Analysis<dim>     &analysis = this->analysis;
    const unsigned int n        = analysis.get_dof_handler().n_dofs();
    const unsigned int n_cell  = analysis.get_strain_operator().dofs_per_cell();
    const unsigned int n_modes = analysis.n_modes();
    const unsigned int n_cells =
      analysis.get_dof_handler().get_triangulation().n_active_cells();

    constraints.clear();
    for (unsigned int m = 0; m < n_modes; ++m)
      {
        AffineConstraints<double> shifted;
        shifted.copy_from(analysis.mode(m).constraints);
        shifted.shift(m * n);
        constraints.merge(shifted);
      }
    constraints.close();

    DynamicSparsityPattern               dsp(n_modes * n);
    std::vector<types::global_dof_index> dofs(n_modes * n_cell);
    for (unsigned int c = 0; c < n_cells; ++c)
      {
        cell_dofs(c, dofs);
        constraints.add_entries_local_to_global(dofs, dsp, /*keep=*/true);
      }
    analysis.get_interface_elements().add_coupled_sparsity(dsp, constraints);
    sparsity.copy_from(dsp);
    tangent.reinit(sparsity);
    cell_matrices.assign(n_cells,
                         FullMatrix<double>(n_modes * n_cell,
                                            n_modes * n_cell));
    coupled_vector.reinit(n_modes * n);

    // A non-associated flow rule makes the tangent unsymmetric.
    factorisation = std::make_unique<FactorisedStiffness>(
      analysis.all_laws_associated() &&
          this->parameters.linear_solver ==
            SolverParameters::LinearSolver::cholmod
        ? FactorisedStiffness::Method::cholmod
        : FactorisedStiffness::Method::umfpack);

    const unsigned int n_local = n_modes * n_cell;
    ChunkScratch       scratch;
    scratch.strain.resize(n_local);
    scratch.stress.resize(n_local);
    scratch.part2.resize(n_cell);
    scratch.strain_rows.resize(6 * n_local);
    scratch.stress_rows.resize(6 * n_local);
    chunk_scratch.assign(analysis.get_point_loop().n_chunks(), scratch);

    // The tangent of the first load step's first iteration: elastic.
    const unsigned int n_q        = analysis.n_quadrature_points();
    const unsigned int n_stations = analysis.get_kinematics().n_stations();
    tangents.resize(std::size_t(n_cells) * n_q * n_stations);
    for (unsigned int p = 0; p < n_cells * n_q; ++p)
      for (unsigned int s = 0; s < n_stations; ++s)
        tangents[std::size_t(p) * n_stations + s] =
          analysis.material_law(p / n_q).elasticity();
    accepted_tangents = tangents;

    // Each cell's matrix with elastic tangents, once: a cell whose points
    // are all elastic takes it as it is in every factorisation.
    analysis.get_point_loop().for_each_chunk([this](const unsigned int begin,
                                                    const unsigned int end,
                                                    const unsigned int chunk) {
      compute_cell_tangents(begin, end, chunk_scratch[chunk]);
    });
    elastic_cell_matrices = cell_matrices;
    cell_is_elastic.assign(n_cells, 1);
  }


  template <int dim>
  bool
  NewtonMethod<dim>::elastic_tangents(const unsigned int c) const
  {
    const unsigned int n_q = this->analysis.n_quadrature_points();
    const unsigned int n_stations =
      this->analysis.get_kinematics().n_stations();
    const SymmetricTensor<4, 3> &elasticity =
      this->analysis.material_law(c).elasticity();
    for (std::size_t k = std::size_t(c) * n_q * n_stations;
         k < std::size_t(c + 1) * n_q * n_stations;
         ++k)
      if (!(tangents[k] == elasticity))
        return false;
    return true;
  }


  template <int dim>
  unsigned int
  NewtonMethod<dim>::max_iterations() const
  {
    return this->parameters.max_newton_iterations;
  }


  template <int dim>
  unsigned int
  NewtonMethod<dim>::max_cut_backs() const
  {
    return this->parameters.max_cut_backs;
  }


  template <int dim>
  ResidualNorms
  NewtonMethod<dim>::starting_residual(const double target)
  {
    return this->analysis.evaluate_residual(target, &tangents);
  }


  template <int dim>
  void
  NewtonMethod<dim>::state_accepted()
  {
    ReturnMappingMethod<dim>::state_accepted();
    accepted_tangents = tangents;
  }


  template <int dim>
  void
  NewtonMethod<dim>::state_rejected()
  {
    tangents = accepted_tangents;
  }


  template <int dim>
  bool
  NewtonMethod<dim>::iterate(const double   target,
                             ResidualNorms &norms,
                             StepResult    &result)
  {
    Analysis<dim>     &analysis = this->analysis;
    const unsigned int n        = analysis.get_dof_handler().n_dofs();
    const unsigned int n_modes  = analysis.n_modes();

    ++result.factorisations;
    if (!factorise_tangent())
      {
        // A singular tangent: the active set is a mechanism (an interface
        // sliding along its whole length, say). An iteration with the
        // elastic factors keeps going, so that the state shows the
        // mechanism rather than stopping at the predictor.
        this->remember_increments();
        this->elastic_corrections();
        for (unsigned int m = 0; m < n_modes; ++m)
          analysis.mode(m).step_increment += this->correction[m];
        norms = analysis.evaluate_residual(target, &tangents);
        return true;
      }
    // The coupled solve: the residuals (each condensed with its mode's
    // constraints) one after the other.
    for (unsigned int m = 0; m < n_modes; ++m)
      for (unsigned int i = 0; i < n; ++i)
        coupled_vector[m * n + i] = analysis.mode(m).residual[i];
    factorisation->solve(coupled_vector);
    constraints.distribute(coupled_vector);
    for (unsigned int m = 0; m < n_modes; ++m)
      for (unsigned int i = 0; i < n; ++i)
        this->correction[m][i] = coupled_vector[m * n + i];
    this->remember_increments();

    // Backtracking on |r|_2: halve the step until the residual falls
    // (Armijo with 1e-4), at most four times.
    const double initial = norms.l2;
    double       scale   = 1;
    for (unsigned int trial = 0;; ++trial)
      {
        for (unsigned int m = 0; m < n_modes; ++m)
          {
            Vector<double> &increment = analysis.mode(m).step_increment;
            increment                 = this->previous_increment[m];
            increment.add(scale, this->correction[m]);
          }
        norms = analysis.evaluate_residual(target, &tangents);
        if (norms.l2 <= (1 - 1e-4 * scale) * initial || trial == 4)
          break;
        scale /= 2;
      }
    return true;
  }


  template <int dim>
  void
  NewtonMethod<dim>::cell_dofs(const unsigned int                    c,
                               std::vector<types::global_dof_index> &dofs) const
  {
    const StrainOperator &B      = this->analysis.get_strain_operator();
    const unsigned int    n      = this->analysis.get_dof_handler().n_dofs();
    const unsigned int    n_cell = B.dofs_per_cell();
    for (unsigned int m = 0; m < this->analysis.n_modes(); ++m)
      for (unsigned int i = 0; i < n_cell; ++i)
        dofs[m * n_cell + i] = m * n + B.cell_dofs(c)[i];
  }


  template <int dim>
  void
  NewtonMethod<dim>::compute_cell_tangents(const unsigned int begin,
                                           const unsigned int end,
                                           ChunkScratch      &scratch)
  {
    const Analysis<dim>  &analysis   = this->analysis;
    const StrainOperator &B          = analysis.get_strain_operator();
    const Kinematics     &kinematics = analysis.get_kinematics();
    const unsigned int    n_cell     = B.dofs_per_cell();
    const unsigned int    n_q        = analysis.n_quadrature_points();
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

    for (unsigned int c = begin; c < end; ++c)
      {
        FullMatrix<double> &cell_matrix = cell_matrices[c];
        cell_matrix                     = 0;
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const unsigned int p = c * n_q + q;
            for (unsigned int s = 0; s < n_stations; ++s)
              {
                const SymmetricTensor<4, 3> &C =
                  tangents[std::size_t(p) * n_stations + s];
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
  bool
  NewtonMethod<dim>::factorise_tangent()
  {
    // The matrices of the cells with a plastic point in parallel (the
    // return mappings give the elastic tangent itself at an elastic point,
    // so the test is exact), then all added in cell order (the same sums on
    // any number of threads).
    this->analysis.get_point_loop().for_each_chunk(
      [this](const unsigned int begin,
             const unsigned int end,
             const unsigned int chunk) {
        for (unsigned int c = begin; c < end; ++c)
          {
            cell_is_elastic[c] = elastic_tangents(c);
            if (!cell_is_elastic[c])
              compute_cell_tangents(c, c + 1, chunk_scratch[chunk]);
          }
      });

    const unsigned int n_local =
      this->analysis.n_modes() *
      this->analysis.get_strain_operator().dofs_per_cell();
    std::vector<types::global_dof_index> dofs(n_local);
    tangent = 0;
    for (unsigned int c = 0; c < cell_matrices.size(); ++c)
      {
        cell_dofs(c, dofs);
        constraints.distribute_local_to_global(cell_is_elastic[c]
                                                 ? elastic_cell_matrices[c]
                                                 : cell_matrices[c],
                                               dofs,
                                               tangent);
      }
    this->analysis.get_interface_elements().add_coupled_tangent(tangent,
                                                                constraints);
    try
      {
        factorisation->factorize(tangent);
      }
    catch (const std::exception &)
      {
        return false; // singular: a mechanism has formed
      }
    return true;
  }


  template class NewtonMethod<2>;
} // namespace thinlayer
