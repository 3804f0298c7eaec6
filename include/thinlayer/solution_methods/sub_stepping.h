#ifndef thinlayer_solution_methods_sub_stepping_h
#define thinlayer_solution_methods_sub_stepping_h

namespace thinlayer
{
  /**
   * The parts of one load step that a method cuts back (Newton with the
   * programme as given, Solver/Maximum cut-backs): the step from the
   * accepted load factor to its target is attempted whole; a part that
   * fails is halved and tried again from the last accepted state, up to
   * the limit of cut-backs; a part that converges short of the target is
   * accepted and the rest of the step attempted, in parts no longer than
   * the last. The step reports as one (one row of history.csv), with its
   * number of cut-backs.
   *
   * LoadStepping, beside it, halves failed steps of the run itself: each
   * of its attempts is a row of its own, and with automatic stepping a
   * method's cut-backs are off (they would repeat that work unrecorded).
   */
  class SubStepping
  {
  public:
    /// What to do after an attempt at target().
    enum class Next
    {
      /// The whole step has converged.
      done,
      /// A part converged: accept it and attempt target() next.
      next_part,
      /// A part failed: return to the accepted state and attempt the
      /// halved part at target().
      retry,
      /// A part failed with no cut-back left: the step has failed, its
      /// last attempt's state kept.
      failed
    };

    /// The step from @p start to @p end, halved at most @p max_cut_backs
    /// times.
    SubStepping(const double       start,
                const double       end,
                const unsigned int max_cut_backs);

    /// The load factor of the next attempt.
    double
    target() const;

    /// Take whether the attempt at target() converged.
    Next
    report(const bool converged);

    /// How often a part was halved.
    unsigned int
    cut_backs() const;

  private:
    /// Whether the next part reaches the end of the step.
    bool
    last() const;

    const double       end;
    const double       total;
    const unsigned int max_cut_backs;
    double             start;
    double             size;
    unsigned int       halvings = 0;
  };
} // namespace thinlayer

#endif
