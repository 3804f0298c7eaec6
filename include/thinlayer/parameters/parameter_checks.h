#ifndef thinlayer_parameters_parameter_checks_h
#define thinlayer_parameters_parameter_checks_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <string>

namespace thinlayer
{
  using namespace dealii;

  /**
   * @file
   * Checks that more than one parameter section makes of its entries, each
   * throwing InputError with the file, the entry and what was expected.
   */

  /**
   * Silences std::cerr while alive: muparser's diagnostics go there, and
   * we report the error ourselves, once, naming the entry.
   */
  class SilencedErrorStream
  {
  public:
    SilencedErrorStream()
      : saved(std::cerr.rdbuf(sink.rdbuf()))
    {}
    ~SilencedErrorStream()
    {
      std::cerr.rdbuf(saved);
    }

  private:
    std::ostringstream sink;
    std::streambuf    *saved;
  };


  /**
   * The message part of a deal.II exception on one line, without the
   * source location that means nothing to a user.
   */
  std::string
  message_of(const ExceptionBase &exception);

  /**
   * Checks that @p expressions, ';'-separated, are @p n_components function
   * expressions (or one for all) of the three comma-separated
   * @p variables (as FunctionParser<3> takes them: "x,y,z", "r,z,theta")
   * and the @p constants, so that a typo is reported when the file is read,
   * naming @p entry, and not in the middle of a run.
   */
  void
  check_expressions(const std::string                   &expressions,
                    const unsigned int                   n_components,
                    const std::string                   &variables,
                    const std::map<std::string, double> &constants,
                    const std::string                   &file,
                    const std::string                   &entry);

  /// @p text as a number, all of it, into @p value; false if it is not
  /// one (empty, trailing characters, out of range).
  bool
  to_number(const std::string &text, double &value);


  /// Whether @p name is a name of a geometry parameter (and of gmsh's
  /// DefineConstant): a letter or '_', then letters, digits or '_'.
  bool
  is_identifier(const std::string &name);


  /// The entry @p name of the current subsection @p section, which must be
  /// > 0, and at most @p maximum.
  double
  positive(const ParameterHandler &prm,
           const std::string      &name,
           const std::string      &file,
           const std::string      &section,
           const double maximum = std::numeric_limits<double>::infinity());

  /// An InputError unless the current subsection @p section's "Dilation
  /// angle" is at most its "Friction angle" (psi <= phi).
  void
  check_dilation_angle(const ParameterHandler &prm,
                       const std::string      &file,
                       const std::string      &section);
} // namespace thinlayer

#endif
