#ifndef thinlayer_analysis_analysis_h
#define thinlayer_analysis_analysis_h

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <thinlayer/analysis/mode_system.h>
#include <thinlayer/analysis/rigid_body_modes.h>
#include <thinlayer/analysis/step_access.h>
#include <thinlayer/discretisation/boundary_data.h>
#include <thinlayer/discretisation/kinematics.h>
#include <thinlayer/discretisation/mode_vectors.h>
#include <thinlayer/elements/continuum_cells.h>
#include <thinlayer/elements/element_group.h>
#include <thinlayer/parallel/cell_partition.h>
#include <thinlayer/parameters/parameters.h>

#include <memory>
#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /**
   * The body of an elasto-plastic analysis of one scene, for any
   * Kinematics: plane strain (one mode, one station) or an axisymmetric
   * body under non-axisymmetric load (one mode per Fourier harmonic, the
   * material evaluated at circumferential stations). It holds the state
   * every solution method works on, and nothing of any one method:
   *
   * - one ModeSystem per mode: constraints, the elastic stiffness
   *   assembled and factorised once, the loads at unit load factor;
   * - the state: per mode the accepted displacements, the current step's
   *   increment and the internal forces; the load factors;
   * - the element groups (ElementGroup: the continuum cells, interface
   *   elements), which hold the point states and laws and do the work at
   *   the points. The analysis loops over them.
   *
   * On many ranks (thinlayer::mpi) every rank follows the same steps on
   * its part. The mesh as read is partitioned (partition_cells(), the two
   * cells of a zero-thickness element on one rank) and split: each rank
   * keeps its cells and one layer of ghost cells (distribute_mesh(), a
   * fully distributed triangulation), and the DoFHandler numbers each
   * rank's DoFs as one range, in rank order. Each rank holds the point
   * states of its own cells and the constraint lines of the DoFs it holds.
   * The state vectors are ModeVectors: each rank stores its own DoFs'
   * entries and, as ghosts, those of the DoFs its cells, elements and
   * constraint lines touch. The point rules read the increments' ghosts
   * and add their forces into ghosts, which compress() sums into the
   * owners; norms and dot products reduce over the ranks. The elastic
   * stiffness is distributed by rows and factorised by MUMPS (ModeSystem).
   * The outputs read the DoFs of each rank's own cells and gather what one
   * file holds on rank 0. What spans the ranks is set up on the whole mesh
   * before it is split (the facing sides of interface elements, the runs
   * of a layer's profile): get_whole_mesh().
   *
   * Its callers see it through three interfaces, each wider than the
   * one before: postprocessing and output read it (AnalysisView); a
   * solution method (owned by the stepping, see StepSolver) sets the step
   * increments and calls the point rules (IterationAccess); the stepping
   * then ends the attempt, and accepts or rejects its state (StepAccess). Data
   * flows one way: the analysis knows no method. For isotropic elasticity the
   * modes decouple, so a constant-stiffness iteration is one
   * forward/backward substitution per mode and one pass of the point
   * rules.
   *
   * Discretisation: FE_Q(2) per component, reduced to the 8-node
   * serendipity element by make_element_constraints() (or kept as Q9), with
   * the hanging nodes of a refined mesh constrained, 2x2 or 3x3 Gauss points,
   * and a quadratic mapping (identical to the bilinear one on gmsh's
   * straight-sided cells, curved where the triangulation has a curved
   * manifold).
   */
  template <int dim>
  class Analysis : public StepAccess<dim>
  {
  public:
    /**
     * An analysis of @p tria with the model sections of @p parameters
     * (mesh geometry constants, kinematics, discretisation, materials,
     * interface elements, boundaries) and the linear solver of its Solver
     * section.
     */
    Analysis(const Parameters &parameters, const Triangulation<dim> &tria);

    ~Analysis();

    /**
     * Distribute DoFs, build constraints, loads and the element groups,
     * and assemble and factorise the stiffness of every mode. Throws
     * InputError if the body is not restrained.
     */
    void
    setup();

    /// @name AnalysisView: what may be read (documented there)
    /// @{

    unsigned int
    n_modes() const override;

    const ModeSystem &
    get_mode_system(const unsigned int m) const override;

    ModeVectors
    new_mode_vectors() const override;

    Vector<double>
    whole(const ModeVector &v) const override;

    Vector<double>
    whole_solution(const unsigned int mode = 0) const override;

    const ModeVectors &
    get_solution() const override;

    const ModeVectors &
    get_step_increment() const override;

    const ModeVectors &
    get_internal_forces() const override;

    double
    accepted_load_factor() const override;

    double
    accepted_force_scale() const override;

    double
    load_factor() const override;

    bool
    is_pending() const override;

    bool
    all_laws_associated() const override;

    double
    secant_stiffness_ratio() const override;

    bool
    has_external_load() const override;

    ModeVector
    displacement_at(const double theta,
                    const bool   increment = false) const override;

    ModeVectors
    displacements(const bool increment = false) const override;

    ModeVector
    displacement_at(const double       theta,
                    const ModeVectors &modes) const override;

    std::vector<NamedProfile>
    profiles() const override;

    const ContinuumCells<dim> &
    get_cells() const override;

    const PointState &
    get_point_state(const unsigned int cell,
                    const unsigned int q,
                    const unsigned int station = 0) const override;

    const SymmetricTensor<2, 3> &
    stress(const unsigned int cell, const unsigned int q) const override;

    const MaterialLaw &
    get_material_law(const unsigned int cell) const override;

    unsigned int
    n_quadrature_points() const override;

    const Kinematics &
    get_kinematics() const override;

    std::string
    warnings() const override;

    OwnedDofPlaces
    owned_dof_places() const override;

    const DoFHandler<dim> &
    get_dof_handler() const override;

    const Triangulation<dim> &
    get_whole_mesh() const override;

    bool
    owns_whole_cell(const unsigned int c) const override;

    const Mapping<dim> &
    get_mapping() const override;

    const CellPartition &
    get_partition() const override;

    const std::vector<IndexSet> &
    get_owned_per_rank() const override;

    const AffineConstraints<double> &
    get_element_constraints() const override;

    types::global_dof_index
    n_dofs() const override;

    types::global_dof_index
    n_equations() const override;

    double
    substitution_seconds() const override;

    double
    linear_iterations_per_solve() const override;

    const LinearSolverChoice &
    get_linear_solver() const override;

    /// @}
    /// @name IterationAccess: what a solution method does
    /// @{

    ModeVectors &
    get_step_increment() override;

    void
    elastic_solve(const unsigned int m, ModeVector &rhs) override;

    void
    elastic_solve(ModeVectors &rhs) override;

    unsigned int
    viscoplastic_update(ModeVectors &body_load_change) override;

    unsigned int
    return_mapping_update(const bool   with_tangents,
                          ModeVectors &stress_excess) override;

    void
    add_coupled_sparsity(const DofSink &add) override;

    void
    add_coupled_tangent(const CellMatrixSink &add) override;

    void
    accept_step(const double load_factor) override;

    /// @}
    /// @name StepAccess: what the stepping does
    /// @{

    void
    begin_phase(const PhaseLoads   loads,
                const bool         reset_displacements,
                const unsigned int boundary_set = 0) override;

    double
    set_initial_stresses() override;

    void
    reduce_strength(const double factor) override;

    bool
    applies_anything(const PhaseLoads   loads,
                     const unsigned int boundary_set = 0) const override;

    StateCheck
    end_attempt(const double load_factor) override;

    void
    accept_step() override;

    void
    reject_step() override;

    /// @}

  private:
    void
    setup_dofs_and_constraints();

    /// The facing sides of the interface elements on @p whole_mesh (a
    /// DoFHandler of the mesh as read, without DoFs).
    std::vector<FacingSides<dim>>
    facing_sides(const DoFHandler<dim> &whole_mesh) const;

    /// On many ranks: partition the mesh as read (each interface element's
    /// two cells together, @p sides) and put the DoFHandler on this rank's
    /// part of it.
    void
    split_mesh(const std::vector<FacingSides<dim>> &sides);

    /// The stiffness's sparsity: whole on one rank, each rank's rows on
    /// several.
    void
    setup_sparsity();

    /// The constrained DoFs of the element constraints and of every
    /// mode's, over all ranks: what n_dofs() and n_equations() subtract.
    void
    count_constrained_dofs();

    /// The layout of the mode vectors: see dof_partitioner.
    void
    setup_dof_partitioner();

    /// The component of every DoF this rank stores: see dof_component.
    void
    setup_dof_components();

    /// Prescribed displacements and loads at unit load factor, and the
    /// state vectors.
    void
    setup_mode_vectors();

    void
    assemble_stiffness();

    /**
     * An InputError if nothing loads the body, or if (in plane strain) its
     * supports leave a rigid-body motion free: a free rotation does not
     * make the factorisation fail, only its solutions meaningless.
     */
    void
    check_supports_and_load() const;

    /// The current phase's vectors at unit load factor from the parts
    /// (ModeSystem) that @p loads names, the boundary values those of
    /// boundary_set.
    void
    set_phase_loads(const PhaseLoads loads);

    /// Right-hand sides at unit load factor, factorisations, and the time
    /// one substitution takes.
    void
    factorise_stiffness();

    /// Solver/Linear solver = amg cg: every mode's AMG-CG, the rigid-body
    /// motions its near-null space, instead of factors.
    void
    set_up_iterative_solvers();

    /// Time one substitution (or iterative solve) of every mode.
    void
    time_substitution();

    /// The InputError of a singular stiffness matrix of mode @p m: what
    /// the scene most likely lacks.
    [[noreturn]] void
    throw_singular(const unsigned int m) const;

    /// An InputError for a rigid-body @p motion the supports hold only
    /// through a stiffness rounding swamps (its @p resistance, as
    /// FreeMotion has it), naming the likely cause: the largest ratio of
    /// bulk to shear modulus, or the range of Young's moduli.
    [[noreturn]] void
    throw_ill_conditioned(const std::string &motion,
                          const double       resistance) const;

    /// Set the internal forces from every group's current stresses.
    void
    compute_internal_forces();

    const Parameters         &parameters;
    const Triangulation<dim> &tria;
    const Kinematics          kinematics;
    const FESystem<dim>       fe;
    const MappingQ<dim>       mapping;
    const QGauss<dim>         quadrature;
    /// On many ranks, this rank's part of @p tria, on which the analysis
    /// runs (declared before the DoFHandler, which must go first).
    std::unique_ptr<parallel::fullydistributed::Triangulation<dim>>
                    distributed_tria;
    DoFHandler<dim> dof_handler;
    /// The Boundary sections' conditions (they also give the constraints),
    /// then each further loading phase's values.
    std::vector<std::unique_ptr<BoundaryData>> boundary_data;
    /// Which of them the current phase applies.
    unsigned int boundary_set = 0;

    AffineConstraints<double>                element_constraints;
    SparsityPattern                          sparsity;
    std::vector<std::unique_ptr<ModeSystem>> systems;

    std::vector<std::unique_ptr<ElementGroup>> groups;
    /// The first group: the continuum.
    const ContinuumCells<dim> *continuum = nullptr;

    ModeVectors solution_vectors;
    ModeVectors increment_vectors;
    ModeVectors internal_force_vectors;
    /// On many ranks: the rank of every cell, and the DoFs each rank owns
    /// (contiguous, in rank order).
    CellPartition partition;
    /// The same over the cells of get_whole_mesh().
    CellPartition         whole_partition;
    std::vector<IndexSet> owned_per_rank;
    /// The DoFs of this rank's cells and of its ghost cells: the lines its
    /// constraints keep.
    IndexSet relevant_dofs;
    /// See count_constrained_dofs().
    types::global_dof_index              n_element_constrained = 0;
    std::vector<types::global_dof_index> n_constrained;
    /// Each rank's DoFs and its ghosts: those of its own cells and
    /// elements and those its own constraint lines name.
    std::shared_ptr<const Utilities::MPI::Partitioner> dof_partitioner;
    /// Where each rank's DoFs lie in a whole vector (whole()).
    mpi::Parts dof_parts;

    /// The component of every DoF this rank stores (its own and its
    /// ghosts), by its place in the mode vectors (on one rank, by DoF).
    std::vector<unsigned int> dof_component;

    double accepted_lambda;
    /// accepted_force_scale(): set by accept_step().
    double accepted_forces = 0;
    /// The load factor of the current state, and whether that state is a
    /// pending attempt.
    double current_lambda;
    bool   pending;
    double substitution_time;
    /// Solver/Linear solver on this run's ranks.
    LinearSolverChoice linear_solver;
  };
} // namespace thinlayer

#include <thinlayer/analysis/analysis_accessors.h>

#endif
