#ifndef thinlayer_analysis_h
#define thinlayer_analysis_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/quadrature_lib.h>
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
#include <thinlayer/parameters.h>

#include <map>
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
    /// Max over points of F / strength: NaN where no material can yield.
    double       max_yield_ratio;
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
   * A plane-strain analysis of one scene with constant stiffness: the
   * stiffness matrix is assembled and factorised once, and every load
   * factor is a forward/backward substitution. Loads and prescribed
   * displacements are linear in the load factor, so their unit vectors are
   * built once too.
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
     * Distribute DoFs, build constraints and loads, assemble and factorise
     * the stiffness. Throws InputError if the body is not restrained.
     */
    void
    setup();

    /**
     * Solve for the total load factor @p load_factor.
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

    /// Stress (3D, tension positive) at point @p q of active cell @p cell.
    const SymmetricTensor<2, 3> &
    stress(const unsigned int cell, const unsigned int q) const;

    unsigned int
    n_quadrature_points() const;

    /// Displacement DoFs of the element's nodes (for Q8 the eliminated
    /// centre nodes are not counted; prescribed DoFs are).
    types::global_dof_index
    n_dofs() const;

    /// Unknowns of the factorised system (n_dofs() less prescribed ones).
    types::global_dof_index
    n_equations() const;

  private:
    void
    assemble_stiffness();

    void
    update_stresses_and_internal_forces();

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

    std::map<types::material_id, SymmetricTensor<4, 3>> elasticity;

    SparsityPattern sparsity;
    /// Unconstrained stiffness, to lift prescribed displacements.
    SparseMatrix<double> stiffness;
    /// Condensed stiffness, factorised once.
    SparseMatrix<double> condensed_stiffness;
    SparseDirectUMFPACK  factorisation;

    /// Prescribed displacement and external load at unit load factor.
    Vector<double> unit_prescribed_displacement;
    Vector<double> unit_load;
    /// -K times unit_prescribed_displacement.
    Vector<double> unit_lift;

    double                             load_factor;
    Vector<double>                     solution;
    Vector<double>                     internal_forces;
    std::vector<SymmetricTensor<2, 3>> stresses;

    IndexSet reaction_dofs;
    IndexSet monitored_dofs;
  };
} // namespace thinlayer

#endif
