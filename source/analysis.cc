#include <deal.II/base/thread_management.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/numerics/vector_tools.h>

#include <thinlayer/analysis.h>
#include <thinlayer/input_error.h>
#include <thinlayer/serendipity_constraints.h>

#include <algorithm>
#include <limits>

namespace thinlayer
{
  namespace
  {
    /// max_i |v_i| of a vector after condensation onto the free DoFs;
    /// @p work holds the condensed copy (reused, so nothing is allocated
    /// in the iterations).
    double
    condensed_max(const Vector<double>            &v,
                  const AffineConstraints<double> &constraints,
                  Vector<double>                  &work)
    {
      work = v;
      constraints.condense(work);
      return work.linfty_norm();
    }

    Kinematics
    make_kinematics(const Parameters &p)
    {
      return p.fourier ? Kinematics::make_fourier(p.harmonics,
                                                  p.station_angles,
                                                  p.antisymmetric)
                       : Kinematics::make_plane_strain();
    }
  } // namespace


  template <int dim>
  Analysis<dim>::Analysis(const Parameters         &parameters,
                          const Triangulation<dim> &tria)
    : parameters(parameters)
    , tria(tria)
    , kinematics(make_kinematics(parameters))
    , fe(FE_Q<dim>(2), kinematics.n_components())
    , mapping(2)
    , quadrature(parameters.gauss_points_per_direction)
    , dof_handler(tria)
    , boundary_data(parameters, kinematics)
    , time_step(std::numeric_limits<double>::infinity())
    , n_parts(kinematics.is_fourier() ? 2 : 1)
    , anderson(parameters.anderson_depth)
    , load_factor(0)
    , substitution_time(0)
  {
    static_assert(dim == 2,
                  "The kinematics so far are plane strain and Fourier, both "
                  "on 2D meshes.");
  }


  template <int dim>
  void
  Analysis<dim>::setup()
  {
    if (!boundary_data.has_constraints())
      throw InputError(parameters.parameter_file,
                       "Boundary <id>/Constrained components",
                       "no displacement component is constrained anywhere; "
                       "the body must be restrained against rigid-body "
                       "motion");

    dof_handler.distribute_dofs(fe);
    dof_component.resize(dof_handler.n_dofs());
    for (unsigned int c = 0; c < kinematics.n_components(); ++c)
      {
        std::vector<bool> mask(kinematics.n_components(), false);
        mask[c] = true;
        for (const auto dof :
             DoFTools::extract_dofs(dof_handler, ComponentMask(mask)))
          dof_component[dof] = c;
      }

    element_constraints.clear();
    if (parameters.serendipity)
      make_serendipity_constraints(dof_handler, element_constraints);
    element_constraints.close();

    modes.clear();
    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    for (unsigned int m = 0; m < kinematics.n_modes(); ++m)
      {
        modes.push_back(std::make_unique<Mode>(
          parameters.linear_solver == LinearSolver::cholmod
            ? FactorisedStiffness::Method::cholmod
            : FactorisedStiffness::Method::umfpack));
        make_mode_constraints(m);
        DoFTools::make_sparsity_pattern(dof_handler,
                                        dsp,
                                        modes[m]->constraints,
                                        /*keep_constrained_dofs=*/true);
      }
    sparsity.copy_from(dsp);

    for (const auto &[id, material] : parameters.materials)
      {
        laws[id]  = create_material_law(material);
        time_step = std::min(time_step, laws[id]->viscoplastic_time_step());
      }

    build_point_cache();

    const unsigned int n = dof_handler.n_dofs();
    for (unsigned int m = 0; m < kinematics.n_modes(); ++m)
      {
        Mode &mode = *modes[m];
        mode.stiffness.reinit(sparsity);
        mode.condensed_stiffness.reinit(sparsity);

        // Prescribed displacements at unit load factor; the nodes tied to
        // them (centre nodes, the axis) follow through the structural lines.
        mode.unit_prescribed_displacement.reinit(n);
        for (const auto &[dof, value] :
             boundary_data.prescribed_values(mapping, dof_handler, m))
          mode.unit_prescribed_displacement[dof] = value;
        mode.structural_constraints.distribute(
          mode.unit_prescribed_displacement);

        mode.unit_load.reinit(n);
        boundary_data.assemble_load_vector(mapping,
                                           dof_handler,
                                           m,
                                           mode.unit_load);
        for (Vector<double> *v : {&mode.unit_rhs,
                                  &mode.solution,
                                  &mode.step_increment,
                                  &mode.internal_forces,
                                  &mode.body_loads,
                                  &mode.body_load_change,
                                  &mode.previous_increment,
                                  &mode.residual,
                                  &mode.correction,
                                  &mode.condensed})
          v->reinit(n);
      }
    if (parameters.method == SolutionMethod::newton)
      setup_newton_system();
    // The point loop's per-cell slots, allocated once.
    const std::size_t slot_size =
      tria.n_active_cells() * modes.size() * fe.n_dofs_per_cell();
    cell_body_loads.assign(slot_size, 0.);
    if (parameters.method != SolutionMethod::viscoplastic)
      cell_internal_forces.assign(slot_size, 0.);
    cell_has_body_loads.assign(tria.n_active_cells(), 0);
    tasks.reserve(n_point_loop_chunks());
    {
      const unsigned int n_cell  = fe.n_dofs_per_cell();
      const unsigned int n_local = modes.size() * n_cell;
      ChunkScratch       scratch;
      scratch.du.resize(n_local);
      scratch.mode_strain.resize(modes.size() * n_parts);
      if (parameters.method == SolutionMethod::newton)
        {
          scratch.strain.resize(n_local);
          scratch.stress.resize(n_local);
          scratch.part2.resize(n_cell);
          scratch.strain_rows.resize(6 * n_local);
          scratch.stress_rows.resize(6 * n_local);
        }
      chunk_scratch.assign(n_point_loop_chunks(), scratch);
    }

    stacked_increment.reinit(n * kinematics.n_modes());
    stacked_correction.reinit(n * kinematics.n_modes());
    if (parameters.method == SolutionMethod::newton)
      {
        // The tangent of the first load step's first iteration: elastic.
        tangents.resize(history.size() * kinematics.n_stations());
        for (unsigned int p = 0; p < history.size(); ++p)
          for (unsigned int s = 0; s < kinematics.n_stations(); ++s)
            tangents[p * kinematics.n_stations() + s] =
              cell_law[p / quadrature.size()]->elasticity();
      }

    assemble_stiffness();

    for (unsigned int m = 0; m < kinematics.n_modes(); ++m)
      {
        Mode &mode = *modes[m];
        mode.stiffness.vmult(mode.unit_rhs, mode.unit_prescribed_displacement);
        mode.unit_rhs.sadd(-1, 1, mode.unit_load);
        try
          {
            mode.factorisation.factorize(mode.condensed_stiffness);
          }
        catch (const std::exception &)
          {
            throw InputError(parameters.parameter_file,
                             "Boundary <id>/Constrained components",
                             "the stiffness matrix" +
                               (kinematics.is_fourier()
                                  ? " of harmonic " +
                                      std::to_string(kinematics.harmonic(m))
                                  : std::string()) +
                               " is singular: constrain enough displacement "
                               "components to prevent rigid-body motion");
          }
      }

    // What one substitution costs, for the benchmarks' ratio of iteration
    // to substitution time.
    {
      std::vector<double> times;
      for (unsigned int k = 0; k < 10; ++k)
        {
          Timer timer;
          for (auto &mode : modes)
            {
              mode->correction = mode->unit_rhs;
              mode->constraints.condense(mode->correction);
              mode->factorisation.solve(mode->correction);
            }
          times.push_back(timer.wall_time());
        }
      std::sort(times.begin(), times.end());
      substitution_time = times[times.size() / 2];
    }

    std::vector<bool> mask(kinematics.n_components(), false);
    mask[parameters.load_component] = true;
    reaction_dofs =
      DoFTools::extract_boundary_dofs(dof_handler,
                                      ComponentMask(mask),
                                      {parameters.load_boundary_id});
  }


  template <int dim>
  void
  Analysis<dim>::make_mode_constraints(const unsigned int m)
  {
    AffineConstraints<double> &structural = modes[m]->structural_constraints;
    structural.clear();
    structural.merge(element_constraints);

    // Components that play no part in this mode (u_theta for n = 0).
    for (unsigned int c = 0; c < kinematics.n_components(); ++c)
      if (kinematics.is_dead_component(m, c))
        {
          std::vector<bool> mask(kinematics.n_components(), false);
          mask[c] = true;
          for (const auto dof :
               DoFTools::extract_dofs(dof_handler, ComponentMask(mask)))
            if (!structural.is_constrained(dof))
              structural.add_line(dof);
        }

    // On the axis r = 0 the field must be single-valued: harmonic 0 has no
    // radial (symmetric) or circumferential (antisymmetric) movement there,
    // harmonic 1 moves sideways rigidly (u_z = 0, u_theta = -+ u_r) and
    // higher harmonics not at all.
    if (kinematics.is_fourier() && parameters.axis_boundary_id >= 0)
      {
        const unsigned int n    = kinematics.harmonic(m);
        const double       sign = kinematics.is_antisymmetric() ? 1. : -1.;
        std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
        const auto zero = [&](const types::global_dof_index dof) {
          if (!structural.is_constrained(dof))
            structural.add_line(dof);
        };
        for (const auto &cell : dof_handler.active_cell_iterators())
          for (const auto f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() ==
                  static_cast<types::boundary_id>(parameters.axis_boundary_id))
              {
                cell->face(f)->get_dof_indices(face_dofs);
                // node[b][c]: the DoF of component c at the face's node b.
                std::map<unsigned int, std::array<types::global_dof_index, 3>>
                  node;
                for (unsigned int k = 0; k < face_dofs.size(); ++k)
                  {
                    const auto c_b = fe.face_system_to_component_index(k);
                    node[c_b.second][c_b.first] = face_dofs[k];
                  }
                for (const auto &[b, d] : node)
                  {
                    const auto r = d[0], z = d[1], theta = d[2];
                    if (n == 0)
                      zero(kinematics.is_antisymmetric() ? theta : r);
                    else if (n == 1)
                      {
                        zero(z);
                        if (!structural.is_constrained(theta))
                          {
                            structural.add_line(theta);
                            structural.add_entry(theta, r, sign);
                          }
                      }
                    else
                      {
                        zero(r);
                        zero(z);
                        zero(theta);
                      }
                  }
              }
      }
    structural.close();

    AffineConstraints<double> &constraints = modes[m]->constraints;
    constraints.clear();
    constraints.merge(structural);
    boundary_data.make_zero_constraints(dof_handler, constraints);
    constraints.close();
  }


  template <int dim>
  void
  Analysis<dim>::build_point_cache()
  {
    const unsigned int n_cells = tria.n_active_cells();
    const unsigned int n_q     = quadrature.size();
    const unsigned int n       = fe.n_dofs_per_cell();
    const unsigned int n_modes = kinematics.n_modes();

    cell_law.resize(n_cells);
    cell_dofs.resize(n_cells * n);
    point_weight.resize(n_cells * n_q);
    // Every strain part at every point, then packed (see
    // StrainOperator).
    std::vector<SymmetricTensor<2, 3>> all_shape_strains(n_cells * n_q *
                                                         n_modes * n * n_parts);

    history_storage.initialize(tria.begin_active(), tria.end(), n_q);
    history.resize(n_cells * n_q);

    FEValues<dim>                        fe_values(mapping,
                            fe,
                            quadrature,
                            update_values | update_gradients |
                              update_quadrature_points | update_JxW_values);
    std::vector<types::global_dof_index> dofs(n);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const unsigned int c = cell->active_cell_index();
        fe_values.reinit(cell);
        cell_law[c] = laws.at(cell->material_id()).get();
        cell->get_dof_indices(dofs);
        std::copy(dofs.begin(), dofs.end(), cell_dofs.begin() + c * n);

        const auto points = history_storage.get_data(cell);
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            const unsigned int p = c * n_q + q;
            const Point<dim>  &x = fe_values.quadrature_point(q);
            point_weight[p]      = kinematics.area_factor(x) * fe_values.JxW(q);
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
                  all_shape_strains[((p * n_modes + m) * n + i) * n_parts] =
                    part1;
                  if (n_parts == 2)
                    all_shape_strains[((p * n_modes + m) * n + i) * n_parts +
                                      1] = part2;
                }
            history[p] = points[q].get();
            history[p]->stations.assign(kinematics.n_stations(), PointState());
          }
      }

    // The non-zero pattern of each mode's and part's operator, over all
    // points, grouped by component.
    const unsigned int n_points = n_cells * n_q;
    strain_operators.resize(n_modes * n_parts);
    strain_entry_dof.clear();
    std::vector<unsigned int> entry_source; // (m * n + i) * n_parts + part
    std::vector<unsigned int> entry_component;
    for (unsigned int m = 0; m < n_modes; ++m)
      for (unsigned int part = 0; part < n_parts; ++part)
        {
          StrainOperator &op = strain_operators[m * n_parts + part];
          for (unsigned int k = 0; k < 6; ++k)
            {
              op.component_begin[k] = strain_entry_dof.size();
              for (unsigned int i = 0; i < n; ++i)
                {
                  const unsigned int j        = (m * n + i) * n_parts + part;
                  bool               non_zero = false;
                  for (unsigned int p = 0; p < n_points && !non_zero; ++p)
                    non_zero = (all_shape_strains[p * n_modes * n * n_parts + j]
                                  .access_raw_entry(k) != 0);
                  if (non_zero)
                    {
                      strain_entry_dof.push_back(i);
                      entry_source.push_back(j);
                      entry_component.push_back(k);
                    }
                }
            }
          op.component_begin[6] = strain_entry_dof.size();
        }
    strain_entries_per_point = strain_entry_dof.size();
    strain_values.resize(std::size_t(n_points) * strain_entries_per_point);
    for (unsigned int p = 0; p < n_points; ++p)
      for (unsigned int e = 0; e < strain_entries_per_point; ++e)
        strain_values[std::size_t(p) * strain_entries_per_point + e] =
          all_shape_strains[p * n_modes * n * n_parts + entry_source[e]]
            .access_raw_entry(entry_component[e]);
  }


  template <int dim>
  void
  Analysis<dim>::shape_strains(const unsigned int     point,
                               const unsigned int     m,
                               const unsigned int     part,
                               SymmetricTensor<2, 3> *B) const
  {
    const StrainOperator &op = strain_operators[m * n_parts + part];
    const double         *values =
      &strain_values[std::size_t(point) * strain_entries_per_point];
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      B[i] = 0;
    for (unsigned int k = 0; k < 6; ++k)
      for (unsigned int e = op.component_begin[k];
           e < op.component_begin[k + 1];
           ++e)
        B[strain_entry_dof[e]].access_raw_entry(k) = values[e];
  }


  template <int dim>
  inline SymmetricTensor<2, 3>
  Analysis<dim>::strain(const unsigned int point,
                        const unsigned int m,
                        const unsigned int part,
                        const double      *u) const
  {
    const StrainOperator &op = strain_operators[m * n_parts + part];
    const double         *values =
      &strain_values[std::size_t(point) * strain_entries_per_point];
    SymmetricTensor<2, 3> e;
    for (unsigned int k = 0; k < 6; ++k)
      {
        double sum = 0;
        for (unsigned int j = op.component_begin[k];
             j < op.component_begin[k + 1];
             ++j)
          sum += u[strain_entry_dof[j]] * values[j];
        e.access_raw_entry(k) = sum;
      }
    return e;
  }


  template <int dim>
  inline void
  Analysis<dim>::add_projection(const unsigned int           point,
                                const unsigned int           m,
                                const unsigned int           part,
                                const SymmetricTensor<2, 3> &t,
                                double                      *target) const
  {
    const StrainOperator &op = strain_operators[m * n_parts + part];
    const double         *values =
      &strain_values[std::size_t(point) * strain_entries_per_point];
    for (unsigned int k = 0; k < 6; ++k)
      {
        // The double contraction counts each off-diagonal pair twice.
        const double tk = (k < 3 ? 1. : 2.) * t.access_raw_entry(k);
        for (unsigned int j = op.component_begin[k];
             j < op.component_begin[k + 1];
             ++j)
          target[strain_entry_dof[j]] += tk * values[j];
      }
  }


  template <int dim>
  void
  Analysis<dim>::assemble_stiffness()
  {
    const unsigned int                   n   = fe.n_dofs_per_cell();
    const unsigned int                   n_q = quadrature.size();
    FullMatrix<double>                   cell_matrix(n, n);
    std::vector<types::global_dof_index> dofs(n);
    std::vector<SymmetricTensor<2, 3>>   strain(n), stress(n);

    for (unsigned int m = 0; m < kinematics.n_modes(); ++m)
      for (unsigned int c = 0; c < tria.n_active_cells(); ++c)
        {
          cell_matrix                    = 0;
          const SymmetricTensor<4, 3> &D = cell_law[c]->elasticity();
          for (unsigned int q = 0; q < n_q; ++q)
            {
              const unsigned int p = c * n_q + q;
              // K_m = int (c1 B1^T D B1 + c2 B2^T D B2) dA_r: the exact
              // integral over the circle, with which the harmonics
              // decouple.
              for (unsigned int part = 0; part < n_parts; ++part)
                {
                  const double weight =
                    (part == 0 ? kinematics.c1(m) : kinematics.c2(m)) *
                    point_weight[p];
                  if (weight == 0)
                    continue;
                  shape_strains(p, m, part, strain.data());
                  for (unsigned int i = 0; i < n; ++i)
                    stress[i] = D * strain[i];
                  for (unsigned int i = 0; i < n; ++i)
                    for (unsigned int j = 0; j < n; ++j)
                      cell_matrix(i, j) += (strain[i] * stress[j]) * weight;
                }
            }
          std::copy(cell_dofs.begin() + c * n,
                    cell_dofs.begin() + (c + 1) * n,
                    dofs.begin());
          modes[m]->stiffness.add(dofs, cell_matrix);
          modes[m]->constraints.distribute_local_to_global(
            cell_matrix, dofs, modes[m]->condensed_stiffness);
        }
  }


  template <int dim>
  void
  Analysis<dim>::solve_increment(const unsigned int m, const double dlambda)
  {
    Mode           &mode      = *modes[m];
    Vector<double> &increment = mode.step_increment;
    increment                 = mode.body_loads;
    increment.add(dlambda, mode.unit_rhs);
    mode.constraints.condense(increment);
    mode.factorisation.solve(increment);
    mode.constraints.distribute(increment);
    increment.add(dlambda, mode.unit_prescribed_displacement);
  }


  template <int dim>
  unsigned int
  Analysis<dim>::n_point_loop_chunks() const
  {
    // A few chunks per thread balance the plastic zone's extra work.
    return std::min(4 * MultithreadInfo::n_threads(), tria.n_active_cells());
  }


  template <int dim>
  unsigned int
  Analysis<dim>::update_stresses(const bool store_tangents)
  {
    const unsigned int n_cells  = tria.n_active_cells();
    const unsigned int n_chunks = n_point_loop_chunks();
    const bool         viscoplastic =
      (parameters.method == SolutionMethod::viscoplastic);

    // The task list keeps its capacity and each chunk has its work space
    // (chunk_scratch); only the task objects themselves are new.
    tasks.clear();
    for (unsigned int k = 0; k < n_chunks; ++k)
      tasks.push_back(
        Threads::new_task([this, k, n_chunks, n_cells, store_tangents]() {
          return update_stresses(k * n_cells / n_chunks,
                                 (k + 1) * n_cells / n_chunks,
                                 store_tangents,
                                 chunk_scratch[k]);
        }));
    unsigned int n_yielding = 0;
    for (auto &task : tasks)
      n_yielding += task.return_value();

    // The serial pass, in cell order.
    const unsigned int n = fe.n_dofs_per_cell();
    for (unsigned int m = 0; m < modes.size(); ++m)
      {
        Mode           &mode = *modes[m];
        Vector<double> &target =
          viscoplastic ? mode.body_load_change : mode.body_loads;
        if (!viscoplastic)
          {
            mode.body_loads      = 0;
            mode.internal_forces = 0;
          }
        for (unsigned int c = 0; c < n_cells; ++c)
          {
            const types::global_dof_index *dofs = &cell_dofs[c * n];
            const std::size_t slot = (std::size_t(c) * modes.size() + m) * n;
            if (cell_has_body_loads[c])
              for (unsigned int i = 0; i < n; ++i)
                target[dofs[i]] += cell_body_loads[slot + i];
            if (!viscoplastic)
              for (unsigned int i = 0; i < n; ++i)
                mode.internal_forces[dofs[i]] += cell_internal_forces[slot + i];
          }
      }
    return n_yielding;
  }


  template <int dim>
  unsigned int
  Analysis<dim>::update_stresses(const unsigned int begin,
                                 const unsigned int end,
                                 const bool         store_tangents,
                                 ChunkScratch      &scratch)
  {
    const bool viscoplastic =
      (parameters.method == SolutionMethod::viscoplastic);
    const unsigned int                  n           = fe.n_dofs_per_cell();
    const unsigned int                  n_q         = quadrature.size();
    const unsigned int                  n_modes     = kinematics.n_modes();
    const unsigned int                  n_stations  = kinematics.n_stations();
    unsigned int                        n_yielding  = 0;
    std::vector<double>                &du          = scratch.du;
    std::vector<SymmetricTensor<2, 3>> &mode_strain = scratch.mode_strain;

    for (unsigned int c = begin; c < end; ++c)
      {
        const MaterialLaw             &law  = *cell_law[c];
        const types::global_dof_index *dofs = &cell_dofs[c * n];
        double *cell_loads = &cell_body_loads[std::size_t(c) * n_modes * n];
        double *cell_forces =
          viscoplastic ? nullptr
                       : &cell_internal_forces[std::size_t(c) * n_modes * n];
        bool has_body_loads = false;
        for (unsigned int m = 0; m < n_modes; ++m)
          for (unsigned int i = 0; i < n; ++i)
            du[m * n + i] = modes[m]->step_increment[dofs[i]];
        if (cell_forces != nullptr)
          std::fill(cell_forces, cell_forces + n_modes * n, 0.);

        for (unsigned int q = 0; q < n_q; ++q)
          {
            const unsigned int p = c * n_q + q;
            // The strain parts of each mode at this point.
            for (unsigned int m = 0; m < n_modes; ++m)
              for (unsigned int part = 0; part < n_parts; ++part)
                {
                  mode_strain[m * n_parts + part] =
                    strain(p, m, part, &du[m * n]);
                }

            for (unsigned int s = 0; s < n_stations; ++s)
              {
                PointState           &state = history[p]->stations[s];
                SymmetricTensor<2, 3> strain;
                for (unsigned int m = 0; m < n_modes; ++m)
                  {
                    strain += kinematics.T1(m, s) * mode_strain[m * n_parts];
                    if (n_parts == 2)
                      strain +=
                        kinematics.T2(m, s) * mode_strain[m * n_parts + 1];
                  }
                // Adds int (T1 B1 + T2 B2)^T t over this point and station
                // to every mode's part of the cell's slot @p target.
                const double weight =
                  kinematics.station_weight(s) * point_weight[p];
                const auto project = [&](const SymmetricTensor<2, 3> &t,
                                         double                      *target) {
                  for (unsigned int m = 0; m < n_modes; ++m)
                    {
                      add_projection(p,
                                     m,
                                     0,
                                     t * (weight * kinematics.T1(m, s)),
                                     target + m * n);
                      if (n_parts == 2)
                        add_projection(p,
                                       m,
                                       1,
                                       t * (weight * kinematics.T2(m, s)),
                                       target + m * n);
                    }
                };
                // The first body load of this cell clears its slot.
                const auto add_body_load = [&](const SymmetricTensor<2, 3> &t) {
                  if (!has_body_loads)
                    {
                      std::fill(cell_loads, cell_loads + n_modes * n, 0.);
                      has_body_loads = true;
                    }
                  project(t, cell_loads);
                };

                if (!viscoplastic)
                  {
                    // Return mapping of the step's elastic trial stress.
                    const SymmetricTensor<2, 3> trial =
                      state.converged_stress + law.elastic_stress(strain);
                    state.yielding = false;
                    if (!law.can_yield())
                      state.stress = trial;
                    else
                      {
                        const ReturnMapping r = law.return_mapping(trial);
                        state.stress          = r.stress;
                        if (store_tangents)
                          tangents[p * n_stations + s] = r.tangent;
                        if (r.region != ReturnRegion::elastic)
                          {
                            state.yielding = true;
                            ++n_yielding;
                            state.step_plastic_strain =
                              law.compliance() * (trial - r.stress);
                            add_body_load(trial - r.stress);
                          }
                        else
                          state.step_plastic_strain = 0;
                      }
                    project(state.stress, cell_forces);
                    continue;
                  }

                state.stress =
                  state.converged_stress +
                  law.elastic_stress(strain - state.step_plastic_strain);

                state.yielding = false;
                if (!law.can_yield())
                  continue;
                const double F = law.yield_function(state.stress);
                if (F <= 0)
                  continue;

                state.yielding = true;
                ++n_yielding;
                const SymmetricTensor<2, 3> viscoplastic_strain =
                  (time_step * F) * law.flow_direction(state.stress);
                state.step_plastic_strain += viscoplastic_strain;

                // Project D (that strain) back onto every mode.
                add_body_load(law.elastic_stress(viscoplastic_strain));
              }
          }
        cell_has_body_loads[c] = has_body_loads;
      }
    return n_yielding;
  }


  template <int dim>
  void
  Analysis<dim>::update_internal_forces()
  {
    const unsigned int  n       = fe.n_dofs_per_cell();
    const unsigned int  n_q     = quadrature.size();
    const unsigned int  n_modes = kinematics.n_modes();
    std::vector<double> cell_forces(n_modes * n);
    for (auto &mode : modes)
      mode->internal_forces = 0;
    for (unsigned int c = 0; c < tria.n_active_cells(); ++c)
      {
        std::fill(cell_forces.begin(), cell_forces.end(), 0.);
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const unsigned int p = c * n_q + q;
            for (unsigned int s = 0; s < kinematics.n_stations(); ++s)
              {
                const SymmetricTensor<2, 3> sigma =
                  history[p]->stations[s].stress *
                  (kinematics.station_weight(s) * point_weight[p]);
                for (unsigned int m = 0; m < n_modes; ++m)
                  for (unsigned int part = 0; part < n_parts; ++part)
                    add_projection(p,
                                   m,
                                   part,
                                   sigma * (part == 0 ? kinematics.T1(m, s)
                                                      : kinematics.T2(m, s)),
                                   &cell_forces[m * n]);
              }
          }
        for (unsigned int m = 0; m < n_modes; ++m)
          for (unsigned int i = 0; i < n; ++i)
            modes[m]->internal_forces[cell_dofs[c * n + i]] +=
              cell_forces[m * n + i];
      }
  }


  template <int dim>
  StepResult
  Analysis<dim>::solve(const double new_load_factor)
  {
    StepResult result = (parameters.method == SolutionMethod::viscoplastic)
                          ? solve_viscoplastic(new_load_factor - load_factor)
                          : solve_with_return_mapping(new_load_factor);

    // The step's state is kept even if it failed, so that the mechanism at
    // failure can be seen.
    accept_step_state();
    load_factor            = new_load_factor;
    result.max_yield_ratio = std::numeric_limits<double>::quiet_NaN();
    for (unsigned int p = 0; p < history.size(); ++p)
      {
        const MaterialLaw &law = *cell_law[p / quadrature.size()];
        if (law.can_yield())
          for (const PointState &state : history[p]->stations)
            result.max_yield_ratio =
              std::isnan(result.max_yield_ratio)
                ? law.yield_ratio(state.stress)
                : std::max(result.max_yield_ratio,
                           law.yield_ratio(state.stress));
      }
    update_internal_forces();
    return result;
  }


  template <int dim>
  void
  Analysis<dim>::accept_step_state()
  {
    for (auto &mode : modes)
      mode->solution += mode->step_increment;
    for (PointHistory *point : history)
      for (PointState &state : point->stations)
        {
          state.converged_stress = state.stress;
          state.plastic_strain += state.step_plastic_strain;
          state.step_plastic_strain = 0;
        }
  }


  template <int dim>
  StepResult
  Analysis<dim>::solve_viscoplastic(const double dlambda)
  {
    for (auto &mode : modes)
      {
        mode->body_loads         = 0;
        mode->step_increment     = 0;
        mode->previous_increment = 0;
      }

    StepResult result{0, false, 0, 0};
    while (result.iterations < parameters.max_iterations && !result.converged)
      {
        ++result.iterations;
        for (unsigned int m = 0; m < modes.size(); ++m)
          {
            modes[m]->previous_increment = modes[m]->step_increment;
            solve_increment(m, dlambda);
            modes[m]->body_load_change = 0;
          }

        result.plastic_points = update_stresses();

        // The criteria take the largest entry over all modes.
        double change = 0, size = 0;
        for (unsigned int m = 0; m < modes.size(); ++m)
          {
            Mode &mode = *modes[m];
            // The body loads are kept condensed (condensing is linear, and
            // idempotent, so solve_increment() may condense them again):
            // the criterion reads them with no copy.
            mode.constraints.condense(mode.body_load_change);
            mode.body_loads += mode.body_load_change;
            if (parameters.convergence_criterion ==
                ConvergenceCriterion::body_loads)
              {
                change = std::max(change, mode.body_load_change.linfty_norm());
                size   = std::max(size, mode.body_loads.linfty_norm());
              }
            else
              {
                mode.previous_increment -= mode.step_increment;
                change =
                  std::max(change, mode.previous_increment.linfty_norm());
                size = std::max(size, mode.step_increment.linfty_norm());
              }
          }
        if (result.plastic_points == 0)
          result.converged = true; // elastic: nothing will change
        else if (parameters.convergence_criterion ==
                   ConvergenceCriterion::body_loads ||
                 result.iterations > 1)
          result.converged = (change <= parameters.tolerance * size);
      }

    return result;
  }


  template <int dim>
  StepResult
  Analysis<dim>::solve_with_return_mapping(const double new_load_factor)
  {
    StepResult   result{0, false, 0, 0};
    const bool   newton = (parameters.method == SolutionMethod::newton);
    const double total  = new_load_factor - load_factor;
    // The tangents at the last accepted state, to restart from after a
    // failed attempt.
    std::vector<SymmetricTensor<4, 3>> accepted_tangents;
    if (newton)
      accepted_tangents = tangents;

    double size = total;
    while (true)
      {
        const bool last = std::abs(load_factor + size - new_load_factor) <=
                          1e-12 * std::abs(total);
        const double target = last ? new_load_factor : load_factor + size;
        if (iterate_with_return_mapping(target, result))
          {
            if (last)
              {
                result.converged = true;
                break;
              }
            // A converged part of a cut-back step.
            accept_step_state();
            load_factor = target;
            if (newton)
              accepted_tangents = tangents;
            size = std::min(size, new_load_factor - load_factor);
            continue;
          }
        if (!newton || result.cut_backs == parameters.max_cut_backs)
          break; // failed: the last attempt's state is kept
        ++result.cut_backs;
        size /= 2;
        tangents = accepted_tangents;
      }
    return result;
  }


  template <int dim>
  bool
  Analysis<dim>::iterate_with_return_mapping(const double target,
                                             StepResult  &result)
  {
    const SolutionMethod method  = parameters.method;
    const double         dlambda = target - load_factor;
    const unsigned int   n       = dof_handler.n_dofs();
    for (auto &mode : modes)
      {
        mode->step_increment = mode->unit_prescribed_displacement;
        mode->step_increment *= dlambda;
      }
    anderson.reset();

    ResidualNorms      norms = evaluate_residual(target, false);
    const unsigned int limit = (method == SolutionMethod::newton)
                                 ? parameters.max_newton_iterations
                                 : parameters.max_iterations;
    for (unsigned int k = 0; k < limit; ++k)
      {
        ++result.iterations;
        if (method == SolutionMethod::newton)
          {
            ++result.factorisations;
            if (!factorise_tangent())
              return false;
            // The coupled solve: the residuals (each condensed with its
            // mode's constraints) one after the other.
            for (unsigned int m = 0; m < modes.size(); ++m)
              for (unsigned int i = 0; i < n; ++i)
                newton_vector[m * n + i] = modes[m]->residual[i];
            newton_factorisation->solve(newton_vector);
            newton_constraints.distribute(newton_vector);
            for (unsigned int m = 0; m < modes.size(); ++m)
              for (unsigned int i = 0; i < n; ++i)
                modes[m]->correction[i] = newton_vector[m * n + i];
          }
        else
          for (auto &mode : modes)
            {
              mode->correction = mode->residual;
              mode->factorisation.solve(mode->correction);
              mode->constraints.distribute(mode->correction);
            }
        for (auto &mode : modes)
          mode->previous_increment = mode->step_increment;

        if (method == SolutionMethod::accelerated_initial_stress)
          {
            for (unsigned int m = 0; m < modes.size(); ++m)
              for (unsigned int i = 0; i < n; ++i)
                {
                  stacked_increment[m * n + i]  = modes[m]->step_increment[i];
                  stacked_correction[m * n + i] = modes[m]->correction[i];
                }
            anderson.update(stacked_increment, stacked_correction);
            for (unsigned int m = 0; m < modes.size(); ++m)
              for (unsigned int i = 0; i < n; ++i)
                modes[m]->step_increment[i] = stacked_increment[m * n + i];
            norms = evaluate_residual(target, false);
          }
        else if (method == SolutionMethod::newton)
          {
            // Backtracking on |r|_2: halve the step until the residual
            // falls (Armijo with 1e-4), at most four times.
            const double initial = norms.l2;
            double       scale   = 1;
            for (unsigned int trial = 0;; ++trial)
              {
                for (auto &mode : modes)
                  {
                    mode->step_increment = mode->previous_increment;
                    mode->step_increment.add(scale, mode->correction);
                  }
                norms = evaluate_residual(target, true);
                if (norms.l2 <= (1 - 1e-4 * scale) * initial || trial == 4)
                  break;
                scale /= 2;
              }
          }
        else
          {
            for (auto &mode : modes)
              mode->step_increment += mode->correction;
            norms = evaluate_residual(target, false);
          }
        result.plastic_points = norms.n_yielding;

        // Converged: the out-of-balance force against the stress excess
        // (the paper's body-load test) or against the forces, or the last
        // change of the step's
        // displacements against their size; and, whatever the criterion,
        // once the residual is at rounding level (elastic steps).
        bool converged = (norms.max <= 1e-10 * norms.forces);
        if (parameters.convergence_criterion ==
            ConvergenceCriterion::body_loads)
          converged =
            converged || (norms.max <= parameters.tolerance * norms.body_loads);
        else if (parameters.convergence_criterion ==
                 ConvergenceCriterion::residual)
          converged =
            converged || (norms.max <= parameters.tolerance * norms.forces);
        else
          {
            double change = 0, size = 0;
            for (auto &mode : modes)
              {
                mode->previous_increment -= mode->step_increment;
                change =
                  std::max(change, mode->previous_increment.linfty_norm());
                size = std::max(size, mode->step_increment.linfty_norm());
              }
            converged = converged || (change <= parameters.tolerance * size);
          }
        if (converged)
          return true;
      }
    return false;
  }


  template <int dim>
  typename Analysis<dim>::ResidualNorms
  Analysis<dim>::evaluate_residual(const double target,
                                   const bool   store_tangents)
  {
    ResidualNorms norms{update_stresses(store_tangents), 0, 0, 0, 0};
    for (auto &mode : modes)
      {
        Vector<double> &r = mode->residual;
        r                 = mode->unit_load;
        r *= target;
        norms.forces = std::max(
          {norms.forces, r.linfty_norm(), mode->internal_forces.linfty_norm()});
        r -= mode->internal_forces;
        mode->constraints.condense(r);
        norms.max = std::max(norms.max, r.linfty_norm());
        norms.l2 += r.norm_sqr();
        norms.body_loads = std::max(norms.body_loads,
                                    condensed_max(mode->body_loads,
                                                  mode->constraints,
                                                  mode->condensed));
      }
    norms.l2 = std::sqrt(norms.l2);
    return norms;
  }


  template <int dim>
  void
  Analysis<dim>::newton_cell_dofs(
    const unsigned int                    c,
    std::vector<types::global_dof_index> &dofs) const
  {
    const unsigned int n      = dof_handler.n_dofs();
    const unsigned int n_cell = fe.n_dofs_per_cell();
    for (unsigned int m = 0; m < kinematics.n_modes(); ++m)
      for (unsigned int i = 0; i < n_cell; ++i)
        dofs[m * n_cell + i] = m * n + cell_dofs[c * n_cell + i];
  }


  template <int dim>
  void
  Analysis<dim>::setup_newton_system()
  {
    const unsigned int n       = dof_handler.n_dofs();
    const unsigned int n_cell  = fe.n_dofs_per_cell();
    const unsigned int n_modes = kinematics.n_modes();

    newton_constraints.clear();
    for (unsigned int m = 0; m < n_modes; ++m)
      {
        AffineConstraints<double> shifted;
        shifted.copy_from(modes[m]->constraints);
        shifted.shift(m * n);
        newton_constraints.merge(shifted);
      }
    newton_constraints.close();

    DynamicSparsityPattern               dsp(n_modes * n);
    std::vector<types::global_dof_index> dofs(n_modes * n_cell);
    for (unsigned int c = 0; c < tria.n_active_cells(); ++c)
      {
        newton_cell_dofs(c, dofs);
        newton_constraints.add_entries_local_to_global(dofs,
                                                       dsp,
                                                       /*keep=*/true);
      }
    newton_sparsity.copy_from(dsp);
    newton_tangent.reinit(newton_sparsity);
    newton_cell_matrices.assign(tria.n_active_cells(),
                                FullMatrix<double>(n_modes * n_cell,
                                                   n_modes * n_cell));
    newton_vector.reinit(n_modes * n);

    // A non-associated flow rule makes the tangent unsymmetric.
    bool associated = true;
    for (const auto &[id, law] : laws)
      associated = associated && law->is_associated();
    newton_factorisation = std::make_unique<FactorisedStiffness>(
      associated && parameters.linear_solver == LinearSolver::cholmod
        ? FactorisedStiffness::Method::cholmod
        : FactorisedStiffness::Method::umfpack);
  }


  template <int dim>
  void
  Analysis<dim>::compute_cell_tangents(const unsigned int begin,
                                       const unsigned int end,
                                       ChunkScratch      &scratch)
  {
    const unsigned int n_cell     = fe.n_dofs_per_cell();
    const unsigned int n_q        = quadrature.size();
    const unsigned int n_modes    = kinematics.n_modes();
    const unsigned int n_stations = kinematics.n_stations();
    const unsigned int n_local    = n_modes * n_cell;
    // Per mode: the strain of each shape function at a station (T1 B1 +
    // T2 B2) and the tangent applied to it; then both as 6 rows of raw
    // components, the strains' shear rows doubled and weighted, so that
    // the cell matrix takes a rank-6 update with contiguous rows.
    std::vector<SymmetricTensor<2, 3>> &strain      = scratch.strain;
    std::vector<SymmetricTensor<2, 3>> &stress      = scratch.stress;
    std::vector<SymmetricTensor<2, 3>> &part2       = scratch.part2;
    std::vector<double>                &strain_rows = scratch.strain_rows;
    std::vector<double>                &stress_rows = scratch.stress_rows;

    for (unsigned int c = begin; c < end; ++c)
      {
        FullMatrix<double> &cell_matrix = newton_cell_matrices[c];
        cell_matrix                     = 0;
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const unsigned int p = c * n_q + q;
            for (unsigned int s = 0; s < n_stations; ++s)
              {
                const SymmetricTensor<4, 3> &C = tangents[p * n_stations + s];
                const double                 weight =
                  kinematics.station_weight(s) * point_weight[p];
                for (unsigned int m = 0; m < n_modes; ++m)
                  {
                    SymmetricTensor<2, 3> *e = &strain[m * n_cell];
                    shape_strains(p, m, 0, e);
                    if (n_parts == 2)
                      shape_strains(p, m, 1, part2.data());
                    for (unsigned int i = 0; i < n_cell; ++i)
                      {
                        e[i] *= kinematics.T1(m, s);
                        if (n_parts == 2)
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
  Analysis<dim>::factorise_tangent()
  {
    const unsigned int n_cell  = fe.n_dofs_per_cell();
    const unsigned int n_modes = kinematics.n_modes();
    const unsigned int n_cells = tria.n_active_cells();

    // The cell matrices in parallel, then added in cell order (the same
    // sums on any number of threads).
    const unsigned int n_chunks = n_point_loop_chunks();
    tasks.clear();
    for (unsigned int k = 0; k < n_chunks; ++k)
      tasks.push_back(Threads::new_task([this, k, n_chunks, n_cells]() {
        compute_cell_tangents(k * n_cells / n_chunks,
                              (k + 1) * n_cells / n_chunks,
                              chunk_scratch[k]);
        return 0u;
      }));
    for (auto &task : tasks)
      task.join();

    std::vector<types::global_dof_index> dofs(n_modes * n_cell);
    newton_tangent = 0;
    for (unsigned int c = 0; c < n_cells; ++c)
      {
        newton_cell_dofs(c, dofs);
        newton_constraints.distribute_local_to_global(newton_cell_matrices[c],
                                                      dofs,
                                                      newton_tangent);
      }
    try
      {
        newton_factorisation->factorize(newton_tangent);
      }
    catch (const std::exception &)
      {
        return false; // singular: a mechanism has formed
      }
    return true;
  }


  template <int dim>
  double
  Analysis<dim>::load() const
  {
    if (parameters.load_measure == LoadMeasure::load_factor)
      return parameters.load_scale * load_factor;

    // The other measures are plane-strain ones (checked when reading).
    if (parameters.load_measure == LoadMeasure::stress_average)
      {
        const auto [i, j]           = parameters.load_stress_component;
        const unsigned int n_q      = quadrature.size();
        double             integral = 0, area = 0;
        for (const auto &cell : tria.active_cell_iterators())
          if (cell->material_id() == parameters.load_material_id)
            for (unsigned int q = 0; q < n_q; ++q)
              {
                const unsigned int p = cell->active_cell_index() * n_q + q;
                integral +=
                  history[p]->stations[0].stress[i][j] * point_weight[p];
                area += point_weight[p];
              }
        return parameters.load_scale * integral / area;
      }

    // Reactions: the residual f_int - f_ext at the supported DoFs, after
    // the residuals of eliminated centre nodes are handed to their masters.
    Vector<double> residual(modes[0]->internal_forces);
    residual.add(-load_factor, modes[0]->unit_load);
    element_constraints.condense(residual);
    double sum = 0;
    for (const auto dof : reaction_dofs)
      sum += residual[dof];
    return parameters.load_scale * sum;
  }


  template <int dim>
  Vector<double>
  Analysis<dim>::displacement_at(const double theta, const bool increment) const
  {
    Vector<double> u(dof_handler.n_dofs());
    for (unsigned int m = 0; m < modes.size(); ++m)
      {
        const Vector<double> &v =
          increment ? modes[m]->step_increment : modes[m]->solution;
        const double t1 = kinematics.T1_at(m, theta);
        const double t2 = kinematics.T2_at(m, theta);
        for (unsigned int i = 0; i < u.size(); ++i)
          u[i] += (dof_component[i] < 2 ? t1 : t2) * v[i];
      }
    return u;
  }


  template <int dim>
  DisplacementMeasure
  Analysis<dim>::displacement() const
  {
    const double         s     = parameters.displacement_scale;
    const double         theta = parameters.displacement_angle;
    const Vector<double> u     = displacement_at(theta);
    // The monitored Cartesian component from the nodal components: for
    // Fourier x = u_r cos(theta) - u_theta sin(theta), y = u_z.
    const auto component =
      [&](const double r_or_x, const double z_or_y, const double u_theta) {
        if (parameters.displacement_component == 1)
          return z_or_y;
        return kinematics.is_fourier()
                 ? r_or_x * std::cos(theta) - u_theta * std::sin(theta)
                 : r_or_x;
      };

    if (parameters.displacement_measure == DisplacementMeasureType::point)
      {
        Point<dim> x;
        for (unsigned int d = 0; d < dim; ++d)
          x[d] = parameters.displacement_point[d];
        Vector<double> value(kinematics.n_components());
        VectorTools::point_value(mapping, dof_handler, u, x, value);
        const double v =
          component(value[0], value[1], value.size() > 2 ? value[2] : 0.);
        return {s * v, s * v, s * v};
      }

    const QGauss<dim - 1>       face_quadrature(3);
    FEFaceValues<dim>           fe_face(mapping,
                              fe,
                              face_quadrature,
                              update_values | update_JxW_values);
    std::vector<Vector<double>> values(
      face_quadrature.size(), Vector<double>(kinematics.n_components()));
    std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
    double                               integral = 0, length = 0;
    double min = std::numeric_limits<double>::max();
    double max = std::numeric_limits<double>::lowest();
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary() &&
            cell->face(f)->boundary_id() == parameters.displacement_boundary_id)
          {
            fe_face.reinit(cell, f);
            fe_face.get_function_values(u, values);
            for (const unsigned int q : fe_face.quadrature_point_indices())
              {
                const Vector<double> &v = values[q];
                integral += component(v[0], v[1], v.size() > 2 ? v[2] : 0.) *
                            fe_face.JxW(q);
                length += fe_face.JxW(q);
              }
            // Extremes over the face's nodes.
            cell->face(f)->get_dof_indices(face_dofs);
            std::map<unsigned int, std::array<double, 3>> node;
            for (unsigned int k = 0; k < face_dofs.size(); ++k)
              {
                const auto c_b = fe.face_system_to_component_index(k);
                node[c_b.second][c_b.first] = u[face_dofs[k]];
              }
            for (const auto &[b, v] : node)
              {
                const double value =
                  component(v[0],
                            v[1],
                            kinematics.n_components() > 2 ? v[2] : 0.);
                min = std::min(min, value);
                max = std::max(max, value);
              }
          }
    return {s * integral / length,
            std::min(s * min, s * max),
            std::max(s * min, s * max)};
  }


  template <int dim>
  const Kinematics &
  Analysis<dim>::get_kinematics() const
  {
    return kinematics;
  }


  template <int dim>
  const DoFHandler<dim> &
  Analysis<dim>::get_dof_handler() const
  {
    return dof_handler;
  }


  template <int dim>
  const Mapping<dim> &
  Analysis<dim>::get_mapping() const
  {
    return mapping;
  }


  template <int dim>
  const Vector<double> &
  Analysis<dim>::get_solution(const unsigned int mode) const
  {
    return modes[mode]->solution;
  }


  template <int dim>
  const PointState &
  Analysis<dim>::point_state(const unsigned int cell,
                             const unsigned int q,
                             const unsigned int station) const
  {
    return history[cell * quadrature.size() + q]->stations[station];
  }


  template <int dim>
  const SymmetricTensor<2, 3> &
  Analysis<dim>::stress(const unsigned int cell, const unsigned int q) const
  {
    return point_state(cell, q).stress;
  }


  template <int dim>
  const MaterialLaw &
  Analysis<dim>::material_law(const unsigned int cell) const
  {
    return *cell_law[cell];
  }


  template <int dim>
  unsigned int
  Analysis<dim>::n_quadrature_points() const
  {
    return quadrature.size();
  }


  template <int dim>
  types::global_dof_index
  Analysis<dim>::n_dofs() const
  {
    return dof_handler.n_dofs() - element_constraints.n_constraints();
  }


  template <int dim>
  types::global_dof_index
  Analysis<dim>::n_equations() const
  {
    types::global_dof_index n = 0;
    for (const auto &mode : modes)
      n += dof_handler.n_dofs() - mode->constraints.n_constraints();
    return n;
  }


  template <int dim>
  double
  Analysis<dim>::substitution_seconds() const
  {
    return substitution_time;
  }


  template <int dim>
  double
  Analysis<dim>::viscoplastic_time_step() const
  {
    return time_step;
  }


  template class Analysis<2>;
} // namespace thinlayer
