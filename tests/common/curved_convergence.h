#ifndef thinlayer_tests_curved_convergence_h
#define thinlayer_tests_curved_convergence_h

// What the tests of curved cells against a closed form share: the L2 error
// of a solved analysis's displacement, and the comparison of its
// convergence on curved and straight cells.

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/numerics/vector_tools.h>

#include <thinlayer/analysis/analysis.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "scene_test_utilities.h"

namespace thinlayer_tests
{
  /// The L2 error of the displacement of @p analysis (harmonic 0 of a
  /// Fourier one) against @p exact.
  inline double
  l2_error(const thinlayer::Analysis<2> &analysis,
           const dealii::Function<2>    &exact)
  {
    const auto &tria = analysis.get_dof_handler().get_triangulation();
    dealii::Vector<double> errors(tria.n_active_cells());
    dealii::VectorTools::integrate_difference(analysis.get_mapping(),
                                              analysis.get_dof_handler(),
                                              analysis.whole_solution(0),
                                              exact,
                                              errors,
                                              dealii::QGauss<2>(5),
                                              dealii::VectorTools::L2_norm);
    return dealii::VectorTools::compute_global_error(
      tria, errors, dealii::VectorTools::L2_norm);
  }


  /**
   * The scenes scene(n, curved) (the text of a parameter file) on n = 2, 4,
   * 8 cells per quarter circle, curved and straight, solved to load factor
   * 1, and the L2 errors of their displacements against @p exact printed;
   * and the truths: the curved cells' error falls at order at least 2.5
   * between n = 4 and 8 (the element's), and on n = 8 lies below a tenth
   * of the straight cells' (the polygon's).
   */
  template <typename Scene>
  void
  compare_curved_and_straight(const Scene               &scene,
                              const dealii::Function<2> &exact)
  {
    const auto error = [&](const unsigned int n, const bool curved) {
      double result = 0;
      with_solved_step(scene(n, curved),
                       "scene.prm",
                       [&](const thinlayer::Analysis<2> &analysis,
                           const thinlayer::Parameters &) {
                         result = l2_error(analysis, exact);
                       });
      return result;
    };
    std::vector<double> curved, straight;
    for (const unsigned int n : {2u, 4u, 8u})
      {
        curved.push_back(error(n, true));
        straight.push_back(error(n, false));
        std::printf("n = %u: L2 error curved %.2e, straight %.2e\n",
                    n,
                    curved.back(),
                    straight.back());
      }
    const double curved_rate   = std::log2(curved[1] / curved[2]);
    const double straight_rate = std::log2(straight[1] / straight[2]);
    std::printf("rates between n = 4 and 8: curved %.2f (at least 2.5: %s), "
                "straight %.2f; curved below a tenth of straight on n = 8: "
                "%s\n",
                curved_rate,
                curved_rate >= 2.5 ? "yes" : "NO",
                straight_rate,
                curved[2] < 0.1 * straight[2] ? "yes" : "NO");
  }
} // namespace thinlayer_tests

#endif
