#ifndef thinlayer_parameters_reference_section_h
#define thinlayer_parameters_reference_section_h

#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>

namespace thinlayer
{
  using namespace dealii;

  struct MeshParameters;

  /**
   * "Reference": the analytic value of the load the run is compared with,
   * and what a scene that verifies a closed form expects of its run: the
   * outcome and the range, as multiples of the analytic load, its load must
   * end in. A run that misses them is reported and exits non-zero, so a
   * verification scene fails on its own truth, whatever its screen output.
   */
  struct ReferenceParameters
  {
    /// Evaluated from the geometry parameters and the Variables; the
    /// middle of analytic_bracket where only that is given; NaN where
    /// neither is.
    double analytic_load;
    /// Bounds known to hold the exact value (limit analysis brackets it
    /// where no closed form is known): {"low", "high"}, empty for none.
    std::map<std::string, double> analytic_bracket;
    /// The outcome the run must end in; empty for any.
    std::string expected_outcome;
    /// The range, as multiples of analytic_load (in load units where there
    /// is none), the run's load (its collapse load where it has one, else
    /// its last converged load) must lie in; NaN for no check.
    double expected_low  = std::numeric_limits<double>::quiet_NaN();
    double expected_high = std::numeric_limits<double>::quiet_NaN();

    /// Whether the parameter file expects anything of the run.
    bool
    expects_something() const
    {
      return !expected_outcome.empty() || std::isfinite(expected_low);
    }

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler     &prm,
          const std::string    &parameter_file,
          const MeshParameters &mesh);

  private:
    /// The names Reference/Variables binds, with this run's values of the
    /// entries they name.
    static std::map<std::string, double>
    variables(ParameterHandler  &prm,
              const std::string &text,
              const std::string &parameter_file);

    /// Analytic load = @p expression, evaluated with @p constants (the
    /// geometry parameters and the Variables); NaN for an empty one.
    static double
    evaluate_analytic_load(const std::string                   &expression,
                           const std::map<std::string, double> &constants,
                           const std::string                   &parameter_file);

    /// Analytic bracket = @p text, checked against analytic_load, which it
    /// sets to its middle where there is none.
    void
    parse_bracket(const std::string &text, const std::string &parameter_file);
  };

} // namespace thinlayer

#endif
