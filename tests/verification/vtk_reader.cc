// Truth checked: a real client reads the output. The thinlayer program
// runs an elastic scene whose exact solution is known, serially and under
// mpirun on two ranks, and VTK's own XML readers (python3-vtk9, the library
// ParaView reads with; vtk_reader.py beside this file) open what it wrote:
// fields.pvd and the files it lists (.vtu serially, .pvtu and its pieces on
// two ranks) and the layer's profile VTUs, each without a reader error or
// warning, with points and cells, the point-data arrays the fields and the
// profile hold with their numbers of components and one tuple per point,
// the same numbers of points and cells on two ranks as serially, and the
// values of the exact solution at every point:
//
// the inclined column (meshes/inclined-column.geo) crossed by a layer of
// material 2 at 30 degrees, every material elastic (E = 1000, nu = 0.25),
// sides free, a traction (0, -p) on the top (p = 1) and u = (a x, 0) on the
// base, a = nu (1 + nu) p / E, is under uniaxial plane-strain compression:
// at load factor L, sigma_yy = -L p, sigma_xx = sigma_xy = 0, sigma_zz =
// -L nu p and u = L (a x, -b y), b = (1 - nu^2) p / E, which quadratic
// elements reproduce to round-off; on the layer the shear and normal
// tractions are -L p cos sin and -L p cos^2, and slip and opening the jump
// of u across the layer's vertical offset tv. The fields' VTU holds Float32
// (6e-8 of each value), checked to 1e-6 of the field's scale; the
// profile's VTU holds 10 significant digits, checked to 1e-8 (see
// vtk_reader.py for the derivation). Two load steps (L = 0.5, 1).
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include <sys/wait.h>

namespace
{
  constexpr const char *young        = "1000";
  constexpr const char *poisson      = "0.25";
  constexpr const char *pressure     = "1";
  constexpr const char *alpha        = "30";
  constexpr const char *aspect_ratio = "10";
  constexpr const char *layer_id     = "2";
  constexpr const char *steps        = "2";

  std::string
  read_text(const std::string &name)
  {
    std::ostringstream text;
    text << std::ifstream(name).rdbuf();
    return text.str();
  }

  /// Run @p command with its output into @p log; its exit status (-1 if it
  /// did not exit).
  int
  run(const std::string &command, const std::string &log)
  {
    const int status =
      std::system((command + " > " + log + " 2>&1 < /dev/null").c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

  /// The scene: the base's displacement a x is written out, as the
  /// parameter file takes it.
  std::string
  scene()
  {
    const double E = std::stod(young), nu = std::stod(poisson),
                 p = std::stod(pressure);
    std::ostringstream a;
    a.precision(17);
    a << nu * (1 + nu) * p / E;
    return std::string("subsection Mesh\n"
                       "  set File = " SOURCE_DIR
                       "/../../meshes/inclined-column.geo\n"
                       "  set Geometry parameters = alpha=") +
           alpha + ", aspect_ratio=" + aspect_ratio +
           ", elements_along=4, elements_block=2\n"
           "end\n"
           "subsection Layers\n"
           "  set Material ids = " +
           layer_id +
           "\n"
           "end\n"
           "subsection Material 1\n"
           "  set Young's modulus = " +
           young + "\n  set Poisson's ratio = " + poisson +
           "\n"
           "end\n"
           "subsection Material 2\n"
           "  set Young's modulus = " +
           young + "\n  set Poisson's ratio = " + poisson +
           "\n"
           "end\n"
           "subsection Boundary 1\n"
           "  set Constrained components = x, y\n"
           "  set Displacement = " +
           a.str() +
           "*x; 0\n"
           "end\n"
           "subsection Boundary 2\n"
           "  set Traction = 0; -" +
           pressure +
           "\n"
           "end\n"
           "subsection Loading\n"
           "  set Load increments = 0.5, 0.5\n"
           "end\n"
           "subsection Monitors\n"
           "  set Displacement boundary id = 2\n"
           "end\n"
           "subsection Output\n"
           "  set Directory = serial\n"
           "  set Print timing = false\n"
           "end\n";
  }
} // namespace


int
main()
{
  for (const char *directory : {"serial", "two-ranks"})
    std::filesystem::remove_all(directory);
  std::ofstream("vtk_reader.prm") << scene();

  // The same program serially and on two ranks, with the suite's mpirun
  // flags (tests/CMakeLists.txt).
  const std::string program  = THINLAYER_EXECUTABLE " vtk_reader.prm";
  const int         serial   = run(program, "serial.log");
  const int         parallel = run(THINLAYER_MPIRUN_2_RANKS " " + program +
                             " -s \"Output/Directory=two-ranks\"",
                           "two-ranks.log");
  std::cout << "thinlayer serially: exit status " << serial
            << "\nthinlayer on 2 ranks (mpirun): exit status " << parallel
            << "\n";
  if (serial != 0)
    std::cout << read_text("serial.log");
  if (parallel != 0)
    std::cout << read_text("two-ranks.log");

  const int reader =
    run(std::string(THINLAYER_VTK_PYTHON " " SOURCE_DIR "/vtk_reader.py") +
          " --young " + young + " --poisson " + poisson + " --pressure " +
          pressure + " --alpha " + alpha + " --aspect-ratio " + aspect_ratio +
          " --layer-id " + layer_id + " --steps " + steps +
          " 'serial:1=serial' '2 ranks:2=two-ranks'",
        "vtk_reader.txt");
  std::cout << read_text("vtk_reader.txt") << "VTK's readers: exit status "
            << reader << "\n";
  return serial == 0 && parallel == 0 && reader == 0 ? 0 : 1;
}
