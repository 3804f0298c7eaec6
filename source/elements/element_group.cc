#include <thinlayer/base/input_error.h>
#include <thinlayer/elements/continuum_cells.h>
#include <thinlayer/elements/element_group.h>
#include <thinlayer/elements/interface_elements.h>
#include <thinlayer/parameters/parameters.h>

namespace thinlayer
{
  std::vector<NamedProfile>
  ElementGroup::profiles(const ModeVectors & /*solution*/,
                         const ModeVectors & /*step_increment*/,
                         const bool /*pending*/) const
  {
    return {};
  }


  template <int dim>
  std::vector<std::unique_ptr<ElementGroup>>
  create_element_groups(const Parameters               &parameters,
                        const DoFHandler<dim>          &dof_handler,
                        const Mapping<dim>             &mapping,
                        const Quadrature<dim>          &quadrature,
                        const Kinematics               &kinematics,
                        const CellPartition            &partition,
                        const std::vector<FacingSides> &facing_sides,
                        const CellPartition            &whole_partition)
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
        // The interface elements join the sides of quadrilaterals: a family
        // of 2D meshes (on a 3D mesh they would join faces, a family of its
        // own).
        if constexpr (dim == 2)
          {
            auto elements = std::make_unique<InterfaceElements>();
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
        else
          throw InputError(
            parameters.parameter_file,
            InterfaceElementParameters::section(
              parameters.interface_elements.begin()->first),
            "interface elements along curves of a 2D mesh; this mesh is " +
              std::to_string(dim) + "D");
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
                        const std::vector<FacingSides> &,
                        const CellPartition &);
  template std::vector<std::unique_ptr<ElementGroup>>
  create_element_groups(const Parameters &,
                        const DoFHandler<3> &,
                        const Mapping<3> &,
                        const Quadrature<3> &,
                        const Kinematics &,
                        const CellPartition &,
                        const std::vector<FacingSides> &,
                        const CellPartition &);
} // namespace thinlayer
