#ifndef thinlayer_analysis_analysis_accessors_h
#define thinlayer_analysis_analysis_accessors_h

// The inline accessors of Analysis (analysis.h, which includes this file
// at its end).

#include <thinlayer/analysis/analysis.h>

namespace thinlayer
{
  // The accessors, inline: each returns a member or looks one up.

  template <int dim>
  inline unsigned int
  Analysis<dim>::n_modes() const
  {
    return systems.size();
  }


  template <int dim>
  inline const ModeSystem &
  Analysis<dim>::get_mode_system(const unsigned int m) const
  {
    return *systems[m];
  }


  template <int dim>
  inline void
  Analysis<dim>::elastic_solve(const unsigned int m, ModeVector &rhs)
  {
    systems[m]->solve(rhs);
  }


  template <int dim>
  inline const ModeVectors &
  Analysis<dim>::get_solution() const
  {
    return solution_vectors;
  }


  template <int dim>
  inline ModeVectors &
  Analysis<dim>::get_step_increment()
  {
    return increment_vectors;
  }


  template <int dim>
  inline const ModeVectors &
  Analysis<dim>::get_step_increment() const
  {
    return increment_vectors;
  }


  template <int dim>
  inline const ModeVectors &
  Analysis<dim>::get_internal_forces() const
  {
    return internal_force_vectors;
  }


  template <int dim>
  inline double
  Analysis<dim>::load_factor() const
  {
    return current_lambda;
  }


  template <int dim>
  inline double
  Analysis<dim>::accepted_load_factor() const
  {
    return accepted_lambda;
  }


  template <int dim>
  inline double
  Analysis<dim>::accepted_force_scale() const
  {
    return accepted_forces;
  }


  template <int dim>
  inline bool
  Analysis<dim>::is_pending() const
  {
    return pending;
  }


  template <int dim>
  inline const ContinuumCells<dim> &
  Analysis<dim>::get_cells() const
  {
    return *continuum;
  }


  template <int dim>
  inline const PointState &
  Analysis<dim>::get_point_state(const unsigned int cell,
                                 const unsigned int q,
                                 const unsigned int station) const
  {
    return continuum->point_state(cell, q, station);
  }


  template <int dim>
  inline const SymmetricTensor<2, 3> &
  Analysis<dim>::stress(const unsigned int cell, const unsigned int q) const
  {
    return get_point_state(cell, q).stress;
  }


  template <int dim>
  inline const MaterialLaw &
  Analysis<dim>::get_material_law(const unsigned int cell) const
  {
    return continuum->material_law(cell);
  }


  template <int dim>
  inline unsigned int
  Analysis<dim>::n_quadrature_points() const
  {
    return quadrature.size();
  }


  template <int dim>
  inline const Kinematics &
  Analysis<dim>::get_kinematics() const
  {
    return kinematics;
  }


  template <int dim>
  inline const DoFHandler<dim> &
  Analysis<dim>::get_dof_handler() const
  {
    return dof_handler;
  }


  template <int dim>
  inline const Triangulation<dim> &
  Analysis<dim>::get_whole_mesh() const
  {
    return tria;
  }


  template <int dim>
  inline bool
  Analysis<dim>::owns_whole_cell(const unsigned int c) const
  {
    return whole_partition.owner.empty() ||
           whole_partition.owner[c] == whole_partition.rank;
  }


  template <int dim>
  inline const Mapping<dim> &
  Analysis<dim>::get_mapping() const
  {
    return mapping;
  }


  template <int dim>
  inline const CellPartition &
  Analysis<dim>::get_partition() const
  {
    return partition;
  }


  template <int dim>
  inline const std::vector<IndexSet> &
  Analysis<dim>::get_owned_per_rank() const
  {
    return owned_per_rank;
  }


  template <int dim>
  inline const AffineConstraints<double> &
  Analysis<dim>::get_element_constraints() const
  {
    return element_constraints;
  }


  template <int dim>
  inline Vector<double>
  Analysis<dim>::whole_solution(const unsigned int mode) const
  {
    return whole(solution_vectors[mode]);
  }


  template <int dim>
  inline types::global_dof_index
  Analysis<dim>::n_dofs() const
  {
    return dof_handler.n_dofs() - n_element_constrained;
  }


  template <int dim>
  inline types::global_dof_index
  Analysis<dim>::n_equations() const
  {
    types::global_dof_index n = 0;
    for (const types::global_dof_index c : n_constrained)
      n += dof_handler.n_dofs() - c;
    return n;
  }


  template <int dim>
  inline double
  Analysis<dim>::substitution_seconds() const
  {
    return substitution_time;
  }


  template <int dim>
  inline const LinearSolverChoice &
  Analysis<dim>::get_linear_solver() const
  {
    return linear_solver;
  }
} // namespace thinlayer

#endif
