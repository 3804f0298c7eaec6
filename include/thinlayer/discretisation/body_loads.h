#ifndef thinlayer_discretisation_body_loads_h
#define thinlayer_discretisation_body_loads_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <thinlayer/discretisation/kinematics.h>
#include <thinlayer/discretisation/mode_vectors.h>

#include <map>
#include <set>

namespace thinlayer
{
  using namespace dealii;

  /**
   * Add the weight of the body at unit load factor to mode @p m's load
   * vector @p load: the consistent nodal forces int N_i b dV of the body
   * force b = -gamma e_y, gamma the unit weight of each cell's material
   * (@p unit_weights by material id; none: weightless). Every mesh of the
   * project has y up: the vertical of a plane-strain section, the axis of
   * a Fourier body's r-z plane, the axis of a 3D body. A Fourier body's
   * weight is axisymmetric: it loads the symmetric harmonic 0 only, with
   * the circle integral and the volume element r dA of the boundary loads
   * (BoundaryData::assemble_load_vector()), so that both are scaled alike.
   * Adds this rank's cells, then sums over ranks (compress).
   */
  template <int dim>
  void
  add_weight(const Mapping<dim>                         &mapping,
             const DoFHandler<dim>                      &dof_handler,
             const Kinematics                           &kinematics,
             const std::map<types::material_id, double> &unit_weights,
             const unsigned int                          m,
             ModeVector                                 &load);

  /// The outward unit normal of boundary face @p f of @p cell, from its
  /// vertices (the cells are straight-sided: gmsh's first-order meshes).
  template <int dim>
  Tensor<1, dim>
  outward_normal(const typename Triangulation<dim>::cell_iterator &cell,
                 const unsigned int                                f);

  /**
   * The level of the ground surface of @p mesh: the highest y of the
   * boundary faces that face upward (outward normal with a positive y
   * component). Where the mesh is split over ranks, @p mesh is the mesh as
   * read, which every rank holds whole.
   */
  template <int dim>
  double
  ground_level(const Triangulation<dim> &mesh);

  /**
   * Add a pressure @p pressure on the ground surface at unit load factor
   * to mode @p m's load vector @p load: the consistent nodal forces of the
   * traction -p e_y on the boundary faces that face straight up at the
   * height @p level (ground_level()), but for those of the boundaries
   * @p held (whose vertical displacement is prescribed: a footing pushed
   * into the ground carries its own load, not the surcharge). Axisymmetric
   * in a Fourier body, like the weight (add_weight()). Adds this rank's
   * cells, then sums over ranks (compress).
   */
  template <int dim>
  void
  add_ground_pressure(const Mapping<dim>                 &mapping,
                      const DoFHandler<dim>              &dof_handler,
                      const Kinematics                   &kinematics,
                      const double                        level,
                      const double                        pressure,
                      const std::set<types::boundary_id> &held,
                      const unsigned int                  m,
                      ModeVector                         &load);
} // namespace thinlayer

#endif
