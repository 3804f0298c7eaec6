#ifndef thinlayer_analysis_h
#define thinlayer_analysis_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/quadrature_point_data.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <thinlayer/boundary_data.h>
#include <thinlayer/material_law.h>
#include <thinlayer/parameters.h>
#include <thinlayer/point_history.h>

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
    /// Max over points of F / strength after the step: NaN where no
    /// material can yield.
    double max_yield_ratio;
    /// Points (and stations) with F > 0 at the end of the step.
    unsigned int plastic_points;
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
   * A plane-strain elasto-plastic analysis of one scene with the paper's
   * constant-stiffness viscoplastic iterations: the elastic stiffness is
   * assembled and factorised once; each iteration is one forward/backward
   * substitution and one pass over the Gauss points, whose
   * strain-displacement data are computed once and cached (the mesh does
   * not move).
   *
   * A load step from load factor lambda_0 to lambda solves, with body
   * loads b = 0 at its start,
   *   K du = (lambda - lambda_0) f + b,
   * then at every point d eps = B du - eps_vp, sigma = sigma_0 + D d eps; where
   * F(sigma) > 0 it adds the viscoplastic strain dt F dQ/dsigma to eps_vp
   * and int B^T D (that strain) to b, until b (or du) stops changing to
   * within the tolerance. A step that reaches the iteration limit has
   * failed: that is how collapse shows.
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
     * assemble and factorise the stiffness. Throws InputError if the body
     * is not restrained.
     */
    void
    setup();

    /**
     * One load step, to the total load factor @p load_factor.
     */
    StepResult
    solve(const double load_factor);

    /// The load monitor (load factor or reaction sum, times its scale).
    double
    load() const;

    /// The displacement monitor, times its scale.
    DisplacementMeasure
    displacement() const;

    const DoFHandler<dim> &
    get_dof_handler() const;

    const Mapping<dim> &
    get_mapping() const;

    const Vector<double> &
    get_solution() const;

    /// The displacement increment of the last load step: at a failed step,
    /// the incipient mechanism.
    const Vector<double> &
    get_step_increment() const;

    /// The state at Gauss point @p q of active cell @p cell (station 0).
    const PointState &
    point_state(const unsigned int cell, const unsigned int q) const;

    /// Stress (3D, tension positive) at point @p q of active cell @p cell.
    const SymmetricTensor<2, 3> &
    stress(const unsigned int cell, const unsigned int q) const;

    /// The material law of active cell @p cell.
    const MaterialLaw &
    material_law(const unsigned int cell) const;

    unsigned int
    n_quadrature_points() const;

    /// Displacement DoFs of the element's nodes (for Q8 the eliminated
    /// centre nodes are not counted; prescribed DoFs are).
    types::global_dof_index
    n_dofs() const;

    /// Unknowns of the factorised system (n_dofs() less prescribed ones).
    types::global_dof_index
    n_equations() const;

    /// The pseudo time step of the viscoplastic iterations.
    double
    viscoplastic_time_step() const;

  private:
    void
    build_point_cache();

    void
    assemble_stiffness();

    /**
     * Solve K du = rhs for the step's displacement increment, with the
     * prescribed displacements of a load-factor increment @p dlambda.
     */
    void
    solve_increment(const double          dlambda,
                    const Vector<double> &body_loads,
                    Vector<double>       &increment) const;

    /**
     * Stresses for the displacement increment @p increment; adds the new
     * viscoplastic body loads of yielding points to @p body_load_change.
     * Returns the number of yielding points.
     */
    unsigned int
    update_stresses(const Vector<double> &increment,
                    Vector<double>       &body_load_change);

    void
    update_internal_forces();

    const Parameters         &parameters;
    const Triangulation<dim> &tria;
    const FESystem<dim>       fe;
    const MappingQ<dim>       mapping;
    const QGauss<dim>         quadrature;
    DoFHandler<dim>           dof_handler;
    BoundaryData<dim>         boundary_data;

    /// The serendipity lines only (to condense residuals for reactions).
    AffineConstraints<double> element_constraints;
    /// Serendipity plus homogeneous Dirichlet lines: the solve's space.
    AffineConstraints<double> constraints;

    std::map<types::material_id, std::unique_ptr<MaterialLaw>> laws;
    double                                                     time_step;

    /**
     * Per active cell: its law and DoFs; per Gauss point: JxW and the 3D
     * strain of every shape function (B). Flat arrays, indexed by active
     * cell index, so the point loop touches no FEValues and no map.
     */
    std::vector<const MaterialLaw *>     cell_law;
    std::vector<types::global_dof_index> cell_dofs;
    std::vector<double>                  point_JxW;
    std::vector<SymmetricTensor<2, 3>>   shape_strains;

    CellDataStorage<typename Triangulation<dim>::cell_iterator, PointHistory>
                                history_storage;
    std::vector<PointHistory *> history;

    SparsityPattern sparsity;
    /// Unconstrained stiffness, to lift prescribed displacements.
    SparseMatrix<double> stiffness;
    /// Condensed stiffness, factorised once.
    SparseMatrix<double> condensed_stiffness;
    SparseDirectUMFPACK  factorisation;

    /// Prescribed displacement and external load at unit load factor.
    Vector<double> unit_prescribed_displacement;
    Vector<double> unit_load;
    /// f - K times unit_prescribed_displacement: the right-hand side of a
    /// unit load factor.
    Vector<double> unit_rhs;

    double         load_factor;
    Vector<double> solution;
    Vector<double> step_increment;
    Vector<double> internal_forces;

    IndexSet reaction_dofs;
    IndexSet monitored_dofs;
  };
} // namespace thinlayer

#endif
