#ifndef thinlayer_discretisation_kinematics_h
#define thinlayer_discretisation_kinematics_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <string>
#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /**
   * Plane strain: the 2D symmetric gradient embedded in a full 3D strain
   * with zero out-of-plane components. Strains and stresses are always
   * stored as 3D tensors so that one material law serves every kinematics
   * (plane strain, Fourier harmonics, 3D); sigma_zz is then kept for free.
   */
  inline SymmetricTensor<2, 3>
  plane_strain(const SymmetricTensor<2, 2> &strain_2d)
  {
    SymmetricTensor<2, 3> strain;
    strain[0][0] = strain_2d[0][0];
    strain[1][1] = strain_2d[1][1];
    strain[0][1] = strain_2d[0][1];
    return strain;
  }

  /**
   * How the displacement unknowns on the mesh make a 3D field:
   * displacement = sum over modes m of u_m(x) T_m(theta), with the material
   * evaluated at a few stations (circumferential angles).
   *
   * - Plane strain (a 2D mesh): one mode, one station, components (u_x,
   *   u_y).
   * - Solid (a 3D mesh): one mode, one station, components (u_x, u_y,
   *   u_z).
   * - Fourier (an axisymmetric body, the mesh being its r-z plane, under
   *   non-axisymmetric load): a mode per harmonic n, components
   *   (u_r, u_z, u_theta). In the symmetric series u_r, u_z go with cos(n
   *   theta) and u_theta with sin(n theta); the antisymmetric series swaps
   *   cos and sin (its n = 0 term is torsion).
   *
   * The strain of a shape function in mode m at station s is
   *   B1 T1(m, s) + B2 T2(m, s):
   * B1 holds the normal and r-z shear parts (cos n theta in the symmetric
   * series), B2 the r-theta and z-theta shears (sin n theta). Tensor
   * indices are (x, y, z) in plane strain and 3D, (r, z, theta) for
   * Fourier.
   *
   * For isotropic elasticity the harmonics decouple: the stiffness of mode
   * m is int (c1 B1^T D B1 + c2 B2^T D B2) dA_r, with c1 = int T1^2 dtheta,
   * c2 = int T2^2 dtheta over the full circle and dA_r = r dA. Plastic
   * strains at the stations are projected back onto every mode with the
   * weights station_weight(s): the trapezoidal rule over [0, pi], doubled
   * for the mirror half of the symmetric field.
   */
  class Kinematics
  {
  public:
    /// One mode and one station, components (u_x, u_y).
    static Kinematics
    make_plane_strain();

    /// One mode and one station on a 3D mesh, components (u_x, u_y, u_z).
    static Kinematics
    make_solid();

    /**
     * Fourier harmonics @p harmonics (n >= 0), material stations at
     * @p station_angles (radians, in [0, pi], increasing, the first 0 and
     * the last pi).
     */
    static Kinematics
    make_fourier(const std::vector<unsigned int> &harmonics,
                 const std::vector<double>       &station_angles,
                 const bool                       antisymmetric);

    bool
    is_fourier() const;

    /// The dimension of the mesh: 3 for a solid, else 2.
    unsigned int
    mesh_dimension() const;

    unsigned int
    n_components() const;

    unsigned int
    n_modes() const
    {
      return harmonics.size();
    }

    unsigned int
    n_stations() const
    {
      return angles.size();
    }

    /// The harmonic number of mode @p m (0 in plane strain).
    unsigned int
    harmonic(const unsigned int m) const;

    bool
    is_antisymmetric() const;

    /// The angle of station @p s (radians).
    double
    station_angle(const unsigned int s) const;

    /// T1_at() and T2_at() at station @p s, tabulated: the point loop asks
    /// for them at every point.
    double
    T1(const unsigned int m, const unsigned int s) const
    {
      return t1_at_stations[m * angles.size() + s];
    }

    double
    T2(const unsigned int m, const unsigned int s) const
    {
      return t2_at_stations[m * angles.size() + s];
    }

    /// int T1(n theta)^2 dtheta over the circle (1 in plane strain).
    double
    c1(const unsigned int m) const;

    /// int T2(n theta)^2 dtheta over the circle (0 in plane strain).
    double
    c2(const unsigned int m) const;

    /// Weight of station @p s when projecting onto the modes.
    double
    station_weight(const unsigned int s) const
    {
      return weights[s];
    }

    /// The trigonometric factors at any angle (for loads and monitors).
    double
    T1_at(const unsigned int m, const double theta) const;

    double
    T2_at(const unsigned int m, const double theta) const;

    /// Whether displacement component @p c varies with T2 (theta of a
    /// Fourier scene) rather than T1 (x, y and, in 3D, z; r and z).
    bool
    is_circumferential(const unsigned int c) const
    {
      return fourier && c == 2;
    }

    /// T1_at() or T2_at() as component @p c varies.
    double
    T_at(const unsigned int c, const unsigned int m, const double theta) const
    {
      return is_circumferential(c) ? T2_at(m, theta) : T1_at(m, theta);
    }

    /// T1() or T2() as component @p c varies.
    double
    T(const unsigned int c, const unsigned int m, const unsigned int s) const
    {
      return is_circumferential(c) ? T2(m, s) : T1(m, s);
    }

    /**
     * Whether component @p c plays no part in mode @p m (u_theta for n = 0
     * of the symmetric series; u_r and u_z for n = 0 of the antisymmetric
     * one): its DoFs are then constrained to zero.
     */
    bool
    is_dead_component(const unsigned int m, const unsigned int c) const;

    /**
     * The two strain parts of a vector shape function whose only non-zero
     * component is @p component, with value @p value and gradient
     * @p gradient at a point with radius @p r (x in plane strain, unused).
     * In plane strain and 3D the first part is sym(e_c (x) grad N) and the
     * second 0; @p dim is the mesh's dimension (mesh_dimension()).
     */
    template <int dim>
    void
    shape_strain(const unsigned int     m,
                 const unsigned int     component,
                 const double           value,
                 const Tensor<1, dim>  &gradient,
                 const double           r,
                 SymmetricTensor<2, 3> &part1,
                 SymmetricTensor<2, 3> &part2) const;

    /// The factor of the area (or volume) element: r for Fourier, else 1.
    template <int dim>
    double
    area_factor(const Point<dim> &x) const;

  private:
    /// Fills t1_at_stations and t2_at_stations.
    void
    tabulate_factors();

    bool                      fourier;
    bool                      antisymmetric;
    unsigned int              dimension = 2;
    std::vector<unsigned int> harmonics;
    std::vector<double>       angles;
    std::vector<double>       weights;
    std::vector<double>       t1_at_stations;
    std::vector<double>       t2_at_stations;
  };
} // namespace thinlayer

#endif
