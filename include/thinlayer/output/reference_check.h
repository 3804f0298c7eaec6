#ifndef thinlayer_output_reference_check_h
#define thinlayer_output_reference_check_h

#include <thinlayer/output/run_summary.h>
#include <thinlayer/parameters/parameters.h>

#include <string>

namespace thinlayer
{
  /**
   * A run held against what its parameter file expects of it
   * (Reference/Expected outcome, Reference/Expected load range): the truth
   * a verification scene names, asserted by the run itself. The test suite
   * relies on it: a scene test whose run misses its closed form exits
   * non-zero, and fails however its reference output was blessed.
   */
  struct ReferenceCheck
  {
    /// Whether anything was expected.
    bool checked = false;
    /// Whether everything expected holds.
    bool passed = true;
    /// What was compared, with the values: one line for the screen.
    std::string description;
  };

  /// @p summary held against @p reference.
  ReferenceCheck
  check_reference(const ReferenceParameters &reference,
                  const RunSummary          &summary);
} // namespace thinlayer

#endif
