#ifndef thinlayer_elements_continuum_cells_h
#define thinlayer_elements_continuum_cells_h

#include <deal.II/base/quadrature.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/full_matrix.h>

#include <thinlayer/discretisation/kinematics.h>
#include <thinlayer/discretisation/strain_operator.h>
#include <thinlayer/elements/element_group.h>
#include <thinlayer/elements/point_loop.h>
#include <thinlayer/materials/material_law.h>
#include <thinlayer/materials/point_history.h>
#include <thinlayer/parallel/cell_partition.h>
#include <thinlayer/parameters/scene_sections.h>

#include <functional>
#include <map>
#include <memory>
#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /**
   * The continuum: every active cell of the mesh with its material law,
   * its Gauss points (the strain-displacement cache StrainOperator and a
   * PointState per point and station), and the point loop over them
   * (PointLoop). As an ElementGroup it assembles the
   * cells' elastic stiffness, K_m = int (c1 B1^T D B1 + c2 B2^T D B2) dA_r
   * (the exact integral over the circle, with which the harmonics
   * decouple), runs the point rules, and assembles Newton's consistent
   * tangent.
   *
   * Newton's tangent: in the Fourier case the stations mix the harmonics,
   * so the tangent couples them (one matrix over all modes, mode m's DoFs
   * shifted by m * n_dofs). The cell matrices are computed in parallel
   * over the point loop's chunks and added in cell order; a cell whose
   * points are all elastic takes its elastic matrix, computed once.
   */
  template <int dim>
  class ContinuumCells : public ElementGroup
  {
  public:
    /**
     * The cells of @p dof_handler's triangulation, with @p quadrature's
     * points, the laws of @p materials by material id, and @p kinematics.
     * The points, their states and the point rules are those of the cells
     * that @p partition gives this rank (all cells where it has no owners).
     * The objects are referenced, not copied.
     */
    ContinuumCells(
      const DoFHandler<dim>                                  &dof_handler,
      const Mapping<dim>                                     &mapping,
      const Quadrature<dim>                                  &quadrature,
      const Kinematics                                       &kinematics,
      const std::map<types::material_id, MaterialParameters> &materials,
      const CellPartition                                    &partition);

    /// @name The ElementGroup interface
    /// @{
    void
    add_sparsity(DynamicSparsityPattern          &dsp,
                 const AffineConstraints<double> &constraints) const override;

    void
    add_dofs(std::vector<types::global_dof_index> &dofs) const override;

    void
    assemble_elastic(const unsigned int    m,
                     const CellMatrixSink &add) const override;

    bool
    all_associated() const override;

    /// With the smallest stable pseudo time step of the materials.
    unsigned int
    viscoplastic_update(const ModeVectors &step_increment,
                        ModeVectors       &body_load_change) override;

    unsigned int
    return_mapping_update(const ModeVectors &step_increment,
                          const bool         with_tangents,
                          ModeVectors       &internal_forces,
                          ModeVectors       &stress_excess) override;

    void
    add_internal_forces(ModeVectors &internal_forces) const override;

    void
    accept() override;

    void
    reject() override;

    /// Every stress component, and every yield ratio of a law that can
    /// yield.
    void
    check_state(StateCheck &check) const override;

    void
    add_coupled_sparsity(const DofSink &add) override;

    void
    add_coupled_tangent(const CellMatrixSink &add) override;
    /// @}

    /// The pseudo time step of the viscoplastic iterations: the smallest
    /// stable one of the materials.
    double
    viscoplastic_time_step() const;

    const StrainOperator &
    get_strain_operator() const;

    unsigned int
    n_quadrature_points() const;

    /// Whether this rank holds the points of active cell @p cell.
    bool
    owns(const unsigned int cell) const;

    /// The state at Gauss point @p q of active cell @p cell (one this rank
    /// owns()) and station @p station.
    const PointState &
    point_state(const unsigned int cell,
                const unsigned int q,
                const unsigned int station) const;

    /// The material law of active cell @p cell.
    const MaterialLaw &
    material_law(const unsigned int cell) const;

    /**
     * Start every point and station of this rank's cells from the stress
     * @p initial(x, material id) at the point's place x, as its converged
     * stress: the initial stresses of the K0 procedure. The internal
     * forces are the analysis's to compute from them.
     */
    void
    set_initial_stresses(
      const std::function<SymmetricTensor<2, 3>(const Point<dim> &,
                                                types::material_id)> &initial);

    /// The laws of the materials of @p reduced with their strengths
    /// divided by @p factor; the other materials' laws as given.
    void
    reduce_strength(const StrengthReductionParameters &reduced,
                    const double                       factor) override;

  private:
    /// Work space of one chunk of Newton's cell matrices.
    struct TangentScratch
    {
      std::vector<SymmetricTensor<2, 3>> strain, stress, part2;
      std::vector<double>                strain_rows, stress_rows;
    };

    /// The DoFs of cell @p c of every mode in the coupled numbering.
    void
    coupled_cell_dofs(const unsigned int                    c,
                      std::vector<types::global_dof_index> &dofs) const;

    /// Newton's matrix of the cell at position @p i of the point loop's
    /// cells, with the kept tangents.
    void
    compute_cell_tangent(const unsigned int i, TangentScratch &scratch);

    /// Whether every tangent of the cell at position @p i of the point
    /// loop's cells is its elastic one.
    bool
    elastic_tangents(const unsigned int i) const;

    const DoFHandler<dim> &dof_handler;
    /// To compute the strain operator again for a rank's cells.
    const Mapping<dim>   &mapping;
    const Quadrature<dim> quadrature;
    const Kinematics     &kinematics;
    const unsigned int    n_q;

    const std::map<types::material_id, MaterialParameters>    &materials;
    std::map<types::material_id, std::unique_ptr<MaterialLaw>> laws;
    double                                                     time_step;
    /// The law of every active cell.
    std::vector<const MaterialLaw *> cell_law;
    StrainOperator                   strain_operator;
    /// Whether this rank holds every cell's points (one rank).
    const bool all_cells;
    /// Where each active cell is among the point loop's cells
    /// (invalid_unsigned_int: another rank's); empty with all_cells.
    std::vector<unsigned int> cell_position;
    /// The state of every point and station of the point loop's cells, at
    /// PointLoop::point_index().
    std::vector<PointState> states;
    PointLoop               point_loop;

    /// Newton's state for the point loop's cells (this rank's), by their
    /// position in its list, allocated by add_coupled_sparsity(): the
    /// consistent tangent at every point and station
    /// (PointLoop::point_index()), each cell's matrix, and whether that
    /// matrix is the elastic one (a cell elastic again needs it
    /// recomputed; one elastic throughout, never).
    std::vector<SymmetricTensor<4, 3>> tangents;
    std::vector<FullMatrix<double>>    cell_matrices;
    std::vector<unsigned char>         holds_elastic_matrix;
    std::vector<TangentScratch>        tangent_scratch;
  };


  template <int dim>
  inline double
  ContinuumCells<dim>::viscoplastic_time_step() const
  {
    return time_step;
  }


  template <int dim>
  inline const StrainOperator &
  ContinuumCells<dim>::get_strain_operator() const
  {
    return strain_operator;
  }


  template <int dim>
  inline unsigned int
  ContinuumCells<dim>::n_quadrature_points() const
  {
    return n_q;
  }


  template <int dim>
  inline bool
  ContinuumCells<dim>::owns(const unsigned int cell) const
  {
    return all_cells || cell_position[cell] != numbers::invalid_unsigned_int;
  }


  template <int dim>
  inline const PointState &
  ContinuumCells<dim>::point_state(const unsigned int cell,
                                   const unsigned int q,
                                   const unsigned int station) const
  {
    Assert(owns(cell),
           ExcMessage("The points of cell " + std::to_string(cell) +
                      " are another rank's."));
    return states[point_loop.point_index(
      all_cells ? cell : cell_position[cell], q, station)];
  }


  template <int dim>
  inline const MaterialLaw &
  ContinuumCells<dim>::material_law(const unsigned int cell) const
  {
    return *cell_law[cell];
  }
} // namespace thinlayer

#endif
