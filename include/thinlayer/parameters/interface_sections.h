#ifndef thinlayer_parameters_interface_sections_h
#define thinlayer_parameters_interface_sections_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <thinlayer/base/name_table.h>

#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace thinlayer
{
  using namespace dealii;

  // The sections of the two ways of modelling an interface: thin layers
  // and interface elements (source/parameters/interface_sections.cc).

  /// "Layers" (called "Interfaces" before, which is still accepted, with a
  /// warning): the thin layers whose profile a run reports.
  struct LayerParameters
  {
    /// Material ids of thin layers (one cell thick).
    std::vector<types::material_id> material_ids;

    static void
    declare(ParameterHandler &prm);
    /// Every id must have its Material section (@p materials).
    void
    parse(ParameterHandler                   &prm,
          const std::string                  &parameter_file,
          const std::set<types::material_id> &materials);
  };

  /**
   * "Interface <id>", one per gmsh physical curve that carries
   * zero-thickness (Goodman-type) interface elements: the mesh is split
   * along the curve when read, and each pair of facing cell sides is
   * coupled by an InterfaceLaw.
   */
  struct InterfaceElementParameters
  {
    enum class Criterion
    {
      elastic,
      tresca,
      mohr_coulomb
    };
    enum class Integration
    {
      gauss,
      lobatto
    };
    static const NameTable<Criterion>   criterion_names;
    static const NameTable<Integration> integration_names;

    std::string name;
    /// k_n and k_s, traction per unit relative displacement.
    double    normal_stiffness;
    double    shear_stiffness;
    Criterion criterion;
    /// c (adhesion), phi and psi (degrees), and the tension cut-off T
    /// (infinity for none).
    double      adhesion;
    double      friction_angle;
    double      dilation_angle;
    double      tensile_strength;
    Integration integration;
    /// Points per cell side: Gauss 2 or 3; Lobatto 3 (the side's nodes).
    unsigned int points;

    static std::string
    section(const unsigned int id);
    static void
    declare(ParameterHandler &prm, const unsigned int id);
    void
    parse(ParameterHandler  &prm,
          const std::string &parameter_file,
          const unsigned int id);
  };
} // namespace thinlayer

#endif
