#ifndef thinlayer_analysis_step_access_h
#define thinlayer_analysis_step_access_h

#include <thinlayer/analysis/iteration_access.h>

namespace thinlayer
{
  /// The loads a phase applies in proportion to its load factor.
  enum class PhaseLoads
  {
    /// The Boundary sections' values and the weight with the surcharge:
    /// a run of one phase (gravity loading, if it has weight).
    boundaries_and_weight,
    /// The weight with the surcharge: the initial phase of gravity
    /// loading (the prescribed displacements held at zero).
    weight,
    /// The Boundary sections' values: the loading after an initial
    /// state.
    boundaries,
    /// Nothing: the loads are held while strengths are reduced.
    none
  };


  /**
   * What the stepping does to an analysis: it begins phases, ends each
   * attempt at a load step and accepts or rejects its state, and hands
   * the analysis to its solution method as an IterationAccess.
   */
  template <int dim>
  class StepAccess : public IterationAccess<dim>
  {
  public:
    using IterationAccess<dim>::accept_step;

    /**
     * Begin a phase that applies @p loads: the loads of the phase before
     * it, at its accepted load factor, are held fixed from now on, and the
     * load factor starts again from 0; so are its prescribed displacements
     * where it left them. With @p reset_displacements the displacements
     * start from zero; the stresses are kept. The boundary values are
     * those of @p boundary_set: 0 the Boundary sections', k the loading
     * phase Phase k + 1's.
     */
    virtual void
    begin_phase(const PhaseLoads   loads,
                const bool         reset_displacements,
                const unsigned int boundary_set = 0) = 0;

    /**
     * The K0 procedure (KZeroStresses): every point of the continuum
     * starts from the at-rest stresses of the weight and the surcharge,
     * which are held as the body's load. Throws InputError where the
     * ground surface is not level or a point's stress lies outside its
     * material's yield surface. Returns the out-of-balance force of the
     * initial stresses against that load, condensed, relative to the load
     * (both the largest entry): zero on a level ground but for the
     * quadrature's error on distorted cells.
     */
    virtual double
    set_initial_stresses() = 0;

    /// Divide the strengths of Strength reduction/Materials and its
    /// Interfaces by @p factor (ElementGroup::reduce_strength()): for
    /// the attempt that follows.
    virtual void
    reduce_strength(const double factor) = 0;

    /// Whether a phase of @p loads (with the boundary values of
    /// @p boundary_set) would apply a load or prescribed displacements in
    /// proportion to its load factor.
    virtual bool
    applies_anything(const PhaseLoads   loads,
                     const unsigned int boundary_set = 0) const = 0;

    /**
     * The solution method has left its state of the step to
     * @p load_factor: it is the current one, pending until accept_step() or
     * reject_step(). Computes its internal forces, and checks whether it
     * is finite (increments, stresses, yield ratios) and how far it is
     * from yield.
     */
    virtual StateCheck
    end_attempt(const double load_factor) = 0;

    /// Make the pending state the accepted one.
    virtual void
    accept_step() = 0;

    /// Return to the accepted state: the pending state is dropped.
    virtual void
    reject_step() = 0;
  };
} // namespace thinlayer

#endif
