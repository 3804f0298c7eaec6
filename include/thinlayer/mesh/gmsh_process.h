#ifndef thinlayer_mesh_gmsh_process_h
#define thinlayer_mesh_gmsh_process_h

#include <map>
#include <ostream>
#include <string>

namespace thinlayer
{
  /// What meshing a .geo with gmsh needs to know.
  struct GmshJob
  {
    /// The .geo file.
    std::string geometry;
    /// Its DefineConstant[] parameters, set with -setnumber.
    std::map<std::string, double> parameters;
    /// Mesh/Maximum cells: gmsh is stopped once its memory shows it is
    /// making far more (see run_gmsh()).
    unsigned int max_cells;
    /// For messages: the parameter file the job came from.
    std::string parameter_file;
    /// The dimension to mesh: 2 (surfaces) or 3 (volumes).
    unsigned int dimension = 2;
    /// Mesh/Meshing time limit: seconds gmsh may run.
    double time_limit = 600;
  };

  /**
   * Mesh @p job with the gmsh program, as a child process this program
   * owns, and return the mesh in gmsh's 2.2 format.
   *
   * The child runs in a process group of its own, with its output in a
   * temporary directory that is removed on every way out. While it runs,
   * @p progress gets a line every five seconds. The child is killed (its
   * whole group) when
   * - SIGINT or SIGTERM asks the run to stop (an Interrupted exception
   *   follows),
   * - its memory passes 100 MB plus 1 kB per allowed cell: gmsh needs
   *   about 0.1 kB per quadrilateral, so a geometry parameter that asks for
   *   vastly more cells than Mesh/Maximum cells is stopped within seconds
   *   instead of meshing until the machine runs out of memory (an
   *   InputError naming Mesh/Geometry parameters),
   * - it runs longer than GmshJob::time_limit (an InputError naming
   *   Mesh/Meshing time limit: a loop without end in the script),
   * - or this function leaves by an exception.
   * gmsh's own errors become an InputError naming the .geo.
   */
  std::string
  run_gmsh(const GmshJob &job, std::ostream &progress);

  /**
   * The geometry of @p job as gmsh unrolls it (gmsh -0: every entity with
   * its points' coordinates evaluated, the parameters set), run as
   * run_gmsh() runs gmsh; arcs_of_geometry() reads its circles.
   */
  std::string
  unrolled_geometry(const GmshJob &job, std::ostream &progress);
} // namespace thinlayer

#endif
