#include <deal.II/base/utilities.h>

#include <thinlayer/base/input_error.h>
#include <thinlayer/parameters/loading_sections.h>
#include <thinlayer/parameters/parameter_checks.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace thinlayer
{
  namespace
  {
    /// More load steps than anyone means (and than memory holds at 1e9).
    constexpr unsigned long max_load_steps = 100000;

    std::vector<double>
    parse_increments(const std::string &text,
                     const std::string &file,
                     const std::string &entry)
    {
      std::vector<double> result;
      for (const auto &item : Utilities::split_string_list(text, ','))
        {
          const auto        star      = item.find('*');
          const std::string count     = star == std::string::npos
                                          ? "1"
                                          : Utilities::trim(item.substr(0, star));
          double            increment = 0;
          if (!to_number(Utilities::trim(item.substr(
                           star == std::string::npos ? 0 : star + 1)),
                         increment) ||
              count.empty() ||
              count.find_first_not_of("0123456789") != std::string::npos ||
              count.size() > 9 || std::stoul(count) > max_load_steps)
            throw InputError(file,
                             entry,
                             "expected a number or 'n*number' (n a whole "
                             "number of steps, at most " +
                               std::to_string(max_load_steps) + "), got '" +
                               item + "'");
          const unsigned long n = std::stoul(count);
          if (n == 0)
            throw InputError(file,
                             entry,
                             "expected a repeat count of at least 1, got '" +
                               item + "' (no steps)");
          if (!std::isfinite(increment))
            throw InputError(file,
                             entry,
                             "expected finite numbers, got '" + item + "'");
          if (increment == 0)
            throw InputError(file,
                             entry,
                             "expected non-zero increments, got '" + item +
                               "': a step of 0 applies nothing");
          if (result.size() + n > max_load_steps)
            throw InputError(file,
                             entry,
                             "expected at most " +
                               std::to_string(max_load_steps) +
                               " load steps, got more");
          result.insert(result.end(), n, increment);
        }
      if (result.empty())
        throw InputError(file, entry, "expected at least one increment");
      return result;
    }


    /// Whether the increments of a programme all have one sign: a loading
    /// rather than a cycle.
    bool
    of_one_sign(const std::vector<double> &increments)
    {
      return std::none_of(increments.begin(),
                          increments.end(),
                          [&](const double d) {
                            return d * increments.front() < 0;
                          });
    }
  } // namespace


  const NameTable<LoadingParameters::StepLength>
    LoadingParameters::step_length_names = {{StepLength::programme,
                                             "programme"},
                                            {StepLength::adaptive, "adaptive"}};


  const NameTable<LoadingParameters::Control> LoadingParameters::control_names =
    {{Control::load, "load"}, {Control::work, "work"}};


  void
  LoadingParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Loading");
    prm.declare_entry(
      "Load increments",
      "1",
      Patterns::Anything(),
      "Increments of the load factor, one per load step, comma-separated; "
      "'n*d' repeats the increment d n times (e.g. '0.5, 10*0.05'). All "
      "tractions, pressures and prescribed displacements scale with the "
      "load factor (and the weight, unless Initial state/Procedure gives it "
      "a phase of its own or the initial stresses carry it).");
    prm.declare_entry(
      "Collapse resolution",
      "0.005",
      Patterns::Double(0, 1),
      "Automatic load stepping: a load step that fails is halved and tried "
      "again from the last accepted state, and steps grow back to the "
      "programme's after easy ones (converged in at most a quarter of "
      "Solver/Maximum iterations); under load, a step that converges on "
      "the mechanism (its secant stiffness below 0.01 of the elastic one) "
      "is cut back the same way and never accepted. A step that still "
      "fails, or lands on the mechanism, when it is at most this fraction "
      "of its load factor ends the run, the collapse load then bracketed "
      "to it (0.005: 0.5%). 0: the programme as given, the first failed "
      "step ending the run (the paper's way).");
    prm.declare_entry(
      "Step length",
      "programme",
      Patterns::Selection(step_length_names.pattern()),
      "With automatic stepping (Collapse resolution > 0): 'programme': no "
      "step longer than the programme's increment, every target of the "
      "programme attempted. 'adaptive': the programme gives only the first "
      "step and where the loading ends; after every easy converged step "
      "the step doubles, without the programme's bound, after a hard one "
      "it keeps its length, and after one that took more than half of "
      "Solver/Maximum iterations it halves. No step reaches past a load "
      "factor that failed until a state there has converged; one that "
      "fails twice is bracketed by bisection. The collapse is bracketed to "
      "the resolution as with the programme. The increments must have one "
      "sign (a loading, not a cycle).");
    prm.declare_entry(
      "Control",
      "load",
      Patterns::Selection(control_names.pattern()),
      "What each load step prescribes. 'load': its load factor, the "
      "programme's. 'work': after the programme's first step, the work of "
      "the loads on the step, f^T du, the load factor found with the "
      "displacements (the indirect continuation of Sysala, Cermak and "
      "Ligursky): the load factor rises towards the limit as the work "
      "grows, so the collapse is reached without a step that fails, as the "
      "plateau of the load (the work doubles at most per step, and the "
      "step grows as with Step length = adaptive); the run also ends where "
      "the load factor reaches the programme's end. For a loading by "
      "tractions, pressures and weight (no prescribed displacement), by "
      "Solver/Method = newton or the default method (Newton throughout), in "
      "the Loading section's phase; with automatic stepping (Collapse "
      "resolution > 0).");
    prm.leave_subsection();
  }


  std::string
  LoadingPhaseParameters::section(const unsigned int n)
  {
    return "Phase " + std::to_string(n);
  }


  void
  LoadingPhaseParameters::declare(
    ParameterHandler                        &prm,
    const unsigned int                       n,
    const std::set<types::global_dof_index> &boundary_ids)
  {
    prm.enter_subsection(section(n));
    prm.declare_entry("Name",
                      "",
                      Patterns::Anything(),
                      "The phase's name in history.csv and summary.json "
                      "(default 'loading <n>').");
    prm.declare_entry("Load increments",
                      "1",
                      Patterns::Anything(),
                      "Increments of this phase's load factor, as "
                      "Loading/Load increments: its Boundary subsections' "
                      "values scale with it, from 0, on top of what the "
                      "phases before it hold.");
    for (const auto id : boundary_ids)
      BoundaryParameters::declare(prm, id, true);
    prm.leave_subsection();
  }


  void
  LoadingPhaseParameters::parse(
    ParameterHandler                                       &prm,
    const std::string                                      &file,
    const unsigned int                                      n,
    const std::set<types::global_dof_index>                &opened,
    const std::map<types::boundary_id, BoundaryParameters> &constrained,
    const LoadingParameters                                &first,
    const KinematicsParameters                             &kinematics,
    const MeshParameters                                   &mesh)
  {
    const std::string outer = section(n) + "/";
    prm.enter_subsection(section(n));
    name = prm.get("Name");
    if (name.empty())
      name = "loading " + std::to_string(n);
    loading.load_increments     = parse_increments(prm.get("Load increments"),
                                               file,
                                               outer + "Load increments");
    loading.collapse_resolution = first.collapse_resolution;
    loading.step_length         = first.step_length;
    if (loading.step_length == LoadingParameters::StepLength::adaptive &&
        !of_one_sign(loading.load_increments))
      throw InputError(file,
                       outer + "Load increments",
                       "expected increments of one sign with "
                       "Loading/Step length = adaptive, got '" +
                         prm.get("Load increments") + "'");
    for (const auto id : opened)
      {
        BoundaryParameters &boundary = boundaries[id];
        prm.enter_subsection(BoundaryParameters::section(id));
        const bool constrains = !prm.get("Constrained components").empty();
        prm.leave_subsection();
        if (constrains)
          throw InputError(file,
                           outer + BoundaryParameters::section(id) +
                             "/Constrained components",
                           "a phase keeps the constraints of the Boundary "
                           "sections (the stiffness is factorised once); "
                           "expected it unset here, and the component "
                           "constrained in 'Boundary " +
                             std::to_string(id) + "'");
        const auto given = constrained.find(id);
        boundary.parse(
          prm,
          file,
          id,
          kinematics,
          mesh,
          outer,
          given == constrained.end()
            ? std::vector<bool>(kinematics.component_names().size(), false)
            : given->second.constrained_components);
      }
    prm.leave_subsection();
  }


  void
  LoadingParameters::parse(ParameterHandler &prm, const std::string &file)
  {
    prm.enter_subsection("Loading");
    load_increments     = parse_increments(prm.get("Load increments"),
                                       file,
                                       "Loading/Load increments");
    collapse_resolution = prm.get_double("Collapse resolution");
    step_length         = step_length_names.value(prm.get("Step length"));
    control             = control_names.value(prm.get("Control"));
    if (control == Control::work && collapse_resolution == 0)
      throw InputError(file,
                       "Loading/Control",
                       "expected 'load' where Loading/Collapse resolution "
                       "is 0 (the programme run as given); 'work' ends at "
                       "the plateau of the load, which needs automatic "
                       "stepping");
    if (control == Control::work && load_increments.front() < 0)
      throw InputError(file,
                       "Loading/Control",
                       "expected a first load increment > 0 with 'work' (its "
                       "step sets the scale of the work), got '" +
                         prm.get("Load increments") + "'");
    if (step_length == StepLength::adaptive)
      {
        if (collapse_resolution == 0)
          throw InputError(file,
                           "Loading/Step length",
                           "expected 'programme' where Loading/Collapse "
                           "resolution is 0 (the programme run as given); "
                           "'adaptive' needs automatic stepping");
        if (!of_one_sign(load_increments))
          throw InputError(file,
                           "Loading/Step length",
                           "expected Loading/Load increments of one sign "
                           "with 'adaptive' (it keeps only the first "
                           "increment and the end), got '" +
                             prm.get("Load increments") + "'");
      }
    prm.leave_subsection();
  }


  const NameTable<InitialStateParameters::Procedure>
    InitialStateParameters::procedure_names = {{Procedure::none, "none"},
                                               {Procedure::k0, "K0 procedure"},
                                               {Procedure::gravity_loading,
                                                "gravity loading"}};


  void
  InitialStateParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Initial state");
    prm.declare_entry(
      "Procedure",
      "none",
      Patterns::Selection(procedure_names.pattern()),
      "The stresses the loading starts from. 'none': a weightless start, "
      "the weight (if any Material/Unit weight) part of the loading. 'K0 "
      "procedure': sigma_v = -(surcharge + the weight of the material "
      "above the point), sigma_h = K0 sigma_v (Material/K0), set at once; "
      "only a level ground surface and horizontal layers have it in "
      "equilibrium (refused where the surface is not level, and where it "
      "lies outside a material's yield surface); zero-thickness interface "
      "elements start from the traction of the stresses beside them (the "
      "same on both sides unless the interface is horizontal, and inside "
      "its slip surface); 2D meshes (plane strain, Fourier). 'gravity "
      "loading': the weight and the surcharge applied "
      "in a phase of their own (Load increments below), elastic-plastic, "
      "any kinematics. Either way the loading then holds them fixed.");
    prm.declare_entry("Load increments",
                      "4*0.25",
                      Patterns::Anything(),
                      "Gravity loading's programme: increments of the "
                      "weight's factor, adding up to 1 (the syntax of "
                      "Loading/Load increments; automatic stepping with "
                      "Loading/Collapse resolution).");
    prm.declare_entry("Surcharge",
                      "0",
                      Patterns::Double(),
                      "A pressure (>= 0) on the ground surface: the "
                      "upward-facing boundary faces at the body's top "
                      "level. It loads the body with its weight.");
    prm.declare_entry("Reset displacements",
                      "true",
                      Patterns::Bool(),
                      "Whether the loading's displacements start from zero "
                      "(those of the initial state are then not part of "
                      "the monitored displacements, the history or the "
                      "fields); the stresses are kept.");
    prm.leave_subsection();
  }


  void
  InitialStateParameters::parse(ParameterHandler &prm, const std::string &file)
  {
    prm.enter_subsection("Initial state");
    procedure       = procedure_names.value(prm.get("Procedure"));
    load_increments = parse_increments(prm.get("Load increments"),
                                       file,
                                       "Initial state/Load increments");
    const double total =
      std::accumulate(load_increments.begin(), load_increments.end(), 0.);
    if (std::abs(total - 1) > 1e-9)
      throw InputError(file,
                       "Initial state/Load increments",
                       "expected increments adding up to 1 (the whole "
                       "weight), got '" +
                         prm.get("Load increments") + "' (sum " +
                         std::to_string(total) + ")");
    surcharge = prm.get_double("Surcharge");
    if (!(surcharge >= 0) || !std::isfinite(surcharge))
      throw InputError(file,
                       "Initial state/Surcharge",
                       "expected a pressure >= 0, got " + prm.get("Surcharge"));
    reset_displacements = prm.get_bool("Reset displacements");
    prm.leave_subsection();
  }


  StrengthReductionParameters::Reduced
  StrengthReductionParameters::reduce(const double cohesion,
                                      const double friction_angle,
                                      const double dilation_angle,
                                      const double factor)
  {
    const double degree = numbers::PI / 180;
    const double phi =
      std::atan(std::tan(friction_angle * degree) / factor) / degree;
    return {cohesion / factor, phi, std::min(dilation_angle, phi)};
  }


  void
  StrengthReductionParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Strength reduction");
    prm.declare_entry(
      "Materials",
      "",
      Patterns::Anything(),
      "Material ids (comma-separated) whose strength a last phase divides "
      "by a factor F raised from 1 until the body fails: c / F and "
      "tan(phi) / F together (the dilation angle at most the reduced "
      "friction angle). The safety factor is summary.json's "
      "collapse_load. Each must have a yield criterion. Empty, with no "
      "Interfaces: no strength reduction.");
    prm.declare_entry("Interfaces",
                      "",
                      Patterns::Anything(),
                      "Curves of zero-thickness interface elements "
                      "(comma-separated ids) whose adhesion and tan(phi) "
                      "are reduced with the materials'; each must have a "
                      "slip criterion.");
    prm.declare_entry("Factor increments",
                      "0.1, 0.1, 0.2, 0.4, 0.8, 1.6",
                      Patterns::Anything(),
                      "Increments of F from 1, one per step (the syntax of "
                      "Loading/Load increments; automatic stepping with "
                      "Loading/Collapse resolution).");
    prm.leave_subsection();
  }


  namespace
  {
    /// The ids of @p text (comma-separated), each a key of @p allowed
    /// whose value is true, of the kind @p what; refused otherwise, with
    /// @p why where its value is false.
    template <typename Id>
    std::set<Id>
    parse_ids(const std::string        &text,
              const std::map<Id, bool> &allowed,
              const std::string        &file,
              const std::string        &entry,
              const std::string        &what,
              const std::string        &why)
    {
      std::set<Id> ids;
      for (const std::string &item : Utilities::split_string_list(text, ','))
        {
          double id = -1;
          if (!to_number(item, id) || id < 0 || id != std::floor(id) ||
              allowed.count(static_cast<Id>(id)) == 0)
            throw InputError(file,
                             entry,
                             "expected " + what + " ids of the scene, got '" +
                               item + "'");
          if (!allowed.at(static_cast<Id>(id)))
            throw InputError(file, entry, what + " " + item + " " + why);
          if (!ids.insert(static_cast<Id>(id)).second)
            throw InputError(file,
                             entry,
                             "'" + item +
                               "' is given twice; expected each id once");
        }
      return ids;
    }
  } // namespace


  void
  StrengthReductionParameters::parse(
    ParameterHandler                         &prm,
    const std::string                        &file,
    const std::map<types::material_id, bool> &can_yield,
    const std::map<types::boundary_id, bool> &can_slip)
  {
    prm.enter_subsection("Strength reduction");
    materials  = parse_ids(prm.get("Materials"),
                          can_yield,
                          file,
                          "Strength reduction/Materials",
                          "material",
                          "is elastic: it has no strength to reduce; expected "
                           "materials with a yield criterion");
    interfaces = parse_ids(prm.get("Interfaces"),
                           can_slip,
                           file,
                           "Strength reduction/Interfaces",
                           "curve",
                           "is elastic: it has no strength to reduce; "
                           "expected curves with a slip criterion");
    factor_increments =
      parse_increments(prm.get("Factor increments"),
                       file,
                       "Strength reduction/Factor increments");
    for (const double increment : factor_increments)
      if (!(increment > 0))
        throw InputError(file,
                         "Strength reduction/Factor increments",
                         "expected increments > 0 (the factor only rises), "
                         "got '" +
                           prm.get("Factor increments") + "'");
    prm.leave_subsection();
  }
} // namespace thinlayer
