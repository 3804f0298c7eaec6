#ifndef thinlayer_discretisation_boundary_data_h
#define thinlayer_discretisation_boundary_data_h

#include <deal.II/base/function_parser.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>

#include <thinlayer/discretisation/kinematics.h>
#include <thinlayer/discretisation/mode_vectors.h>
#include <thinlayer/parameters/parameters.h>

#include <map>
#include <memory>

namespace thinlayer
{
  using namespace dealii;

  /**
   * The boundary conditions of a scene at unit load factor: prescribed
   * displacements on chosen components, Cartesian tractions and normal
   * pressures, each a function expression per boundary id. Everything is
   * linear in the load factor, so the analysis builds the load vectors and
   * the prescribed-displacement vectors once and scales them.
   *
   * The expressions are functions of (x, y) in plane strain, of (x, y, z)
   * on a 3D mesh. With Fourier kinematics they are functions of
   * (r, z, theta) giving Cartesian components; each mode gets its share by
   * integration over theta, int f . T(n theta) r dtheta for loads, and the
   * amplitude (1/c) int u T(n theta) dtheta for prescribed displacements.
   */
  class BoundaryData
  {
  public:
    /**
     * The conditions of the @p boundaries sections of @p parameter_file,
     * whose expressions may use the geometry parameters @p constants. An
     * expression that gives a value that is not a finite number where it
     * is evaluated on the boundary is an InputError naming its entry and
     * the point.
     */
    BoundaryData(
      const std::map<types::boundary_id, BoundaryParameters> &boundaries,
      const std::map<std::string, double>                    &constants,
      const Kinematics                                       &kinematics,
      const std::string                                      &parameter_file);

    /**
     * Add homogeneous constraints for every constrained component (the
     * same for every mode).
     */
    template <int dim>
    void
    make_zero_constraints(const DoFHandler<dim>     &dof_handler,
                          AffineConstraints<double> &constraints) const;

    /**
     * The prescribed displacement of mode @p mode at unit load factor, DoF
     * by DoF. Where boundary ids share a node (a corner), the lowest id's
     * value wins.
     */
    template <int dim>
    std::map<types::global_dof_index, double>
    prescribed_values(const Mapping<dim>    &mapping,
                      const DoFHandler<dim> &dof_handler,
                      const unsigned int     mode) const;

    /**
     * The external load vector of mode @p mode, tractions and pressures at
     * unit load factor (unconstrained): each rank integrates over the
     * faces of its own cells, @p load (laid out with the DoFs of those
     * cells as ghosts) sums them on the DoFs' owners. A collective call.
     */
    template <int dim>
    void
    assemble_load_vector(const Mapping<dim>    &mapping,
                         const DoFHandler<dim> &dof_handler,
                         const unsigned int     mode,
                         ModeVector            &load) const;

    /// Whether any boundary prescribes a displacement component.
    bool
    has_constraints() const;

    /**
     * What prescribed_values() found worth a warning: two boundary ids
     * that prescribe different displacements at a shared node (the lowest
     * id wins, as documented, but the other's value is lost).
     */
    const std::vector<std::string> &
    get_warnings() const;

  private:
    struct Condition
    {
      ComponentMask                      constrained;
      std::unique_ptr<FunctionParser<3>> displacement;
      std::unique_ptr<FunctionParser<3>> traction;
      std::unique_ptr<FunctionParser<3>> pressure;
      bool                               loaded;
      /// "Boundary <id>", for messages.
      std::string section;
    };

    /**
     * The Cartesian vector of @p f at (x, y) in plane strain, or its
     * cylindrical components (r, z, theta) at (r, z, theta) for Fourier;
     * @p entry ("Boundary 2/Traction") names @p f in an error.
     */
    template <int dim>
    Tensor<1, 3>
    evaluate(const FunctionParser<3> &f,
             const Point<dim>        &x,
             const double             theta,
             const std::string       &entry) const;

    /// The pressure of @p c at (x, y) (and theta), checked like evaluate().
    template <int dim>
    double
    pressure(const Condition &c, const Point<dim> &x, const double theta) const;

    /// An InputError unless every value of @p v is a finite number.
    template <int dim>
    void
    check_finite(const Vector<double> &v,
                 const Point<dim>     &x,
                 const double          theta,
                 const std::string    &entry) const;

    /// Add a warning for @p dof, where @p winner's value replaced
    /// @p loser's.
    template <int dim>
    void
    note_conflict(const Mapping<dim>           &mapping,
                  const DoFHandler<dim>        &dof_handler,
                  const types::global_dof_index dof,
                  const types::boundary_id      winner,
                  const types::boundary_id      loser) const;

    const Kinematics                       &kinematics;
    const std::string                       parameter_file;
    mutable std::vector<std::string>        warnings;
    std::map<types::boundary_id, Condition> conditions;
  };
} // namespace thinlayer

#endif
