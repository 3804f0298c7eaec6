#include <thinlayer/materials/elasticity.h>
#include <thinlayer/materials/mohr_coulomb.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace thinlayer
{
  namespace
  {
    /**
     * Within this angle of a corner of the Tresca/Mohr-Coulomb hexagon
     * (|theta| = 30 degrees) the flow direction is the average of the two
     * faces that meet there, as Smith and Griffiths do: the exact gradient
     * has 1/cos(3 theta) in it.
     */
    const double corner_lode_angle = 29.0 * numbers::PI / 180.0;


    /**
     * The tangent of an isotropic function of a symmetric tensor, sigma =
     * sum_i sigma_i(trial_1..3) e_i (x) e_i, from the derivatives of its
     * principal values, @p principal_tangent(i, j) = d sigma_i / d trial_j,
     * and the spin of its eigenvectors: the off-diagonal terms
     * (sigma_i - sigma_j) / (trial_i - trial_j) (their limit for equal
     * trial values).
     */
    SymmetricTensor<4, 3>
    isotropic_function_tangent(
      const std::array<std::pair<double, Tensor<1, 3>>, 3> &trial,
      const std::array<double, 3>                          &sigma,
      const double (&principal_tangent)[3][3])
    {
      std::array<SymmetricTensor<2, 3>, 3> E;
      for (unsigned int i = 0; i < 3; ++i)
        E[i] = symmetrize(outer_product(trial[i].second, trial[i].second));
      SymmetricTensor<4, 3> T;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          if (principal_tangent[i][j] != 0)
            T += principal_tangent[i][j] * outer(E[i], E[j]);
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = i + 1; j < 3; ++j)
          {
            const double gap = trial[i].first - trial[j].first;
            const double scale =
              std::abs(trial[0].first) + std::abs(trial[2].first);
            const double ratio =
              (std::abs(gap) > 1e-10 * scale)
                ? (sigma[i] - sigma[j]) / gap
                : principal_tangent[i][i] - principal_tangent[i][j];
            const SymmetricTensor<2, 3> M =
              symmetrize(outer_product(trial[i].second, trial[j].second));
            T += (2 * ratio) * outer(M, M);
          }
      return T;
    }


    /**
     * What a return onto planes of the Mohr-Coulomb surface in
     * principal-stress space needs: the principal trial stresses, the
     * principal elasticity, the friction and dilation angles' sines, the
     * strength c cos(phi) and the rounding slack of the tests.
     */
    struct PrincipalReturnData
    {
      const std::array<double, 3> &trial;
      const double (&elasticity)[3][3];
      double sin_phi;
      double sin_psi;
      double strength;
      double slack;
    };


    /// Normal (or flow, with sin(psi)) of the plane of principal stresses
    /// i > j: (e_i - e_j)/2 + (e_i + e_j)/2 sin(angle).
    std::array<double, 3>
    principal_plane(const unsigned int i,
                    const unsigned int j,
                    const double       sin_angle)
    {
      std::array<double, 3> v{{0, 0, 0}};
      v[i] = 0.5 * (1 + sin_angle);
      v[j] = 0.5 * (-1 + sin_angle);
      return v;
    }


    double
    dot(const std::array<double, 3> &a, const std::array<double, 3> &b)
    {
      return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }


    /**
     * The return of the principal trial stresses onto the @p k (one or
     * two) planes @p active: with perfect plasticity the planes are linear
     * in the principal stresses, so it is one linear solve for the plastic
     * multipliers. Fills @p sigma and the principal tangent
     * @p P = d sigma / d trial; false if a multiplier is negative or, with
     * @p check_order, the ordering s1 >= s2 >= s3 breaks.
     */
    bool
    return_to_planes(
      const unsigned int                                          k,
      const std::array<std::pair<unsigned int, unsigned int>, 2> &active,
      const bool                                                  check_order,
      const PrincipalReturnData                                  &data,
      std::array<double, 3>                                      &sigma,
      double (&P)[3][3])
    {
      const std::array<double, 3> &st = data.trial;
      const auto D_times = [&data](const std::array<double, 3> &v) {
        std::array<double, 3> w;
        for (unsigned int i = 0; i < 3; ++i)
          w[i] = data.elasticity[i][0] * v[0] + data.elasticity[i][1] * v[1] +
                 data.elasticity[i][2] * v[2];
        return w;
      };
      std::array<std::array<double, 3>, 2> n, Dm;
      for (unsigned int a = 0; a < k; ++a)
        {
          n[a] =
            principal_plane(active[a].first, active[a].second, data.sin_phi);
          Dm[a] = D_times(
            principal_plane(active[a].first, active[a].second, data.sin_psi));
        }
      // A(a, b) = n_a . D m_b, and the multipliers A^-1 F_trial.
      double A[2][2], Ainv[2][2], gamma[2];
      for (unsigned int a = 0; a < k; ++a)
        for (unsigned int b = 0; b < k; ++b)
          A[a][b] = dot(n[a], Dm[b]);
      if (k == 1)
        Ainv[0][0] = 1 / A[0][0];
      else
        {
          const double det = A[0][0] * A[1][1] - A[0][1] * A[1][0];
          Ainv[0][0]       = A[1][1] / det;
          Ainv[1][1]       = A[0][0] / det;
          Ainv[0][1]       = -A[0][1] / det;
          Ainv[1][0]       = -A[1][0] / det;
        }
      for (unsigned int a = 0; a < k; ++a)
        {
          gamma[a] = 0;
          for (unsigned int b = 0; b < k; ++b)
            gamma[a] += Ainv[a][b] * (dot(n[b], st) - data.strength);
          if (gamma[a] < -data.slack / A[a][a])
            return false;
        }
      sigma = st;
      for (unsigned int a = 0; a < k; ++a)
        for (unsigned int i = 0; i < 3; ++i)
          sigma[i] -= gamma[a] * Dm[a][i];
      if (check_order && (sigma[1] > sigma[0] + data.slack ||
                          sigma[2] > sigma[1] + data.slack))
        return false;
      // d sigma / d trial = I - sum_ab D m_a Ainv_ab n_b^T.
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          {
            P[i][j] = (i == j) ? 1 : 0;
            for (unsigned int a = 0; a < k; ++a)
              for (unsigned int b = 0; b < k; ++b)
                P[i][j] -= Dm[a][i] * Ainv[a][b] * n[b][j];
          }
      return true;
    }
  } // namespace


  bool
  MohrCoulomb::can_yield() const
  {
    return true;
  }


  double
  MohrCoulomb::yield_function(const SymmetricTensor<2, 3> &stress) const
  {
    if (stress[0][2] == 0 && stress[1][2] == 0)
      {
        const double centre     = 0.5 * (stress[0][0] + stress[1][1]);
        const double half_range = 0.5 * (stress[0][0] - stress[1][1]);
        const double radius =
          std::sqrt(half_range * half_range + stress[0][1] * stress[0][1]);
        const double s1 = std::max(centre + radius, stress[2][2]);
        const double s3 = std::min(centre - radius, stress[2][2]);
        return 0.5 * (s1 - s3) + 0.5 * (s1 + s3) * sin_phi - cohesion * cos_phi;
      }
    const StressInvariants inv(stress);
    return inv.mean * sin_phi +
           inv.equivalent * (std::cos(inv.lode_angle) / std::sqrt(3.) -
                             std::sin(inv.lode_angle) * sin_phi / 3) -
           cohesion * cos_phi;
  }


  SymmetricTensor<2, 3>
  MohrCoulomb::flow_direction(const SymmetricTensor<2, 3> &stress) const
  {
    // Q has the form of F with psi in place of phi (and no cohesion).
    const StressInvariants inv(stress);
    if (std::abs(inv.lode_angle) > corner_lode_angle)
      {
        // Corner: the average of the two faces' gradients, which is
        // the smooth gradient at theta = +-30 degrees without the
        // Lode-angle term.
        const double s = (inv.lode_angle > 0) ? 0.5 : -0.5;
        return invariant_gradient(inv, sin_psi, 0.5 - s * sin_psi / 3, 0);
      }
    const double c = std::cos(inv.lode_angle);
    const double s = std::sin(inv.lode_angle);
    return invariant_gradient(inv,
                              sin_psi,
                              c / std::sqrt(3.) - s * sin_psi / 3,
                              inv.equivalent *
                                (-s / std::sqrt(3.) - c * sin_psi / 3));
  }


  double
  MohrCoulomb::yield_ratio(const SymmetricTensor<2, 3> &stress) const
  {
    // The strength available at this mean stress; floored so that a
    // cohesionless point in tension reports a large ratio, not a
    // division by zero.
    const double available = cohesion * cos_phi - trace(stress) / 3 * sin_phi;
    return yield_function(stress) / std::max(available, 1e-12 * youngs_modulus);
  }


  double
  MohrCoulomb::mobilised_strength(const SymmetricTensor<2, 3> &stress) const
  {
    // Mohr's circle of the largest and smallest principal stresses
    // (tension positive) against the strength line at its centre.
    const std::array<double, 3> s      = eigenvalues(stress);
    const double                radius = 0.5 * (s[0] - s[2]);
    const double available = cohesion * cos_phi - 0.5 * (s[0] + s[2]) * sin_phi;
    if (available <= 0)
      return 1;
    return std::min(1., radius / available);
  }


  double
  MohrCoulomb::viscoplastic_time_step() const
  {
    const double nu = poissons_ratio;
    return 4 * (1 + nu) * (1 - 2 * nu) /
           (youngs_modulus * (1 - 2 * nu + sin_phi * sin_phi));
  }


  bool
  MohrCoulomb::is_associated() const
  {
    return sin_psi == sin_phi;
  }


  ReturnMapping
  MohrCoulomb::return_mapping(const SymmetricTensor<2, 3> &trial,
                              const bool                   with_tangent) const
  {
    // A trial that is not a finite number (or whose invariants
    // overflow) stays as it is: its yield ratio is not finite, and the
    // analysis fails the step on it rather than the eigensolver here.
    const double f = yield_function(trial);
    if (!std::isfinite(f) || f <= 0)
      return {trial, stiffness, ReturnRegion::elastic};

    // The eigenproblem scaled to order one where its iterations would
    // overflow (stresses near the largest double); elsewhere as it is.
    double magnitude = 0;
    for (unsigned int k = 0;
         k < SymmetricTensor<2, 3>::n_independent_components;
         ++k)
      magnitude = std::max(magnitude, std::abs(trial.access_raw_entry(k)));
    magnitude                 = magnitude > 1e100 ? magnitude : 1.;
    auto                  eig = eigenvectors(trial / magnitude);
    std::array<double, 3> st;
    for (unsigned int i = 0; i < 3; ++i)
      st[i] = eig[i].first * magnitude;
    const double K = youngs_modulus / (3 * (1 - 2 * poissons_ratio));
    const double G = youngs_modulus / (2 * (1 + poissons_ratio));
    // Principal elasticity.
    double Dp[3][3];
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        Dp[i][j] = K - 2 * G / 3 + (i == j ? 2 * G : 0);

    const double scale    = std::abs(st[0]) + std::abs(st[2]) + cohesion;
    const double slack    = 1e-12 * scale;
    const double strength = cohesion * cos_phi;

    // Tries the return onto the planes @p active (one or two); fills
    // sigma and the principal tangent P; false if a multiplier is
    // negative or the ordering breaks.
    std::array<double, 3> sigma;
    double                P[3][3];
    const auto            try_return =
      [&](const unsigned int                                          k,
          const std::array<std::pair<unsigned int, unsigned int>, 2> &active,
          const bool check_order) {
        return return_to_planes(k,
                                active,
                                check_order,
                                {st, Dp, sin_phi, sin_psi, strength, slack},
                                sigma,
                                P);
      };

    ReturnRegion region = ReturnRegion::surface;
    if (!try_return(1, {{{0, 2}, {0, 2}}}, true))
      {
        // Which edge: the main-plane return pushed s2 above s1, or
        // below s3.
        try_return(1, {{{0, 2}, {0, 2}}}, false);
        const bool upper = (sigma[1] > sigma[0]);
        region           = upper ? ReturnRegion::edge_s1_equals_s2
                                 : ReturnRegion::edge_s2_equals_s3;
        const bool ok    = upper ? try_return(2, {{{0, 2}, {1, 2}}}, true)
                                 : try_return(2, {{{0, 2}, {0, 1}}}, true);
        if (!ok && sin_phi > 0)
          {
            // The apex: a hydrostatic state at c cot(phi); perfectly
            // plastic, so the stress does not depend on the strain.
            region = ReturnRegion::apex;
            sigma.fill(cohesion * cos_phi / sin_phi);
            for (auto &row : P)
              for (double &v : row)
                v = 0;
          }
      }

    SymmetricTensor<2, 3> stress;
    for (unsigned int i = 0; i < 3; ++i)
      stress +=
        sigma[i] * symmetrize(outer_product(eig[i].second, eig[i].second));
    if (!with_tangent)
      return {stress, {}, region};
    // d sigma / d strain = (d sigma / d trial) : D.
    return {stress,
            isotropic_function_tangent(eig, sigma, P) * stiffness,
            region};
  }
} // namespace thinlayer
