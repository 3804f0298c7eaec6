#ifndef thinlayer_parameters_parameters_h
#define thinlayer_parameters_parameters_h

#include <thinlayer/parameters/adaptivity_section.h>
#include <thinlayer/parameters/interface_sections.h>
#include <thinlayer/parameters/loading_sections.h>
#include <thinlayer/parameters/reference_section.h>
#include <thinlayer/parameters/run_sections.h>
#include <thinlayer/parameters/scene_sections.h>
#include <thinlayer/parameters/sweep_section.h>

#include <map>
#include <string>
#include <vector>

namespace thinlayer
{
  /**
   * @file
   * The parameter file, one struct per section in the style of deal.II's
   * step-44: each declares its entries (declare()) and reads them back
   * (parse()) side by side, and checks them while reading, so that code
   * that receives a section can trust it. Every check names the file, the
   * entry and what was expected (InputError). Each component of the code
   * receives only the sections it needs.
   *
   * Enumerations have one NameTable each, which gives the entry's
   * Patterns::Selection, its parsing and the name written into results.
   *
   * The sections are declared in scene_sections.h, interface_sections.h,
   * run_sections.h, reference_section.h, sweep_section.h and
   * adaptivity_section.h, each implemented
   * in the source file of its name; ParameterReader (parameter_reader.h) reads
   * a file into Parameters.
   */

  /**
   * Everything one analysis needs, read from a parameter file (plus
   * command-line overrides) by ParameterReader: one member per section.
   */
  struct Parameters
  {
    /// The parameter file, as given on the command line (for messages).
    std::string parameter_file;

    /// Every entry as used, overrides applied, in parameter-file format:
    /// the record of what ran.
    std::string effective_parameters;
    /// What the file asks of that is accepted but should change (a
    /// section's former name): one line each, shown when the run starts.
    std::vector<std::string> warnings;

    MeshParameters                                   mesh;
    KinematicsParameters                             kinematics;
    DiscretisationParameters                         discretisation;
    LayerParameters                                  layers;
    std::map<types::material_id, MaterialParameters> materials;
    std::map<types::boundary_id, BoundaryParameters> boundaries;
    /// Physical curves of zero-thickness interface elements.
    std::map<types::boundary_id, InterfaceElementParameters> interface_elements;
    InitialStateParameters                                   initial_state;
    LoadingParameters                                        loading;
    /// The further loading phases, Phase 2, 3, ... in order.
    std::vector<LoadingPhaseParameters> loading_phases;
    StrengthReductionParameters         strength_reduction;
    SolverParameters                    solver;
    MonitorParameters                   monitors;
    ReferenceParameters                 reference;
    SweepParameters                     sweep;
    AdaptivityParameters                adaptivity;
    OutputParameters                    output;
  };
} // namespace thinlayer

#endif
