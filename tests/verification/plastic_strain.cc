// Truth checked: the plastic strain a run records belongs to the stress it
// accepts. After every accepted load step, at every Gauss point,
//   plastic strain = eps(u) - C^-1 sigma
// must hold to round-off, with eps(u) computed here from the accepted
// displacement by deal.II's FEValues (independently of the code's strain
// operator). The scene is Prandtl's strip footing (prm/, coarse mesh)
// loaded to 0.95 of its collapse, well into plastic flow. Checked for the
// paper's viscoplastic method, whose last increment of a step has no
// stress of its own (so it must not enter the plastic strain), at a loose
// TOL of 1e-3 where that increment is large, and for
// the default method (return mapping).
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/fe/fe_values.h>

#include <thinlayer/analysis/analysis.h>
#include <thinlayer/mesh/scene.h>
#include <thinlayer/parameters/parameter_reader.h>
#include <thinlayer/parameters/parameters.h>
#include <thinlayer/stepping/step_solver.h>

#include <cstdio>

using namespace dealii;

namespace
{
  /// max over points of |plastic strain - (eps(u) - C^-1 sigma)|, and of
  /// |eps(u)|.
  std::pair<double, double>
  mismatch(const thinlayer::Analysis<2> &analysis)
  {
    const auto     &dof_handler = analysis.get_dof_handler();
    const QGauss<2> quadrature(
      static_cast<unsigned int>(std::sqrt(analysis.n_quadrature_points())));
    FEValues<2>                            fe_values(analysis.get_mapping(),
                          dof_handler.get_fe(),
                          quadrature,
                          update_gradients);
    const thinlayer::ModeVector            u = analysis.displacement_at(0);
    std::vector<std::vector<Tensor<1, 2>>> gradients(
      quadrature.size(), std::vector<Tensor<1, 2>>(2));
    double worst = 0, largest = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        fe_values.reinit(cell);
        fe_values.get_function_gradients(u, gradients);
        const unsigned int c = cell->active_cell_index();
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          {
            SymmetricTensor<2, 3> strain;
            strain[0][0] = gradients[q][0][0];
            strain[1][1] = gradients[q][1][1];
            strain[0][1] = 0.5 * (gradients[q][0][1] + gradients[q][1][0]);
            const thinlayer::PointState &state = analysis.get_point_state(c, q);
            const SymmetricTensor<2, 3>  from_stress =
              strain - analysis.get_material_law(c).compliance() * state.stress;
            worst =
              std::max(worst, (state.plastic_strain - from_stress).norm());
            largest = std::max(largest, strain.norm());
          }
      }
    return {worst, largest};
  }
} // namespace


int
main()
{
  for (const std::string method :
       {"viscoplastic", "accelerated with newton fallback"})
    {
      const thinlayer::Parameters p = thinlayer::ParameterReader().read(
        SOURCE_DIR "/../../prm/prandtl-strip-footing.prm",
        {"Solver/Method=" + method,
         "Solver/Convergence criterion=default",
         "Solver/Tolerance=1e-3",
         "Solver/Maximum iterations=2000"});
      const thinlayer::Scene<2> scene(p, std::cout);
      thinlayer::Analysis<2>    analysis(p, scene.triangulation());
      analysis.setup();
      thinlayer::StepSolver<2> solver(p.solver, analysis);

      for (const double load_factor : {0.5, 0.8, 0.9, 0.95})
        {
          const thinlayer::StepResult result = solver.solve(load_factor);
          solver.accept();
          const auto [worst, largest] = mismatch(analysis);
          std::printf("%s, load factor %.2f: converged %s, yielding points "
                      "%s, max |plastic strain - (eps - C^-1 sigma)| / max "
                      "|eps| below 1e-10: %s\n",
                      method.c_str(),
                      load_factor,
                      result.converged ? "yes" : "NO",
                      result.plastic_points > 0 ? "yes" : "none",
                      worst < 1e-10 * largest ? "yes" : "NO");
          if (!(worst < 1e-10 * largest))
            std::printf("  mismatch %.3e, max |eps| %.3e\n", worst, largest);
        }
    }
}
