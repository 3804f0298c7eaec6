#ifndef thinlayer_elements_interface_elements_h
#define thinlayer_elements_interface_elements_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>

#include <thinlayer/discretisation/kinematics.h>
#include <thinlayer/elements/element_group.h>
#include <thinlayer/elements/interface_geometry.h>
#include <thinlayer/elements/interface_values.h>
#include <thinlayer/elements/traction_recovery.h>
#include <thinlayer/materials/interface_law.h>
#include <thinlayer/mesh/interface_pairing.h>
#include <thinlayer/parameters/parameters.h>

#include <array>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /// The state of one interface point at one station: tractions and
  /// relative displacements in the local frame (s, n, t).
  struct InterfacePointState
  {
    Tensor<1, 3> converged_traction;
    Tensor<1, 3> traction;
    Tensor<1, 3> plastic_jump;
    Tensor<1, 3> step_plastic_jump;
    Tensor<1, 3> pending_plastic_jump;
    bool         yielding = false;
  };


  /**
   * Zero-thickness (Goodman-type) interface elements along physical
   * curves of a 2D mesh or surfaces of a 3D one. The mesh is split along
   * each interface when read (split_along_curves()), so it shows as pairs
   * of facing cell sides, boundary faces with the interface's id; an
   * element pairs two facing sides (6 nodes of the quadratic field on a
   * curve, 16 on a surface: two 8-node faces) and couples their DoFs
   * through an InterfaceLaw of the relative displacement
   *   delta = u(+ side) - u(- side)
   * in the local frame (s, n, t):
   * - on a curve s runs along it (runs from the lower-left end, as
   *   LayerProfile), n = s turned a quarter turn anticlockwise, t out of
   *   the plane (theta in Fourier scenes);
   * - on a surface n is the upward normal (upward()), s = t1 the first
   *   tangent (first_tangent()), t = t2 = t1 x n, at each point: the two
   *   shears slip together, on sqrt(t_s^2 + t_t^2), as the law has it.
   * The integral over the side uses Gauss or Lobatto points (per
   * direction of a face), weighted by r in Fourier scenes.
   *
   * As an ElementGroup the elements take part in everything the cells do:
   * the elastic stiffness of every mode, the viscoplastic point rule, the
   * return mapping with internal forces and stress excess, the acceptance
   * and rejection of a step, Newton's tangent, and a profile per curve.
   * Station by station as the point loop: the relative displacement of the
   * harmonics summed at each station (u_r, u_z with T1, u_theta with T2), the
   * tractions projected back with the station weights.
   */
  template <int dim>
  class InterfaceElements : public ElementGroup
  {
  public:
    /**
     * One element for each of @p pairs (pair_facing_sides() on the whole
     * mesh, whose cells @p partition gives ranks); the elements whose plus
     * side is a cell of this rank (all, where @p partition names no
     * owners) are this rank's to run, on their cells as @p dof_handler
     * holds them (found by CellId: it may hold only part of the mesh).
     * Throws InputError (naming @p parameter_file and the curve's section)
     * where an interface stiffness exceeds max_stiffness_ratio E / h of the
     * cells beside it (@p materials).
     */
    void
    reinit(
      const std::vector<FacingSides<dim>> &pairs,
      const DoFHandler<dim>               &dof_handler,
      const Mapping<dim>                  &mapping,
      const Kinematics                    &kinematics,
      const std::map<types::boundary_id, InterfaceElementParameters> &curves,
      const std::map<types::material_id, MaterialParameters>         &materials,
      const CellPartition                                            &partition,
      const std::string &parameter_file);

    /// The laws of the curves of @p reduced (Interfaces) with their
    /// adhesion and tan(phi) divided by @p factor, the dilation angle at
    /// most the reduced friction angle; the other curves' as given.
    void
    reduce_strength(const StrengthReductionParameters &reduced,
                    const double                       factor) override;

    /// What set_initial_tractions() found at this rank's points, each with
    /// the place and the curve of the worst point.
    struct InitialTractions
    {
      /// The largest difference between the tractions the two sides'
      /// stresses put on the interface, over the larger of the two.
      double                            mismatch = 0;
      dealii::Point<dim>                mismatch_at;
      types::boundary_id                mismatch_curve     = 0;
      std::array<types::material_id, 2> mismatch_materials = {{0, 0}};
      /// The largest yield function of a law that can yield, over the
      /// traction's magnitude.
      double             yield_ratio = -std::numeric_limits<double>::infinity();
      dealii::Point<dim> yield_at;
      types::boundary_id yield_curve = 0;
    };

    /**
     * Start every point of this rank's elements from the traction of the
     * initial stress field @p initial (at a point, in a cell of a material;
     * as ContinuumCells::set_initial_stresses()): sigma n in the local
     * frame, the mean of the two sides' (their materials' stresses), with
     * nothing slipped. Only where the two sides agree is the field in
     * equilibrium across the interface, and only an admissible traction is
     * a state of the law: both are measured for the caller to judge.
     */
    InitialTractions
    set_initial_tractions(
      const std::function<SymmetricTensor<2, 3>(const dealii::Point<dim> &,
                                                types::material_id)> &initial);

    /**
     * The largest interface stiffness accepted, in units of E / h (E the
     * smaller Young's modulus of the two cells beside an element, h its
     * side's length, or the square root of its face's area). Stiffer interfaces
     * add no accuracy (the interface's compliance is already a millionth of the
     * cells'), but the tractions, k times a jump that is the difference of two
     * nearly equal displacements, lose their digits to round-off: in
     * benchmarks/interfaces.py, Cases 2 and 3 at 1.25e6 E/h and above end
     * in "collapses" at a tenth of the sliding load, or do not converge.
     */
    static constexpr double max_stiffness_ratio = 1e6;

    bool
    empty() const;

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

    /// Every traction, and every yield ratio of a law that can yield.
    void
    check_state(StateCheck &check) const override;

    void
    add_coupled_sparsity(const DofSink &add) override;

    /// With the tangents of the last return_mapping_update() with
    /// tangents. Uses work space sized in reinit(): it runs at every
    /// factorisation.
    void
    add_coupled_tangent(const CellMatrixSink &add) override;

    /// Two profiles per interface: "interface-<id>", its tractions
    /// recovered at the nodes (TractionRecovery), and
    /// "interface-<id>-gauss", the values at the integration points.
    std::vector<NamedProfile>
    profiles(const ModeVectors &solution,
             const ModeVectors &step_increment,
             const bool         pending) const override;
    /// @}

    /// The profile of curve @p curve, its values those of the integration
    /// points: with the displacements @p solution plus, where @p pending,
    /// the step's @p step_increment.
    Profile
    profile(const types::boundary_id curve,
            const ModeVectors       &solution,
            const ModeVectors       &step_increment,
            const bool               pending) const;

  private:
    /// One term of the jump operator: the side-signed shape value of a
    /// local DoF of the element.
    struct Entry
    {
      unsigned int local_dof;
      unsigned int component;
      double       value;
    };

    struct IntegrationPoint
    {
      unsigned int       element;
      types::boundary_id curve;
      unsigned int       run;
      double             arc_length;
      dealii::Point<dim> position;
      /// The local axes (s, n, t) as rows, in the displacement's
      /// components: (x, y, theta or z) on a curve, (x, y, z) on a surface.
      Tensor<2, 3> frame;
      /// Quadrature weight times side length or face area, times r for
      /// Fourier.
      double             weight;
      std::vector<Entry> entries;
      /// On a surface: the patch of the face the point stands for (its
      /// weight's share), for the profile's VTU.
      std::array<dealii::Point<3>, 4> patch;
    };

    struct Element
    {
      const InterfaceLaw *law;
      /// The curve the element lies on: whose law it has.
      types::boundary_id curve;
      /// The active cell on the plus side: the element's rank is its.
      unsigned int plus_cell;
      /// The materials of the plus and the minus side.
      std::array<types::material_id, 2>    materials;
      std::vector<types::global_dof_index> dofs;
      /// The same DoFs of every mode in Newton's coupled numbering.
      std::vector<types::global_dof_index> coupled_dofs;
    };

    /// The jump at station @p s in the local frame, of the modes'
    /// vectors @p vectors at the element's DoFs. Allocates nothing: it runs
    /// in every iteration.
    Tensor<1, 3>
    local_jump(const IntegrationPoint &point,
               const unsigned int      s,
               const ModeVectors      &vectors) const;

    /// Add the nodal forces of local traction @p traction at point
    /// @p point and station @p s, times the station and point weights, to
    /// every mode's vector of @p target.
    void
    add_forces(const IntegrationPoint &point,
               const unsigned int      s,
               const Tensor<1, 3>     &traction,
               ModeVectors            &target) const;

    /// An InputError unless the stiffnesses of @p curve are at most
    /// max_stiffness_ratio E / h for the cells of @p pair.
    static void
    check_stiffness(
      const FacingSides<dim>                                 &pair,
      const InterfaceElementParameters                       &curve,
      const std::map<types::material_id, MaterialParameters> &materials,
      const std::string                                      &parameter_file);

    /// The element of @p pair: its integration points along the side,
    /// each with the jump operator over the two cells' DoFs where it is
    /// this rank's (@p own), its points' places alone where not.
    void
    add_element(const FacingSides<dim>           &pair,
                const InterfaceElementParameters &curve,
                const bool                        own,
                const DoFHandler<dim>            &dof_handler,
                const Mapping<dim>               &mapping);

    /**
     * Run @p rule(point, station, law, state, jump, point_station) at every
     * point and station, with the jump of the modes' step increments; the
     * sum of what it returns (its yielding count).
     */
    template <typename Rule>
    unsigned int
    for_each_point(const ModeVectors &step_increment, const Rule &rule);

    /// Add the element of @p pair, whose points lie at @p places, to its
    /// curve's traction recovery.
    void
    add_to_recovery(const FacingSides<dim>                      &pair,
                    const std::vector<InterfacePointPlace<dim>> &places);

    /// The 3 x (modes x element DoFs) map from the element's DoFs of all
    /// modes to the local jump at point @p point and station @p s.
    void
    jump_operator(const IntegrationPoint &point,
                  const unsigned int      s,
                  FullMatrix<double>     &G) const;

    const Kinematics *kinematics = nullptr;
    /// The curves' parameters (reinit()'s), for the laws strength
    /// reduction makes anew.
    const std::map<types::boundary_id, InterfaceElementParameters> *curves =
      nullptr;
    std::map<types::boundary_id, std::unique_ptr<InterfaceLaw>> laws;
    std::vector<Element>                                        elements;
    std::vector<IntegrationPoint>                               points;
    /// Per curve: its tractions' recovery at the nodes.
    std::map<types::boundary_id, TractionRecovery> recoveries;
    /// Point-major: points[p] at station s is states[p * n_stations + s].
    /// Every point has a slot (the points lie along curves, a small share
    /// of the body's), but only this rank's are ever computed or read.
    std::vector<InterfacePointState> states;
    std::vector<Tensor<2, 3>>        tangents;
    /// The rank of every element and point (empty: all this rank's), and
    /// this rank.
    std::vector<unsigned int> element_owner, point_owner;
    unsigned int              rank = 0;

    /// Whether this rank runs element @p k (every one on one rank).
    bool
    owns_element(const unsigned int k) const
    {
      return element_owner.empty() || element_owner[k] == rank;
    }

    /// Whether this rank runs integration point @p p.
    bool
    owns_point(const unsigned int p) const
    {
      return point_owner.empty() || point_owner[p] == rank;
    }
    /// Work space of add_coupled_tangent(): a matrix per element, and the
    /// jump operator of one point.
    mutable std::vector<FullMatrix<double>> coupled_matrices;
    mutable FullMatrix<double>              jump_scratch;
  };
} // namespace thinlayer

#endif
