// Truth checked: Lame's closed-form solution for a thick cylinder under
// internal pressure in plane strain (inner radius a = 1, outer b = 2,
// pressure p = 1, E = 1, nu = 0.3; E = 1 keeps the errors above the absolute
// floor of 1e-6 below which numdiff ignores differences):
//   u_r = (1 + nu)/E * a^2 p/(b^2 - a^2) * ((1 - 2 nu) r + b^2/r).
// A quarter of the cylinder with symmetry conditions is refined uniformly;
// the errors of the displacement in L2 and in the H1 seminorm must fall at
// the rates of quadratic elements, 3 and 2. The curved boundaries are
// represented by the quadratic mapping; interior edges are straight, so the
// cell centres follow the same serendipity (Gordon-Hall) rule as the
// displacement, as for the classical isoparametric 8-node element.
#include <deal.II/base/convergence_table.h>
#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>
#include <deal.II/numerics/vector_tools.h>

#include <thinlayer/analysis/analysis.h>
#include <thinlayer/mesh/scene.h>
#include <thinlayer/parameters/parameter_reader.h>
#include <thinlayer/parameters/parameters.h>
#include <thinlayer/stepping/step_solver.h>

#include <iostream>

using namespace dealii;

const double a = 1, b = 2, pressure = 1, E = 1, nu = 0.3;

class LameDisplacement : public Function<2>
{
public:
  LameDisplacement()
    : Function<2>(2)
  {}
  void
  vector_value(const Point<2> &x, Vector<double> &u) const override
  {
    const double r  = x.norm();
    const double ur = (1 + nu) / E * a * a * pressure / (b * b - a * a) *
                      ((1 - 2 * nu) * r + b * b / r);
    u[0] = ur * x[0] / r;
    u[1] = ur * x[1] / r;
  }
  void
  vector_gradient(const Point<2>            &x,
                  std::vector<Tensor<1, 2>> &g) const override
  {
    // u = f(r) x / r with f/r = A (1 - 2nu) + A b^2 / r^2, A the prefactor.
    const double A  = (1 + nu) / E * a * a * pressure / (b * b - a * a);
    const double r2 = x.norm_square();
    const double g0 = A * ((1 - 2 * nu) + b * b / r2); // u_i = g0 x_i
    const double dg = -2 * A * b * b / (r2 * r2);      // dg0/dx_j = dg x_j
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = 0; j < 2; ++j)
        g[i][j] = g0 * (i == j) + dg * x[i] * x[j];
  }
};

void
make_quarter_cylinder(Triangulation<2> &tria, const unsigned int refinements)
{
  GridGenerator::quarter_hyper_shell(tria, Point<2>(), a, b, 4);
  tria.set_all_manifold_ids(numbers::flat_manifold_id);
  for (const auto &face : tria.active_face_iterators())
    if (face->at_boundary())
      {
        const Point<2> c = face->center();
        if (std::abs(c[0]) < 1e-10)
          face->set_boundary_id(2); // x = 0: symmetry, u_x = 0
        else if (std::abs(c[1]) < 1e-10)
          face->set_boundary_id(3); // y = 0: symmetry, u_y = 0
        else
          {
            face->set_boundary_id(c.norm() < 0.5 * (a + b) ? 0 : 1);
            face->set_manifold_id(0);
          }
      }
  tria.set_manifold(0, SphericalManifold<2>());
  tria.refine_global(refinements);
}

void
convergence(const std::string &element, const std::string &gauss)
{
  ConvergenceTable table;
  for (unsigned int refinements = 0; refinements < 5; ++refinements)
    {
      Triangulation<2> tria;
      make_quarter_cylinder(tria, refinements);

      const std::string prm =
        "subsection Mesh\n  set File = made-in-code\nend\n"
        "subsection Discretisation\n"
        "  set Element = " +
        element +
        "\n"
        "  set Gauss points per direction = " +
        gauss +
        "\n"
        "end\n"
        "subsection Material 0\n"
        "  set Young's modulus = 1\n  set Poisson's ratio = 0.3\n"
        "end\n"
        "subsection Boundary 0\n  set Pressure = 1\nend\n"
        "subsection Boundary 2\n  set Constrained components = x\nend\n"
        "subsection Boundary 3\n  set Constrained components = y\nend\n"
        "subsection Monitors\n  set Displacement boundary id = 0\nend\n";
      const thinlayer::Parameters p =
        thinlayer::ParameterReader().read_from_string(prm, "cylinder.prm");
      thinlayer::check_ids(p, tria);
      thinlayer::Analysis<2> analysis(p, tria);
      analysis.setup();
      {
        thinlayer::StepSolver<2> solver(p.solver, analysis);
        solver.solve(1.0);
        solver.accept();
      }

      const LameDisplacement exact;
      Vector<double>         errors(tria.n_active_cells());
      const QGauss<2>        quadrature(5);
      table.add_value("cells", tria.n_active_cells());
      table.add_value("dofs", analysis.n_dofs());
      for (const auto &[norm, name] :
           {std::make_pair(VectorTools::L2_norm, "L2"),
            std::make_pair(VectorTools::H1_seminorm, "H1")})
        {
          VectorTools::integrate_difference(analysis.get_mapping(),
                                            analysis.get_dof_handler(),
                                            analysis.whole_solution(),
                                            exact,
                                            errors,
                                            quadrature,
                                            norm);
          table.add_value(
            name, VectorTools::compute_global_error(tria, errors, norm));
        }
    }
  for (const auto &column : {"L2", "H1"})
    {
      table.set_scientific(column, true);
      table.set_precision(column, 2);
      table.evaluate_convergence_rates(column,
                                       "cells",
                                       ConvergenceTable::reduction_rate_log2,
                                       2);
    }
  std::cout << element << ", " << gauss << 'x' << gauss
            << " Gauss points (rates are orders in h):\n";
  table.write_text(std::cout, TableHandler::org_mode_table);
}

int
main()
{
  convergence("Q8", "2");
  convergence("Q8", "3");
  convergence("Q9", "3");
}
