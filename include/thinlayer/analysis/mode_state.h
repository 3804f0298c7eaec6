#ifndef thinlayer_analysis_mode_state_h
#define thinlayer_analysis_mode_state_h

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <thinlayer/solvers/factorised_stiffness.h>

namespace thinlayer
{
  using namespace dealii;

  /**
   * Everything that exists once per mode (one in plane strain, one per
   * Fourier harmonic): its constraints (the axis conditions depend on the
   * harmonic), its elastic stiffness and factorisation, its loads and
   * displacements, and what the point loop returns for it. The solution
   * methods keep their own work vectors.
   */
  struct ModeState
  {
    explicit ModeState(const FactorisedStiffness::Method method)
      : factorisation(method)
    {}

    /// Serendipity, dead-component and axis lines.
    AffineConstraints<double> structural_constraints;
    /// The above plus homogeneous Dirichlet lines: the solve's space.
    AffineConstraints<double> constraints;
    SparseMatrix<double>      stiffness;
    SparseMatrix<double>      condensed_stiffness;
    FactorisedStiffness       factorisation;
    Vector<double>            unit_prescribed_displacement;
    Vector<double>            unit_load;
    /// f - K u_prescribed at unit load factor.
    Vector<double> unit_rhs;
    /// The displacement amplitudes at the last accepted load step.
    Vector<double> solution;
    /// The current iterate of the load step's displacement increment.
    Vector<double> step_increment;

    /// Return mapping: int B^T sigma, the internal forces of the stresses.
    Vector<double> internal_forces;
    /// Viscoplastic: the step's accumulated body loads (kept condensed).
    /// Return mapping: the stress excess int B^T (trial - sigma).
    Vector<double> body_loads;
    /// Viscoplastic: the body loads of the last iteration's viscoplastic
    /// strains.
    Vector<double> body_load_change;
    /// Return mapping: the out-of-balance force, condensed onto the free
    /// DoFs.
    Vector<double> residual;
    /// A condensed copy, work space of the residual evaluation.
    Vector<double> condensed;
  };
} // namespace thinlayer

#endif
