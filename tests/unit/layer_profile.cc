// Truth checked: the interface profile (slip, opening and tractions along a
// thin layer) against a closed-form state. Case 1's column
// (meshes/inclined-column.geo, a band at alpha = 30 degrees, aspect ratio
// 10), all of one elastic material (E = 1, nu = 0.3), with its base moved
// as the exact field of uniaxial stress sigma_yy = -p (p = 1, the top's
// traction) prescribes, so that the whole body is under that uniform
// stress, which Q8 represents exactly:
// - the traction on the band, whose normal is n = (-sin a, cos a) and
//   tangent s = (cos a, sin a): shear -p sin a cos a, normal -p cos^2 a;
// - the face-to-face difference of displacement, eps d with d the offset
//   between the facing points of the band's two faces (here vertical, its
//   height t_v = 1 / (AR cos^2 a)): slip (eps d) . s and opening (eps d) . n.
// In plane strain eps = (nu (1 + nu), -(1 - nu^2)) p / E; revolved as a
// hollow cylinder (x0 = 1, Fourier harmonic 0) it is (nu, -1) p / E in
// (r, z), and the base's radial displacement nu p r / E. Only eps_yy
// enters, d being vertical.
// Also: one run along the band, from the left, its arc length increasing
// through the band's length; and the cell averages of the fields
// (CellFields) of every cell the uniform stress, sigma_zz = nu (sigma_xx +
// sigma_yy) in plane strain, each cell's on the rank that owns it.
// Run on 2 ranks (layer_profile.mpirun=2.output), where each rank holds
// the points of its own cells, the same truths hold for the values every
// rank receives; rank 0 prints, and says over how many ranks the band's
// cells lie.
#include <deal.II/base/mpi.h>

#include <thinlayer/parallel/mpi.h>
#include <thinlayer/postprocess/cell_fields.h>
#include <thinlayer/postprocess/layer_profile.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>

#include "../common/parallel_truths.h"
#include "../common/scene_test_utilities.h"

namespace
{
  /// The column, uniform uniaxial stress, with @p kinematics and the
  /// base's prescribed displacement @p base.
  std::string
  column(const std::string &geometry,
         const std::string &kinematics,
         const std::string &base,
         const std::string &top_traction)
  {
    return "subsection Mesh\n"
           "  set File = " SOURCE_DIR "/../../meshes/inclined-column.geo\n"
           "  set Geometry parameters = alpha=30, aspect_ratio=10, "
           "elements_along=4, elements_block=2" +
           geometry + "\nend\n" + kinematics +
           "subsection Material 1\n"
           "  set Young's modulus = 1\n  set Poisson's ratio = 0.3\nend\n"
           "subsection Material 2\n"
           "  set Young's modulus = 1\n  set Poisson's ratio = 0.3\nend\n"
           "subsection Boundary 1\n"
           "  set Constrained components = " +
           (kinematics.empty() ? "x, y" : "r, z") +
           "\n  set Displacement = " + base +
           "\nend\n"
           "subsection Boundary 2\n  set Traction = " +
           top_traction +
           "\nend\n"
           "subsection Layers\n  set Material ids = 2\nend\n"
           "subsection Monitors\n  set Displacement boundary id = 2\nend\n";
  }


  void
  check(const std::string &title,
        const std::string &prm,
        const double       eps_vertical,
        const double       sigma_zz)
  {
    std::cout << title << '\n';
    thinlayer_tests::with_solved_step(
      prm,
      "column.prm",
      [&](const thinlayer::Analysis<2> &analysis,
          const thinlayer::Parameters &) {
        const thinlayer::LayerProfile<2> profile(analysis, 2, "column.prm");
        const auto                       values = profile.evaluate(analysis, 0);
        const double                     a      = 30 * M_PI / 180;
        const double t_v        = 1 / (10 * std::cos(a) * std::cos(a));
        const double jump[2]    = {0, eps_vertical * t_v};
        const double exact_slip = jump[0] * std::cos(a) + jump[1] * std::sin(a);
        const double exact_opening =
          -jump[0] * std::sin(a) + jump[1] * std::cos(a);
        const double exact_shear  = -std::sin(a) * std::cos(a);
        const double exact_normal = -std::cos(a) * std::cos(a);
        double       error = 0, out_of_plane = 0;
        for (const auto &v : values)
          {
            error = std::max(
              {error,
               std::abs(v.slip - exact_slip) / std::abs(exact_slip),
               std::abs(v.opening - exact_opening) / std::abs(exact_opening),
               std::abs(v.shear_traction - exact_shear) / std::abs(exact_shear),
               std::abs(v.normal_traction - exact_normal) /
                 std::abs(exact_normal)});
            out_of_plane = std::max({out_of_plane,
                                     std::abs(v.slip_out_of_plane),
                                     std::abs(v.shear_traction_out_of_plane)});
          }
        std::printf("  %u samples; exact: slip %.5f, opening %.5f, shear "
                    "%.5f, normal %.5f\n",
                    profile.n_points(),
                    exact_slip,
                    exact_opening,
                    exact_shear,
                    exact_normal);
        std::printf("  largest relative error: %s\n",
                    error < 1e-8 ? "below 1e-8"
                                 : std::to_string(error).c_str());
        std::printf("  out-of-plane slip and shear: %s\n",
                    out_of_plane < 1e-12 ? "zero" : "NOT zero");

        // The run and its arc length, from the CSV.
        std::istringstream csv(
          thinlayer::profile_csv(profile.profile(analysis),
                                 analysis.get_kinematics()));
        std::string line;
        std::getline(csv, line);
        double previous = -1, first = -1, last = -1, x_previous = -1;
        bool   one_run = true, increasing = true, rightwards = true;
        while (std::getline(csv, line))
          {
            unsigned int run;
            double       arc, x;
            std::sscanf(line.c_str(), "%u,%lf,%lf", &run, &arc, &x);
            one_run    = one_run && run == 0;
            increasing = increasing && arc > previous;
            rightwards = rightwards && x > x_previous;
            if (first < 0)
              first = arc;
            previous = last = arc;
            x_previous      = x;
          }
        std::printf("  one run: %s; arc length increasing: %s, from the "
                    "left: %s, within the band's length %.4f: %s\n",
                    one_run ? "yes" : "NO",
                    increasing ? "yes" : "NO",
                    rightwards ? "yes" : "NO",
                    1 / std::cos(a),
                    first > 0 && last < 1 / std::cos(a) ? "yes" : "NO");

        // Every cell's averages: sigma_yy = -1, sigma_zz as given, the
        // other components zero.
        // Each rank has its own cells' averages.
        const thinlayer::CellFields fields(analysis);
        const double                exact_stress[4] = {0, -1, sigma_zz, 0};
        double                      field_error     = 0;
        for (unsigned int k = 0; k < 4; ++k)
          for (unsigned int c = 0; c < fields.stress[0][k].size(); ++c)
            if (analysis.get_cells().owns(c))
              field_error =
                std::max(field_error,
                         std::abs(fields.stress[0][k][c] - exact_stress[k]));
        field_error = thinlayer::mpi::max(field_error);
        std::printf("  every cell's average stress (0, -1, %.2f, 0): %s\n",
                    sigma_zz,
                    field_error < 1e-8 ? "yes" : "NO");

        bool holds_band = false;
        for (const auto &cell :
             analysis.get_dof_handler().active_cell_iterators())
          holds_band = holds_band ||
                       (cell->material_id() == 2 &&
                        analysis.get_cells().owns(cell->active_cell_index()));
        if (thinlayer::mpi::n_ranks() > 1)
          std::printf("  the band's cells on %u ranks\n",
                      thinlayer::mpi::sum(holds_band ? 1u : 0u));
      });
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi_session(argc, argv, 1);
  // Every rank checks the same values; rank 0 prints.
  if (!truths::print_on_rank_zero())
    return 1;
  check("Plane strain:", column("", "", "0.39*x; 0", "0; -1"), -0.91, -0.3);
  check("Fourier, harmonic 0, revolved as a hollow cylinder:",
        column(", x0=1",
               "subsection Kinematics\n  set Type = fourier\n  set Harmonics "
               "= 0\n  set Stations = 0\nend\n",
               "0.3*r*cos(theta); 0.3*r*sin(theta); 0",
               "0; 0; -1"),
        -1,
        0);
}
