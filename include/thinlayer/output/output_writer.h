#ifndef thinlayer_output_output_writer_h
#define thinlayer_output_output_writer_h

#include <deal.II/base/data_out_base.h>

#include <thinlayer/analysis/analysis_view.h>
#include <thinlayer/output/background_writer.h>
#include <thinlayer/parameters/parameters.h>
#include <thinlayer/postprocess/displacement_measure.h>
#include <thinlayer/postprocess/layer_profile.h>
#include <thinlayer/solution_methods/step_result.h>

#include <fstream>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /**
   * One row of history.csv: one load step.
   */
  struct HistoryRow
  {
    /// The load step attempted, and the attempt's number in the run (they
    /// differ once a failed step has been cut back and retried).
    unsigned int        step;
    unsigned int        attempt;
    double              load_factor;
    double              load;
    DisplacementMeasure displacement;
    StepResult          result;
    /// Whether the attempt's state was accepted.
    bool accepted;
    /// The attempt's secant stiffness along its increment against the
    /// elastic one (AnalysisView::secant_stiffness_ratio()).
    double stiffness_ratio;
    /// The phase of the run (Phase): "initial state" or "loading".
    std::string phase;
  };

  /**
   * The files of one run in its output directory: history.csv (one row per
   * attempt at a load step, flushed as it goes so a long run can be
   * watched),
   * fields-NNNN.vtu with fields.pvd for ParaView, and whole files such as
   * summary.json at the end, into @p directory (a ResultsDirectory's
   * staging directory, which exists). Every write is checked: one that
   * fails throws a WriteError that names the file.
   *
   * On many ranks every rank holds the whole state, and rank 0 writes
   * every file but the fields: each rank writes the piece of its own cells
   * as fields-NNNN.RRRR.vtu, listed in fields-NNNN.pvtu (which fields.pvd
   * lists), as deal.II's parallel codes write them.
   *
   * The fields (write_fields(), write_revolved_view()) are encoded and
   * written by a BackgroundWriter while the stepping goes on: the stepping
   * builds their patches from the analysis and hands them over. finish()
   * waits for them.
   */
  class OutputWriter
  {
  public:
    OutputWriter(const OutputParameters &parameters,
                 const std::string      &directory);

    void
    write_history_row(const HistoryRow &row);

    /**
     * The fields of load step @p step as fields-NNNN.vtu (on several ranks
     * fields-NNNN.pvtu and its pieces; every rank calls it). fields.pvd
     * lists the states of the load-displacement curve, @p on_curve: the
     * converged, accepted ones. A step that ended the run without such a
     * state (a failed step, a probe beyond it) is listed in attempts.pvd
     * instead, so that ParaView's time steps are equilibrium states. For
     * Fourier kinematics the displacement is the one in the cut at angle
     * @p theta. The profiles of @p interfaces add their cell fields (zero
     * off the layers).
     */
    template <int dim>
    void
    write_fields(const unsigned int                    step,
                 const double                          load_factor,
                 const bool                            on_curve,
                 const AnalysisView<dim>              &analysis,
                 const double                          theta,
                 const std::vector<LayerProfile<dim>> &interfaces);

    /**
     * The profile of every one of @p interfaces at load step @p step
     * (load factor @p load_factor), as `layer-<id>-NNNN.csv`, and of
     * every curve of zero-thickness elements as
     * `interface-<id>-NNNN.csv`, their tractions recovered at the nodes;
     * with Output/Gauss-point profiles also the raw ones as
     * `layer-<id>-gauss-NNNN.csv` and `interface-<id>-gauss-NNNN.csv`;
     * @p with_vtu, also each as a VTU
     * polyline, listed in `layer-<id>.pvd` and `interface-<id>.pvd` if
     * the state is @p on_curve (as write_fields()), else in
     * `layer-<id>-attempts.pvd` and `interface-<id>-attempts.pvd`.
     */
    template <int dim>
    void
    write_interface_profiles(const unsigned int                    step,
                             const double                          load_factor,
                             const bool                            on_curve,
                             const AnalysisView<dim>              &analysis,
                             const std::vector<LayerProfile<dim>> &interfaces,
                             const bool                            with_vtu);

    /**
     * The body revolved about its axis (revolved_view(), @p slices
     * angles) as revolved-NNNN.vtu (on many ranks a piece per rank and
     * revolved-NNNN.pvtu), and revolved.pvd listing every step so far.
     * Every rank takes part.
     */
    void
    write_revolved_view(const unsigned int     step,
                        const double           load_factor,
                        const bool             on_curve,
                        const AnalysisView<2> &analysis,
                        const unsigned int     slices);

    /**
     * Vertex positions, displacements and the last step's displacement
     * increments as displacements.csv (x, y, u_x, u_y, du_x, du_y; in 3D
     * with z, u_z and du_z),
     * overwritten every step so that it holds the last one: at a failed
     * step the increment is the mechanism at failure, for plots. For
     * Fourier kinematics the field in the cut at angle @p theta.
     */
    template <int dim>
    void
    write_displacements(const AnalysisView<dim> &analysis,
                        const double             theta) const;

    /// Any other file (the mesh, the parameters), written whole.
    void
    write_file(const std::string &name, const std::string &content) const;


    /**
     * Wait for the fields still being written, and learn, on every rank,
     * whether every rank wrote its files (every rank calls it): a failed
     * write throws a WriteError that names the file, on every rank. A run
     * calls it before its summary, which must come last.
     */
    void
    finish();


  private:
    /// What fields.pvd lists for the fields of BASE: BASE.vtu on one rank,
    /// BASE.pvtu on several.
    std::string
    record_name(const std::string &base) const;

    /**
     * Write a step's fields off the stepping's path: @p write_vtu's text as
     * BASE.vtu on one rank; on several, this rank's part as the piece
     * BASE.RRRR.vtu and, by rank 0, BASE.pvtu listing every rank's piece
     * (its text from @p write_record); then, by rank 0, @p pvd as the file
     * @p pvd_name. Both functions run on the BackgroundWriter's thread and
     * must hold copies of what they write. Every rank calls it, and first
     * learns whether an earlier write failed anywhere.
     */
    void
    write_in_background(
      const std::string                  &base,
      std::function<void(std::ostream &)> write_vtu,
      std::function<void(std::ostream &, const std::vector<std::string> &)>
                         write_record,
      const std::string &pvd_name,
      const std::string &pvd);

    /// Throw on every rank if any rank's background writes failed so far
    /// (every rank calls it).
    void
    agree_on_write_errors();

    /// A file written by this rank, whichever it is.
    void
    write_own_file(const std::string &name, const std::string &content) const;

    std::string  directory;
    unsigned int vtu_subdivisions;
    /// Whether the profiles' raw values at the integration points are
    /// written too (Output/Gauss-point profiles).
    bool gauss_point_profiles;
    /// Whether this rank writes (rank 0).
    bool          writes;
    std::ofstream history;
    /// The records of fields.pvd and revolved.pvd (the curve's states),
    /// and of attempts.pvd and revolved-attempts.pvd (the others).
    std::vector<std::pair<double, std::string>> pvd_records;
    std::vector<std::pair<double, std::string>> attempt_records;
    std::vector<std::pair<double, std::string>> revolved_records;
    std::vector<std::pair<double, std::string>> revolved_attempt_records;
    std::map<std::string, std::vector<std::pair<double, std::string>>>
      profile_records;
    /// The fields' files being written. Last, so that it is destroyed
    /// first: its jobs use the members above.
    BackgroundWriter background;
  };


  /**
   * @p content as the file @p name in @p directory, written beside it and
   * renamed into place, so that a reader never sees half a file. Throws a
   * WriteError that names the file where the write fails.
   */
  void
  write_whole_file(const std::string &directory,
                   const std::string &name,
                   const std::string &content);
} // namespace thinlayer

#endif
