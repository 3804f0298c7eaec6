#include <thinlayer/discretisation/mode_vectors.h>

namespace thinlayer
{
  void
  condense(const AffineConstraints<double> &constraints, ModeVector &v)
  {
    // The arithmetic and order of AffineConstraints::condense(), on the
    // lines this rank owns.
    v.zero_out_ghost_values();
    for (const auto &line : constraints.get_lines())
      if (v.in_local_range(line.index))
        {
          Assert(line.inhomogeneity == 0,
                 ExcMessage("Forces are condensed with homogeneous lines."));
          const double value = v(line.index);
          for (const auto &[dof, weight] : line.entries)
            v(dof) += value * weight;
        }
    v.compress(VectorOperation::add);
    for (const auto &line : constraints.get_lines())
      if (v.in_local_range(line.index))
        v(line.index) = 0;
  }


  void
  distribute(const AffineConstraints<double> &constraints, ModeVector &v)
  {
    // The DoFs an owned line names are the rank's own or its ghosts.
    v.update_ghost_values();
    for (const auto &line : constraints.get_lines())
      if (v.in_local_range(line.index))
        {
          double value = line.inhomogeneity;
          for (const auto &[dof, weight] : line.entries)
            value += v(dof) * weight;
          v(line.index) = value;
        }
    v.zero_out_ghost_values();
  }
} // namespace thinlayer
