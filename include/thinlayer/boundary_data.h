#ifndef thinlayer_boundary_data_h
#define thinlayer_boundary_data_h

#include <deal.II/base/function_parser.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>

#include <thinlayer/parameters.h>

#include <map>
#include <memory>

namespace thinlayer
{
  using namespace dealii;

  /**
   * The boundary conditions of a scene at unit load factor: prescribed
   * displacements on chosen components, Cartesian tractions and normal
   * pressures, each a function expression per boundary id. Everything is
   * linear in the load factor, so the analysis builds the load vector and
   * the prescribed-displacement vector once and scales them.
   */
  template <int dim>
  class BoundaryData
  {
  public:
    explicit BoundaryData(const Parameters &parameters);

    /**
     * Add homogeneous constraints for every constrained component (the
     * constant-stiffness matrix is built with these).
     */
    void
    make_zero_constraints(const DoFHandler<dim>     &dof_handler,
                          AffineConstraints<double> &constraints) const;

    /**
     * The prescribed displacement at unit load factor, DoF by DoF. Where
     * boundary ids share a node (a corner), the lowest id's value wins.
     */
    std::map<types::global_dof_index, double>
    prescribed_values(const Mapping<dim>    &mapping,
                      const DoFHandler<dim> &dof_handler) const;

    /**
     * The external load vector of tractions and pressures at unit load
     * factor (unconstrained).
     */
    void
    assemble_load_vector(const Mapping<dim>    &mapping,
                         const DoFHandler<dim> &dof_handler,
                         Vector<double>        &load) const;

    /// Whether any boundary prescribes a displacement component.
    bool
    has_constraints() const;

  private:
    struct Condition
    {
      ComponentMask                        constrained;
      std::unique_ptr<FunctionParser<dim>> displacement;
      std::unique_ptr<FunctionParser<dim>> traction;
      std::unique_ptr<FunctionParser<dim>> pressure;
      bool                                 loaded;
    };
    std::map<types::boundary_id, Condition> conditions;
  };
} // namespace thinlayer

#endif
