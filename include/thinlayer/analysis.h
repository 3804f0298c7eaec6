#ifndef thinlayer_analysis_h
#define thinlayer_analysis_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/quadrature_point_data.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/thread_management.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <thinlayer/anderson_acceleration.h>
#include <thinlayer/boundary_data.h>
#include <thinlayer/factorised_stiffness.h>
#include <thinlayer/kinematics.h>
#include <thinlayer/material_law.h>
#include <thinlayer/parameters.h>
#include <thinlayer/point_history.h>

#include <array>
#include <map>
#include <memory>
#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /**
   * What one load step reports (history.csv has one row per step).
   */
  struct StepResult
  {
    unsigned int iterations;
    bool         converged;
    /// Max over points (and stations) of F / strength after the step: NaN
    /// where no material can yield.
    double max_yield_ratio;
    /// Points (and stations) with F > 0 at the end of the step.
    unsigned int plastic_points;
    /// Newton: how often the step was halved.
    unsigned int cut_backs = 0;
    /// Newton: tangent factorisations.
    unsigned int factorisations = 0;
  };

  /**
   * A displacement component over a boundary: length-weighted mean, and the
   * extremes over its nodes (their spread shows how uniform it is).
   */
  struct DisplacementMeasure
  {
    double mean;
    double min;
    double max;
  };

  /**
   * An elasto-plastic analysis of one scene, for any Kinematics: plane
   * strain (one mode, one station) or an axisymmetric body under
   * non-axisymmetric load (one mode per Fourier harmonic, the material
   * evaluated at circumferential stations).
   *
   * The elastic stiffness of every mode is assembled and factorised once;
   * for isotropic elasticity the modes decouple, so each iteration is one
   * forward/backward substitution per mode and one pass over the Gauss
   * points and stations, whose strain-displacement data are computed once
   * and cached (the mesh does not move).
   *
   * A load step from load factor lambda_0 to lambda solves, with body
   * loads b_m = 0 at its start,
   *   K_m du_m = (lambda - lambda_0) f_m + b_m     for every mode m,
   * then at every point and station strain = sum_m B_m(theta_s) du_m,
   * d eps = strain - eps_vp, sigma = sigma_0 + D d eps; where F(sigma) > 0 it
   * adds the viscoplastic strain dt F dQ/dsigma to eps_vp and projects
   * D (that strain) back onto every mode's body loads, until the body
   * loads (or the displacement increments) stop changing to within the
   * tolerance. A step that reaches the iteration limit has failed: that is
   * how collapse shows.
   *
   * The other solution methods (Parameters::method) iterate on the
   * out-of-balance force r = lambda f - int B^T sigma, every point's stress
   * coming from the return mapping of its elastic trial stress
   * sigma_0 + D (strain of the step): the initial-stress method corrects
   * the step's displacement by K^-1 r with the elastic factor (the stress
   * excess int B^T (trial - sigma) playing the part of the body loads; r is
   * exactly the change of those between iterations), optionally with
   * Anderson acceleration; Newton by K_t^-1 r with the consistent tangent,
   * refactorised every iteration, a backtracking line search on |r|, and
   * the step halved when it does not converge. In the Fourier case the
   * consistent tangent couples the harmonics (plastic stresses at the
   * stations mix them), so Newton solves one system over all modes.
   *
   * Discretisation: FE_Q(2) per component, reduced to the 8-node
   * serendipity element by make_serendipity_constraints() (or kept as Q9),
   * 2x2 or 3x3 Gauss points, and a quadratic mapping (identical to the
   * bilinear one on gmsh's straight-sided cells, curved where the
   * triangulation has a curved manifold).
   */
  template <int dim>
  class Analysis
  {
  public:
    Analysis(const Parameters &parameters, const Triangulation<dim> &tria);

    /**
     * Distribute DoFs, build constraints, loads and the point cache,
     * assemble and factorise the stiffness of every mode. Throws
     * InputError if the body is not restrained.
     */
    void
    setup();

    /**
     * One load step, to the total load factor @p load_factor, with the
     * method the parameters ask for.
     */
    StepResult
    solve(const double load_factor);

    /// The load monitor (load factor or reaction sum, times its scale).
    double
    load() const;

    /// The displacement monitor, times its scale.
    DisplacementMeasure
    displacement() const;

    const Kinematics &
    get_kinematics() const;

    const DoFHandler<dim> &
    get_dof_handler() const;

    const Mapping<dim> &
    get_mapping() const;

    /// The displacement amplitudes of mode @p mode.
    const Vector<double> &
    get_solution(const unsigned int mode = 0) const;

    /**
     * The displacement at angle @p theta, summed over the modes, as a DoF
     * vector: components (x, y) in plane strain, (r, z, theta) for Fourier.
     * With @p increment, the last load step's increment instead (at a
     * failed step, the incipient mechanism).
     */
    Vector<double>
    displacement_at(const double theta, const bool increment = false) const;

    /// The state at Gauss point @p q of active cell @p cell and station
    /// @p station.
    const PointState &
    point_state(const unsigned int cell,
                const unsigned int q,
                const unsigned int station = 0) const;

    /// Stress (3D, tension positive) at point @p q of active cell @p cell,
    /// station 0.
    const SymmetricTensor<2, 3> &
    stress(const unsigned int cell, const unsigned int q) const;

    /// The material law of active cell @p cell.
    const MaterialLaw &
    material_law(const unsigned int cell) const;

    unsigned int
    n_quadrature_points() const;

    /// Displacement DoFs of the element's nodes per mode (for Q8 the
    /// eliminated centre nodes are not counted; prescribed DoFs are).
    types::global_dof_index
    n_dofs() const;

    /// Unknowns of the factorised systems, summed over the modes.
    types::global_dof_index
    n_equations() const;

    /**
     * Wall time of one forward/backward substitution with the stored
     * elastic factors of all modes (the median of ten, measured in
     * setup()): the floor of a constant-stiffness iteration's cost.
     */
    double
    substitution_seconds() const;

    /// The pseudo time step of the viscoplastic iterations.
    double
    viscoplastic_time_step() const;

  private:
    /**
     * Everything that exists once per mode: its constraints (the axis
     * conditions depend on the harmonic), stiffness, factorisation, loads
     * and displacements.
     */
    struct Mode
    {
      explicit Mode(const FactorisedStiffness::Method method)
        : factorisation(method)
      {}

      /// Serendipity, dead-component and axis lines.
      AffineConstraints<double> structural_constraints;
      /// The above plus homogeneous Dirichlet lines: the solve's space.
      AffineConstraints<double> constraints;
      SparseMatrix<double>      stiffness;
      SparseMatrix<double>      condensed_stiffness;
      FactorisedStiffness       factorisation;
      Vector<double>            unit_prescribed_displacement;
      Vector<double>            unit_load;
      /// f - K u_prescribed at unit load factor.
      Vector<double> unit_rhs;
      Vector<double> solution;
      Vector<double> step_increment;
      Vector<double> internal_forces;
      /// Return-mapping methods: the out-of-balance force and correction.
      Vector<double> residual;
      Vector<double> correction;
      // Work vectors of the iterations.
      Vector<double> body_loads;
      Vector<double> body_load_change;
      Vector<double> previous_increment;
      /// A condensed copy for the convergence criterion.
      Vector<double> condensed;
    };

    void
    make_mode_constraints(const unsigned int m);

    void
    build_point_cache();

    void
    assemble_stiffness();

    /// The strain-displacement parts @p part (0 or 1) of all shape
    /// functions of mode @p m at point @p point, into @p B (one per DoF of
    /// the cell).
    void
    shape_strains(const unsigned int     point,
                  const unsigned int     m,
                  const unsigned int     part,
                  SymmetricTensor<2, 3> *B) const;

    /// The strain part @p part of mode @p m at @p point for the cell's
    /// nodal values @p u of that mode: sum_i u_i B_i.
    SymmetricTensor<2, 3>
    strain(const unsigned int point,
           const unsigned int m,
           const unsigned int part,
           const double      *u) const;

    /// @p target_i += B_i : @p t for every DoF i of the cell (part @p part
    /// of mode @p m at @p point).
    void
    add_projection(const unsigned int           point,
                   const unsigned int           m,
                   const unsigned int           part,
                   const SymmetricTensor<2, 3> &t,
                   double                      *target) const;

    void
    solve_increment(const unsigned int m, const double dlambda);

    /// The paper's method for one load step.
    StepResult
    solve_viscoplastic(const double dlambda);

    /**
     * A return-mapping method (initial stress, accelerated, Newton) for one
     * load step from load_factor to @p new_load_factor; Newton halves the
     * step up to Parameters::max_cut_backs times.
     */
    StepResult
    solve_with_return_mapping(const double new_load_factor);

    /**
     * Iterations of a return-mapping method from load_factor to
     * @p target, starting from the converged state; counts into @p result.
     * True if converged.
     */
    bool
    iterate_with_return_mapping(const double target, StepResult &result);

    /**
     * Stresses at every point and station by return mapping of the trial
     * stresses of the modes' step increments; then each mode's residual
     * (condensed onto the free DoFs) at load factor @p target, and the
     * stress excess in body_loads.
     */
    struct ResidualNorms
    {
      unsigned int n_yielding;
      /// max |r| and |r|_2 over the free DoFs of all modes.
      double max;
      double l2;
      /// max |b| of the stress excess, and max |f| of the internal and
      /// external forces: the scales max |r| is measured against.
      double body_loads;
      double forces;
    };

    ResidualNorms
    evaluate_residual(const double target, const bool store_tangents);

    /// The indices in Newton's system of cell @p c's DoFs, mode by mode.
    void
    newton_cell_dofs(const unsigned int                    c,
                     std::vector<types::global_dof_index> &dofs) const;

    /// Newton: set up newton_constraints, newton_sparsity and the matrix.
    void
    setup_newton_system();

    /// Work space of one chunk of the point loop (and of Newton's cell
    /// tangents), allocated once in setup().
    struct ChunkScratch
    {
      /// The cell's nodal increments, per mode.
      std::vector<double> du;
      /// The strain parts of each mode at a point.
      std::vector<SymmetricTensor<2, 3>> mode_strain;
      /// compute_cell_tangents(): per mode and DoF, strain and stress; as
      /// six rows of raw components.
      std::vector<SymmetricTensor<2, 3>> strain, stress, part2;
      std::vector<double>                strain_rows, stress_rows;
    };

    /// The cell matrices of the consistent tangent of the active cells
    /// [@p begin, @p end) into newton_cell_matrices.
    void
    compute_cell_tangents(const unsigned int begin,
                          const unsigned int end,
                          ChunkScratch      &scratch);

    /// Assemble and factorise the consistent tangent, coupling the modes;
    /// false if the factorisation fails (a singular tangent at a mechanism).
    bool
    factorise_tangent();

    /// Make the current stresses the converged ones, add the step's
    /// increment to the solution and its plastic strain to the total.
    void
    accept_step_state();

    /**
     * Stresses at every point and station for the modes' increments.
     * Viscoplastic: adds the new viscoplastic body loads to each mode's
     * body_load_change. Return-mapping methods: sets each mode's
     * internal_forces and its stress excess in body_loads, and with
     * @p store_tangents keeps the consistent tangents. Returns the number
     * of yielding points and stations.
     *
     * The cells are split into chunks run as parallel tasks. Each cell
     * writes its nodal forces into its own slot of cell_body_loads and
     * cell_internal_forces, and one serial pass adds the slots into the
     * global vectors in cell order: the sums, and so the iterations, do
     * not depend on the number of threads, and no per-chunk global vectors
     * are zeroed and summed every iteration.
     */
    unsigned int
    update_stresses(const bool store_tangents = false);

    /// The number of chunks the point loop is split into.
    unsigned int
    n_point_loop_chunks() const;

    /// update_stresses() for the active cells [@p begin, @p end): fills
    /// their slots of cell_body_loads (and cell_internal_forces) and marks
    /// in cell_has_body_loads whether a cell's body loads are non-zero.
    unsigned int
    update_stresses(const unsigned int begin,
                    const unsigned int end,
                    const bool         store_tangents,
                    ChunkScratch      &scratch);

    void
    update_internal_forces();

    const Parameters         &parameters;
    const Triangulation<dim> &tria;
    const Kinematics          kinematics;
    const FESystem<dim>       fe;
    const MappingQ<dim>       mapping;
    const QGauss<dim>         quadrature;
    DoFHandler<dim>           dof_handler;
    BoundaryData              boundary_data;

    /// The serendipity lines only (to condense residuals for reactions).
    AffineConstraints<double>          element_constraints;
    SparsityPattern                    sparsity;
    std::vector<std::unique_ptr<Mode>> modes;

    std::map<types::material_id, std::unique_ptr<MaterialLaw>> laws;
    double                                                     time_step;

    /**
     * Per active cell: its law and DoFs; per Gauss point: its area weight
     * (JxW, times r for Fourier) and the strain parts of every shape
     * function in every mode. Flat arrays, indexed by active cell index, so
     * the point loop touches no FEValues and no map.
     */
    std::vector<const MaterialLaw *>     cell_law;
    std::vector<types::global_dof_index> cell_dofs;
    std::vector<double>                  point_weight;
    unsigned int                         n_parts;

    /**
     * The strain-displacement operator of each mode and part, stored by
     * its non-zero entries only: for each raw component k of
     * SymmetricTensor<2,3>, the entries [component_begin[k],
     * component_begin[k+1]) name a DoF of the cell (strain_entry_dof) whose
     * shape function has a non-zero component k at some point. A shape
     * function of u_x in plane strain has only xx and xy, for example. The
     * values, strain_entries_per_point per point, are in the same order.
     * Grouped by component, the strain is six short gathered dot products,
     * and the point loop reads a third of the memory a full
     * SymmetricTensor per shape function needs; memory traffic is what
     * limits it.
     */
    struct StrainOperator
    {
      std::array<unsigned int, 7> component_begin;
    };
    /// Indexed by m * n_parts + part.
    std::vector<StrainOperator> strain_operators;
    std::vector<unsigned int>   strain_entry_dof;
    std::vector<double>         strain_values;
    unsigned int                strain_entries_per_point;

    CellDataStorage<typename Triangulation<dim>::cell_iterator, PointHistory>
                                history_storage;
    std::vector<PointHistory *> history;

    /// The component of every DoF.
    std::vector<unsigned int> dof_component;

    /// Each cell's nodal body loads (viscoplastic: their increments), per
    /// mode: n_modes * dofs_per_cell entries from c * n_modes *
    /// dofs_per_cell on.
    std::vector<double> cell_body_loads;
    /// Each cell's nodal internal forces (return-mapping methods), laid
    /// out as cell_body_loads.
    std::vector<double> cell_internal_forces;
    /// Whether a cell's slot of cell_body_loads holds anything (0 when none
    /// of its points yields): the serial pass skips the cells with 0.
    std::vector<unsigned char> cell_has_body_loads;
    /// The point loop's tasks, one per chunk (kept to reuse the storage).
    std::vector<Threads::Task<unsigned int>> tasks;
    /// One per chunk.
    std::vector<ChunkScratch> chunk_scratch;

    /// Newton: the consistent tangent at every point and station.
    std::vector<SymmetricTensor<4, 3>> tangents;

    /**
     * Newton's system. The stations mix the harmonics, so the consistent
     * tangent couples the modes: it is one matrix over all of them, mode
     * m's DoFs shifted by m * n_dofs, each block condensed with its mode's
     * constraints. (In plane strain it is the one mode's matrix.)
     */
    AffineConstraints<double>            newton_constraints;
    SparsityPattern                      newton_sparsity;
    SparseMatrix<double>                 newton_tangent;
    std::unique_ptr<FactorisedStiffness> newton_factorisation;
    /// Each cell's matrix of the tangent, computed in parallel.
    std::vector<FullMatrix<double>> newton_cell_matrices;
    /// The modes' residuals, then corrections, one after the other.
    Vector<double> newton_vector;

    AndersonAcceleration anderson;
    /// The step increments of all modes, one after the other, and their
    /// corrections: the vectors Anderson acceleration works on.
    Vector<double> stacked_increment;
    Vector<double> stacked_correction;

    double load_factor;
    double substitution_time;

    IndexSet reaction_dofs;
  };
} // namespace thinlayer

#endif
