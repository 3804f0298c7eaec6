#include <deal.II/base/utilities.h>

#include <thinlayer/base/input_error.h>
#include <thinlayer/parameters/parameter_checks.h>
#include <thinlayer/parameters/parameters.h>

#include <algorithm>
#include <cmath>
#include <limits>

// The sections of the two ways of modelling an interface: the thin layers a
// run profiles ("Layers"), and the interface elements, of zero thickness,
// along physical curves ("Interface N").

namespace thinlayer
{
  void
  LayerParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Layers");
    prm.declare_entry(
      "Material ids",
      "",
      Patterns::List(Patterns::Integer(0, 2147483647)),
      "Thin layers (material ids of layers one cell thick) whose profile "
      "is written at every step: slip, opening, shear and normal traction "
      "and plasticity against arc length, as layer-<id>-NNNN.csv (and .vtu), "
      "and as "
      "cell fields in the VTU. Empty for none.");
    prm.leave_subsection();
  }


  void
  LayerParameters::parse(ParameterHandler                   &prm,
                         const std::string                  &file,
                         const std::set<types::material_id> &materials)
  {
    prm.enter_subsection("Layers");
    material_ids.clear();
    for (const int id : Utilities::string_to_int(
           Utilities::split_string_list(prm.get("Material ids"))))
      {
        if (materials.count(id) == 0)
          throw InputError(file,
                           "Layers/Material ids",
                           "expected the id of a material the file describes "
                           "('subsection Material " +
                             std::to_string(id) + "' is missing)");
        if (std::find(material_ids.begin(), material_ids.end(), id) ==
            material_ids.end())
          material_ids.push_back(id);
      }
    prm.leave_subsection();
  }


  const NameTable<InterfaceElementParameters::Criterion>
    InterfaceElementParameters::criterion_names = {
      {InterfaceElementParameters::Criterion::elastic, "elastic"},
      {InterfaceElementParameters::Criterion::tresca, "tresca"},
      {InterfaceElementParameters::Criterion::mohr_coulomb, "mohr-coulomb"}};

  const NameTable<InterfaceElementParameters::Integration>
    InterfaceElementParameters::integration_names = {
      {InterfaceElementParameters::Integration::gauss, "gauss"},
      {InterfaceElementParameters::Integration::lobatto, "lobatto"}};


  std::string
  InterfaceElementParameters::section(const unsigned int id)
  {
    return "Interface " + std::to_string(id);
  }


  void
  InterfaceElementParameters::declare(ParameterHandler  &prm,
                                      const unsigned int id)
  {
    prm.enter_subsection(section(id));
    prm.declare_entry("Name",
                      "",
                      Patterns::Anything(),
                      "A name for this interface (the gmsh physical curve, "
                      "or surface in 3d, with the same number), used in "
                      "output.");
    prm.declare_entry("Normal stiffness",
                      "1e8",
                      Patterns::Double(),
                      "k_n: normal traction per unit opening (> 0); high "
                      "against E / L of the cells beside it, so that the "
                      "interface adds little elastic compliance.");
    prm.declare_entry("Shear stiffness",
                      "1e8",
                      Patterns::Double(),
                      "k_s: shear traction per unit slip (> 0).");
    prm.declare_entry("Slip criterion",
                      "elastic",
                      Patterns::Selection(criterion_names.pattern()),
                      "elastic: never slips; tresca: |tau| = c; "
                      "mohr-coulomb: |tau| + sigma_n tan(phi) = c (tension "
                      "positive).");
    prm.declare_entry("Adhesion",
                      "0",
                      Patterns::Double(0),
                      "c: the shear strength at zero normal traction.");
    prm.declare_entry("Friction angle",
                      "0",
                      Patterns::Double(0, 89),
                      "phi in degrees (mohr-coulomb).");
    prm.declare_entry("Dilation angle",
                      "0",
                      Patterns::Double(0, 89),
                      "psi in degrees (mohr-coulomb), at most phi: the "
                      "opening per unit slip while slipping is tan(psi).");
    prm.declare_entry("Tensile strength",
                      "",
                      Patterns::Anything(),
                      "The tension cut-off T: sigma_n <= T. Empty for the "
                      "default: the apex c / tan(phi) for mohr-coulomb, none "
                      "for tresca.");
    prm.declare_entry("Integration",
                      "gauss",
                      Patterns::Selection(integration_names.pattern()),
                      "gauss: Gauss points along each cell side (each "
                      "direction of a face in 3d); lobatto: "
                      "Newton-Cotes/Lobatto points at the side's three "
                      "nodes (3 x 3 on a face), which keep tractions from "
                      "oscillating at high stiffness.");
    prm.declare_entry("Points per side",
                      "3",
                      Patterns::Integer(2, 3),
                      "Gauss points per cell side (2 or 3; per direction "
                      "of a face in 3d); Lobatto always uses 3.");
    prm.leave_subsection();
  }


  void
  InterfaceElementParameters::parse(ParameterHandler  &prm,
                                    const std::string &file,
                                    const unsigned int id)
  {
    const std::string section = InterfaceElementParameters::section(id);
    prm.enter_subsection(section);
    name             = prm.get("Name");
    normal_stiffness = positive(prm, "Normal stiffness", file, section, 1e30);
    shear_stiffness  = positive(prm, "Shear stiffness", file, section, 1e30);
    const std::string criterion_text = prm.get("Slip criterion");
    criterion                        = criterion_names.value(criterion_text);
    adhesion                         = prm.get_double("Adhesion");
    friction_angle                   = prm.get_double("Friction angle");
    dilation_angle                   = prm.get_double("Dilation angle");
    if (criterion == Criterion::tresca && !(adhesion > 0))
      throw InputError(file,
                       section + "/Adhesion",
                       "expected a value > 0 for the tresca criterion, got " +
                         prm.get("Adhesion"));
    if (criterion != Criterion::mohr_coulomb &&
        (friction_angle != 0 || dilation_angle != 0))
      throw InputError(file,
                       section + "/Friction angle",
                       "friction and dilation angles only with the "
                       "mohr-coulomb criterion; expected 0 for " +
                         criterion_text);
    if (criterion == Criterion::elastic &&
        (adhesion != 0 || !prm.get("Tensile strength").empty()))
      throw InputError(file,
                       section +
                         (adhesion != 0 ? "/Adhesion" : "/Tensile strength"),
                       "an elastic interface curve never slips or opens "
                       "plastically and has no strength; expected it "
                       "unset, or Slip criterion = tresca or mohr-coulomb");
    if (criterion == Criterion::mohr_coulomb &&
        !(adhesion > 0 || friction_angle > 0))
      throw InputError(file,
                       section + "/Adhesion",
                       "expected an adhesion or a friction angle above 0 "
                       "for the mohr-coulomb criterion");
    check_dilation_angle(prm, file, section);
    const std::string tension = prm.get("Tensile strength");
    if (tension.empty())
      tensile_strength =
        (criterion == Criterion::mohr_coulomb && friction_angle > 0)
          ? adhesion / std::tan(friction_angle * numbers::PI / 180)
          : std::numeric_limits<double>::infinity();
    else
      {
        if (!to_number(tension, tensile_strength) ||
            !std::isfinite(tensile_strength))
          throw InputError(file,
                           section + "/Tensile strength",
                           "expected a number or nothing, got '" + tension +
                             "'");
        if (!(tensile_strength >= 0))
          throw InputError(file,
                           section + "/Tensile strength",
                           "expected a value >= 0, got " + tension);
      }
    integration = integration_names.value(prm.get("Integration"));
    points      = integration == Integration::lobatto
                    ? 3
                    : prm.get_integer("Points per side");
    prm.leave_subsection();
  }
} // namespace thinlayer
