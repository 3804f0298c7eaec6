#ifndef thinlayer_analysis_analysis_view_h
#define thinlayer_analysis_analysis_view_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>

#include <thinlayer/analysis/linear_solver_choice.h>
#include <thinlayer/analysis/mode_system.h>
#include <thinlayer/analysis/rigid_body_modes.h>
#include <thinlayer/discretisation/kinematics.h>
#include <thinlayer/discretisation/mode_vectors.h>
#include <thinlayer/elements/continuum_cells.h>
#include <thinlayer/elements/element_group.h>
#include <thinlayer/materials/material_law.h>
#include <thinlayer/materials/point_history.h>
#include <thinlayer/parallel/cell_partition.h>

#include <string>
#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /**
   * What may be read of an analysis, and nothing that changes it: the
   * view postprocessing, output and the run's report work through (as
   * ASPECT's SimulatorAccess). Analysis implements it, and so do the
   * wider interfaces of the solution methods (IterationAccess) and the
   * stepping (StepAccess), each of which adds what its callers may change.
   *
   * Getters named get_X() return an object the analysis holds; the other
   * names compute or count.
   */
  template <int dim>
  class AnalysisView
  {
  public:
    virtual ~AnalysisView() = default;

    /// @name The state and the load factors
    /// @{

    virtual unsigned int
    n_modes() const = 0;

    /// The linear system of mode @p m.
    virtual const ModeSystem &
    get_mode_system(const unsigned int m) const = 0;

    /// One zero vector per mode, laid out as the state's (each rank's own
    /// DoFs and its ghosts): what a solution method iterates with.
    virtual ModeVectors
    new_mode_vectors() const = 0;

    /// @p v whole, its entries gathered from every rank (on one rank a
    /// copy): for checks that compare with a whole vector (the tests); the
    /// outputs and monitors read each rank's own cells instead. A
    /// collective call.
    virtual Vector<double>
    whole(const ModeVector &v) const = 0;

    /// The displacement amplitudes of mode @p mode, whole (see whole()).
    virtual Vector<double>
    whole_solution(const unsigned int mode = 0) const = 0;

    /// The displacements of the last accepted state, per mode.
    virtual const ModeVectors &
    get_solution() const = 0;

    /// The displacement increment of the current step, per mode: what the
    /// solution methods iterate on.
    virtual const ModeVectors &
    get_step_increment() const = 0;

    /// The internal forces int B^T sigma of the current stresses, per mode
    /// (set by the point rules and StepAccess::end_attempt()).
    virtual const ModeVectors &
    get_internal_forces() const = 0;

    /// The load factor of the last accepted state.
    virtual double
    accepted_load_factor() const = 0;

    /// The largest internal force (reactions included) of the last
    /// accepted state: the force scale of a step that starts there.
    virtual double
    accepted_force_scale() const = 0;

    /// The load factor of the current state: of the last attempt while it
    /// is pending, else the accepted one.
    virtual double
    load_factor() const = 0;

    /// Whether the current state is a pending step (solution plus
    /// step increment) rather than the accepted one.
    virtual bool
    is_pending() const = 0;

    /// @}
    /// @name Questions about the state
    /// @{

    /// Whether every flow rule is associated (a symmetric consistent
    /// tangent).
    virtual bool
    all_laws_associated() const = 0;

    /**
     * The secant stiffness along the pending step's increment against the
     * elastic one: (f . du_elastic) / (f . du), with f the step's load
     * increment and du_elastic = K^-1 f its elastic response, summed over
     * the modes. Near 1 while the body is elastic, it falls towards 0 as a
     * mechanism lets the displacement grow at constant load. NaN where the
     * step has no load increment (prescribed displacements only).
     */
    virtual double
    secant_stiffness_ratio() const = 0;

    /// Whether the scene applies tractions or pressures; without, it is
    /// driven by prescribed displacements alone.
    virtual bool
    has_external_load() const = 0;

    /**
     * The displacement at angle @p theta, summed over the modes, as a DoF
     * vector: components (x, y) in plane strain, (r, z, theta) for Fourier.
     * With @p increment, the last load step's increment instead (at a
     * failed step, the incipient mechanism). Each rank has the DoFs of its
     * own cells, ghosts included. A collective call.
     */
    virtual ModeVector
    displacement_at(const double theta, const bool increment = false) const = 0;

    /// The displacements of every mode, ghosts imported: the current
    /// state's (a pending step's includes its increment), or with
    /// @p increment the last load step's increment. A collective call.
    virtual ModeVectors
    displacements(const bool increment = false) const = 0;

    /// displacement_at() of the modes @p modes of displacements(): for
    /// many angles of one state, without communication.
    virtual ModeVector
    displacement_at(const double theta, const ModeVectors &modes) const = 0;

    /// The profiles every element group writes, of the current state.
    virtual std::vector<NamedProfile>
    profiles() const = 0;

    /// The continuum cells: the point states and laws of the body.
    virtual const ContinuumCells<dim> &
    get_cells() const = 0;

    /// The state at Gauss point @p q of active cell @p cell and station
    /// @p station.
    virtual const PointState &
    get_point_state(const unsigned int cell,
                    const unsigned int q,
                    const unsigned int station = 0) const = 0;

    /// Stress (3D, tension positive) at point @p q of active cell @p cell,
    /// station 0.
    virtual const SymmetricTensor<2, 3> &
    stress(const unsigned int cell, const unsigned int q) const = 0;

    /// The material law of active cell @p cell.
    virtual const MaterialLaw &
    get_material_law(const unsigned int cell) const = 0;

    virtual unsigned int
    n_quadrature_points() const = 0;

    /// @}
    /// @name The discretisation
    /// @{

    virtual const Kinematics &
    get_kinematics() const = 0;

    /// Warnings about the scene found while setting it up (boundary
    /// conditions that disagree at a node), one per line, from every rank.
    /// A collective call.
    virtual std::string
    warnings() const = 0;

    /// The support points and components of this rank's DoFs: for the
    /// rigid-body motions and the reactions' moments.
    virtual OwnedDofPlaces
    owned_dof_places() const = 0;

    /// The DoFs, on this rank's part of the mesh (on one rank, the whole
    /// mesh).
    virtual const DoFHandler<dim> &
    get_dof_handler() const = 0;

    /// The mesh as read, every cell on every rank: for setting up what
    /// spans the ranks (the runs of a layer's profile). Its cells are found
    /// in get_dof_handler()'s mesh by CellId (cell_of()).
    virtual const Triangulation<dim> &
    get_whole_mesh() const = 0;

    /// Whether this rank owns active cell @p c of get_whole_mesh().
    virtual bool
    owns_whole_cell(const unsigned int c) const = 0;

    virtual const Mapping<dim> &
    get_mapping() const = 0;

    /// Which rank owns each active cell (on one rank an empty owner list:
    /// every cell is rank 0's).
    virtual const CellPartition &
    get_partition() const = 0;

    /// The DoFs each rank owns, contiguous and in rank order (empty on one
    /// rank).
    virtual const std::vector<IndexSet> &
    get_owned_per_rank() const = 0;

    /// The serendipity lines only (to condense residuals for reactions).
    virtual const AffineConstraints<double> &
    get_element_constraints() const = 0;

    /// Displacement DoFs of the element's nodes per mode (for Q8 the
    /// eliminated centre nodes are not counted; prescribed DoFs are).
    virtual types::global_dof_index
    n_dofs() const = 0;

    /// Unknowns of the factorised systems, summed over the modes.
    virtual types::global_dof_index
    n_equations() const = 0;

    /**
     * Wall time of one forward/backward substitution with the stored
     * elastic factors of all modes (the median of ten, measured in
     * setup()): the floor of a constant-stiffness iteration's cost.
     */
    virtual double
    substitution_seconds() const = 0;

    /// With Solver/Linear solver = amg cg, the mean CG iterations of a
    /// solve so far (all modes); NaN with factors.
    virtual double
    linear_iterations_per_solve() const = 0;

    /// The linear algebra of the elastic stiffness and the tangents, and
    /// what the run reports of it.
    virtual const LinearSolverChoice &
    get_linear_solver() const = 0;

    /// @}
  };
} // namespace thinlayer

#endif
