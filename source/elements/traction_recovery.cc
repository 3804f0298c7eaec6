#include <thinlayer/elements/traction_recovery.h>

#include <cmath>
#include <stdexcept>

namespace thinlayer
{
  namespace
  {
    /// The k-th Lagrange polynomial of degree @p degree (0 or 1) on [0, 1]
    /// through equispaced points (degree 0: the constant 1 at 1/2), at
    /// @p x.
    double
    lagrange(const unsigned int degree, const unsigned int k, const double x)
    {
      double value = 1;
      for (unsigned int j = 0; j <= degree; ++j)
        if (j != k)
          value *= (x - double(j) / degree) /
                   (double(k) / degree - double(j) / degree);
      return value;
    }

    /// Where the k-th of those points lies.
    double
    node_place(const unsigned int degree, const unsigned int k)
    {
      return degree == 0 ? 0.5 : double(k) / degree;
    }
  } // namespace


  void
  TractionRecovery::add_element(
    const std::vector<unsigned int>          &samples,
    const std::vector<std::array<double, 2>> &places,
    const std::vector<double>                &element_weights,
    const bool                                surface,
    const std::function<std::vector<unsigned int>(double, double)> &key)
  {
    if (places.size() != samples.size() ||
        element_weights.size() != samples.size() || samples.empty())
      throw std::logic_error("TractionRecovery: an element's samples, "
                             "places and weights differ in number");
    const unsigned int n_1d = surface ? static_cast<unsigned int>(std::lround(
                                          std::sqrt(double(samples.size()))))
                                      : samples.size();
    if ((surface ? n_1d * n_1d : n_1d) != samples.size())
      throw std::logic_error("TractionRecovery: a surface element's samples "
                             "are not a square tensor product");
    // Linear between the corners where the rule resolves it: see the
    // class's documentation for why not the quadratic side's nodes.
    const unsigned int degree = n_1d > 1 ? 1 : 0;

    // The element's nodes, lexicographic: the second direction slower.
    std::vector<unsigned int> element_nodes;
    for (unsigned int l = 0; l <= (surface ? degree : 0); ++l)
      for (unsigned int k = 0; k <= degree; ++k)
        {
          const auto [it, inserted] =
            nodes.emplace(key(node_place(degree, k),
                              surface ? node_place(degree, l) : 0.),
                          nodes.size());
          element_nodes.push_back(it->second);
        }

    const unsigned int largest =
      *std::max_element(samples.begin(), samples.end());
    if (shapes.size() <= largest)
      {
        shapes.resize(largest + 1);
        weights.resize(largest + 1, 0.);
      }
    for (unsigned int s = 0; s < samples.size(); ++s)
      {
        auto &sample_shapes = shapes[samples[s]];
        sample_shapes.clear();
        for (unsigned int l = 0, i = 0; l <= (surface ? degree : 0); ++l)
          for (unsigned int k = 0; k <= degree; ++k, ++i)
            {
              const double value =
                (degree == 0 ? 1. : lagrange(degree, k, places[s][0])) *
                (surface && degree > 0 ? lagrange(degree, l, places[s][1])
                                       : 1.);
              sample_shapes.emplace_back(element_nodes[i], value);
            }
        weights[samples[s]] = element_weights[s];
      }
  }


  void
  TractionRecovery::recover(std::vector<InterfaceValues> &values) const
  {
    if (shapes.empty())
      return;
    const unsigned int n_samples = shapes.size();
    if (values.size() % n_samples != 0)
      throw std::logic_error("TractionRecovery: the values are not a whole "
                             "number of stations of the profile's samples");
    constexpr std::array<double InterfaceValues::*, 3> tractions = {
      {&InterfaceValues::shear_traction,
       &InterfaceValues::normal_traction,
       &InterfaceValues::shear_traction_out_of_plane}};
    for (unsigned int first = 0; first < values.size(); first += n_samples)
      for (const auto traction : tractions)
        {
          std::vector<double> force(nodes.size(), 0.), length(nodes.size(), 0.);
          for (unsigned int s = 0; s < n_samples; ++s)
            for (const auto &[node, shape] : shapes[s])
              {
                force[node] += shape * values[first + s].*traction * weights[s];
                length[node] += shape * weights[s];
              }
          for (unsigned int s = 0; s < n_samples; ++s)
            if (!shapes[s].empty())
              {
                double value = 0;
                for (const auto &[node, shape] : shapes[s])
                  value += shape * force[node] / length[node];
                values[first + s].*traction = value;
              }
        }
  }
} // namespace thinlayer
