#include <thinlayer/interface_values.h>
#include <thinlayer/text_format.h>

#include <sstream>

namespace thinlayer
{
  std::string
  profile_csv(
    const std::vector<ProfileSample>                                &samples,
    const Kinematics                                                &kinematics,
    const std::function<std::vector<InterfaceValues>(unsigned int)> &values)
  {
    const auto         number = text_format::csv_number;
    std::ostringstream out;
    out << "run,arc_length,x,y,angle,slip,slip_out_of_plane,opening,"
           "slip_increment,opening_increment,shear_traction,"
           "shear_traction_out_of_plane,normal_traction,yield_ratio,"
           "plastic\n";
    for (unsigned int station = 0; station < kinematics.n_stations(); ++station)
      {
        const double angle =
          kinematics.station_angle(station) * 180 / numbers::PI;
        const std::vector<InterfaceValues> at_station = values(station);
        for (unsigned int k = 0; k < samples.size(); ++k)
          {
            const ProfileSample   &s = samples[k];
            const InterfaceValues &v = at_station[k];
            out << s.run << ',' << number(s.arc_length) << ','
                << number(s.position[0]) << ',' << number(s.position[1]) << ','
                << number(angle) << ',' << number(v.slip) << ','
                << number(v.slip_out_of_plane) << ',' << number(v.opening)
                << ',' << number(v.slip_increment) << ','
                << number(v.opening_increment) << ','
                << number(v.shear_traction) << ','
                << number(v.shear_traction_out_of_plane) << ','
                << number(v.normal_traction) << ',' << number(v.yield_ratio)
                << ',' << (v.plastic ? 1 : 0) << '\n';
          }
      }
    return out.str();
  }
} // namespace thinlayer
