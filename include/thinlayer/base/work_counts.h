#ifndef thinlayer_base_work_counts_h
#define thinlayer_base_work_counts_h

#include <chrono>

namespace thinlayer
{
  /**
   * The units of work a solution method spends, counted where the work is
   * done: factorisations and forward/backward substitutions of a direct
   * solver (the elastic stiffness, Newton's tangent, on one rank or by
   * MUMPS on several), and sweeps of the point rules over every point of
   * the body. Iterations of different methods cost different amounts
   * (Newton's an assembly, a factorisation and a substitution; the
   * constant-stiffness methods' a substitution): these counts are the
   * currency in which summary.json and the benchmarks compare them, beside
   * the time, which depends on the machine and its load.
   */
  struct WorkCounts
  {
    unsigned long factorisations = 0;
    unsigned long substitutions  = 0;
    unsigned long sweeps         = 0;
    /// Iterations of the Krylov solves of Newton's corrections, each a
    /// product with the tangent and a substitution (counted among the
    /// substitutions) with a factor kept from an earlier one.
    unsigned long krylov_iterations = 0;
    /// The wall time of the factorisations (numerical and, where it is
    /// redone, symbolic), tangents and elastic stiffness alike: with the
    /// substitution's, the floors a method's time per iteration is
    /// measured against.
    double factorisation_seconds = 0;

    /// The work done since @p earlier.
    WorkCounts
    since(const WorkCounts &earlier) const
    {
      return {factorisations - earlier.factorisations,
              substitutions - earlier.substitutions,
              sweeps - earlier.sweeps,
              krylov_iterations - earlier.krylov_iterations,
              factorisation_seconds - earlier.factorisation_seconds};
    }
  };


  /// Adds the wall time of its scope to @p seconds (a WorkCounts field),
  /// also when the scope ends by an exception (a singular matrix).
  class WorkTimer
  {
  public:
    explicit WorkTimer(double &seconds)
      : seconds(seconds)
      , start(std::chrono::steady_clock::now())
    {}

    ~WorkTimer()
    {
      seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
    }

  private:
    double                                     &seconds;
    const std::chrono::steady_clock::time_point start;
  };

  /**
   * The process's running counts. One process runs one body at a time,
   * and a run reports the difference over its load programme
   * (WorkCounts::since()), so that set-up work and earlier runs of a
   * sweep are not in it.
   */
  WorkCounts &
  work_counts();
} // namespace thinlayer

#endif
