// Truths checked for the strain-displacement cache (StrainOperator) and
// the kinematics behind it, on meshes of distorted straight-sided cells
// where the quadratic element holds every linear field exactly:
// 1. Plane strain: u = A x gives the strain sym(A) (embedded in 3D, the
//    out-of-plane components 0) at every Gauss point, to 1e-12; the point
//    weights sum to the area.
// 2. 3D (Kinematics::make_solid()): u = A x gives sym(A) at every point of
//    a mesh of hexahedra; the weights sum to the volume.
// 3. Fourier: harmonic 0 with u_r = r gives eps_rr = eps_tt = 1, the rest
//    0; harmonic 1 with (u_r, u_z, u_theta) = (1, 0, -1) (cos, cos, sin), a
//    rigid translation, gives no strain in either part; the weights (r dA)
//    sum to int r dA.
#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <thinlayer/discretisation/kinematics.h>
#include <thinlayer/discretisation/strain_operator.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>

#include "../common/truths.h"

using namespace thinlayer;
using truths::expect;

namespace
{
  /// A vector field given by a lambda.
  template <int dim>
  class Field : public Function<dim>
  {
  public:
    Field(const unsigned int                                         n,
          const std::function<double(const Point<dim> &, unsigned)> &f)
      : Function<dim>(n)
      , f(f)
    {}

    double
    value(const Point<dim> &x, const unsigned int c) const override
    {
      return f(x, c);
    }

  private:
    std::function<double(const Point<dim> &, unsigned)> f;
  };


  /// The largest deviation over every point of @p B's strain of mode
  /// @p m, part @p part, for the nodal values @p u, from @p expected; and
  /// the sum of the point weights.
  std::pair<double, double>
  deviation(const StrainOperator        &B,
            const unsigned int           n_cells,
            const unsigned int           n_q,
            const unsigned int           m,
            const unsigned int           part,
            const Vector<double>        &u,
            const SymmetricTensor<2, 3> &expected)
  {
    double              worst = 0, weights = 0;
    std::vector<double> local(B.dofs_per_cell());
    for (unsigned int c = 0; c < n_cells; ++c)
      {
        for (unsigned int i = 0; i < B.dofs_per_cell(); ++i)
          local[i] = u[B.cell_dofs(c)[i]];
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const unsigned int p = c * n_q + q;
            worst =
              std::max(worst,
                       (B.strain(p, m, part, local.data()) - expected).norm());
            weights += B.point_weight(p);
          }
      }
    return {worst, weights};
  }


  /// A mesh of @p n cells per direction on [1, 2]^dim, its interior
  /// vertices moved (the cells stay straight-sided).
  template <int dim>
  void
  distorted_mesh(Triangulation<dim> &tria, const unsigned int n)
  {
    GridGenerator::subdivided_hyper_cube(tria, n, 1, 2);
    GridTools::distort_random(0.2, tria, /*keep_boundary=*/true, 42);
  }


  /// Strain of u = A x against sym(A), for the kinematics @p kinematics.
  template <int dim>
  void
  linear_field(const Kinematics &kinematics, const std::string &name)
  {
    Triangulation<dim> tria;
    distorted_mesh(tria, 3);
    const FESystem<dim> fe(FE_Q<dim>(2), dim);
    DoFHandler<dim>     dof_handler(tria);
    dof_handler.distribute_dofs(fe);
    const MappingQ<dim> mapping(1);
    const QGauss<dim>   quadrature(3);
    StrainOperator      B;
    B.reinit(dof_handler, mapping, quadrature, kinematics);

    double A[3][3] = {{0.3, -1.2, 0.7}, {2.1, 0.4, -0.5}, {0.9, 1.3, -0.8}};
    Vector<double> u(dof_handler.n_dofs());
    VectorTools::interpolate(mapping,
                             dof_handler,
                             Field<dim>(dim,
                                        [&](const Point<dim> &x, unsigned c) {
                                          double v = 0;
                                          for (unsigned int d = 0; d < dim; ++d)
                                            v += A[c][d] * x[d];
                                          return v;
                                        }),
                             u);
    SymmetricTensor<2, 3> expected;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        expected[i][j] = 0.5 * (A[i][j] + A[j][i]);
    const auto [worst, weights] =
      deviation(B, tria.n_active_cells(), quadrature.size(), 0, 0, u, expected);
    // Deviations at rounding level are not printed: they vary with the
    // compiler's arithmetic.
    std::printf("  %s: sum of weights %.12f\n", name.c_str(), weights);
    expect(worst < 1e-12, name + ": the strain of u = A x is sym(A)");
    expect(std::abs(weights - 1) < 1e-12, name + ": the weights sum to 1");
  }
} // namespace


int
main()
{
  std::cout << "1. Plane strain\n";
  linear_field<2>(Kinematics::make_plane_strain(), "plane strain");

  std::cout << "2. 3D\n";
  linear_field<3>(Kinematics::make_solid(), "3D");

  std::cout << "3. Fourier\n";
  {
    Triangulation<2> tria;
    distorted_mesh(tria, 3);
    const FESystem<2> fe(FE_Q<2>(2), 3);
    DoFHandler<2>     dof_handler(tria);
    dof_handler.distribute_dofs(fe);
    const MappingQ<2> mapping(1);
    const QGauss<2>   quadrature(3);
    const Kinematics  kinematics =
      Kinematics::make_fourier({0, 1},
                               {0, numbers::PI / 2, numbers::PI},
                               false);
    StrainOperator B;
    B.reinit(dof_handler, mapping, quadrature, kinematics);
    const unsigned int n_cells = tria.n_active_cells(), n_q = quadrature.size();

    // Harmonic 0 (mode 0): u_r = r.
    Vector<double> u(dof_handler.n_dofs());
    VectorTools::interpolate(mapping,
                             dof_handler,
                             Field<2>(3,
                                      [](const Point<2> &x, unsigned c) {
                                        return c == 0 ? x[0] : 0.;
                                      }),
                             u);
    SymmetricTensor<2, 3> expected;
    expected[0][0] = expected[2][2] = 1;
    const auto [worst, weights] = deviation(B, n_cells, n_q, 0, 0, u, expected);
    // int r dA over [1, 2]^2 = (4 - 1) / 2.
    std::printf("  harmonic 0, u_r = r: sum of weights %.12f\n", weights);
    expect(worst < 1e-12, "eps_rr = eps_tt = 1");
    expect(std::abs(weights - 1.5) < 1e-12, "the weights sum to int r dA");

    // Harmonic 1 (mode 1): a rigid translation along x.
    VectorTools::interpolate(mapping,
                             dof_handler,
                             Field<2>(3,
                                      [](const Point<2> &, unsigned c) {
                                        return c == 0 ? 1. : c == 1 ? 0. : -1.;
                                      }),
                             u);
    const double part1 = deviation(B, n_cells, n_q, 1, 0, u, {}).first;
    const double part2 = deviation(B, n_cells, n_q, 1, 1, u, {}).first;
    expect(part1 < 1e-12 && part2 < 1e-12, "no strain in either part");
  }
  return truths::conclude();
}
