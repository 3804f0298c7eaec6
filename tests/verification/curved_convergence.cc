// Truth checked, in plane strain and under Fourier kinematics: curved
// cells converge at the element's order where the straight polygon does
// not.
//
// Plane strain: Lame's thick cylinder from a gmsh geometry with circles.
// meshes/circular-inclusion.geo gives the half annulus 1 <= r <= 2 (its
// thin inner ring 1 <= r <= 1.02, one cell across, and the rest both
// elastic, E = 1, nu = 0.3),
// pressure p = 1 inside, the outer circle held, y = 0 a line of symmetry.
// In plane strain u_r = A r + B / r with u_r(2) = 0 and sigma_rr(1) = -p:
//   B = p / (2 (lambda + mu) / b^2 + 2 mu / a^2), A = -B / b^2.
// On the meshes with n = 2, 4, 8 cells along each quarter circle (and n
// across the rest) the L2
// error of the displacement must fall as the element's where the cells
// follow the circles (Mesh/Curved cells = true: order 3, asked at least
// 2.5 between the two finer meshes), and stays at the polygon's where they
// do not (order 2 at best): on the finest mesh the curved cells' error is
// asked to be below a tenth of the straight ones'.
//
// Fourier: the r-z plane of a
// thick spherical shell a = 1 <= rho <= b = 2 (meshes/spherical-shell.geo,
// its circles gmsh arcs), harmonic 0, elastic (E = 1, nu = 0.3), pressure
// p = 1 inside, the outside held: u_rho = A rho + B / rho^2 with
// u_rho(b) = 0 and sigma_rhorho(a) = -p,
//   B = p / ((3 lambda + 2 mu) / b^3 + 4 mu / a^3), A = -B / b^3.
// On n = 2, 4, 8 cells along each quarter circle (n across) the L2 error of
// the displacement must fall as the element's where the cells follow the
// circles (order at least 2.5 between the two finer meshes), and on n = 8
// be below a tenth of the straight cells' (the polygon revolved: a
// faceted sphere). Release only: twelve solves.
#include "../common/curved_convergence.h"

#include <deal.II/base/function.h>

#include <string>

using namespace dealii;

namespace cylinder
{
  const double a = 1, b = 2, pressure = 1, E = 1, nu = 0.3;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  const double mu     = E / (2 * (1 + nu));
  const double B = pressure / (2 * (lambda + mu) / (b * b) + 2 * mu / (a * a));
  const double A = -B / (b * b);

  class Lame : public Function<2>
  {
  public:
    Lame()
      : Function<2>(2)
    {}
    void
    vector_value(const Point<2> &x, Vector<double> &u) const override
    {
      const double r = x.norm();
      u[0]           = (A * r + B / r) * x[0] / r;
      u[1]           = (A * r + B / r) * x[1] / r;
    }
  };


  /// The scene on @p n cells per quarter circle.
  std::string
  scene(const unsigned int n, const bool curved)
  {
    const std::string prm =
      "subsection Mesh\n"
      "  set File = " SOURCE_DIR "/../../meshes/circular-inclusion.geo\n"
      "  set Geometry parameters = radius=1, thickness=0.02, outer=2, "
      "n_around=" +
      std::to_string(n) + ", n_radial=" + std::to_string(n) +
      ", growth=1\n"
      "  set Curved cells = " +
      (curved ? "true" : "false") +
      "\n"
      "end\n"
      "subsection Material 1\n"
      "  set Young's modulus = 1\n  set Poisson's ratio = 0.3\n"
      "end\n"
      "subsection Material 2\n"
      "  set Young's modulus = 1\n  set Poisson's ratio = 0.3\n"
      "end\n"
      "subsection Boundary 1\n  set Pressure = 1\nend\n"
      "subsection Boundary 2\n  set Constrained components = y\nend\n"
      "subsection Boundary 3\n  set Constrained components = x, y\nend\n"
      "subsection Monitors\n  set Displacement boundary id = 1\nend\n";
    return prm;
  }
} // namespace cylinder


namespace sphere
{
  const double a = 1, b = 2, pressure = 1, E = 1, nu = 0.3;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  const double mu     = E / (2 * (1 + nu));
  const double B =
    pressure / ((3 * lambda + 2 * mu) / (b * b * b) + 4 * mu / (a * a * a));
  const double A = -B / (b * b * b);

  /// The exact displacement in the components (r, z, theta).
  class Lame : public Function<2>
  {
  public:
    Lame()
      : Function<2>(3)
    {}
    void
    vector_value(const Point<2> &x, Vector<double> &u) const override
    {
      const double rho   = x.norm();
      const double u_rho = A * rho + B / (rho * rho);
      u[0]               = u_rho * x[0] / rho;
      u[1]               = u_rho * x[1] / rho;
      u[2]               = 0;
    }
  };


  /// The scene on @p n cells per quarter circle.
  std::string
  scene(const unsigned int n, const bool curved)
  {
    const std::string prm =
      "subsection Mesh\n"
      "  set File = " SOURCE_DIR "/../../meshes/spherical-shell.geo\n"
      "  set Geometry parameters = inner=1, outer=2, n_around=" +
      std::to_string(n) + ", n_radial=" + std::to_string(n) +
      "\n"
      "  set Curved cells = " +
      (curved ? "true" : "false") +
      "\n"
      "end\n"
      "subsection Kinematics\n"
      "  set Type = fourier\n  set Harmonics = 0\n  set Stations = 0\n"
      "  set Axis boundary id = 3\n"
      "end\n"
      "subsection Material 1\n"
      "  set Young's modulus = 1\n  set Poisson's ratio = 0.3\n"
      "end\n"
      "subsection Boundary 1\n  set Pressure = 1\nend\n"
      "subsection Boundary 2\n  set Constrained components = r, z\nend\n"
      "subsection Monitors\n  set Displacement boundary id = 1\nend\n";
    return prm;
  }
} // namespace sphere


int
main()
{
  thinlayer_tests::compare_curved_and_straight(cylinder::scene,
                                               cylinder::Lame());
  thinlayer_tests::compare_curved_and_straight(sphere::scene, sphere::Lame());
}
