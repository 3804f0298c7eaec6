#ifndef thinlayer_analysis_analysis_h
#define thinlayer_analysis_analysis_h

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/quadrature_point_data.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <thinlayer/analysis/mode_state.h>
#include <thinlayer/discretisation/boundary_data.h>
#include <thinlayer/discretisation/kinematics.h>
#include <thinlayer/discretisation/strain_operator.h>
#include <thinlayer/elements/interface_elements.h>
#include <thinlayer/elements/point_loop.h>
#include <thinlayer/materials/material_law.h>
#include <thinlayer/materials/point_history.h>
#include <thinlayer/parameters/parameters.h>
#include <thinlayer/solution_methods/solution_method.h>

#include <map>
#include <memory>
#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /**
   * The norms of the out-of-balance force that the return-mapping methods
   * test for convergence (Analysis::evaluate_residual()).
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

  /**
   * The body of an elasto-plastic analysis of one scene, for any
   * Kinematics: plane strain (one mode, one station) or an axisymmetric
   * body under non-axisymmetric load (one mode per Fourier harmonic, the
   * material evaluated at circumferential stations). It holds what every
   * solution method works on, and nothing of any one method:
   *
   * - the modes (ModeState): constraints, the elastic stiffness assembled
   *   and factorised once, loads, displacements;
   * - the point history (one PointState per Gauss point and station), the
   *   strain-displacement cache (StrainOperator) and the point loop
   *   (PointLoop) over them;
   * - the residual evaluation of the return-mapping methods, and the
   *   acceptance of a load step's state.
   *
   * A load step is solved by the SolutionMethod that the Solver section
   * names (create_solution_method()). Its state, converged or not (a
   * failed step shows the mechanism), stays pending until the run accepts
   * it or rejects it to retry a smaller step (LoadStepping); the method is
   * told either way. For isotropic elasticity the modes decouple,
   * so a constant-stiffness iteration is one forward/backward substitution
   * per mode and one pass of the point loop.
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
     * boundaries) and the method and linear solver of its Solver section.
     */
    Analysis(const Parameters &parameters, const Triangulation<dim> &tria);

    ~Analysis();

    /**
     * Distribute DoFs, build constraints, loads and the point cache,
     * assemble and factorise the stiffness of every mode, and set up the
     * solution method. Throws InputError if the body is not restrained.
     */
    void
    setup();

    /**
     * An attempt at a load step from the accepted state to the total load
     * factor @p load_factor, with the solution method. Its state (converged
     * or not: a failed step shows the mechanism) is the current one, and
     * stays pending until accept_step() or reject_step(). A step whose
     * displacements are not finite has not converged
     * (StepResult::non_finite).
     */
    StepResult
    solve(const double load_factor);

    /// Make the pending state of the last solve() the accepted one.
    void
    accept_step();

    /// Return to the accepted state: the pending state is dropped.
    void
    reject_step();

    /// The load factor of the current state: of the last attempt while it
    /// is pending, else the accepted one.
    double
    load_factor() const;

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

    /// @name What the solution methods work on
    /// @{

    /// The load factor of the last accepted state.
    double
    accepted_load_factor() const;

    unsigned int
    n_modes() const;

    ModeState &
    mode(const unsigned int m);

    const ModeState &
    mode(const unsigned int m) const;

    /// All modes, for the point loop.
    std::vector<std::unique_ptr<ModeState>> &
    get_modes();

    const std::vector<std::unique_ptr<ModeState>> &
    get_modes() const;

    /**
     * The paper's point rule at every point and station for the modes'
     * step increments (PointLoop::viscoplastic_update()). Returns the
     * number of yielding points and stations.
     */
    unsigned int
    update_viscoplastic_stresses();

    /**
     * Stresses at every point and station by return mapping of the trial
     * stresses of the modes' step increments (with @p tangents, keeping
     * the consistent tangents there); then each mode's residual (condensed
     * onto the free DoFs) at load factor @p target, and the stress excess
     * in body_loads.
     */
    ResidualNorms
    evaluate_residual(const double                        target,
                      std::vector<SymmetricTensor<4, 3>> *tangents = nullptr);

    /**
     * Make the current stresses the converged ones, add the step's
     * increment to the solution and its plastic strain to the total, and
     * take @p load_factor as the accepted load factor: for a method that
     * accepts a converged part of a step (cut-back).
     */
    void
    accept_step(const double load_factor);

    /// The pseudo time step of the viscoplastic iterations.
    double
    viscoplastic_time_step() const;

    /// Whether every material's flow rule is associated (a symmetric
    /// consistent tangent).
    bool
    all_laws_associated() const;

    const StrainOperator &
    get_strain_operator() const;

    PointLoop &
    get_point_loop();

    /// The zero-thickness interface elements (none unless the scene has
    /// Interface curve sections).
    const InterfaceElements &
    get_interface_elements() const;

    /// Whether the current state is a pending step (solution plus
    /// step_increment) rather than the accepted one.
    bool
    is_pending() const;

    /// @}

    const Kinematics &
    get_kinematics() const;

    /// Warnings about the scene found while setting it up (boundary
    /// conditions that disagree at a node), one per line.
    std::string
    warnings() const;

    const DoFHandler<dim> &
    get_dof_handler() const;

    const Mapping<dim> &
    get_mapping() const;

    /// The serendipity lines only (to condense residuals for reactions).
    const AffineConstraints<double> &
    get_element_constraints() const;

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

  private:
    void
    setup_dofs_and_constraints();

    /// The laws of the materials, the point history and the strain cache.
    void
    setup_points();

    /// Prescribed displacements and loads at unit load factor.
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

    /// Right-hand sides at unit load factor, factorisations, and the time
    /// one substitution takes.
    void
    factorise_stiffness();

    const Parameters         &parameters;
    const Triangulation<dim> &tria;
    const Kinematics          kinematics;
    const FESystem<dim>       fe;
    const MappingQ<dim>       mapping;
    const QGauss<dim>         quadrature;
    DoFHandler<dim>           dof_handler;
    BoundaryData              boundary_data;

    AffineConstraints<double>               element_constraints;
    SparsityPattern                         sparsity;
    std::vector<std::unique_ptr<ModeState>> modes;

    std::map<types::material_id, std::unique_ptr<MaterialLaw>> laws;
    double                                                     time_step;

    /// The law of every active cell.
    std::vector<const MaterialLaw *> cell_law;
    StrainOperator                   strain_operator;
    CellDataStorage<typename Triangulation<dim>::cell_iterator, PointHistory>
                                history_storage;
    std::vector<PointHistory *> history;
    PointLoop                   point_loop;
    InterfaceElements           interface_elements;

    /// The component of every DoF.
    std::vector<unsigned int> dof_component;

    std::unique_ptr<SolutionMethod<dim>> method;

    double accepted_lambda;
    /// The load factor of the current state, and whether that state is a
    /// pending attempt.
    double current_lambda;
    bool   pending;
    double substitution_time;
  };


  // The accessors, inline: each returns a member or looks one up.

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
  inline unsigned int
  Analysis<dim>::n_modes() const
  {
    return modes.size();
  }


  template <int dim>
  inline ModeState &
  Analysis<dim>::mode(const unsigned int m)
  {
    return *modes[m];
  }


  template <int dim>
  inline const ModeState &
  Analysis<dim>::mode(const unsigned int m) const
  {
    return *modes[m];
  }


  template <int dim>
  inline std::vector<std::unique_ptr<ModeState>> &
  Analysis<dim>::get_modes()
  {
    return modes;
  }


  template <int dim>
  inline const std::vector<std::unique_ptr<ModeState>> &
  Analysis<dim>::get_modes() const
  {
    return modes;
  }


  template <int dim>
  inline double
  Analysis<dim>::viscoplastic_time_step() const
  {
    return time_step;
  }


  template <int dim>
  inline const StrainOperator &
  Analysis<dim>::get_strain_operator() const
  {
    return strain_operator;
  }


  template <int dim>
  inline PointLoop &
  Analysis<dim>::get_point_loop()
  {
    return point_loop;
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
  inline const Mapping<dim> &
  Analysis<dim>::get_mapping() const
  {
    return mapping;
  }


  template <int dim>
  inline const AffineConstraints<double> &
  Analysis<dim>::get_element_constraints() const
  {
    return element_constraints;
  }


  template <int dim>
  inline const Vector<double> &
  Analysis<dim>::get_solution(const unsigned int mode) const
  {
    return modes[mode]->solution;
  }


  template <int dim>
  inline const PointState &
  Analysis<dim>::point_state(const unsigned int cell,
                             const unsigned int q,
                             const unsigned int station) const
  {
    return history[cell * quadrature.size() + q]->stations[station];
  }


  template <int dim>
  inline const SymmetricTensor<2, 3> &
  Analysis<dim>::stress(const unsigned int cell, const unsigned int q) const
  {
    return point_state(cell, q).stress;
  }


  template <int dim>
  inline const MaterialLaw &
  Analysis<dim>::material_law(const unsigned int cell) const
  {
    return *cell_law[cell];
  }


  template <int dim>
  inline unsigned int
  Analysis<dim>::n_quadrature_points() const
  {
    return quadrature.size();
  }


  template <int dim>
  inline types::global_dof_index
  Analysis<dim>::n_dofs() const
  {
    return dof_handler.n_dofs() - element_constraints.n_constraints();
  }


  template <int dim>
  inline types::global_dof_index
  Analysis<dim>::n_equations() const
  {
    types::global_dof_index n = 0;
    for (const auto &mode : modes)
      n += dof_handler.n_dofs() - mode->constraints.n_constraints();
    return n;
  }


  template <int dim>
  inline double
  Analysis<dim>::substitution_seconds() const
  {
    return substitution_time;
  }


  template <int dim>
  inline const InterfaceElements &
  Analysis<dim>::get_interface_elements() const
  {
    return interface_elements;
  }


  template <int dim>
  inline bool
  Analysis<dim>::is_pending() const
  {
    return pending;
  }
} // namespace thinlayer

#endif
