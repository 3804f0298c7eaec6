#ifndef thinlayer_parameters_scene_checks_h
#define thinlayer_parameters_scene_checks_h

#include <thinlayer/parameters/parameters.h>

#include <set>
#include <string>

namespace thinlayer
{
  /**
   * @file
   * Checks that span sections of a scene's parameters, once they are all
   * read: what one section asks of another, each an InputError naming the
   * file, the entry and what was expected.
   */

  /**
   * A reaction read off a boundary that constrains nothing is 0 whatever
   * the load; a phase named twice (or like the initial state, the loading
   * or the strength reduction) makes rows of history.csv that cannot be
   * told apart.
   */
  void
  check_monitors_and_phases(const Parameters &p);

  /**
   * What Initial state/Procedure needs of the rest of the scene, and the
   * weight of a Fourier body, which only harmonic 0 of the symmetric series
   * carries.
   */
  void
  check_initial_state(const Parameters &p);

  /**
   * What the refinement cycles cannot be combined with: a sweep (each of
   * whose runs would be a series of cycles) and layer profiles (which read
   * a layer one cell thick).
   */
  void
  check_adaptivity(const Parameters &p);

  /**
   * Entries the user gave that mean nothing in this scene: accepted
   * silently, they would let a user believe they had an effect. @p given
   * are the entries given a value other than their default (one at its
   * default is as if left out), @p written all that the file and the
   * command line set.
   */
  void
  check_entries_mean_something(const Parameters            &p,
                               const std::set<std::string> &given,
                               const std::set<std::string> &written);
} // namespace thinlayer

#endif
