#include <deal.II/grid/grid_out.h>

#include <thinlayer/base/file_utilities.h>
#include <thinlayer/base/input_error.h>
#include <thinlayer/mesh/curved_geometry.h>
#include <thinlayer/mesh/geometry_script.h>
#include <thinlayer/mesh/gmsh_process.h>
#include <thinlayer/mesh/mesh_checks.h>
#include <thinlayer/mesh/mesh_splitting.h>
#include <thinlayer/mesh/msh_file.h>
#include <thinlayer/mesh/scene.h>
#include <thinlayer/parallel/mpi.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

namespace thinlayer
{
  namespace
  {
    GmshJob
    gmsh_job(const Parameters &p)
    {
      return {p.mesh.file,
              p.mesh.geometry_parameters,
              p.mesh.max_cells,
              p.parameter_file,
              p.kinematics.dimension,
              p.mesh.meshing_time_limit};
    }

    /**
     * Mesh a .geo with the gmsh program, setting its DefineConstant[]
     * parameters with -setnumber. Returns the mesh in gmsh's 2.2 format.
     */
    std::string
    mesh_geometry(const Parameters &p, std::ostream &progress)
    {
      const GeometryScript script(p.mesh.file, p.parameter_file);
      for (const auto &[name, value] : p.mesh.geometry_parameters)
        if (!script.has_word(name))
          throw InputError(p.parameter_file,
                           "Mesh/Geometry parameters",
                           "'" + name + "' is not a parameter of " +
                             p.mesh.file);
      if (!p.mesh.trust_geometry_scripts)
        script.check_safe();

      return run_gmsh(gmsh_job(p), progress);
    }

    /**
     * Every cell a convex quadrilateral of a size the arithmetic can carry.
     * For a bilinear cell the Jacobian is positive everywhere exactly when
     * it is positive at the four corners, where it is the cross product of
     * the two edges that meet there: a repeated vertex, a bow-tie, a
     * re-entrant corner or a cell of zero area shows as a corner whose
     * product is not positive. A cell whose corner products are below
     * 1e-12 of the mesh's extent squared (a thin layer of aspect ratio
     * 10^6 is still far above) turns the stiffness into rounding error.
     */
    template <int dim>
    double
    squared_extent(const Triangulation<dim> &tria)
    {
      Point<dim> low = tria.get_vertices()[0], high = low;
      for (const auto &v : tria.get_vertices())
        for (unsigned int d = 0; d < dim; ++d)
          {
            low[d]  = std::min(low[d], v[d]);
            high[d] = std::max(high[d], v[d]);
          }
      return (high - low).norm_square();
    }


    void
    check_cell_shapes(const Triangulation<2> &tria, const std::string &file)
    {
      const double extent = squared_extent(tria);
      for (const auto &cell : tria.active_cell_iterators())
        {
          // deal.II numbers a quadrilateral's vertices lexicographically;
          // 0, 1, 3, 2 goes round it anticlockwise.
          const Point<2> v[4]       = {cell->vertex(0),
                                       cell->vertex(1),
                                       cell->vertex(3),
                                       cell->vertex(2)};
          double         smallest   = std::numeric_limits<double>::max();
          int            coincident = -1;
          double         area       = 0;
          for (unsigned int k = 0; k < 4; ++k)
            {
              const Tensor<1, 2> a = v[(k + 1) % 4] - v[k];
              const Tensor<1, 2> b = v[(k + 3) % 4] - v[k];
              smallest = std::min(smallest, a[0] * b[1] - a[1] * b[0]);
              area +=
                (v[k][0] * v[(k + 1) % 4][1] - v[(k + 1) % 4][0] * v[k][1]) / 2;
              if (coincident < 0 && a.norm_square() <= 1e-24 * extent)
                coincident = k;
            }
          if (smallest > 1e-12 * extent && coincident < 0)
            continue;
          std::ostringstream where;
          where << "cell " << cell->active_cell_index() << " of physical "
                << "surface " << cell->material_id() << ", corners";
          for (const auto &corner : v)
            where << " (" << corner[0] << ", " << corner[1] << ')';
          std::ostringstream what;
          if (coincident >= 0)
            what << ": two corners coincide at (" << v[coincident][0] << ", "
                 << v[coincident][1]
                 << ") (to 1e-12 of the mesh's size), a quadrilateral "
                 << "collapsed to a triangle of area " << std::abs(area)
                 << "; expected four distinct corners";
          else if (smallest <= 0)
            what << ": expected a convex quadrilateral, got one that is "
                    "folded (a bow-tie), not convex, or flat at a corner "
                    "(area "
                 << area << ")";
          else
            what << ": the cell (area " << area
                 << ") is smaller than 1e-12 of the mesh's extent squared, "
                    "too small for the stiffness to be computed";
          throw InputError(file, "", where.str() + what.str());
        }
    }


    template <int dim>
    std::string
    text_of(const Point<dim> &x)
    {
      std::ostringstream text;
      text << x;
      return text.str();
    }


    /**
     * Every cell a hexahedron whose trilinear map has a positive Jacobian
     * at its eight corners, where it is the triple product of the three
     * edges that meet there (the usual test of a hexahedron's validity; it
     * catches inverted, folded and flattened cells and repeated corners),
     * and whose corner products are above 1e-18 of the mesh's extent cubed
     * (a thin layer of aspect ratio 10^6 is still far above).
     */
    void
    check_cell_shapes(const Triangulation<3> &tria, const std::string &file)
    {
      const double extent = squared_extent(tria);
      const double scale  = extent * std::sqrt(extent);
      for (const auto &cell : tria.active_cell_iterators())
        {
          double smallest = std::numeric_limits<double>::max();
          int    worst    = 0;
          for (unsigned int v = 0; v < 8; ++v)
            {
              // deal.II numbers a hexahedron's vertices lexicographically:
              // bit d of v says on which side of direction d it lies.
              Tensor<1, 3> edge[3];
              for (unsigned int d = 0; d < 3; ++d)
                edge[d] = (cell->vertex(v ^ (1u << d)) - cell->vertex(v)) *
                          ((v & (1u << d)) ? -1. : 1.);
              const double product =
                scalar_product(edge[0], cross_product_3d(edge[1], edge[2]));
              if (product < smallest)
                {
                  smallest = product;
                  worst    = v;
                }
            }
          if (smallest > 1e-18 * scale)
            continue;
          std::ostringstream where;
          where << "cell " << cell->active_cell_index() << " of physical "
                << "volume " << cell->material_id() << ", corners";
          for (unsigned int v = 0; v < 8; ++v)
            where << " (" << cell->vertex(v) << ')';
          throw InputError(
            file,
            "",
            where.str() +
              (smallest <= 0
                 ? ": expected a hexahedron whose corners each span a "
                   "positive volume, got one that is inverted, folded or "
                   "flat at corner ("
                 : ": the cell is smaller than 1e-18 of the mesh's extent "
                   "cubed at corner (") +
              text_of(cell->vertex(worst)) + ")");
        }
    }


    std::string
    describe(const std::set<unsigned int> &ids, const bool boundary = false)
    {
      std::string text;
      for (const auto id : ids)
        text += (text.empty() ? "" : ", ") + std::to_string(id) +
                ((boundary && id == 0) ? " (untagged)" : "");
      return text.empty() ? "none" : text;
    }
  } // namespace


  template <int dim>
  Scene<dim>::Scene(const Parameters &p, std::ostream &progress)
  {
    AssertThrow(p.kinematics.dimension == dim,
                ExcMessage("A scene's dimension is the kinematics'."));
    std::error_code error;
    if (!std::filesystem::is_regular_file(p.mesh.file, error) ||
        !std::ifstream(p.mesh.file))
      throw InputError(p.parameter_file,
                       "Mesh/File",
                       "cannot read the mesh file '" + p.mesh.file + "'" +
                         (error ? ": " + error.message()
                          : std::filesystem::exists(p.mesh.file, error) &&
                              !std::filesystem::is_regular_file(p.mesh.file,
                                                                error)
                            ? std::string(": not a regular file")
                            : std::string()));

    const std::string extension =
      std::filesystem::path(p.mesh.file).extension().string();
    if (extension == ".geo")
      // gmsh meshes once, on rank 0.
      msh = mpi::on_root([&]() { return mesh_geometry(p, progress); });
    else if (extension == ".msh")
      msh = read_file(p.mesh.file);
    else
      throw InputError(p.parameter_file,
                       "Mesh/File",
                       "expected a .geo or .msh file, got '" + p.mesh.file +
                         "'");

    // The geometry as gmsh unrolls it: its physical groups (every surface
    // must be in one) and its arcs (Mesh/Curved cells).
    const std::string unrolled = extension == ".geo" ? mpi::on_root([&]() {
      return unrolled_geometry(gmsh_job(p), progress);
    })
                                                     : std::string();
    if (extension == ".geo")
      check_bodies_in_groups(unrolled, p.mesh.file, dim);

    // The mesh is read once: the checks, the splitting and the
    // triangulation all work on what was read.
    MshFile mesh(msh, p.mesh.file);
    if (const std::string repeated = repeated_corner(mesh); !repeated.empty())
      throw InputError(p.mesh.file,
                       "",
                       repeated + (dim == 2 ? ": expected a quadrilateral "
                                              "with four distinct corners"
                                            : ": expected a hexahedron with "
                                              "eight distinct corners"));
    // Conforming as read, before interface elements split it; checked once
    // each cell is known to have a shape (a flat cell puts its nodes on
    // its neighbours' sides, which check_cell_shapes() names better).
    const MshFile as_read = mesh;
    if (!p.interface_elements.empty())
      {
        std::set<unsigned int> curves;
        for (const auto &[id, curve] : p.interface_elements)
          curves.insert(id);
        mesh = split_along_curves(mesh, curves);
        msh  = mesh.text();
      }
    check_physical_faces_on_boundary(mesh, dim, "Interface");
    create_triangulation(mesh, tria);
    if (tria.n_active_cells() > p.mesh.max_cells)
      throw InputError(p.parameter_file,
                       "Mesh/Maximum cells",
                       "the mesh of " + p.mesh.file + " has " +
                         std::to_string(tria.n_active_cells()) +
                         " cells, more than the limit of " +
                         std::to_string(p.mesh.max_cells) +
                         "; check the geometry parameters, or raise the "
                         "limit");
    check_cell_shapes(tria, p.mesh.file);
    check_conforming(as_read, dim);
    check_ids(p, tria);

    if (extension == ".geo" && p.mesh.curved_cells)
      {
        const std::vector<GeometryArc> arcs   = arcs_of_geometry(unrolled);
        const unsigned int             curved = attach_arcs(tria, arcs);
        if (curved > 0)
          progress << "  curved " << curved << " cell "
                   << (dim == 2 ? "sides" : "faces") << " along " << arcs.size()
                   << " circular arc" << (arcs.size() == 1 ? "" : "s")
                   << " of the geometry" << std::endl;
      }
  }


  template <int dim>
  const Triangulation<dim> &
  Scene<dim>::triangulation() const
  {
    return tria;
  }


  template <int dim>
  Triangulation<dim> &
  Scene<dim>::triangulation_to_refine()
  {
    refined = true;
    return tria;
  }


  template <int dim>
  std::string
  Scene<dim>::mesh_text() const
  {
    if (!refined)
      return msh;
    // The refined mesh's active cells, with their material ids and the
    // boundary ids of their faces as gmsh's physical groups (gmsh's format
    // 1, deal.II's), to 12 digits.
    std::ostringstream text;
    text.precision(12);
    GridOut out;
    out.set_flags(GridOutFlags::Msh(/*write_faces=*/true));
    out.write_msh(tria, text);
    return text.str();
  }


  template <int dim>
  void
  check_ids(const Parameters &p, const Triangulation<dim> &tria)
  {
    // gmsh's names for the groups that carry the material and boundary ids.
    const std::string      cell_group = dim == 2 ? "surface" : "volume";
    const std::string      face_group = dim == 2 ? "curve" : "surface";
    std::set<unsigned int> mesh_materials, mesh_boundaries;
    for (const auto &cell : tria.active_cell_iterators())
      {
        mesh_materials.insert(cell->material_id());
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            mesh_boundaries.insert(face->boundary_id());
      }

    if (p.kinematics.fourier)
      {
        // The mesh is the r-z plane: r = x >= 0, and faces on the axis need
        // the per-harmonic axis conditions.
        double size = 0, min_x = 0;
        for (const auto &v : tria.get_vertices())
          {
            size  = std::max(size, v.norm());
            min_x = std::min(min_x, v[0]);
          }
        if (min_x < -1e-12 * size)
          throw InputError(p.parameter_file,
                           "Kinematics/Type",
                           "Fourier kinematics need the mesh in the r-z plane "
                           "with r = x >= 0, but it reaches x = " +
                             std::to_string(min_x));
        std::set<unsigned int> on_axis;
        for (const auto &face : tria.active_face_iterators())
          if (face->at_boundary() &&
              std::abs(face->vertex(0)[0]) <= 1e-12 * size &&
              std::abs(face->vertex(1)[0]) <= 1e-12 * size)
            on_axis.insert(face->boundary_id());
        if (!on_axis.empty() && on_axis.count(static_cast<unsigned int>(
                                  p.kinematics.axis_boundary_id)) == 0)
          throw InputError(p.parameter_file,
                           "Kinematics/Axis boundary id",
                           "the mesh reaches the axis r = 0 on boundary id " +
                             describe(on_axis, true) +
                             ": set that id, so that every harmonic gets its "
                             "axis conditions");
      }

    for (const auto id : mesh_materials)
      if (p.materials.count(id) == 0)
        throw InputError(p.parameter_file,
                         "Material " + std::to_string(id),
                         "the mesh has cells with material id " +
                           std::to_string(id) + " (a physical " + cell_group +
                           ") but this file has no "
                           "'subsection Material " +
                           std::to_string(id) + "'");
    for (const auto &[id, material] : p.materials)
      if (mesh_materials.count(id) == 0)
        throw InputError(p.parameter_file,
                         "Material " + std::to_string(id),
                         "the mesh has no physical " + cell_group + " " +
                           std::to_string(id) + " (its material ids: " +
                           describe(mesh_materials) + ")");
    for (const auto &[id, boundary] : p.boundaries)
      if (mesh_boundaries.count(id) == 0)
        throw InputError(p.parameter_file,
                         "Boundary " + std::to_string(id),
                         "the mesh has no physical " + face_group + " " +
                           std::to_string(id) +
                           " on its boundary (its boundary ids: " +
                           describe(mesh_boundaries, true) + ")");
    for (unsigned int k = 0; k < p.loading_phases.size(); ++k)
      for (const auto &[id, boundary] : p.loading_phases[k].boundaries)
        if (mesh_boundaries.count(id) == 0)
          throw InputError(p.parameter_file,
                           LoadingPhaseParameters::section(k + 2) +
                             "/Boundary " + std::to_string(id),
                           "the phase names boundary " + std::to_string(id) +
                             ", but the mesh has no physical " + face_group +
                             " " + std::to_string(id) +
                             " on its boundary (its boundary ids: " +
                             describe(mesh_boundaries, true) + ")");
    if (p.monitors.displacement_measure ==
          MonitorParameters::DisplacementMeasure::boundary_average &&
        mesh_boundaries.count(p.monitors.displacement_boundary_id) == 0)
      throw InputError(p.parameter_file,
                       "Monitors/Displacement boundary id",
                       "the mesh has no boundary id " +
                         std::to_string(p.monitors.displacement_boundary_id) +
                         " (its boundary ids: " +
                         describe(mesh_boundaries, true) + ")");
    if (p.monitors.load_measure ==
          MonitorParameters::LoadMeasure::stress_average &&
        mesh_materials.count(p.monitors.load_material_id) == 0)
      throw InputError(p.parameter_file,
                       "Monitors/Load material id",
                       "the mesh has no material id " +
                         std::to_string(p.monitors.load_material_id) +
                         " (its material ids: " + describe(mesh_materials) +
                         ")");
    if (p.monitors.load_measure == MonitorParameters::LoadMeasure::reaction &&
        mesh_boundaries.count(p.monitors.load_boundary_id) == 0)
      throw InputError(p.parameter_file,
                       "Monitors/Load boundary id",
                       "the mesh has no boundary id " +
                         std::to_string(p.monitors.load_boundary_id) +
                         " (its boundary ids: " +
                         describe(mesh_boundaries, true) + ")");
  }


  template class Scene<2>;
  template class Scene<3>;
  template void
  check_ids(const Parameters &, const Triangulation<2> &);
  template void
  check_ids(const Parameters &, const Triangulation<3> &);
} // namespace thinlayer
