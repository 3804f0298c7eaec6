#ifndef thinlayer_mesh_scene_h
#define thinlayer_mesh_scene_h

#include <deal.II/grid/tria.h>

#include <thinlayer/parameters/parameters.h>

#include <ostream>
#include <string>

namespace thinlayer
{
  using namespace dealii;

  /**
   * The mesh of a scene, from a gmsh geometry (.geo) meshed by gmsh with the
   * parameter file's geometry parameters, or from a gmsh mesh (.msh).
   * Physical surfaces become material ids and physical curves boundary ids
   * (in 3D: physical volumes and physical surfaces); a scene is then a
   * parameter file plus a .geo, with nothing about a particular case in
   * C++. @p dim is the mesh's: 2 for plane strain and Fourier kinematics,
   * 3 for Kinematics/Type = 3d.
   */
  template <int dim>
  class Scene
  {
  public:
    /**
     * Build the mesh and check it against the parameter file: every
     * material id of the mesh has a material, every material and boundary
     * section and every monitored boundary id exists in the mesh, every
     * cell is a convex quadrilateral (a hexahedron whose Jacobian is
     * positive at its corners), and there are at most Mesh/Maximum
     * cells. Throws InputError otherwise, before anything is written. A
     * .geo is meshed by gmsh (run_gmsh()), which reports on @p progress
     * while it runs.
     */
    Scene(const Parameters &parameters, std::ostream &progress);

    const Triangulation<dim> &
    triangulation() const;

    /**
     * The mesh, to be refined in place between the cycles of an adaptive
     * run; the analysis of the previous cycle must be gone, for it refers
     * to the cells.
     */
    Triangulation<dim> &
    triangulation_to_refine();

    /// The mesh in gmsh's format (kept with the results): as read, or once
    /// refined, the refined mesh's cells with their material and boundary
    /// ids.
    std::string
    mesh_text() const;

  private:
    Triangulation<dim> tria;
    std::string        msh;
    bool               refined = false;
  };

  /**
   * Checks that the ids of @p tria and of @p parameters match; the part of
   * Scene's work that also applies to meshes made in code.
   */
  template <int dim>
  void
  check_ids(const Parameters &parameters, const Triangulation<dim> &tria);
} // namespace thinlayer

#endif
