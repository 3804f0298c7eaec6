// Truths checked for the recovery of interface tractions at the nodes
// (TractionRecovery):
// 1. On a curve of 5 sides of lengths 1, 2, 1, 3, 1 with 3 Gauss points
//    each, and on a surface of 3 x 2 faces with 2 x 2 points each:
//    - a uniform traction is recovered exactly (1e-13);
//    - any tractions keep their resultant: the recovered ones, integrated
//      by the same points and weights, give the raw ones' (1e-12), for
//      pseudo-random values;
//    - each recovered traction lies between the smallest and the largest
//      raw one (a mean with positive weights).
// 2. The mode a thin layer of Q8 2x2 cells carries, linear within each
//    cell and antisymmetric about its centre (-a, +a at its two points),
//    on 6 equal sides: recovered as zero on every side away from the ends
//    (1e-13), as the two sides of a shared node cancel there.
// 3. node_key(): on a 2 x 1 grid of squares, the two cells name their
//    shared side's vertices, its midpoint and their own centres alike
//    where they share them, and differently where they do not.
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <thinlayer/elements/traction_recovery.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "../common/truths.h"

using namespace dealii;
using namespace thinlayer;

namespace
{
  /// Deterministic values in [-1, 1].
  double
  pseudo_random(unsigned int &state)
  {
    state = 1103515245u * state + 12345u;
    return (state >> 8) / double(1u << 24) * 2 - 1;
  }

  /// Samples with a traction @p value (normal, shear and out of plane
  /// alike), one per entry.
  std::vector<InterfaceValues>
  with_tractions(const std::vector<double> &values)
  {
    std::vector<InterfaceValues> result(values.size());
    for (unsigned int k = 0; k < values.size(); ++k)
      {
        result[k].normal_traction             = values[k];
        result[k].shear_traction              = -2 * values[k];
        result[k].shear_traction_out_of_plane = 3 * values[k];
      }
    return result;
  }

  /// The curve of @p lengths, @p rule points per side: the recovery and
  /// the samples' weights.
  TractionRecovery
  curve(const std::vector<double> &lengths,
        const unsigned int         points,
        std::vector<double>       &weights)
  {
    const double              g = std::sqrt(3. / 5.), h = 1 / std::sqrt(3.);
    const std::vector<double> places =
      points == 3 ? std::vector<double>{(1 - g) / 2, 0.5, (1 + g) / 2}
                  : std::vector<double>{(1 - h) / 2, (1 + h) / 2};
    const std::vector<double> rule =
      points == 3 ? std::vector<double>{5. / 18, 8. / 18, 5. / 18}
                  : std::vector<double>{0.5, 0.5};
    TractionRecovery recovery;
    for (unsigned int e = 0; e < lengths.size(); ++e)
      {
        std::vector<unsigned int>          samples;
        std::vector<std::array<double, 2>> at;
        std::vector<double>                w;
        for (unsigned int q = 0; q < points; ++q)
          {
            samples.push_back(weights.size());
            at.push_back({{places[q], 0.}});
            w.push_back(rule[q] * lengths[e]);
            weights.push_back(w.back());
          }
        recovery.add_element(samples, at, w, false, [e](double x, double) {
          return std::vector<unsigned int>{e + (x > 0.5 ? 1u : 0u)};
        });
      }
    return recovery;
  }

  /// The surface of nx x nz unit faces, 2 x 2 points each.
  TractionRecovery
  surface(const unsigned int   nx,
          const unsigned int   nz,
          std::vector<double> &weights)
  {
    const double     h        = 1 / std::sqrt(3.);
    const double     places[] = {(1 - h) / 2, (1 + h) / 2};
    TractionRecovery recovery;
    for (unsigned int j = 0; j < nz; ++j)
      for (unsigned int i = 0; i < nx; ++i)
        {
          std::vector<unsigned int>          samples;
          std::vector<std::array<double, 2>> at;
          std::vector<double>                w;
          for (unsigned int b = 0; b < 2; ++b)
            for (unsigned int a = 0; a < 2; ++a)
              {
                samples.push_back(weights.size());
                at.push_back({{places[a], places[b]}});
                w.push_back(0.25);
                weights.push_back(0.25);
              }
          recovery.add_element(samples, at, w, true, [=](double x, double z) {
            return std::vector<unsigned int>{i + (x > 0.5 ? 1u : 0u),
                                             j + (z > 0.5 ? 1u : 0u)};
          });
        }
    return recovery;
  }

  /// Truths 1 for @p recovery with the samples' @p weights.
  void
  check_recovery(const char                *name,
                 const TractionRecovery    &recovery,
                 const std::vector<double> &weights)
  {
    std::printf("%s, %zu samples:\n", name, weights.size());
    std::vector<InterfaceValues> uniform =
      with_tractions(std::vector<double>(weights.size(), 0.7));
    recovery.recover(uniform);
    double off = 0;
    for (const InterfaceValues &v : uniform)
      off = std::max({off,
                      std::abs(v.normal_traction - 0.7),
                      std::abs(v.shear_traction + 1.4),
                      std::abs(v.shear_traction_out_of_plane - 2.1)});
    truths::expect(off < 1e-13, "a uniform traction recovered exactly");

    unsigned int        state = 7;
    std::vector<double> raw;
    for (unsigned int k = 0; k < weights.size(); ++k)
      raw.push_back(pseudo_random(state));
    std::vector<InterfaceValues> values = with_tractions(raw);
    recovery.recover(values);
    double before = 0, after = 0, after_shear = 0;
    bool   between         = true;
    const auto [low, high] = std::minmax_element(raw.begin(), raw.end());
    for (unsigned int k = 0; k < weights.size(); ++k)
      {
        before += weights[k] * raw[k];
        after += weights[k] * values[k].normal_traction;
        after_shear += weights[k] * values[k].shear_traction;
        between = between && values[k].normal_traction >= *low - 1e-14 &&
                  values[k].normal_traction <= *high + 1e-14;
      }
    truths::expect(std::abs(after - before) < 1e-12 &&
                     std::abs(after_shear + 2 * before) < 1e-12,
                   "the resultant kept");
    truths::expect(between,
                   "every recovered traction within the raw ones' range");
  }
} // namespace


int
main()
{
  {
    std::vector<double> weights;
    const auto          recovery = curve({1, 2, 1, 3, 1}, 3, weights);
    check_recovery("a curve of 5 sides, 3 Gauss points each",
                   recovery,
                   weights);
  }
  {
    std::vector<double> weights;
    const auto          recovery = surface(3, 2, weights);
    check_recovery("a surface of 3 x 2 faces, 2 x 2 points each",
                   recovery,
                   weights);
  }
  {
    std::vector<double> weights;
    const auto recovery = curve(std::vector<double>(6, 1.), 2, weights);
    std::vector<double> mode;
    for (unsigned int e = 0; e < 6; ++e)
      mode.insert(mode.end(), {-1., 1.});
    std::vector<InterfaceValues> values = with_tractions(mode);
    recovery.recover(values);
    double inner = 0;
    for (unsigned int k = 2; k < 10; ++k)
      inner = std::max(inner, std::abs(values[k].normal_traction));
    std::printf("the mode linear within each of 6 sides, 2 points each:\n");
    truths::expect(inner < 1e-13, "recovered as zero away from the ends");
  }
  {
    Triangulation<2> tria;
    GridGenerator::subdivided_hyper_rectangle(tria,
                                              {2, 1},
                                              Point<2>(0, 0),
                                              Point<2>(2, 1));
    const auto left  = tria.begin_active(),
               right = std::next(tria.begin_active());
    const auto key   = [](const auto &cell, double x, double y) {
      return TractionRecovery::node_key(cell, Point<2>(x, y));
    };
    std::printf("node_key on two squares side by side:\n");
    truths::expect(key(left, 1, 0) == key(right, 0, 0) &&
                     key(left, 1, 0.5) == key(right, 0, 0.5) &&
                     key(left, 1, 0.5).size() == 2,
                   "the shared side's vertices and midpoint named alike");
    truths::expect(key(left, 0.5, 0.5) != key(right, 0.5, 0.5) &&
                     key(left, 0.5, 0.5).size() == 4 &&
                     key(left, 0, 0) != key(right, 0, 0),
                   "their centres and other corners named apart");
  }
  return truths::conclude();
}
