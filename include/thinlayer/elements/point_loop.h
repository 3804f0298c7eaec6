#ifndef thinlayer_elements_point_loop_h
#define thinlayer_elements_point_loop_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/thread_management.h>

#include <thinlayer/discretisation/kinematics.h>
#include <thinlayer/discretisation/mode_vectors.h>
#include <thinlayer/discretisation/strain_operator.h>
#include <thinlayer/materials/material_law.h>
#include <thinlayer/materials/point_history.h>

#include <memory>
#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /**
   * The loop over every Gauss point and station that turns the modes' step
   * increments into stresses and nodal forces: the hot loop of every
   * solution method. Two point rules share it:
   *
   * - viscoplastic_update(): the paper's viscoplastic strain increment,
   *   sigma = sigma_0 + D (strain - eps_vp), and where F > 0 the new
   *   viscoplastic strain dt F dQ/dsigma, whose D-projection is added to
   *   each mode's body-load change;
   * - return_mapping_update(): the return mapping of the elastic trial
   *   stress sigma_0 + D strain, adding to each mode's internal forces and
   *   stress excess, optionally keeping the consistent tangents.
   *
   * The cells are split into chunks run as parallel tasks. Each cell writes
   * its nodal forces into its own slot, and one serial pass adds the slots
   * into the global vectors in cell order: the sums, and so the
   * iterations, do not depend on the number of threads, and no per-chunk
   * global vectors are zeroed and summed every iteration. Everything is
   * allocated in reinit(): an iteration allocates nothing.
   *
   * On many ranks each loop runs over the cells this rank owns; what they
   * add is then summed over the ranks by the Analysis. The point states
   * and every per-cell slot are kept only for those cells, by their
   * position in get_cells() (point_index()): a rank's memory for them
   * falls with the number of ranks.
   */
  class PointLoop
  {
  public:
    /**
     * Set up for the active cells @p cells (ascending: on many ranks, the
     * cells this rank owns) of @p strain_operator, with @p n_q points per
     * cell, the law of every active cell, and the states of the loop's
     * points and stations (point_index()). The objects are referenced, not
     * copied.
     */
    void
    reinit(const StrainOperator                   &strain_operator,
           const Kinematics                       &kinematics,
           const unsigned int                      n_q,
           const std::vector<const MaterialLaw *> &cell_law,
           const std::vector<unsigned int>        &cells,
           std::vector<PointState>                &states);

    /// The cells the point rules run over (ascending).
    const std::vector<unsigned int> &
    get_cells() const
    {
      return cells;
    }

    /**
     * The paper's point rule with pseudo time step @p time_step. Returns
     * the number of yielding points and stations.
     */
    unsigned int
    viscoplastic_update(const double       time_step,
                        const ModeVectors &step_increment,
                        ModeVectors       &body_load_change);

    /**
     * Return mapping at every point and station. With @p tangents (one per
     * point and station of the loop's cells, at point_index()), the
     * consistent tangents are stored there. Returns the number of yielding
     * points and stations.
     */
    unsigned int
    return_mapping_update(const ModeVectors                  &step_increment,
                          std::vector<SymmetricTensor<4, 3>> *tangents,
                          ModeVectors                        &internal_forces,
                          ModeVectors                        &stress_excess);

    /// Add the internal forces int B^T sigma of the current stresses of
    /// the loop's cells.
    void
    add_internal_forces(ModeVectors &internal_forces) const;

    /// Where the state (and the tangent of return_mapping_update()'s
    /// @p tangents) of point @p q, station @p s of the cell at position
    /// @p i in get_cells() is kept: point-major, in the order of the cells.
    std::size_t
    point_index(const unsigned int i,
                const unsigned int q,
                const unsigned int s) const
    {
      return (std::size_t(i) * n_q + q) * kinematics->n_stations() + s;
    }

    /// How many chunks the cells are split into.
    unsigned int
    n_chunks() const
    {
      return chunks;
    }

    /**
     * Run @p work(begin, end, chunk) for the positions [begin, end) in
     * get_cells() of every chunk as parallel tasks, and wait for them; for
     * other per-cell work of the same size (Newton's cell tangents).
     */
    template <typename Work>
    void
    for_each_chunk(const Work &work)
    {
      tasks.clear();
      for (unsigned int k = 0; k < chunks; ++k)
        tasks.push_back(Threads::new_task([this, k, &work]() {
          work(chunk_begin(k), chunk_begin(k + 1), k);
          return 0u;
        }));
      for (auto &task : tasks)
        task.join();
    }

  private:
    /// Work space of one chunk, allocated once.
    struct ChunkScratch
    {
      /// The cell's nodal increments, per mode.
      std::vector<double> du;
      /// The strain parts of each mode at a point.
      std::vector<SymmetricTensor<2, 3>> mode_strain;
    };

    /// The first position in get_cells() of chunk @p k.
    unsigned int
    chunk_begin(const unsigned int k) const
    {
      return std::size_t(k) * cells.size() / chunks;
    }

    /// Both point rules: the parallel cell loop, then the serial pass
    /// adding the cells' body loads to @p body_loads and (return mapping)
    /// their internal forces to @p internal_forces.
    template <typename PointRule>
    unsigned int
    update(const ModeVectors &step_increment,
           const PointRule   &rule,
           ModeVectors       &body_loads,
           ModeVectors       *internal_forces);

    /// The cells at positions [@p begin, @p end) of get_cells(): their slots of
    /// cell_body_loads (and cell_internal_forces), and cell_has_body_loads.
    template <typename PointRule>
    unsigned int
    update_cells(const unsigned int begin,
                 const unsigned int end,
                 const ModeVectors &step_increment,
                 const PointRule   &rule,
                 ChunkScratch      &scratch);

    const StrainOperator                   *strain_operator = nullptr;
    const Kinematics                       *kinematics      = nullptr;
    const std::vector<const MaterialLaw *> *cell_law        = nullptr;
    std::vector<PointState>                *states          = nullptr;
    unsigned int                            n_q             = 0;
    unsigned int                            chunks          = 0;
    /// The cells the point rules run over.
    std::vector<unsigned int> cells;

    /// Each loop cell's nodal body loads (viscoplastic: their increments),
    /// per mode: n_modes * dofs_per_cell entries from i * n_modes *
    /// dofs_per_cell on for the cell at position i in cells.
    std::vector<double> cell_body_loads;
    /// Each loop cell's nodal internal forces (return mapping), laid out
    /// as cell_body_loads.
    std::vector<double> cell_internal_forces;
    /// Whether a cell's slot of cell_body_loads holds anything (0 when none
    /// of its points yields): the serial pass skips the cells with 0.
    std::vector<unsigned char> cell_has_body_loads;
    /// The tasks, one per chunk (kept to reuse the storage).
    std::vector<Threads::Task<unsigned int>> tasks;
    std::vector<ChunkScratch>                chunk_scratch;
  };
} // namespace thinlayer

#endif
