#include <thinlayer/analysis/linear_solver_choice.h>
#include <thinlayer/base/text_format.h>

namespace thinlayer
{
  LinearSolverChoice
  choose_linear_solver(const SolverParameters &parameters,
                       const unsigned int      n_ranks,
                       const unsigned int      dimension)
  {
    using Given             = SolverParameters::LinearSolver;
    using Kind              = LinearSolverChoice::Kind;
    const Given       given = parameters.linear_solver;
    const std::string entry =
      "Linear solver = " + SolverParameters::linear_solver_names.name(given);
    const std::string ranks = n_ranks == 1 ? std::string("one rank")
                                           : std::to_string(n_ranks) + " ranks";
    const std::string compression =
      "MUMPS with block low-rank compression to " +
      text_format::printf("%g", parameters.block_low_rank_tolerance);

    LinearSolverChoice choice;
    switch (given)
      {
        case Given::amg_cg:
          choice.kind        = Kind::amg_cg;
          choice.description = "conjugate gradients preconditioned by "
                               "PETSc's GAMG (" +
                               entry + ")";
          return choice;
        case Given::block_low_rank:
          // SolverParameters::parse() refuses it on one rank.
          choice.kind                     = Kind::mumps;
          choice.block_low_rank_tolerance = parameters.block_low_rank_tolerance;
          choice.description              = compression + " (" + entry + ")";
          return choice;
        case Given::automatic:
          if (n_ranks == 1)
            {
              choice.kind        = Kind::cholmod;
              choice.description = "CHOLMOD (automatic: one rank)";
            }
          else if (dimension == 3)
            {
              choice.kind = Kind::mumps;
              choice.block_low_rank_tolerance =
                parameters.block_low_rank_tolerance;
              choice.description =
                compression + " (automatic: " + ranks + ", a 3D mesh)";
            }
          else
            {
              choice.kind = Kind::mumps;
              choice.description =
                "MUMPS (automatic: " + ranks +
                ", a plane mesh, its fronts too small to compress)";
            }
          return choice;
        case Given::cholmod:
        case Given::umfpack:
          if (n_ranks > 1)
            {
              choice.kind        = Kind::mumps;
              choice.description = "MUMPS (" + entry + " on " + ranks + ")";
            }
          else
            {
              choice.kind =
                given == Given::cholmod ? Kind::cholmod : Kind::umfpack;
              choice.description =
                (given == Given::cholmod ? "CHOLMOD" : "UMFPACK") +
                std::string(" (") + entry + ")";
            }
          return choice;
      }
    return choice;
  }
} // namespace thinlayer
