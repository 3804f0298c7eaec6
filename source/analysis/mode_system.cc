#include <thinlayer/analysis/mode_system.h>

namespace thinlayer
{
  namespace
  {
    /// The entries @p v owns, in order.
    ArrayView<double>
    owned_entries(ModeVector &v)
    {
      return make_array_view(v.begin(), v.begin() + v.locally_owned_size());
    }


    ArrayView<const double>
    owned_entries(const ModeVector &v)
    {
      return make_array_view(v.begin(), v.begin() + v.locally_owned_size());
    }
  } // namespace


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
        Vector<double> whole;
        gather_on_owner(rhs, whole);
        if (mpi::rank() == owner)
          factorisation.solve(make_array_view(whole));
        scatter_from_owner(whole, rhs);
      }
    else
      factorisation.solve(owned_entries(rhs));
  }


  void
  ModeSystem::gather_on_owner(const ModeVector &rhs,
                              Vector<double>   &whole) const
  {
    mpi::gather(owned_entries(rhs), whole, owner);
  }


  void
  ModeSystem::scatter_from_owner(const Vector<double> &whole,
                                 ModeVector           &rhs) const
  {
    mpi::scatter(whole, owned_entries(rhs), owner);
  }
} // namespace thinlayer
