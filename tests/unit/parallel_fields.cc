// Truths checked for the fields a run on several ranks writes (run on
// three ranks, a coarse Prandtl scene of 60 cells, VTU subdivisions 2):
// 1. fields.pvd lists one fields-NNNN.pvtu per written step, and no whole
//    fields-NNNN.vtu is written.
// 2. Every .pvtu lists one piece per rank, fields-NNNN.RRRR.vtu, each of
//    them written.
// 3. Each piece holds exactly its rank's cells (partition_cells() of the
//    scene's mesh, times 2 x 2 subdivisions), so the pieces together hold
//    every cell once.
// 4. The pieces carry the fields a one-rank file carries, by name.
// 5. Nothing half-written is left (no .partial file), and history.csv and
//    summary.json are there once.
// 6. fields.pvd lists the states of the load-displacement curve only: the
//    third step (to 1.1 of the collapse load, the programme as given)
//    fails, and its fields are listed in attempts.pvd instead.
// Rank 0 reads the files and prints whether each truth held.
#include <deal.II/base/mpi.h>

#include <thinlayer/app/run.h>
#include <thinlayer/mesh/scene.h>
#include <thinlayer/parallel/cell_partition.h>
#include <thinlayer/parallel/mpi.h>
#include <thinlayer/parameters/parameter_reader.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>

#include "../common/truths.h"

using namespace thinlayer;

namespace
{
  const std::string prm =
    "subsection Mesh\n"
    "  set File = " SOURCE_DIR "/../../meshes/prandtl.geo\n"
    "  set Geometry parameters = half_width=1, width=4, depth=2, "
    "n_footing=4, n_side=6, n_depth=6, growth=1.2\n"
    "end\n"
    "subsection Material 1\n"
    "  set Young's modulus = 1\n"
    "  set Poisson's ratio = 0.3\n"
    "  set Yield criterion = tresca\n"
    "  set Cohesion = 1e-3\n"
    "end\n"
    "subsection Boundary 1\n"
    "  set Pressure = (2 + pi) * 1e-3\n"
    "end\n"
    "subsection Boundary 3\n"
    "  set Constrained components = x\n"
    "end\n"
    "subsection Boundary 4\n"
    "  set Constrained components = x, y\n"
    "end\n"
    "subsection Boundary 5\n"
    "  set Constrained components = x\n"
    "end\n"
    "subsection Loading\n"
    "  set Load increments = 0.5, 0.3, 0.3\n"
    "  set Collapse resolution = 0\n"
    "end\n"
    "subsection Monitors\n"
    "  set Load measure = reaction\n"
    "  set Load boundary id = 4\n"
    "  set Load component = y\n"
    "  set Displacement boundary id = 1\n"
    "  set Displacement component = y\n"
    "end\n"
    "subsection Output\n"
    "  set Directory = parallel_fields_results\n"
    "  set Write VTU = true\n"
    "  set VTU subdivisions = 2\n"
    "  set Progress interval = 0\n"
    "end\n";


  std::string
  read(const std::filesystem::path &path)
  {
    std::ifstream      in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }


  /// Every match of the first group of @p pattern in @p text.
  std::vector<std::string>
  all_matches(const std::string &text, const std::string &pattern)
  {
    std::vector<std::string> found;
    const std::regex         re(pattern);
    for (auto it = std::sregex_iterator(text.begin(), text.end(), re);
         it != std::sregex_iterator();
         ++it)
      found.push_back((*it)[1]);
    return found;
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi_session(argc, argv, 1);
  const unsigned int               n = mpi::n_ranks();

  const Parameters p =
    ParameterReader().read_from_string(prm, "parallel_fields.prm");
  std::ostringstream quiet;
  run_scene(p, quiet);
  // The scene again (every rank takes part in meshing it), for the cells
  // each rank owned in the run.
  const Scene<2> scene(p, quiet);
  if (!mpi::is_root())
    return 0;
  const CellPartition partition = partition_cells(scene.triangulation(), n, 0);
  std::vector<unsigned int> owned(n, 0);
  for (const unsigned int r : partition.owner)
    ++owned[r];

  const std::filesystem::path dir = p.output.directory;
  std::cout << "ranks: " << n << ", cells: " << partition.owner.size() << '\n';

  const std::vector<std::string> records =
    all_matches(read(dir / "fields.pvd"), "file=\"([^\"]+)\"");
  bool records_are_pvtu = !records.empty();
  for (const std::string &record : records)
    records_are_pvtu &=
      std::regex_match(record, std::regex("fields-\\d{4}\\.pvtu"));
  bool no_whole_vtu = true;
  for (const auto &entry : std::filesystem::directory_iterator(dir))
    no_whole_vtu &= !std::regex_match(entry.path().filename().string(),
                                      std::regex("fields-\\d{4}\\.vtu"));
  const std::vector<std::string> attempts =
    all_matches(read(dir / "attempts.pvd"), "file=\"([^\"]+)\"");
  std::cout << "written steps: " << records.size() << " in fields.pvd, "
            << attempts.size() << " in attempts.pvd\n";
  truths::expect(records_are_pvtu && no_whole_vtu,
                 "1. fields.pvd lists a .pvtu per step, no whole .vtu");

  bool pieces_listed = true, pieces_own_cells = true, fields_named = true;
  const std::vector<std::string> one_rank_fields = {"displacement",
                                                    "stress_xx",
                                                    "stress_yy",
                                                    "stress_zz",
                                                    "stress_xy",
                                                    "equivalent_stress",
                                                    "plastic_strain",
                                                    "yield_ratio",
                                                    "material_id"};
  for (const std::string &record : records)
    {
      const std::string pvtu   = read(dir / record);
      const auto        pieces = all_matches(pvtu, "Source=\"([^\"]+)\"");
      const std::string stem   = record.substr(0, record.size() - 5);
      pieces_listed &= pieces.size() == n;
      fields_named &=
        all_matches(pvtu, "PDataArray type=\"Float32\" Name=\"([^\"]+)\"") ==
        one_rank_fields;
      for (unsigned int r = 0; r < pieces.size() && r < n; ++r)
        {
          pieces_listed &=
            pieces[r] == stem + "." + Utilities::int_to_string(r, 4) + ".vtu";
          const auto cells =
            all_matches(read(dir / pieces[r]), "NumberOfCells=\"(\\d+)\"");
          pieces_own_cells &=
            cells.size() == 1 && std::stoul(cells[0]) == 4 * owned[r];
        }
    }
  truths::expect(pieces_listed,
                 "2. every .pvtu lists fields-NNNN.RRRR.vtu for each rank");
  truths::expect(pieces_own_cells,
                 "3. each piece holds its rank's cells (x 4 subdivisions)");
  truths::expect(fields_named, "4. the fields of a one-rank file, by name");

  bool partial = false;
  for (const auto &entry : std::filesystem::directory_iterator(dir))
    partial |= entry.path().extension() == ".partial";
  truths::expect(!partial && std::filesystem::exists(dir / "history.csv") &&
                   std::filesystem::exists(dir / "summary.json"),
                 "5. no .partial file; history.csv and summary.json written");
  truths::expect(records.size() == 2 && attempts.size() == 1 &&
                   attempts[0] == "fields-0003.pvtu",
                 "6. fields.pvd lists the two converged steps, attempts.pvd "
                 "the failed third");
  return truths::conclude();
}
