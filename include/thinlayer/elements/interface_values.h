#ifndef thinlayer_elements_interface_values_h
#define thinlayer_elements_interface_values_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <thinlayer/discretisation/kinematics.h>

#include <array>
#include <string>
#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /**
   * What an engineer reads off an interface at one point of it: the
   * relative displacement of its two faces (slip along it, opening across
   * it) and the traction on its plane (shear along it, normal across it).
   * Signs: the tangent s points along the interface in the direction of
   * increasing arc length, the normal n is s turned a quarter turn
   * anticlockwise; slip and opening are (u on the +n face) - (u on the -n
   * face) along s and n; tractions are sigma n along s and n, tension
   * positive. "Out of plane" is z in plane strain (always zero) and theta
   * in Fourier scenes. On an interface surface of a 3D body "slip" and
   * "shear traction" are along its first tangent t1 and the "out of plane"
   * ones along t2 = t1 x n (see Profile).
   */
  struct InterfaceValues
  {
    double slip;
    double slip_out_of_plane;
    double opening;
    /// The same over the last load step alone: at a failed step, the
    /// incipient mechanism.
    double slip_increment;
    double opening_increment;
    double shear_traction;
    double shear_traction_out_of_plane;
    double normal_traction;
    /// The mobilised strength tau_mob / tau_max in [0, 1]
    /// (MaterialLaw::mobilised_strength()), the largest across a layer's
    /// thickness; 0 for an elastic material.
    double mobilised_strength;
    /// Whether a Gauss point across the thickness yields.
    bool plastic;
  };


  /// Where a profile sample lies: its run along the interface, its arc
  /// length along that run, and its position (z = 0 on a 2D mesh).
  struct ProfileSample
  {
    unsigned int run;
    double       arc_length;
    Point<3>     position;
  };


  /**
   * Where a sample of an interface surface (in a 3D body) lies: its
   * position, its frame (the first tangent t1 and the normal n; t2 = t1 x
   * n), and the patch of the surface it stands for, a quadrilateral.
   */
  struct SurfaceSample
  {
    Point<3>                position;
    Tensor<1, 3>            tangent;
    Tensor<1, 3>            normal;
    std::array<Point<3>, 4> patch;
  };


  /**
   * An interface's profile at one state: where its samples lie, and their
   * values at every station (one station in plane strain and 3D). A curve
   * (in a 2D mesh) has @p samples, a surface (in a 3D body)
   * @p surface_samples.
   */
  struct Profile
  {
    std::vector<ProfileSample>                samples;
    std::vector<SurfaceSample>                surface_samples;
    std::vector<std::vector<InterfaceValues>> stations;
  };


  /**
   * On many ranks, where each rank has computed the values of the samples
   * whose points it holds and left the others zero (InterfaceValues{}):
   * every rank receives every sample's values. Nothing on one rank.
   */
  void
  sum_over_ranks(std::vector<InterfaceValues> &values);


  /**
   * The CSV of a profile (thin layer or zero-thickness elements): one row
   * per sample and station, the run, arc length, position, station angle
   * (degrees) and the values. For a surface: the position x, y, z, the
   * frame (t1 and n) and the values.
   */
  std::string
  profile_csv(const Profile &profile, const Kinematics &kinematics);

  /**
   * The profile as a VTU for ParaView: each run a polyline through its
   * samples (z = 0), the values as point data (in Fourier scenes one set
   * per station, suffixed with its angle in degrees). A surface: each
   * sample's patch a quadrilateral, the values as cell data.
   */
  std::string
  profile_vtu(const Profile &profile, const Kinematics &kinematics);


} // namespace thinlayer

#endif
