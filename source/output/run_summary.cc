#include <thinlayer/base/text_format.h>
#include <thinlayer/output/run_summary.h>

#include <cmath>
#include <limits>
#include <string>

#include <nlohmann/json.hpp>

namespace thinlayer
{
  namespace
  {
    /**
     * Collects the figures as the members of a JSON object, in visit()
     * order; a number that is not finite becomes null, JSON's "no value".
     */
    struct JsonWriter
    {
      nlohmann::ordered_json object = nlohmann::ordered_json::object();

      static nlohmann::ordered_json
      number(const double value)
      {
        return std::isfinite(value) ? nlohmann::ordered_json(value)
                                    : nlohmann::ordered_json(nullptr);
      }

      template <typename T>
      void
      operator()(const std::string &name, const T &value)
      {
        object[name] = value;
      }

      void
      operator()(const std::string &name, const double value)
      {
        object[name] = number(value);
      }

      void
      operator()(const std::string                   &name,
                 const std::map<std::string, double> &values)
      {
        nlohmann::ordered_json nested = nlohmann::ordered_json::object();
        for (const auto &[key, value] : values)
          nested[key] = number(value);
        object[name] = nested;
      }

      void
      operator()(const std::string &name, const std::vector<PhaseSummary> &list)
      {
        nlohmann::ordered_json array = nlohmann::ordered_json::array();
        for (const PhaseSummary &phase : list)
          array.push_back(
            {{"name", phase.name},
             {"outcome", phase.outcome},
             {"reason", phase.reason},
             {"load_steps", phase.load_steps},
             {"collapse_load", number(phase.collapse_load)},
             {"last_converged_load", number(phase.last_converged_load)},
             {"final_displacement", number(phase.final_displacement)}});
        object[name] = array;
      }

      /// The cycles of an adaptive run; null for a single run.
      void
      operator()(const std::string &name, const AdaptivitySummary &adaptivity)
      {
        if (adaptivity.cycles.empty())
          {
            object[name] = nullptr;
            return;
          }
        nlohmann::ordered_json cycles = nlohmann::ordered_json::array();
        for (const CycleSummary &c : adaptivity.cycles)
          cycles.push_back({{"cycle", c.cycle},
                            {"refined_cells", c.refined_cells},
                            {"cells", c.cells},
                            {"dofs", c.dofs},
                            {"equations", c.equations},
                            {"outcome", c.outcome},
                            {"collapse_load", number(c.collapse_load)},
                            {"relative_error", number(c.relative_error)},
                            {"wall_seconds", number(c.wall_seconds)}});
        object[name] = {{"indicator", adaptivity.indicator},
                        {"marking", adaptivity.marking},
                        {"cycles", cycles},
                        {"stop_reason", adaptivity.stop_reason},
                        {"extrapolated_collapse_load",
                         number(adaptivity.extrapolated_collapse_load)},
                        {"extrapolated_relative_error",
                         number(adaptivity.extrapolated_relative_error)},
                        {"estimated_error", number(adaptivity.estimated_error)},
                        {"rate", number(adaptivity.rate)}};
      }
    };


    /// Writes the names or the values of the single-valued figures as CSV
    /// fields (nested figures are left to summary.json).
    struct CsvWriter
    {
      enum class Content
      {
        names,
        values,
        /// A run that stopped with an error: not converged, no values.
        error
      };
      Content     content;
      std::string text;
      /// Whether a field has been written: the separator goes before
      /// every field but the first, empty ones included.
      bool any = false;

      void
      field(const std::string &name, const std::string &value)
      {
        text += (any ? "," : "") +
                (content == Content::names    ? text_format::csv_field(name)
                 : content == Content::values ? value
                                              : std::string());
        any = true;
      }

      void
      operator()(const std::string &name, const double value)
      {
        field(name, text_format::csv_number(value));
      }

      void
      operator()(const std::string &name, const unsigned int value)
      {
        field(name, std::to_string(value));
      }

      void
      operator()(const std::string &name, const bool value)
      {
        if (content == Content::error)
          {
            text += any ? ",0" : "0";
            any = true;
          }
        else
          field(name, value ? "1" : "0");
      }

      void
      operator()(const std::string &name, const std::string &value)
      {
        field(name, text_format::csv_field(value));
      }

      void
      operator()(const std::string &, const std::map<std::string, double> &)
      {}

      void
      operator()(const std::string &, const std::vector<PhaseSummary> &)
      {}

      void
      operator()(const std::string &, const AdaptivitySummary &)
      {}
    };
  } // namespace


  RunSummary::RunSummary()
    : collapse_load(std::numeric_limits<double>::quiet_NaN())
    , safety_factor(std::numeric_limits<double>::quiet_NaN())
    , knee_load(std::numeric_limits<double>::quiet_NaN())
    , last_converged_load(std::numeric_limits<double>::quiet_NaN())
    , first_failed_load(std::numeric_limits<double>::quiet_NaN())
    , reference_load(std::numeric_limits<double>::quiet_NaN())
    , relative_error(std::numeric_limits<double>::quiet_NaN())
    , final_displacement(std::numeric_limits<double>::quiet_NaN())
    , final_displacement_min(std::numeric_limits<double>::quiet_NaN())
    , final_displacement_max(std::numeric_limits<double>::quiet_NaN())
    , seconds_per_factorisation(std::numeric_limits<double>::quiet_NaN())
    , seconds_per_substitution(std::numeric_limits<double>::quiet_NaN())
    , linear_iterations_per_solve(std::numeric_limits<double>::quiet_NaN())
    , seconds_per_iteration(std::numeric_limits<double>::quiet_NaN())
    , wall_seconds(std::numeric_limits<double>::quiet_NaN())
    , peak_memory_mb(std::numeric_limits<double>::quiet_NaN())
    , program_memory_mb(std::numeric_limits<double>::quiet_NaN())
  {}


  std::string
  RunSummary::json() const
  {
    JsonWriter writer;
    visit(writer);
    // Text that is not valid UTF-8 (a file name, a reason quoting input) is
    // written with replacement characters rather than stopping the run.
    return writer.object.dump(
             2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) +
           '\n';
  }


  std::string
  RunSummary::csv_header()
  {
    CsvWriter writer{CsvWriter::Content::names, ""};
    RunSummary().visit(writer);
    return writer.text;
  }


  std::string
  RunSummary::csv_row() const
  {
    CsvWriter writer{CsvWriter::Content::values, ""};
    visit(writer);
    return writer.text;
  }


  std::string
  RunSummary::csv_error_row()
  {
    CsvWriter writer{CsvWriter::Content::error, ""};
    RunSummary().visit(writer);
    return writer.text;
  }
} // namespace thinlayer
