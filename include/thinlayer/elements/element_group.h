#ifndef thinlayer_elements_element_group_h
#define thinlayer_elements_element_group_h

#include <deal.II/base/quadrature.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>

#include <thinlayer/discretisation/kinematics.h>
#include <thinlayer/discretisation/mode_vectors.h>
#include <thinlayer/elements/interface_values.h>
#include <thinlayer/mesh/interface_pairing.h>
#include <thinlayer/parallel/cell_partition.h>
#include <thinlayer/parameters/loading_sections.h>

#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace thinlayer
{

  using namespace dealii;

  struct Parameters;

  /**
   * What a check of the current state finds over the points of the
   * element groups: whether every stress (or traction) and yield ratio is
   * a finite number, and the largest yield ratio (NaN where no law can
   * yield).
   */
  struct StateCheck
  {
    bool   finite          = true;
    double max_yield_ratio = std::numeric_limits<double>::quiet_NaN();

    /// Take the yield ratio @p ratio of one point into the maximum.
    void
    add_yield_ratio(const double ratio)
    {
      max_yield_ratio =
        std::isnan(max_yield_ratio) ? ratio : std::max(max_yield_ratio, ratio);
    }
  };


  /// What receives the matrix of a cell or element (elastic, or Newton's
  /// tangent): its DoFs and the matrix.
  using CellMatrixSink =
    std::function<void(const std::vector<types::global_dof_index> &,
                       const FullMatrix<double> &)>;

  /// What receives the DoFs of a cell or element, for a sparsity pattern.
  using DofSink =
    std::function<void(const std::vector<types::global_dof_index> &)>;

  /// A profile along a line of an element group, with the name of its
  /// output files (e.g. "interface-3").
  struct NamedProfile
  {
    std::string name;
    Profile     profile;
    /// Whether it holds the raw values at the integration points, which
    /// the output writes only on request (Output/Gauss-point profiles).
    bool gauss_points = false;
  };


  /**
   * A family of elements that takes part in the analysis: the continuum
   * cells (ContinuumCells), zero-thickness interface elements
   * (InterfaceElements). The Analysis holds a list of groups and does to
   * each what it does to the body, in the order of the list: it builds the
   * sparsity, assembles the elastic stiffness, runs the point rules of the
   * solution methods, accepts or rejects a step's state, checks it, and
   * assembles Newton's tangent. What a group adds to a vector it adds to
   * what is there, so the sums come out in the same order on every run.
   *
   * Every group works on the DoFs of the analysis's one DoFHandler, one
   * copy per mode (ModeVectors), and holds its own point states and laws.
   *
   * On many ranks (thinlayer::mpi) a group is built for the cells and
   * elements the partition gives this rank (an interface element goes
   * with the cell on its plus side): its sparsity, elastic matrices, point
   * states and rules, internal forces, state check and Newton's tangent
   * are theirs alone. What they add to vectors and matrices is summed or
   * distributed over the ranks by the Analysis, which also combines the
   * ranks' state checks; what reads the states of other ranks' points (a
   * profile, the fields) combines every rank's share of them.
   *
   * To add a family: derive from this class in a new file pair under
   * elements/, and construct it in create_element_groups().
   */
  class ElementGroup
  {
  public:
    virtual ~ElementGroup() = default;

    /// @name The elastic system
    /// @{

    /// Add the couplings of the group's DoFs (of the cells and elements
    /// this rank owns) to @p dsp, with the fill-in of @p constraints.
    virtual void
    add_sparsity(DynamicSparsityPattern          &dsp,
                 const AffineConstraints<double> &constraints) const = 0;

    /// Append the DoFs of every cell or element this rank owns to @p dofs
    /// (in any order, repeated): the entries of the mode vectors the
    /// group reads and adds to, which a rank holds as its own or as ghosts.
    virtual void
    add_dofs(std::vector<types::global_dof_index> &dofs) const = 0;

    /// Hand the elastic matrix of mode @p m of every cell or element this
    /// rank owns, in order, to @p add with its DoFs: the analysis puts
    /// them where its linear system wants them.
    virtual void
    assemble_elastic(const unsigned int m, const CellMatrixSink &add) const = 0;

    /// Whether every flow rule of the group is associated (its consistent
    /// tangent symmetric).
    virtual bool
    all_associated() const = 0;

    /// @}
    /// @name The point rules
    /// @{

    /**
     * The paper's viscoplastic rule at every point and station for the
     * step's displacement increments @p step_increment: the stresses of
     * the increment less the step's viscoplastic strain, and where F > 0 a
     * new viscoplastic strain, whose body load is added to
     * @p body_load_change. Returns the number of yielding points and
     * stations.
     */
    virtual unsigned int
    viscoplastic_update(const ModeVectors &step_increment,
                        ModeVectors       &body_load_change) = 0;

    /**
     * The return mapping of the elastic trial stress of @p step_increment
     * at every point and station; the nodal forces of the stresses are
     * added to @p internal_forces, those of the stress excess (trial less
     * returned) to @p stress_excess. With @p with_tangents, the consistent
     * tangents are kept for add_coupled_tangent(). Returns the number of
     * yielding points and stations.
     */
    virtual unsigned int
    return_mapping_update(const ModeVectors &step_increment,
                          const bool         with_tangents,
                          ModeVectors       &internal_forces,
                          ModeVectors       &stress_excess) = 0;

    /// Add the nodal forces of the current stresses of this rank's cells
    /// or elements (all on one rank) to @p internal_forces.
    virtual void
    add_internal_forces(ModeVectors &internal_forces) const = 0;

    /// Make the current stresses the converged ones, and the step's
    /// plastic strain part of the total.
    virtual void
    accept() = 0;

    /// Return to the converged stresses: the step's state is dropped.
    virtual void
    reject() = 0;

    /**
     * Divide the strengths of the group's parts that @p reduced names by
     * @p factor: c / factor and tan(phi) / factor, the dilation angle at
     * most the reduced friction angle (strength reduction; factor 1
     * restores them). Nothing by default.
     */
    virtual void
    reduce_strength(const StrengthReductionParameters &reduced,
                    const double                       factor);

    /// Take the current state's finiteness and yield ratios (of this
    /// rank's points) into @p check.
    virtual void
    check_state(StateCheck &check) const = 0;

    /// @}
    /// @name Newton's coupled tangent (DoF m * n_dofs + i for mode m)
    /// @{

    /// Hand the DoFs of all modes of every cell or element this rank owns,
    /// in order, to @p add, and allocate what add_coupled_tangent() works
    /// in.
    virtual void
    add_coupled_sparsity(const DofSink &add) = 0;

    /// Hand the tangent matrix of the last return_mapping_update() with
    /// tangents of every cell or element this rank owns, in order, with
    /// its DoFs of all modes, to @p add: the solution method puts them
    /// where its coupled system wants them.
    virtual void
    add_coupled_tangent(const CellMatrixSink &add) = 0;

    /// @}

    /**
     * The profiles the group writes along its lines, of the state with
     * displacements @p solution plus, where @p pending, the step's
     * @p step_increment. On many ranks every rank calls it, and receives
     * every sample's values from the rank that holds its points. None by
     * default: the cells' fields are written whole.
     */
    virtual std::vector<NamedProfile>
    profiles(const ModeVectors &solution,
             const ModeVectors &step_increment,
             const bool         pending) const;
  };


  /**
   * The element groups of the scene that @p parameters describe, on the
   * DoFs of @p dof_handler: the continuum cells first (with @p quadrature),
   * then the interface elements along the Interface sections, if
   * any; each with the points of the cells that @p partition gives this
   * rank (every cell where it names no owners). The interface elements
   * join @p facing_sides, found on the whole mesh, whose cells
   * @p whole_partition gives ranks. The one place that knows every element
   * family. Throws InputError (naming the parameter file and its section)
   * where a group cannot be built as the parameters ask.
   */
  template <int dim>
  std::vector<std::unique_ptr<ElementGroup>>
  create_element_groups(const Parameters                    &parameters,
                        const DoFHandler<dim>               &dof_handler,
                        const Mapping<dim>                  &mapping,
                        const Quadrature<dim>               &quadrature,
                        const Kinematics                    &kinematics,
                        const CellPartition                 &partition,
                        const std::vector<FacingSides<dim>> &facing_sides,
                        const CellPartition                 &whole_partition);
} // namespace thinlayer

#endif
