#include <deal.II/base/numbers.h>

#include <thinlayer/discretisation/kinematics.h>

#include <algorithm>
#include <cmath>

namespace thinlayer
{
  Kinematics
  Kinematics::make_plane_strain()
  {
    Kinematics k;
    k.fourier       = false;
    k.antisymmetric = false;
    k.harmonics     = {0};
    k.angles        = {0};
    k.weights       = {1};
    k.tabulate_factors();
    return k;
  }


  Kinematics
  Kinematics::make_solid()
  {
    Kinematics k = make_plane_strain();
    k.dimension  = 3;
    return k;
  }


  Kinematics
  Kinematics::make_fourier(const std::vector<unsigned int> &harmonics,
                           const std::vector<double>       &station_angles,
                           const bool                       antisymmetric)
  {
    Kinematics k;
    k.fourier       = true;
    k.antisymmetric = antisymmetric;
    k.harmonics     = harmonics;
    k.angles        = station_angles;
    // The trapezoidal rule over [0, pi], doubled: the field over (pi, 2 pi)
    // mirrors the one over (0, pi), and the products T(m theta) with it
    // are even.
    // One station (harmonic 0 alone, checked when reading) stands for the
    // whole circle.
    const unsigned int S = station_angles.size();
    k.weights.assign(S, S == 1 ? 2 * numbers::PI : 0.);
    for (unsigned int s = 0; s + 1 < S; ++s)
      {
        const double h = station_angles[s + 1] - station_angles[s];
        k.weights[s] += h;
        k.weights[s + 1] += h;
      }
    k.tabulate_factors();
    return k;
  }


  void
  Kinematics::tabulate_factors()
  {
    t1_at_stations.resize(harmonics.size() * angles.size());
    t2_at_stations.resize(harmonics.size() * angles.size());
    for (unsigned int m = 0; m < harmonics.size(); ++m)
      for (unsigned int s = 0; s < angles.size(); ++s)
        {
          t1_at_stations[m * angles.size() + s] = T1_at(m, angles[s]);
          t2_at_stations[m * angles.size() + s] = T2_at(m, angles[s]);
        }
  }


  bool
  Kinematics::is_fourier() const
  {
    return fourier;
  }


  unsigned int
  Kinematics::mesh_dimension() const
  {
    return dimension;
  }


  unsigned int
  Kinematics::n_components() const
  {
    return fourier ? 3 : dimension;
  }


  unsigned int
  Kinematics::harmonic(const unsigned int m) const
  {
    return harmonics[m];
  }


  bool
  Kinematics::is_antisymmetric() const
  {
    return antisymmetric;
  }


  double
  Kinematics::station_angle(const unsigned int s) const
  {
    return angles[s];
  }


  double
  Kinematics::T1_at(const unsigned int m, const double theta) const
  {
    if (!fourier)
      return 1;
    const double a = harmonics[m] * theta;
    return antisymmetric ? std::sin(a) : std::cos(a);
  }


  double
  Kinematics::T2_at(const unsigned int m, const double theta) const
  {
    if (!fourier)
      return 0;
    const double a = harmonics[m] * theta;
    return antisymmetric ? std::cos(a) : std::sin(a);
  }


  double
  Kinematics::c1(const unsigned int m) const
  {
    if (!fourier)
      return 1;
    if (harmonics[m] > 0)
      return numbers::PI;
    return antisymmetric ? 0 : 2 * numbers::PI;
  }


  double
  Kinematics::c2(const unsigned int m) const
  {
    if (!fourier)
      return 0;
    if (harmonics[m] > 0)
      return numbers::PI;
    return antisymmetric ? 2 * numbers::PI : 0;
  }


  bool
  Kinematics::is_dead_component(const unsigned int m,
                                const unsigned int c) const
  {
    if (!fourier || harmonics[m] > 0)
      return false;
    return antisymmetric ? (c != 2) : (c == 2);
  }


  template <int dim>
  void
  Kinematics::shape_strain(const unsigned int     m,
                           const unsigned int     component,
                           const double           N,
                           const Tensor<1, dim>  &gradient,
                           const double           r,
                           SymmetricTensor<2, 3> &part1,
                           SymmetricTensor<2, 3> &part2) const
  {
    Assert(dim == dimension,
           ExcMessage("The mesh's dimension is not the kinematics'."));
    part1 = 0;
    part2 = 0;
    if (!fourier)
      {
        // Plane strain and 3D: sym(e_c (x) grad N).
        for (unsigned int d = 0; d < dim; ++d)
          part1[component][d] =
            d == component ? gradient[d] : 0.5 * gradient[d];
        return;
      }
    // (r, z, theta) with N_r = gradient[0], N_z = gradient[1]; the
    // antisymmetric series is the symmetric one with n -> -n.
    const double n = (antisymmetric ? -1. : 1.) * harmonics[m];
    switch (component)
      {
        case 0: // u_r
          part1[0][0] = gradient[0];
          part1[2][2] = N / r;
          part1[0][1] = 0.5 * gradient[1];
          part2[0][2] = -0.5 * n * N / r;
          break;
        case 1: // u_z
          part1[1][1] = gradient[1];
          part1[0][1] = 0.5 * gradient[0];
          part2[1][2] = -0.5 * n * N / r;
          break;
        case 2: // u_theta
          part1[2][2] = n * N / r;
          part2[0][2] = 0.5 * (gradient[0] - N / r);
          part2[1][2] = 0.5 * gradient[1];
          break;
      }
  }


  template <int dim>
  double
  Kinematics::area_factor(const Point<dim> &x) const
  {
    return fourier ? x[0] : 1.;
  }


  template void
  Kinematics::shape_strain(const unsigned int,
                           const unsigned int,
                           const double,
                           const Tensor<1, 2> &,
                           const double,
                           SymmetricTensor<2, 3> &,
                           SymmetricTensor<2, 3> &) const;
  template void
  Kinematics::shape_strain(const unsigned int,
                           const unsigned int,
                           const double,
                           const Tensor<1, 3> &,
                           const double,
                           SymmetricTensor<2, 3> &,
                           SymmetricTensor<2, 3> &) const;
  template double
  Kinematics::area_factor(const Point<2> &) const;
  template double
  Kinematics::area_factor(const Point<3> &) const;
} // namespace thinlayer
