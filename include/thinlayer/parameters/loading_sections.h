#ifndef thinlayer_parameters_loading_sections_h
#define thinlayer_parameters_loading_sections_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <thinlayer/base/name_table.h>
#include <thinlayer/parameters/scene_sections.h>

#include <map>
#include <set>
#include <string>
#include <vector>

namespace thinlayer
{
  using namespace dealii;

  // The phases of a run: the initial state the body starts from, and the
  // loading that follows it (source/parameters/loading_sections.cc).

  /// "Loading": the load programme.
  struct LoadingParameters
  {
    /// Increments of the load factor, one per load step: the programme.
    std::vector<double> load_increments;
    /// Automatic stepping: a failed step is halved and retried until the
    /// collapse load is bracketed to this fraction of the load factor; 0
    /// runs the programme as given (LoadStepping).
    double collapse_resolution;

    /// How the step length is chosen with automatic stepping.
    enum class StepLength
    {
      /// Each step at most the programme's increment, its targets all
      /// attempted.
      programme,
      /// The programme's first increment and end only; the steps between
      /// grow with the ease of the last one (LoadStepping).
      adaptive
    };
    StepLength                         step_length = StepLength::programme;
    static const NameTable<StepLength> step_length_names;

    /// What each step of the loading prescribes.
    enum class Control
    {
      /// The load factor: the programme's targets.
      load,
      /// The work of the load on the step, f^T du: the load factor is an
      /// unknown of the step (Programme::run_by_work()).
      work
    };
    Control                         control = Control::load;
    static const NameTable<Control> control_names;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm, const std::string &parameter_file);
  };


  /**
   * "Phase <n>" (n = 2, 3, ...; the Loading section with the Boundary
   * sections is phase 1): a further loading, as a footing is first loaded
   * vertically and then pushed sideways. It holds what the phases before
   * it reached (their loads at their last load factor, their prescribed
   * displacements where they ended) and applies its own boundary values
   * from load factor 0 by its own programme. Its "Boundary <id>"
   * subsections give Displacement, Traction and Pressure as the Boundary
   * sections do; which components are constrained stays the Boundary
   * sections' throughout the run (the stiffness is factorised once).
   */
  struct LoadingPhaseParameters
  {
    std::string name;
    /// The phase's programme (the Loading section's collapse resolution).
    LoadingParameters loading;
    /// What the phase applies, per boundary id, with the constrained
    /// components of the Boundary section of that id (none without one).
    std::map<types::boundary_id, BoundaryParameters> boundaries;

    /// "Phase <n>".
    static std::string
    section(const unsigned int n);
    /// Declares the section with a "Boundary <id>" subsection for every
    /// id of @p boundary_ids.
    static void
    declare(ParameterHandler                        &prm,
            const unsigned int                       n,
            const std::set<types::global_dof_index> &boundary_ids);
    /// The boundaries of @p boundary_ids that the phase's section opens
    /// (@p opened, "Phase <n>/Boundary <id>"), checked as the Boundary
    /// sections are, with the constraints of @p constrained (the Boundary
    /// sections).
    void
    parse(ParameterHandler                        &prm,
          const std::string                       &parameter_file,
          const unsigned int                       n,
          const std::set<types::global_dof_index> &opened,
          const std::map<types::boundary_id, BoundaryParameters> &constrained,
          const LoadingParameters                                &first,
          const KinematicsParameters                             &kinematics,
          const MeshParameters                                   &mesh);
  };


  /**
   * "Initial state": the stresses the body carries before its loading, as
   * a geotechnical model starts from the ground's weight rather than from
   * a weightless body. Either set at once by the K0 procedure (which only
   * a level ground has in equilibrium), or reached by a phase of its own
   * that applies the weight in steps (gravity loading, elastic-plastic).
   * Either way the loading that follows holds the weight (and the
   * surcharge) fixed and applies the Boundary sections' values.
   */
  struct InitialStateParameters
  {
    enum class Procedure
    {
      /// A weightless start: the weight, if any, is part of the loading.
      none,
      /// sigma_v from the weight above and the surcharge, sigma_h = K0
      /// sigma_v per material.
      k0,
      /// The weight in a phase of its own, by the load programme below.
      gravity_loading
    };
    static const NameTable<Procedure> procedure_names;

    Procedure procedure;
    /// Gravity loading's programme: increments of the weight's factor,
    /// adding up to 1.
    std::vector<double> load_increments;
    /// A pressure on the ground surface (the highest upward-facing
    /// boundary faces), part of the ground's weight.
    double surcharge;
    /// Whether the loading's displacements start from zero: those of the
    /// weight are of no interest to a footing's settlement or a wall's
    /// movement.
    bool reset_displacements;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm, const std::string &parameter_file);
  };

  /**
   * "Strength reduction": a safety factor, as PLAXIS's safety phase and
   * Griffiths and Lane's (1999) slopes find it. After the initial state
   * and the loading, the strengths of the named materials are divided by
   * a factor F raised step by step from 1: c / F and tan(phi) / F
   * together (the dilation angle kept at most the reduced friction angle),
   * the loads held, until the body can no longer be in equilibrium. The
   * safety factor is the plateau of F against the monitored displacement,
   * bracketed by automatic stepping as a collapse load is.
   */
  struct StrengthReductionParameters
  {
    /// The materials and the curves of interface elements whose strength
    /// is reduced; none of either: no such phase.
    std::set<types::material_id> materials;
    std::set<types::boundary_id> interfaces;
    /// Increments of F, from 1.
    std::vector<double> factor_increments;

    /// A strength reduced by a factor: c / factor, atan(tan(phi) /
    /// factor), the dilation angle at most that (angles in degrees).
    struct Reduced
    {
      double cohesion, friction_angle, dilation_angle;
    };
    static Reduced
    reduce(const double cohesion,
           const double friction_angle,
           const double dilation_angle,
           const double factor);

    /// Whether a strength reduction phase runs.
    bool
    active() const
    {
      return !materials.empty() || !interfaces.empty();
    }

    static void
    declare(ParameterHandler &prm);
    /// Checks the materials against @p can_yield (the mesh's materials,
    /// whether each has a yield criterion) and the curves against
    /// @p can_slip (the interface curves, whether each has a slip
    /// criterion).
    void
    parse(ParameterHandler                         &prm,
          const std::string                        &parameter_file,
          const std::map<types::material_id, bool> &can_yield,
          const std::map<types::boundary_id, bool> &can_slip);
  };
} // namespace thinlayer

#endif
