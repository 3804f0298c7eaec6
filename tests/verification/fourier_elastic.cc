// Truths checked for the Fourier (axisymmetric body, non-axisymmetric load)
// kinematics, elastic:
// 1. Harmonic 0: Lame's thick cylinder (a = 1, b = 2, internal pressure 1,
//    plane strain u_z = 0, E = 1, nu = 0.3) in the r-z plane,
//      u_r = (1 + nu)/E a^2 p/(b^2 - a^2) ((1 - 2 nu) r + b^2/r);
//    the L2 and H1 errors must fall at rates 3 and 2 under refinement.
// 2. Harmonic 1: Saint-Venant's pure bending of a solid cylinder (radius 1,
//    length 2, curvature k): sigma_zz = E k x, all else zero, and
//      u_x = -k/2 (z^2 + nu (x^2 - y^2)), u_y = -k nu x y, u_z = k x z,
//    i.e. u_r = -k/2 (z^2 + nu r^2) cos, u_theta = k/2 (z^2 - nu r^2) sin,
//    u_z = k r z cos: quadratic, so the Q8 solution must be exact to
//    round-off with 3x3 Gauss points (2x2 does not integrate the r-weighted
//    terms exactly). The cylinder reaches the axis, so this also checks the
//    axis conditions of harmonic 1, and the decomposition into harmonic 1
//    of the Cartesian end traction and prescribed displacement.
// 3. A uniform horizontal traction on the end face loads harmonic 1 only
//    (the load vectors of harmonics 0, 2, 3 vanish), and a run with
//    harmonics 1 and 3 reproduces, at a station, the sum of runs with each
//    harmonic alone.
// 4. The antisymmetric series, harmonic 0: torsion of a solid cylinder
//    (radius 1, length 2) by an end shear tau_z_theta = G k r, base fixed:
//    u_theta = k r z exactly, linear, so the Q8 solution must be exact
//    (with 3x3 Gauss points, which integrate the r-weighted terms exactly).
#include <deal.II/base/convergence_table.h>
#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/numerics/vector_tools.h>

#include <thinlayer/analysis/analysis.h>
#include <thinlayer/mesh/scene.h>
#include <thinlayer/parameters/parameter_reader.h>
#include <thinlayer/parameters/parameters.h>
#include <thinlayer/stepping/step_solver.h>

#include <cstdio>
#include <functional>
#include <iostream>

using namespace dealii;

namespace
{
  const double nu = 0.3;

  // Colorized rectangle: 0 at r = r0 (inner or axis), 1 at r = r1, 2 at
  // z = 0, 3 at z = z1.
  void
  make_rectangle(Triangulation<2>  &tria,
                 const double       r0,
                 const double       r1,
                 const double       z1,
                 const unsigned int nr,
                 const unsigned int nz)
  {
    GridGenerator::subdivided_hyper_rectangle(
      tria, {nr, nz}, Point<2>(r0, 0), Point<2>(r1, z1), true);
    // Colorizing also numbers the cells by quadrant: one material here.
    for (const auto &cell : tria.active_cell_iterators())
      cell->set_material_id(0);
  }

  /// The largest nodal difference between the first mode's solution and
  /// @p exact (a function of the point and the component).
  double
  largest_nodal_error(
    const thinlayer::Analysis<2>                                &analysis,
    const std::function<double(const Point<2> &, unsigned int)> &exact)
  {
    std::map<types::global_dof_index, Point<2>> support;
    DoFTools::map_dofs_to_support_points(analysis.get_mapping(),
                                         analysis.get_dof_handler(),
                                         support);
    const auto          &fe    = analysis.get_dof_handler().get_fe();
    const Vector<double> u     = analysis.whole_solution(0);
    double               error = 0;
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : analysis.get_dof_handler().active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          {
            const unsigned int c = fe.system_to_component_index(i).first;
            error                = std::max(error,
                             std::abs(u[dofs[i]] - exact(support[dofs[i]], c)));
          }
      }
    return error;
  }

  thinlayer::Parameters
  read(const std::string &prm)
  {
    return thinlayer::ParameterReader().read_from_string(
      "subsection Mesh\n  set File = made-in-code\nend\n" + prm, "fourier.prm");
  }

  class LameCylinder : public Function<2>
  {
  public:
    LameCylinder()
      : Function<2>(3)
    {}
    void
    vector_value(const Point<2> &x, Vector<double> &u) const override
    {
      const double A = (1 + nu) / 3.;
      u              = 0;
      u[0]           = A * ((1 - 2 * nu) * x[0] + 4 / x[0]);
    }
    void
    vector_gradient(const Point<2>            &x,
                    std::vector<Tensor<1, 2>> &g) const override
    {
      const double A = (1 + nu) / 3.;
      for (auto &t : g)
        t = 0;
      g[0][0] = A * ((1 - 2 * nu) - 4 / (x[0] * x[0]));
    }
  };

  void
  harmonic_0()
  {
    ConvergenceTable table;
    for (unsigned int level = 0; level < 5; ++level)
      {
        Triangulation<2> tria;
        make_rectangle(tria, 1, 2, 0.5, 2 << level, 1 << level);
        const thinlayer::Parameters p = read(
          "subsection Kinematics\n  set Type = fourier\n"
          "  set Harmonics = 0\nend\n"
          "subsection Material 0\n  set Young's modulus = 1\n"
          "  set Poisson's ratio = 0.3\nend\n"
          "subsection Boundary 0\n  set Pressure = 1\nend\n"
          "subsection Boundary 2\n  set Constrained components = z\nend\n"
          "subsection Boundary 3\n  set Constrained components = z\nend\n"
          "subsection Monitors\n  set Displacement boundary id = 0\nend\n");
        thinlayer::check_ids(p, tria);
        thinlayer::Analysis<2> analysis(p, tria);
        analysis.setup();
        {
          thinlayer::StepSolver<2> solver(p.solver, analysis);
          solver.solve(1);
          solver.accept();
        }

        Vector<double>  errors(tria.n_active_cells());
        const QGauss<2> quadrature(5);
        table.add_value("cells", tria.n_active_cells());
        for (const auto &[norm, name] :
             {std::make_pair(VectorTools::L2_norm, "L2"),
              std::make_pair(VectorTools::H1_seminorm, "H1")})
          {
            VectorTools::integrate_difference(analysis.get_mapping(),
                                              analysis.get_dof_handler(),
                                              analysis.whole_solution(0),
                                              LameCylinder(),
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
    std::cout
      << "1. Harmonic 0, Lame thick cylinder (rates are orders in h):\n";
    table.write_text(std::cout, TableHandler::org_mode_table);
  }

  class Bending : public Function<2>
  {
  public:
    Bending()
      : Function<2>(3)
    {}
    double
    value(const Point<2> &x, const unsigned int component) const override
    {
      const double k = 0.01, r = x[0], z = x[1];
      switch (component)
        {
          case 0:
            return -k / 2 * (z * z + nu * r * r);
          case 1:
            return k * r * z;
          default:
            return k / 2 * (z * z - nu * r * r);
        }
    }
  };

  void
  harmonic_1()
  {
    std::cout << "\n2. Harmonic 1, pure bending of a solid cylinder:\n";
    for (const std::string gauss : {"3", "2"})
      {
        Triangulation<2> tria;
        make_rectangle(tria, 0, 1, 2, 3, 5);
        const thinlayer::Parameters p = read(
          "subsection Kinematics\n  set Type = fourier\n"
          "  set Harmonics = 1\n  set Axis boundary id = 0\nend\n"
          "subsection Discretisation\n  set Gauss points per direction = " +
          gauss +
          "\nend\n"
          "subsection Material 0\n  set Young's modulus = 1\n"
          "  set Poisson's ratio = 0.3\nend\n"
          "subsection Boundary 2\n  set Constrained components = r, z, theta\n"
          "  set Displacement = -0.005*0.3*r^2*cos(2*theta); "
          "-0.01*0.3*r^2*sin(theta)*cos(theta); 0\nend\n"
          "subsection Boundary 3\n  set Traction = 0; 0; 0.01*r*cos(theta)\n"
          "end\n"
          "subsection Monitors\n  set Displacement boundary id = 3\nend\n");
        thinlayer::check_ids(p, tria);
        thinlayer::Analysis<2> analysis(p, tria);
        analysis.setup();
        {
          thinlayer::StepSolver<2> solver(p.solver, analysis);
          solver.solve(1);
          solver.accept();
        }

        // Largest nodal error against the exact amplitudes; the largest
        // displacement is k/2 (z^2 + nu r^2) = 0.0215 at r = 1, z = 2.
        const Bending exact;
        const double  error =
          largest_nodal_error(analysis,
                              [&](const Point<2> &x, const unsigned int c) {
                                return exact.value(x, c);
                              });
        const double size = 0.0215;
        std::printf(
          "  %sx%s Gauss points: largest nodal error / largest "
          "displacement %s\n",
          gauss.c_str(),
          gauss.c_str(),
          error / size < 1e-10
            ? "below 1e-10 (exact)"
            : ("= " + std::to_string(error / size).substr(0, 8)).c_str());
      }
  }

  void
  superposition()
  {
    std::cout << "\n3. Load decomposition and superposition:\n";
    const auto run = [](const std::string &harmonics,
                        const std::string &traction) {
      auto tria = std::make_unique<Triangulation<2>>();
      make_rectangle(*tria, 0, 1, 1, 4, 4);
      auto p = std::make_unique<thinlayer::Parameters>(read(
        "subsection Kinematics\n  set Type = fourier\n  set Harmonics = " +
        harmonics +
        "\n  set Axis boundary id = 0\n"
        "  set Stations = 0, 22.5, 45, 67.5, 90, 112.5, 135, 157.5, 180\n"
        "end\n"
        "subsection Material 0\n  set Young's modulus = 1\nend\n"
        "subsection Boundary 2\n  set Constrained components = r, z, theta\n"
        "end\n"
        "subsection Boundary 3\n  set Traction = " +
        traction +
        "\nend\n"
        "subsection Monitors\n  set Displacement boundary id = 3\nend\n"));
      auto a = std::make_unique<thinlayer::Analysis<2>>(*p, *tria);
      a->setup();
      thinlayer::StepSolver<2> solver(p->solver, *a);
      solver.solve(1);
      solver.accept();
      return std::make_tuple(std::move(tria), std::move(p), std::move(a));
    };

    // A uniform horizontal traction: only harmonic 1 may move.
    {
      auto [tria, p, a] = run("0, 1, 2, 3", "1; 0; 0");
      for (unsigned int m = 0; m < 4; ++m)
        std::printf("  uniform horizontal traction, harmonic %u: largest "
                    "displacement amplitude %s\n",
                    m,
                    a->whole_solution(m).linfty_norm() < 1e-12
                      ? "zero (below 1e-12)"
                      : "non-zero");
    }

    // Harmonics 1 and 3 together against each alone, at 30 degrees.
    const std::string traction = "1 + cos(3*theta)*cos(theta); "
                                 "cos(3*theta)*sin(theta); r*cos(3*theta)";
    auto [t13, p13, a13]       = run("1, 3", traction);
    auto [t1, p1, a1]          = run("1", traction);
    auto [t3, p3, a3]          = run("3", traction);
    const double theta         = numbers::PI / 6;
    // One rank: each analysis's vector holds every DoF.
    const auto whole = [](const thinlayer::ModeVector &v) {
      return Vector<double>(v.begin(), v.end());
    };
    Vector<double> sum = whole(a1->displacement_at(theta));
    sum += whole(a3->displacement_at(theta));
    Vector<double> both = whole(a13->displacement_at(theta));
    both -= sum;
    std::printf("  harmonics {1, 3} against {1} + {3} at 30 degrees: "
                "difference / size %s\n",
                both.linfty_norm() / sum.linfty_norm() < 1e-12 ? "below 1e-12"
                                                               : "LARGE");
  }

  void
  torsion()
  {
    std::cout << "\n4. Antisymmetric series, harmonic 0: torsion\n";
    Triangulation<2> tria;
    make_rectangle(tria, 0, 1, 2, 3, 4);
    // E = 1, nu = 0.3: G = 1/2.6; twist k = 0.01. The traction on the top
    // face is Cartesian: tau (-sin theta, cos theta, 0) with tau = G k r.
    const thinlayer::Parameters p =
      read("subsection Kinematics\n  set Type = fourier\n"
           "  set Series = antisymmetric\n  set Harmonics = 0\n"
           "  set Axis boundary id = 0\nend\n"
           "subsection Discretisation\n  set Gauss points per direction = 3\n"
           "end\n"
           "subsection Material 0\n  set Young's modulus = 1\n"
           "  set Poisson's ratio = 0.3\nend\n"
           "subsection Boundary 2\n  set Constrained components = r, z, theta\n"
           "end\n"
           "subsection Boundary 3\n  set Traction = -0.01/2.6*r*sin(theta); "
           "0.01/2.6*r*cos(theta); 0\nend\n"
           "subsection Monitors\n  set Displacement boundary id = 3\nend\n");
    thinlayer::check_ids(p, tria);
    thinlayer::Analysis<2> analysis(p, tria);
    analysis.setup();
    {
      thinlayer::StepSolver<2> solver(p.solver, analysis);
      solver.solve(1);
      solver.accept();
    }

    const double error =
      largest_nodal_error(analysis,
                          [](const Point<2> &x, const unsigned int c) {
                            return (c == 2) ? 0.01 * x[0] * x[1] : 0.;
                          });
    // The largest twist displacement is k r z = 0.02.
    std::printf("  largest nodal error / 0.02: %s\n",
                error / 0.02 < 1e-10 ? "below 1e-10 (exact)" : "LARGE");
  }
} // namespace

int
main()
{
  harmonic_0();
  harmonic_1();
  superposition();
  torsion();
}
