#include <thinlayer/elements/continuum_cells.h>
#include <thinlayer/elements/element_group.h>
#include <thinlayer/elements/interface_elements.h>
#include <thinlayer/parameters/parameters.h>

namespace thinlayer
{
  void
  ElementGroup::reduce_strength(const StrengthReductionParameters &,
                                const double)
  {}


  std::vector<NamedProfile>
  ElementGroup::profiles(const ModeVectors & /*solution*/,
                         const ModeVectors & /*step_increment*/,
                         const bool /*pending*/) const
  {
    return {};
  }


  template <int dim>
  std::vector<std::unique_ptr<ElementGroup>>
  create_element_groups(const Parameters                    &parameters,
                        const DoFHandler<dim>               &dof_handler,
                        const Mapping<dim>                  &mapping,
                        const Quadrature<dim>               &quadrature,
                        const Kinematics                    &kinematics,
                        const CellPartition                 &partition,
                        const std::vector<FacingSides<dim>> &facing_sides,
                        const CellPartition                 &whole_partition)
  {
    std::vector<std::unique_ptr<ElementGroup>> groups;
    groups.push_back(std::make_unique<ContinuumCells<dim>>(dof_handler,
                                                           mapping,
                                                           quadrature,
                                                           kinematics,
                                                           parameters.materials,
                                                           partition));
    if (!parameters.interface_elements.empty())
      {
        auto elements = std::make_unique<InterfaceElements<dim>>();
        elements->reinit(facing_sides,
                         dof_handler,
                         mapping,
                         kinematics,
                         parameters.interface_elements,
                         parameters.materials,
                         whole_partition,
                         parameters.parameter_file);
        groups.push_back(std::move(elements));
      }
    return groups;
  }


  template std::vector<std::unique_ptr<ElementGroup>>
  create_element_groups(const Parameters &,
                        const DoFHandler<2> &,
                        const Mapping<2> &,
                        const Quadrature<2> &,
                        const Kinematics &,
                        const CellPartition &,
                        const std::vector<FacingSides<2>> &,
                        const CellPartition &);
  template std::vector<std::unique_ptr<ElementGroup>>
  create_element_groups(const Parameters &,
                        const DoFHandler<3> &,
                        const Mapping<3> &,
                        const Quadrature<3> &,
                        const Kinematics &,
                        const CellPartition &,
                        const std::vector<FacingSides<3>> &,
                        const CellPartition &);
} // namespace thinlayer
