// Truth checked on two ranks: input that one rank alone could not run is
// refused as on one rank, by every rank together: one message naming the
// file and the entry (printed by rank 0 only), the same non-zero exit
// status on every rank, the previous run and a file of the user's beside it
// kept byte for byte, and no staging directory left. The cases:
// - interface elements too soft for the cells beside them: MUMPS's L D L^T
//   meets a negative pivot where CHOLMOD on one rank finds the matrix not
//   positive definite (before, two ranks divided by the round-off and ran);
// - a mesh file that does not exist, met by rank 0 alone (it meshes);
// - an entry that is not a number.
#include <deal.II/base/mpi.h>

#include <thinlayer/parallel/mpi.h>

#include "../common/bad_input_utilities.h"
#include "../common/truths.h"

using namespace bad_input;
using namespace dealii;

namespace
{
  const std::string meshes = std::string(SOURCE_DIR) + "/../../meshes/";

  void
  barrier()
  {
    MPI_Barrier(thinlayer::mpi::communicator());
  }


  /// Run @p arguments on every rank; rank 0 prints what check() prints,
  /// with the exit statuses of all ranks.
  void
  check_on_ranks(const std::string              &what,
                 const std::vector<std::string> &arguments)
  {
    if (thinlayer::mpi::is_root())
      {
        std::filesystem::remove_all("results");
        std::filesystem::copy("previous",
                              "results",
                              std::filesystem::copy_options::recursive);
      }
    barrier();
    std::ostringstream out, err;
    const int status = thinlayer::run_command_line(arguments, out, err);
    const int lowest =
      Utilities::MPI::min(status, thinlayer::mpi::communicator());
    const int highest =
      Utilities::MPI::max(status, thinlayer::mpi::communicator());
    const bool silent_elsewhere =
      Utilities::MPI::max(thinlayer::mpi::is_root() || err.str().empty() ? 0
                                                                         : 1,
                          thinlayer::mpi::communicator()) == 0;
    const bool kept =
      thinlayer::mpi::is_root() && contents("results") == previous_run &&
      read_text("thesis.tex") == "\\chapter{}\n" && !staging_left();
    if (thinlayer::mpi::is_root())
      truths::failures +=
        (lowest != 0 && lowest == highest && silent_elsewhere && kept) ? 0 : 1;
    if (thinlayer::mpi::is_root())
      std::cout << "* " << what << "\n  exit status " << lowest
                << (lowest == highest ? " on every rank" : " NOT on every rank")
                << ", message only from rank 0: "
                << (silent_elsewhere ? "yes" : "NO") << ", previous run kept: "
                << (contents("results") == previous_run ? "yes" : "NO")
                << ", foreign file kept: "
                << (read_text("thesis.tex") == "\\chapter{}\n" ? "yes" : "NO")
                << ", staging left behind: " << (staging_left() ? "YES" : "no")
                << "\n  " << err.str() << '\n';
    barrier();
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi_session(argc, argv, 1);
  const bool                       root = thinlayer::mpi::is_root();
  if (root)
    {
      std::cout << "ranks: " << thinlayer::mpi::n_ranks() << "\n\n";
      write("good.geo", good_geo);
      write("thesis.tex", "\\chapter{}\n");
      write("good.prm", scene());
      write("soft-interface.prm", soft_interface_scene(meshes));
    }
  barrier();

  // The valid scene runs on both ranks, so that every failure below is due
  // to its one change.
  {
    std::ostringstream out, err;
    const int status = thinlayer::run_command_line({"good.prm"}, out, err);
    barrier();
    if (root)
      keep_valid_run(status);
    barrier();
  }

  check_on_ranks("an interface curve with a shear stiffness of 1e-20 E/h",
                 {"soft-interface.prm"});
  check_on_ranks("a mesh file that does not exist",
                 {"good.prm", "-s", "Mesh/File=missing.geo"});
  check_on_ranks("a Young's modulus that is not a number",
                 {"good.prm", "-s", "Material 1/Young's modulus=stiff"});
  return root ? truths::conclude() : 0;
}
