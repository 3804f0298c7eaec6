#include <thinlayer/analysis/mode_system.h>

namespace thinlayer
{
  void
  ModeSystem::condense(ModeVector &v) const
  {
    thinlayer::condense(constraints, v);
  }


  void
  ModeSystem::distribute(ModeVector &v) const
  {
    thinlayer::distribute(constraints, v);
  }


  void
  ModeSystem::solve(ModeVector &rhs)
  {
    if (iterative)
      iterative->solve(owned_entries(rhs));
    else if (distributed_factorisation)
      distributed_factorisation->solve(owned_entries(rhs));
    else if (spread())
      {
        gather_on_owner(rhs);
        substitute_on_owner();
        scatter_from_owner(rhs);
      }
    else
      factorisation.solve(owned_entries(rhs));
  }


  FactorCost
  ModeSystem::elastic_cost() const
  {
    if (iterative)
      return FactorCost();
    if (distributed_factorisation)
      return distributed_factorisation->cost();
    // A spread mode's factor is on its owner alone.
    const FactorCost local = factorisation.cost();
    return spread() ? FactorCost{mpi::max(local.factorisation),
                                 mpi::max(local.substitution)}
                    : local;
  }


  void
  ModeSystem::gather_on_owner(const ModeVector &rhs)
  {
    mpi::gather(parts, owned_entries(rhs), whole_rhs, owner);
  }


  void
  ModeSystem::substitute_on_owner()
  {
    if (mpi::rank() == owner)
      factorisation.solve(make_array_view(whole_rhs));
  }


  void
  ModeSystem::scatter_from_owner(ModeVector &rhs) const
  {
    mpi::scatter(parts, whole_rhs, owned_entries(rhs), owner);
  }
} // namespace thinlayer
