#include <thinlayer/discretisation/mode_vectors.h>

#include <algorithm>

namespace thinlayer
{
  namespace
  {
    using Line = AffineConstraints<double>::ConstraintLine;

    /**
     * The lines of @p constraints whose DoF @p v owns: a contiguous range,
     * since close() sorts the lines by DoF and a rank owns a contiguous
     * range of DoFs. A rank thus walks its own lines only, not every rank's.
     */
    std::pair<std::vector<Line>::const_iterator,
              std::vector<Line>::const_iterator>
    owned_lines(const AffineConstraints<double> &constraints,
                const ModeVector                &v)
    {
      const auto &lines        = constraints.get_lines();
      const auto [first, last] = v.get_partitioner()->local_range();
      const auto before        = [](const Line                   &line,
                             const types::global_dof_index dof) {
        return line.index < dof;
      };
      return {std::lower_bound(lines.begin(), lines.end(), first, before),
              std::lower_bound(lines.begin(), lines.end(), last, before)};
    }
  } // namespace


  void
  condense(const AffineConstraints<double> &constraints, ModeVector &v)
  {
    // The arithmetic and order of AffineConstraints::condense(), on the
    // lines this rank owns.
    const auto [begin, end] = owned_lines(constraints, v);
    v.zero_out_ghost_values();
    for (auto line = begin; line != end; ++line)
      {
        Assert(line->inhomogeneity == 0,
               ExcMessage("Forces are condensed with homogeneous lines."));
        const double value = v(line->index);
        for (const auto &[dof, weight] : line->entries)
          v(dof) += value * weight;
      }
    v.compress(VectorOperation::add);
    for (auto line = begin; line != end; ++line)
      v(line->index) = 0;
  }


  void
  distribute(const AffineConstraints<double> &constraints, ModeVector &v)
  {
    // The DoFs an owned line names are the rank's own or its ghosts.
    const auto [begin, end] = owned_lines(constraints, v);
    v.update_ghost_values();
    for (auto line = begin; line != end; ++line)
      {
        double value = line->inhomogeneity;
        for (const auto &[dof, weight] : line->entries)
          value += v(dof) * weight;
        v(line->index) = value;
      }
    v.zero_out_ghost_values();
  }
} // namespace thinlayer
