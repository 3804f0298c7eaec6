// What the tests of a rough wall share (meshes/wall-backfill.geo): running
// one of its parameter files with the wall's friction delta given to the
// thin column (as sin(phi_w) = tan(delta), Davis 1968) or to the interface
// elements, on a mesh of its own.
#ifndef thinlayer_tests_wall_backfill_h
#define thinlayer_tests_wall_backfill_h

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "run_results.h"

namespace wall_backfill
{
  inline double
  radians(const double degrees)
  {
    return degrees * M_PI / 180;
  }


  /// The wall's normal thrust coefficient (the run's collapse load) of
  /// prm/@p stem.prm, or of its "-zero-thickness" variant if
  /// @p interface, with wall friction @p delta (degrees) and the mesh's
  /// geometry parameters @p geometry (zero_thickness = 1 added for the
  /// interface elements).
  inline double
  thrust(const std::string &stem,
         const bool         interface,
         const double       delta,
         const std::string &geometry)
  {
    const std::string prm = std::string(SOURCE_DIR) + "/../../prm/" + stem +
                            (interface ? "-zero-thickness" : "") + ".prm";
    char friction[96];
    if (interface)
      std::snprintf(friction,
                    sizeof(friction),
                    "Interface 6/Friction angle=%.17g",
                    delta);
    else
      std::snprintf(friction,
                    sizeof(friction),
                    "Material 2/Friction angle=%.17g",
                    std::asin(std::tan(radians(delta))) * 180 / M_PI);
    const std::vector<std::string> arguments = {
      prm,
      "-s",
      friction,
      "-s",
      "Mesh/Geometry parameters=" + geometry +
        (interface ? ", zero_thickness=1" : ""),
      "-s",
      "Output/Directory=results",
      "-s",
      "Output/Write VTU=false"};
    return run_results::run_and_read(arguments, "collapse_load");
  }
} // namespace wall_backfill

#endif
