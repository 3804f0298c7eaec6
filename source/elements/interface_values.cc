#include <deal.II/lac/vector.h>

#include <thinlayer/base/text_format.h>
#include <thinlayer/elements/interface_values.h>
#include <thinlayer/parallel/mpi.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace thinlayer
{
  void
  sum_over_ranks(std::vector<InterfaceValues> &values)
  {
    if (mpi::n_ranks() == 1)
      return;
    // Every member, the flag as 0 or 1: a sum of the owner's value and
    // zeros is the owner's value.
    constexpr unsigned int n = 10;
    static_assert(sizeof(InterfaceValues) == n * sizeof(double),
                  "every member of InterfaceValues is packed below");
    Vector<double> packed(n * values.size());
    for (unsigned int k = 0; k < values.size(); ++k)
      {
        const InterfaceValues &v      = values[k];
        const double           row[n] = {v.slip,
                                         v.slip_out_of_plane,
                                         v.opening,
                                         v.slip_increment,
                                         v.opening_increment,
                                         v.shear_traction,
                                         v.shear_traction_out_of_plane,
                                         v.normal_traction,
                                         v.mobilised_strength,
                               v.plastic ? 1. : 0.};
        std::copy(row, row + n, packed.begin() + n * k);
      }
    mpi::sum(packed);
    for (unsigned int k = 0; k < values.size(); ++k)
      {
        const double *row = packed.begin() + n * k;
        values[k]         = {row[0],
                             row[1],
                             row[2],
                             row[3],
                             row[4],
                             row[5],
                             row[6],
                             row[7],
                             row[8],
                             row[9] != 0};
      }
  }


  namespace
  {
    /// The CSV of a surface's profile (one station).
    std::string
    surface_csv(const Profile &profile)
    {
      const auto         number = text_format::csv_number;
      std::ostringstream out;
      out << "x,y,z,t1_x,t1_y,t1_z,n_x,n_y,n_z,slip_1,slip_2,opening,"
             "slip_increment_1,opening_increment,shear_traction_1,"
             "shear_traction_2,normal_traction,mobilised_strength,plastic\n";
      const auto &values = profile.stations[0];
      for (unsigned int k = 0; k < profile.surface_samples.size(); ++k)
        {
          const SurfaceSample   &s = profile.surface_samples[k];
          const InterfaceValues &v = values[k];
          for (unsigned int d = 0; d < 3; ++d)
            out << number(s.position[d]) << ',';
          for (unsigned int d = 0; d < 3; ++d)
            out << number(s.tangent[d]) << ',';
          for (unsigned int d = 0; d < 3; ++d)
            out << number(s.normal[d]) << ',';
          out << number(v.slip) << ',' << number(v.slip_out_of_plane) << ','
              << number(v.opening) << ',' << number(v.slip_increment) << ','
              << number(v.opening_increment) << ',' << number(v.shear_traction)
              << ',' << number(v.shear_traction_out_of_plane) << ','
              << number(v.normal_traction) << ','
              << number(v.mobilised_strength) << ',' << (v.plastic ? 1 : 0)
              << '\n';
        }
      return out.str();
    }
  } // namespace


  std::string
  profile_csv(const Profile &profile, const Kinematics &kinematics)
  {
    if (!profile.surface_samples.empty())
      return surface_csv(profile);
    const std::vector<ProfileSample> &samples = profile.samples;
    const auto                        number  = text_format::csv_number;
    std::ostringstream                out;
    out << "run,arc_length,x,y,angle,slip,slip_out_of_plane,opening,"
           "slip_increment,opening_increment,shear_traction,"
           "shear_traction_out_of_plane,normal_traction,mobilised_strength,"
           "plastic\n";
    for (unsigned int station = 0; station < kinematics.n_stations(); ++station)
      {
        const double angle =
          kinematics.station_angle(station) * 180 / numbers::PI;
        const std::vector<InterfaceValues> &at_station =
          profile.stations[station];
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
                << number(v.normal_traction) << ','
                << number(v.mobilised_strength) << ',' << (v.plastic ? 1 : 0)
                << '\n';
          }
      }
    return out.str();
  }


  std::string
  profile_vtu(const Profile &profile, const Kinematics &kinematics)
  {
    const std::vector<ProfileSample> &samples = profile.samples;
    std::ostringstream                out;
    out << std::setprecision(10);
    const bool surface = !profile.surface_samples.empty();
    if (surface)
      {
        // Each sample's patch a quadrilateral, its values the cell's.
        const auto &patches = profile.surface_samples;
        out << "<?xml version=\"1.0\"?>\n"
            << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" "
               "byte_order=\"LittleEndian\">\n<UnstructuredGrid>\n"
            << "<Piece NumberOfPoints=\"" << 4 * patches.size()
            << "\" NumberOfCells=\"" << patches.size() << "\">\n"
            << "<Points>\n<DataArray type=\"Float64\" "
               "NumberOfComponents=\"3\" format=\"ascii\">\n";
        for (const SurfaceSample &s : patches)
          for (const Point<3> &x : s.patch)
            out << x[0] << ' ' << x[1] << ' ' << x[2] << '\n';
        out << "</DataArray>\n</Points>\n<Cells>\n"
            << "<DataArray type=\"Int64\" Name=\"connectivity\" "
               "format=\"ascii\">\n";
        for (std::size_t k = 0; k < 4 * patches.size(); ++k)
          out << k << '\n';
        out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" "
               "format=\"ascii\">\n";
        for (std::size_t k = 1; k <= patches.size(); ++k)
          out << 4 * k << '\n';
        out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" "
               "format=\"ascii\">\n";
        for (std::size_t k = 0; k < patches.size(); ++k)
          out << "9\n"; // VTK_QUAD
        out << "</DataArray>\n</Cells>\n<CellData>\n";
      }
    else
      {
        // The runs, each a polyline through its samples in order.
        std::vector<std::vector<unsigned int>> runs;
        for (unsigned int k = 0; k < samples.size(); ++k)
          {
            if (samples[k].run >= runs.size())
              runs.resize(samples[k].run + 1);
            runs[samples[k].run].push_back(k);
          }
        out << "<?xml version=\"1.0\"?>\n"
            << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" "
               "byte_order=\"LittleEndian\">\n<UnstructuredGrid>\n"
            << "<Piece NumberOfPoints=\"" << samples.size()
            << "\" NumberOfCells=\"" << runs.size() << "\">\n"
            << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" "
               "format=\"ascii\">\n";
        for (const ProfileSample &s : samples)
          out << s.position[0] << ' ' << s.position[1] << " 0\n";
        out << "</DataArray>\n</Points>\n<Cells>\n"
            << "<DataArray type=\"Int64\" Name=\"connectivity\" "
               "format=\"ascii\">\n";
        for (const auto &run : runs)
          for (const unsigned int k : run)
            out << k << '\n';
        out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" "
               "format=\"ascii\">\n";
        std::size_t offset = 0;
        for (const auto &run : runs)
          out << (offset += run.size()) << '\n';
        out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" "
               "format=\"ascii\">\n";
        for (std::size_t r = 0; r < runs.size(); ++r)
          out << "4\n"; // VTK_POLY_LINE
        out << "</DataArray>\n</Cells>\n<PointData>\n";
      }

    using Field = double                              InterfaceValues::*;
    const std::vector<std::pair<const char *, Field>> fields = {
      {"slip", &InterfaceValues::slip},
      {"slip_out_of_plane", &InterfaceValues::slip_out_of_plane},
      {"opening", &InterfaceValues::opening},
      {surface ? "slip_increment_1" : "slip_increment",
       &InterfaceValues::slip_increment},
      {"opening_increment", &InterfaceValues::opening_increment},
      {surface ? "shear_traction_1" : "shear_traction",
       &InterfaceValues::shear_traction},
      {surface ? "shear_traction_2" : "shear_traction_out_of_plane",
       &InterfaceValues::shear_traction_out_of_plane},
      {"normal_traction", &InterfaceValues::normal_traction},
      {"mobilised_strength", &InterfaceValues::mobilised_strength}};
    for (unsigned int station = 0; station < kinematics.n_stations(); ++station)
      {
        const std::string suffix =
          kinematics.is_fourier()
            ? "_" + std::to_string(static_cast<int>(std::round(
                      kinematics.station_angle(station) * 180 / numbers::PI)))
            : std::string();
        const auto &values = profile.stations[station];
        for (const auto &[name, field] : fields)
          {
            out << "<DataArray type=\"Float64\" Name=\"" << name << suffix
                << "\" format=\"ascii\">\n";
            for (const InterfaceValues &v : values)
              out << (std::isfinite(v.*field) ? v.*field : 0.) << '\n';
            out << "</DataArray>\n";
          }
        out << "<DataArray type=\"UInt8\" Name=\"plastic" << suffix
            << "\" format=\"ascii\">\n";
        for (const InterfaceValues &v : values)
          out << (v.plastic ? 1 : 0) << '\n';
        out << "</DataArray>\n";
      }
    out << (surface ? "</CellData>" : "</PointData>")
        << "\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
    return out.str();
  }
} // namespace thinlayer
