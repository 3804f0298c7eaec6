#ifndef thinlayer_discretisation_mode_vectors_h
#define thinlayer_discretisation_mode_vectors_h

#include <deal.II/base/array_view.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /**
   * A vector over the DoFs of the one DoFHandler, distributed as deal.II's
   * parallel codes distribute it: each rank stores the DoFs it owns (a
   * contiguous range, as the distributed DoFHandler numbers them) and, as
   * ghosts, the other DoFs its cells and elements touch and its constraints
   * read. Operations on the vector (norms, dot products, additions) act on the
   * owned entries and reduce over the ranks; the ghosts are for the point
   * rules, which read them (update_ghost_values()) and add forces into them
   * (compress()). On one rank it owns every DoF and has no ghosts.
   */
  using ModeVector = LinearAlgebra::distributed::Vector<double>;

  /**
   * One ModeVector per mode (one in plane strain, one per Fourier
   * harmonic): displacements, forces and loads, the currency between the
   * analysis, its element groups and the solution methods. Each holder says
   * what its vectors mean; the type says only how they are laid out.
   */
  using ModeVectors = std::vector<ModeVector>;


  /// The entries of the DoFs @p v owns, in order: what the solvers and the
  /// gathers take of it.
  inline ArrayView<double>
  owned_entries(ModeVector &v)
  {
    return make_array_view(v.begin(), v.begin() + v.locally_owned_size());
  }


  inline ArrayView<const double>
  owned_entries(const ModeVector &v)
  {
    return make_array_view(v.begin(), v.begin() + v.locally_owned_size());
  }


  /**
   * The ghost values of some mode vectors imported for as long as this
   * object lives, and zeroed again at its end: vectors outside a point rule
   * or a read of the fields hold no ghost values, so that assigning them
   * and adding forces into them need no communication. Every rank must
   * create and destroy it at the same point (importing is collective).
   */
  class GhostValues
  {
  public:
    explicit GhostValues(const ModeVectors &vectors)
    {
      for (const ModeVector &v : vectors)
        add(v);
    }

    explicit GhostValues(const ModeVector &vector)
    {
      add(vector);
    }

    GhostValues(const GhostValues &) = delete;

    GhostValues &
    operator=(const GhostValues &) = delete;

    ~GhostValues()
    {
      for (const ModeVector *v : vectors)
        v->zero_out_ghost_values();
    }

    /// Import the ghost values of @p v too.
    void
    add(const ModeVector &v)
    {
      v.update_ghost_values();
      vectors.push_back(&v);
    }

  private:
    std::vector<const ModeVector *> vectors;
  };


  /**
   * Condense @p v, a vector of forces, with the homogeneous @p constraints:
   * add each constrained DoF's value to the DoFs its line names, then zero
   * it; on one rank what AffineConstraints::condense() does. On several,
   * each rank takes the lines it owns, adds into its ghosts where another
   * rank owns a DoF they name, and compress() sums those into their owners.
   * The ghost values of @p v are dropped first. A collective call.
   */
  void
  condense(const AffineConstraints<double> &constraints, ModeVector &v);

  /**
   * Set each constrained DoF of @p v to its line's combination of the DoFs
   * it names plus its inhomogeneity: AffineConstraints::distribute() on one
   * rank. On several, each rank sets the lines it owns, reading the DoFs
   * they name (its own or its ghosts). A collective call.
   */
  void
  distribute(const AffineConstraints<double> &constraints, ModeVector &v);
} // namespace thinlayer

#endif
