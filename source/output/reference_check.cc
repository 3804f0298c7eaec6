#include <thinlayer/base/text_format.h>
#include <thinlayer/output/reference_check.h>

#include <cmath>

namespace thinlayer
{
  ReferenceCheck
  check_reference(const ReferenceParameters &reference,
                  const RunSummary          &summary)
  {
    ReferenceCheck check;
    check.checked = reference.expects_something();
    if (!check.checked)
      return check;

    std::string parts;
    const auto  add = [&](const bool holds, const std::string &what) {
      if (!parts.empty())
        parts += "; ";
      parts += what + (holds ? "" : " (MISSED)");
      check.passed = check.passed && holds;
    };
    if (!reference.expected_outcome.empty())
      add(summary.outcome == reference.expected_outcome,
          "outcome " + summary.outcome + ", expected " +
            reference.expected_outcome);
    if (std::isfinite(reference.expected_low))
      {
        const bool   collapse = std::isfinite(summary.collapse_load);
        const double load =
          collapse ? summary.collapse_load : summary.last_converged_load;
        const bool   relative = std::isfinite(reference.analytic_load);
        const double ratio = relative ? load / reference.analytic_load : load;
        // A NaN ratio (no step converged) lies in no range.
        add(ratio >= reference.expected_low && ratio <= reference.expected_high,
            std::string(collapse ? "collapse load " : "last converged load ") +
              text_format::printf("%.6g", load) +
              (relative
                 ? " = " + text_format::printf("%.6g", ratio) + " x analytic"
                 : std::string()) +
              ", expected in [" +
              text_format::printf("%.7g", reference.expected_low) + ", " +
              text_format::printf("%.7g", reference.expected_high) + "]");
      }
    check.description = (check.passed ? "passed: " : "FAILED: ") + parts;
    return check;
  }
} // namespace thinlayer
