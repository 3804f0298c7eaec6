#ifndef thinlayer_discretisation_strain_operator_h
#define thinlayer_discretisation_strain_operator_h

#include <deal.II/base/quadrature.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <thinlayer/discretisation/kinematics.h>

#include <array>
#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /**
   * The strain-displacement operator B of every mode at every Gauss point,
   * computed once (the mesh does not move) so that the iterations touch no
   * FEValues and no map: per active cell its DoFs, per Gauss point its
   * area weight (JxW, times r for Fourier) and the strain parts of every
   * shape function in every mode (Kinematics::shape_strain(); part 0 goes
   * with T1, part 1 with T2 of the mode at a station).
   *
   * B is stored by its non-zero entries only: for each raw component k of
   * SymmetricTensor<2,3>, a list of the cell's DoFs whose shape function
   * has a non-zero component k at some point (a shape function of u_x in
   * plane strain has only xx and xy, for example), with their values at
   * every point in the same order. Grouped by component, a strain is six
   * short gathered dot products, and the point loop reads a third of the
   * memory a full SymmetricTensor per shape function needs; memory traffic
   * is what limits it.
   *
   * Points are numbered cell by cell: point p = c * n_q + q.
   */
  class StrainOperator
  {
  public:
    /**
     * Compute the operator for the active cells of @p dof_handler with
     * @p quadrature and @p mapping.
     */
    template <int dim>
    void
    reinit(const DoFHandler<dim> &dof_handler,
           const Mapping<dim>    &mapping,
           const Quadrature<dim> &quadrature,
           const Kinematics      &kinematics);

    /**
     * The same, keeping the operator, weights and DoFs only of the active
     * cells @p cells (ascending; a rank's own cells), which are then the
     * only cells and points to ask for: on several ranks each rank's cells
     * are its share of the memory.
     */
    template <int dim>
    void
    reinit(const DoFHandler<dim>           &dof_handler,
           const Mapping<dim>              &mapping,
           const Quadrature<dim>           &quadrature,
           const Kinematics                &kinematics,
           const std::vector<unsigned int> &cells);

    /// 1 in plane strain, 2 for Fourier kinematics.
    unsigned int
    n_parts() const
    {
      return parts;
    }

    unsigned int
    dofs_per_cell() const
    {
      return n_cell_dofs;
    }

    /// The DoFs of active cell @p c (dofs_per_cell() of them).
    const types::global_dof_index *
    cell_dofs(const unsigned int c) const
    {
      return &dofs[kept_cell(c) * n_cell_dofs];
    }

    /// The area weight of point @p point.
    double
    point_weight(const unsigned int point) const
    {
      return weights[kept_point(point)];
    }

    /// The strain parts @p part of all shape functions of mode @p m at
    /// @p point, into @p B (one per DoF of the cell).
    void
    shape_strains(const unsigned int     point,
                  const unsigned int     m,
                  const unsigned int     part,
                  SymmetricTensor<2, 3> *B) const
    {
      const Pattern &pattern = patterns[m * parts + part];
      const double  *v       = point_values(point);
      for (unsigned int i = 0; i < n_cell_dofs; ++i)
        B[i] = 0;
      for (unsigned int k = 0; k < 6; ++k)
        for (unsigned int e = pattern.component_begin[k];
             e < pattern.component_begin[k + 1];
             ++e)
          B[entry_dof[e]].access_raw_entry(k) = v[e];
    }

    /// The strain part @p part of mode @p m at @p point for the cell's
    /// nodal values @p u of that mode: sum_i u_i B_i.
    SymmetricTensor<2, 3>
    strain(const unsigned int point,
           const unsigned int m,
           const unsigned int part,
           const double      *u) const
    {
      const Pattern        &pattern = patterns[m * parts + part];
      const double         *values  = point_values(point);
      SymmetricTensor<2, 3> e;
      for (unsigned int k = 0; k < 6; ++k)
        {
          double sum = 0;
          for (unsigned int j = pattern.component_begin[k];
               j < pattern.component_begin[k + 1];
               ++j)
            sum += u[entry_dof[j]] * values[j];
          e.access_raw_entry(k) = sum;
        }
      return e;
    }

    /// @p target_i += B_i : @p t for every DoF i of the cell (part @p part
    /// of mode @p m at @p point): the projection of a stress onto nodal
    /// forces.
    void
    add_projection(const unsigned int           point,
                   const unsigned int           m,
                   const unsigned int           part,
                   const SymmetricTensor<2, 3> &t,
                   double                      *target) const
    {
      const Pattern &pattern = patterns[m * parts + part];
      const double  *values  = point_values(point);
      for (unsigned int k = 0; k < 6; ++k)
        {
          // The double contraction counts each off-diagonal pair twice.
          const double tk = (k < 3 ? 1. : 2.) * t.access_raw_entry(k);
          for (unsigned int j = pattern.component_begin[k];
               j < pattern.component_begin[k + 1];
               ++j)
            target[entry_dof[j]] += tk * values[j];
        }
    }

  private:
    /**
     * Call @p f(kept point, q, FEValues) for each Gauss point q of each
     * kept cell (cell_slot), in order.
     */
    template <int dim, typename Function>
    void
    for_each_point(const DoFHandler<dim> &dof_handler,
                   const Mapping<dim>    &mapping,
                   const Quadrature<dim> &quadrature,
                   const Function        &f) const;

    /// The non-zero entries of one mode's and part's operator, grouped by
    /// component: entries [component_begin[k], component_begin[k+1]).
    struct Pattern
    {
      std::array<unsigned int, 7> component_begin;
    };

    /// Where active cell @p c is among the kept ones.
    std::size_t
    kept_cell(const unsigned int c) const
    {
      Assert(cell_slot.empty() || cell_slot[c] != numbers::invalid_unsigned_int,
             ExcMessage("Cell " + std::to_string(c) + " is not kept here."));
      return cell_slot.empty() ? c : cell_slot[c];
    }

    /// Where point @p point (c * n_q + q) is kept.
    std::size_t
    kept_point(const unsigned int point) const
    {
      return cell_slot.empty() ? point
                               : kept_cell(point / n_q) * n_q + point % n_q;
    }

    const double *
    point_values(const unsigned int point) const
    {
      return &values[kept_point(point) * entries_per_point];
    }

    unsigned int parts       = 1;
    unsigned int n_cell_dofs = 0;
    unsigned int n_q         = 0;
    /// The DoFs of each kept cell.
    std::vector<types::global_dof_index> dofs;
    /// The place of each active cell among the kept ones (empty: every
    /// cell is kept, in order).
    std::vector<unsigned int> cell_slot;
    std::vector<double>       weights;
    /// Indexed by m * n_parts + part.
    std::vector<Pattern>      patterns;
    std::vector<unsigned int> entry_dof;
    std::vector<double>       values;
    unsigned int              entries_per_point = 0;
  };
} // namespace thinlayer

#endif
