#ifndef thinlayer_discretisation_initial_stresses_h
#define thinlayer_discretisation_initial_stresses_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/grid/tria.h>

#include <thinlayer/parameters/parameters.h>

#include <array>
#include <map>
#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /**
   * The initial stresses of the K0 procedure on a 2D mesh (plane strain,
   * or the r-z plane of a Fourier body; y up): at a point x,
   * sigma_v = -(q + int gamma dy), the surcharge q and the weight of the
   * material above x along the vertical, and sigma_h = K0 sigma_v (the
   * horizontal and the out-of-plane or hoop stress) with the K0 of x's
   * material; no shear. Only a level ground surface with horizontal layers
   * has this field in equilibrium with the weight, so a ground surface
   * that is not level (a boundary face facing upward that is not
   * horizontal at the top level: a slope, a step, a structure above the
   * ground) is refused. The sides of zero-thickness interface elements
   * (boundary faces of the split mesh with an Interface section's id) are
   * inside the body, not ground.
   *
   * The weight above a point is summed exactly over the cells the
   * vertical through it crosses (straight-sided cells: the length of the
   * vertical inside each times its unit weight), found among the cells
   * whose horizontal extent holds the point's x.
   */
  class KZeroStresses
  {
  public:
    /// The field of @p mesh (the mesh as read, whole) with the materials,
    /// the surcharge and the parameter file of @p parameters. Throws
    /// InputError, naming Initial state/Procedure, where the ground
    /// surface is not level.
    KZeroStresses(const Triangulation<2> &mesh, const Parameters &parameters);

    /// The height of the ground surface.
    double
    ground_level() const;

    /// q plus the weight per unit area of the material above @p x: the
    /// magnitude of sigma_v.
    double
    overburden(const Point<2> &x) const;

    /// The stress at @p x in a cell of material @p material (3D, tension
    /// positive; components x (or r), y, and z (or theta)).
    SymmetricTensor<2, 3>
    stress(const Point<2> &x, const types::material_id material) const;

  private:
    struct Cell
    {
      std::array<Point<2>, 4> vertices;
      double                  x_min, x_max;
      double                  unit_weight;
    };

    /// The cells whose horizontal extent [x_min, x_max) holds @p x.
    const std::vector<unsigned int> &
    bin(const double x) const;

    const Parameters &parameters;
    double            level;
    std::vector<Cell> cells;
    /// The cells by horizontal bins of equal width, each cell in every bin
    /// its extent overlaps.
    double                                 x_start, bin_width;
    std::vector<std::vector<unsigned int>> bins;
  };
} // namespace thinlayer

#endif
