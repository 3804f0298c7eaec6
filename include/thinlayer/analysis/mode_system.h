#ifndef thinlayer_analysis_mode_system_h
#define thinlayer_analysis_mode_system_h

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <thinlayer/solvers/factorised_stiffness.h>

namespace thinlayer
{
  using namespace dealii;

  /**
   * The linear system of one mode (one in plane strain, one per Fourier
   * harmonic): its constraints (the axis conditions depend on the
   * harmonic), its elastic stiffness and factorisation, and its loads at
   * unit load factor. Fixed once the analysis is set up; the state (the
   * displacements and forces of every mode) is the Analysis's, and what a
   * solution method iterates with is the method's.
   */
  struct ModeSystem
  {
    explicit ModeSystem(const FactorisedStiffness::Method method)
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
  };
} // namespace thinlayer

#endif
