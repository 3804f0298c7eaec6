#include <thinlayer/solvers/anderson_acceleration.h>

#include <cmath>

namespace thinlayer
{
  template <typename VectorType>
  AndersonAcceleration<VectorType>::AndersonAcceleration(
    const unsigned int depth)
    : depth(depth)
    , has_previous(false)
  {
    AssertThrow(depth > 0,
                ExcMessage(
                  "Anderson acceleration needs a depth of at least 1."));
  }


  template <typename VectorType>
  void
  AndersonAcceleration<VectorType>::reset()
  {
    has_previous = false;
    dX.clear();
    dG.clear();
  }


  template <typename VectorType>
  void
  AndersonAcceleration<VectorType>::update(VectorType &x, const VectorType &g)
  {
    if (has_previous)
      {
        // Recycle the oldest difference vectors once the history is full.
        VectorType dx, dg;
        if (dX.size() == depth)
          {
            dx.swap(dX.front());
            dg.swap(dG.front());
            dX.pop_front();
            dG.pop_front();
          }
        dx = x;
        dx -= previous_x;
        dg = g;
        dg -= previous_g;
        dX.push_back(std::move(dx));
        dG.push_back(std::move(dg));
      }
    previous_x   = x;
    previous_g   = g;
    has_previous = true;

    // Least squares by modified Gram-Schmidt on the columns of dG: dG = Q R,
    // gamma = R^-1 Q^T g. Columns that are (nearly) dependent on earlier
    // ones are dropped, which keeps the update bounded when the iteration
    // stagnates.
    const unsigned int m = dG.size();
    if (Q.size() < m)
      Q.resize(m);
    kept.clear();
    R.assign(m * m, 0.);
    for (unsigned int j = 0; j < m; ++j)
      {
        VectorType &q       = Q[kept.size()];
        q                   = dG[j];
        const double norm_0 = q.l2_norm();
        for (unsigned int k = 0; k < kept.size(); ++k)
          {
            const double r = Q[k] * q;
            R[k * m + j]   = r;
            q.add(-r, Q[k]);
          }
        const double norm = q.l2_norm();
        if (norm_0 == 0 || norm < 1e-10 * norm_0)
          continue;
        R[kept.size() * m + j] = norm;
        q /= norm;
        kept.push_back(j);
      }

    // Back substitution for the kept columns: R_kk gamma = Q^T g.
    const unsigned int k = kept.size();
    gamma.assign(k, 0.);
    for (int i = k - 1; i >= 0; --i)
      {
        double value = Q[i] * g;
        for (unsigned int l = i + 1; l < k; ++l)
          value -= R[i * m + kept[l]] * gamma[l];
        gamma[i] = value / R[i * m + kept[i]];
      }

    x += g;
    for (unsigned int i = 0; i < k; ++i)
      {
        x.add(-gamma[i], dX[kept[i]]);
        x.add(-gamma[i], dG[kept[i]]);
      }
  }


  template class AndersonAcceleration<Vector<double>>;
  // The stacked mode vectors of all modes, distributed over the ranks.
  template class AndersonAcceleration<
    LinearAlgebra::distributed::Vector<double>>;
} // namespace thinlayer
