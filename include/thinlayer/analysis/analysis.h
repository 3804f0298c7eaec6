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
   * of a layer's profile): whole_mesh().
   *
   * A solution method (owned by the stepping, see StepSolver) sets the
   * step increments and calls the point rules; the stepping then ends the
   * attempt (end_attempt()), and accepts or rejects its state. Data flows
   * one way: the analysis knows no method. For isotropic elasticity the
   * modes decouple, so a constant-stiffness iteration is one
   * forward/backward substitution per mode and one pass of the point
   * rules.
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

    /// @name The state and the load factors
    /// @{

    unsigned int
    n_modes() const;

    /// The linear system of mode @p m.
    const ModeSystem &
    mode_system(const unsigned int m) const;

    /// Solve K_m x = @p rhs in place with mode @p m's elastic factors
    /// (@p rhs condensed with its constraints). A collective call.
    void
    elastic_solve(const unsigned int m, ModeVector &rhs);

    /// The same for every mode m with @p rhs[m]: where the harmonics are
    /// spread over the ranks, their substitutions run at the same time.
    void
    elastic_solve(ModeVectors &rhs);

    /// One zero vector per mode, laid out as the state's (each rank's own
    /// DoFs and its ghosts): what a solution method iterates with.
    ModeVectors
    new_mode_vectors() const;

    /// @p v whole, its entries gathered from every rank (on one rank a
    /// copy): for checks that compare with a whole vector (the tests); the
    /// outputs and monitors read each rank's own cells instead. A
    /// collective call.
    Vector<double>
    whole(const ModeVector &v) const;

    /// The displacements of the last accepted state, per mode.
    const ModeVectors &
    solution() const;

    /// The displacement increment of the current step, per mode: what the
    /// solution methods iterate on.
    ModeVectors &
    step_increment();

    const ModeVectors &
    step_increment() const;

    /// The internal forces int B^T sigma of the current stresses, per mode
    /// (set by return_mapping_update() and end_attempt()).
    const ModeVectors &
    internal_forces() const;

    /// The load factor of the last accepted state.
    double
    accepted_load_factor() const;

    /// The largest internal force (reactions included) of the last
    /// accepted state: the force scale of a step that starts there.
    double
    accepted_force_scale() const;

    /// The load factor of the current state: of the last attempt while it
    /// is pending, else the accepted one.
    double
    load_factor() const;

    /// Whether the current state is a pending step (solution plus
    /// step_increment) rather than the accepted one.
    bool
    is_pending() const;

    /// @}
    /// @name Phases: the initial state, then the loading
    /// @{

    /// The loads a phase applies in proportion to its load factor.
    enum class PhaseLoads
    {
      /// The Boundary sections' values and the weight with the surcharge:
      /// a run of one phase (gravity loading, if it has weight).
      boundaries_and_weight,
      /// The weight with the surcharge: the initial phase of gravity
      /// loading (the prescribed displacements held at zero).
      weight,
      /// The Boundary sections' values: the loading after an initial
      /// state.
      boundaries,
      /// Nothing: the loads are held while strengths are reduced.
      none
    };

    /**
     * Begin a phase that applies @p loads: the loads of the phase before
     * it, at its accepted load factor, are held fixed from now on, and the
     * load factor starts again from 0; so are its prescribed displacements
     * where it left them. With @p reset_displacements the displacements
     * start from zero; the stresses are kept. The boundary values are
     * those of @p boundary_set: 0 the Boundary sections', k the loading
     * phase Phase k + 1's.
     */
    void
    begin_phase(const PhaseLoads   loads,
                const bool         reset_displacements,
                const unsigned int boundary_set = 0);

    /**
     * The K0 procedure (KZeroStresses): every point of the continuum
     * starts from the at-rest stresses of the weight and the surcharge,
     * which are held as the body's load. Throws InputError where the
     * ground surface is not level or a point's stress lies outside its
     * material's yield surface. Returns the out-of-balance force of the
     * initial stresses against that load, condensed, relative to the load
     * (both the largest entry): zero on a level ground but for the
     * quadrature's error on distorted cells.
     */
    double
    set_initial_stresses();

    /// Divide the strengths of Strength reduction/Materials and its
    /// Interface curves by @p factor (ElementGroup::reduce_strength()): for
    /// the attempt that follows.
    void
    reduce_strength(const double factor);

    /// Whether a phase of @p loads (with the boundary values of
    /// @p boundary_set) would apply a load or prescribed displacements in
    /// proportion to its load factor.
    bool
    applies_anything(const PhaseLoads   loads,
                     const unsigned int boundary_set = 0) const;

    /// @}
    /// @name What the solution methods do to the state
    /// @{

    /**
     * The paper's viscoplastic point rule of every group for the step
     * increments; the body loads of the new viscoplastic strains are added
     * to @p body_load_change. Returns the number of yielding points and
     * stations.
     */
    unsigned int
    viscoplastic_update(ModeVectors &body_load_change);

    /**
     * Stresses at every point and station by the return mapping of the
     * trial stresses of the step increments: sets the internal forces, and
     * @p stress_excess to the nodal forces of trial less returned stress.
     * With @p with_tangents, every group keeps its consistent tangents
     * for add_coupled_tangent(). Returns the number of yielding points
     * and stations.
     */
    unsigned int
    return_mapping_update(const bool with_tangents, ModeVectors &stress_excess);

    /// Whether every flow rule is associated (a symmetric consistent
    /// tangent).
    bool
    all_laws_associated() const;

    /// Hand the DoFs of all modes (DoF m * n_dofs + i of mode m) of every
    /// cell and element this rank owns to @p add, every group's: the
    /// couplings of Newton's tangent.
    void
    add_coupled_sparsity(const DofSink &add);

    /// Hand every group's tangent matrices of the last return mapping with
    /// tangents, of the cells and elements this rank owns, to @p add.
    void
    add_coupled_tangent(const CellMatrixSink &add);

    /// @}
    /// @name The end of an attempt, and its state accepted or rejected
    /// @{

    /**
     * The solution method has left its state of the step to
     * @p load_factor: it is the current one, pending until accept_step() or
     * reject_step(). Computes its internal forces, and checks whether it
     * is finite (increments, stresses, yield ratios) and how far it is
     * from yield.
     */
    StateCheck
    end_attempt(const double load_factor);

    /// Make the pending state the accepted one.
    void
    accept_step();

    /**
     * Make the current stresses the converged ones, add the step's
     * increment to the solution and its plastic strain to the total, and
     * take @p load_factor as the accepted load factor: for a method that
     * accepts a converged part of a step (cut-back).
     */
    void
    accept_step(const double load_factor);

    /// Return to the accepted state: the pending state is dropped.
    void
    reject_step();

    /// @}
    /// @name Questions about the state
    /// @{

    /**
     * The secant stiffness along the pending step's increment against the
     * elastic one: (f . du_elastic) / (f . du), with f the step's load
     * increment and du_elastic = K^-1 f its elastic response, summed over
     * the modes. Near 1 while the body is elastic, it falls towards 0 as a
     * mechanism lets the displacement grow at constant load. NaN where the
     * step has no load increment (prescribed displacements only).
     */
    double
    secant_stiffness_ratio() const;

    /// Whether the scene applies tractions or pressures; without, it is
    /// driven by prescribed displacements alone.
    bool
    has_external_load() const;

    /**
     * The displacement at angle @p theta, summed over the modes, as a DoF
     * vector: components (x, y) in plane strain, (r, z, theta) for Fourier.
     * With @p increment, the last load step's increment instead (at a
     * failed step, the incipient mechanism). Each rank has the DoFs of its
     * own cells, ghosts included. A collective call.
     */
    ModeVector
    displacement_at(const double theta, const bool increment = false) const;

    /// The displacements of every mode, ghosts imported: the current
    /// state's (a pending step's includes its increment), or with
    /// @p increment the last load step's increment. A collective call.
    ModeVectors
    displacements(const bool increment = false) const;

    /// displacement_at() of the modes @p modes of displacements(): for
    /// many angles of one state, without communication.
    ModeVector
    displacement_at(const double theta, const ModeVectors &modes) const;

    /// The profiles every element group writes, of the current state.
    std::vector<NamedProfile>
    profiles() const;

    /// The continuum cells: the point states and laws of the body.
    const ContinuumCells<dim> &
    cells() const;

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

    /// @}

    const Kinematics &
    get_kinematics() const;

    /// Warnings about the scene found while setting it up (boundary
    /// conditions that disagree at a node), one per line, from every rank.
    /// A collective call.
    std::string
    warnings() const;

    /// The support points and components of this rank's DoFs: for the
    /// rigid-body motions and the reactions' moments.
    OwnedDofPlaces
    owned_dof_places() const;

    /// The DoFs, on this rank's part of the mesh (on one rank, the whole
    /// mesh).
    const DoFHandler<dim> &
    get_dof_handler() const;

    /// The mesh as read, every cell on every rank: for setting up what
    /// spans the ranks (the runs of a layer's profile). Its cells are found
    /// in get_dof_handler()'s mesh by CellId (cell_of()).
    const Triangulation<dim> &
    whole_mesh() const;

    /// Whether this rank owns active cell @p c of whole_mesh().
    bool
    owns_whole_cell(const unsigned int c) const;

    const Mapping<dim> &
    get_mapping() const;

    /// Which rank owns each active cell (on one rank an empty owner list:
    /// every cell is rank 0's).
    const CellPartition &
    get_partition() const;

    /// The DoFs each rank owns, contiguous and in rank order (empty on one
    /// rank).
    const std::vector<IndexSet> &
    get_owned_per_rank() const;

    /// The serendipity lines only (to condense residuals for reactions).
    const AffineConstraints<double> &
    get_element_constraints() const;

    /// The displacement amplitudes of mode @p mode, whole (see whole()).
    Vector<double>
    get_solution(const unsigned int mode = 0) const;

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

    /// With Solver/Linear solver = amg cg, the mean CG iterations of a
    /// solve so far (all modes); NaN with factors.
    double
    linear_iterations_per_solve() const;

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
    /// The same over the cells of whole_mesh().
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
  };
} // namespace thinlayer

#include <thinlayer/analysis/analysis_accessors.h>

#endif
