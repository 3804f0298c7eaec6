// Truth checked: the constrained Q2 space is the quadratic serendipity
// space. On rectangles (and 3D boxes) the 8-node (20-node) interpolant
// reproduces quadratics and x^2 y exactly, but not x^2 y^2; the
// unconstrained Q9 (Q27) reproduces all three. On a sheared parallelogram
// complete quadratics stay exact (the space is affine-invariant), while x^2 y
// picks up an eta^3 term in reference coordinates and is exact for neither.
#include <deal.II/base/function_lib.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <thinlayer/discretisation/serendipity_constraints.h>

#include <cstdio>
#include <functional>
#include <iostream>

using namespace dealii;

template <int dim>
class Monomial : public Function<dim>
{
public:
  Monomial(std::function<double(const Point<dim> &)> f)
    : f(f)
  {}
  double
  value(const Point<dim> &p, const unsigned int = 0) const override
  {
    return f(p);
  }

private:
  std::function<double(const Point<dim> &)> f;
};

// L2 norm of (interpolant - f), relative to the L2 norm of f.
template <int dim>
double
interpolation_error(const Triangulation<dim> &tria,
                    const bool                serendipity,
                    const Function<dim>      &f)
{
  FE_Q<dim>       fe(2);
  DoFHandler<dim> dof_handler(tria);
  dof_handler.distribute_dofs(fe);
  AffineConstraints<double> constraints;
  if (serendipity)
    thinlayer::make_serendipity_constraints(dof_handler, constraints);
  constraints.close();

  const MappingQ<dim> mapping(1);
  Vector<double>      u(dof_handler.n_dofs());
  VectorTools::interpolate(mapping, dof_handler, f, u);
  constraints.distribute(u); // the centre nodes take the serendipity value

  Vector<double>    cell_errors(tria.n_active_cells());
  const QGauss<dim> quadrature(5);
  VectorTools::integrate_difference(
    mapping, dof_handler, u, f, cell_errors, quadrature, VectorTools::L2_norm);
  const double error =
    VectorTools::compute_global_error(tria, cell_errors, VectorTools::L2_norm);

  Vector<double> zero(dof_handler.n_dofs());
  VectorTools::integrate_difference(mapping,
                                    dof_handler,
                                    zero,
                                    f,
                                    cell_errors,
                                    quadrature,
                                    VectorTools::L2_norm);
  return error / VectorTools::compute_global_error(tria,
                                                   cell_errors,
                                                   VectorTools::L2_norm);
}

template <int dim>
void
report(const std::string        &mesh,
       const Triangulation<dim> &tria,
       const std::string        &name,
       const Function<dim>      &f)
{
  for (const bool serendipity : {true, false})
    {
      const double e = interpolation_error(tria, serendipity, f);
      // Exact means round-off; otherwise the error is printed (it is
      // deterministic) so that a change of space shows.
      std::printf(
        "%-14s %-4s %-11s %s\n",
        mesh.c_str(),
        serendipity ? (dim == 2 ? "Q8" : "Q20") : (dim == 2 ? "Q9" : "Q27"),
        name.c_str(),
        e < 1e-12
          ? "exact"
          : ("relative L2 error " + std::to_string(e).substr(0, 7)).c_str());
    }
}

int
main()
{
  {
    Triangulation<2> rectangle;
    GridGenerator::subdivided_hyper_rectangle(rectangle,
                                              {3, 2},
                                              Point<2>(0.2, -0.3),
                                              Point<2>(1.4, 0.9));
    // The same grid under a shear and stretch: every cell a parallelogram.
    Triangulation<2> parallelogram;
    parallelogram.copy_triangulation(rectangle);
    GridTools::transform(
      [](const Point<2> &p) {
        return Point<2>(0.2 + 1.1 * p[0] + 0.6 * p[1],
                        -0.3 + 0.3 * p[0] + 0.9 * p[1]);
      },
      parallelogram);

    const Monomial<2> quadratic([](const Point<2> &p) {
      return 1 + p[0] - 2 * p[1] + 3 * p[0] * p[0] - p[0] * p[1] +
             0.5 * p[1] * p[1];
    });
    const Monomial<2> x2y([](const Point<2> &p) { return p[0] * p[0] * p[1]; });
    const Monomial<2> xy2([](const Point<2> &p) { return p[0] * p[1] * p[1]; });
    const Monomial<2> x2y2(
      [](const Point<2> &p) { return p[0] * p[0] * p[1] * p[1]; });

    for (const auto &[mesh, tria] :
         {std::make_pair(std::string("rectangle"), &rectangle),
          std::make_pair(std::string("parallelogram"), &parallelogram)})
      {
        report(mesh, *tria, "quadratic", quadratic);
        report(mesh, *tria, "x^2 y", x2y);
        report(mesh, *tria, "x y^2", xy2);
        report(mesh, *tria, "x^2 y^2", x2y2);
      }
  }
  {
    Triangulation<3> box;
    GridGenerator::subdivided_hyper_rectangle(box,
                                              {2, 2, 1},
                                              Point<3>(0.1, 0.2, -0.3),
                                              Point<3>(1.1, 0.9, 0.5));
    report("box", box, "x^2 y + P2", Monomial<3>([](const Point<3> &p) {
             return p[0] * p[0] * p[1] + p[2] * p[2] - p[0] * p[2];
           }));
    report("box", box, "x y z", Monomial<3>([](const Point<3> &p) {
             return p[0] * p[1] * p[2];
           }));
    report("box", box, "x^2 y^2", Monomial<3>([](const Point<3> &p) {
             return p[0] * p[0] * p[1] * p[1];
           }));
  }
}
