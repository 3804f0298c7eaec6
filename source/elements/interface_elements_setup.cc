// The setting up of zero-thickness interface elements: pairing the
// sides, their strength and initial tractions, and the check of their
// stiffness against the cells beside them. The element loops are in
// interface_elements.cc.
#include <deal.II/base/quadrature_lib.h>

#include <thinlayer/base/input_error.h>
#include <thinlayer/elements/interface_elements.h>
#include <thinlayer/parallel/distributed_mesh.h>
#include <thinlayer/parameters/parameters.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

namespace thinlayer
{


  template <int dim>
  void
  InterfaceElements<dim>::reinit(
    const std::vector<FacingSides<dim>>                            &pairs,
    const DoFHandler<dim>                                          &dof_handler,
    const Mapping<dim>                                             &mapping,
    const Kinematics                                               &kinematics,
    const std::map<types::boundary_id, InterfaceElementParameters> &curves,
    const std::map<types::material_id, MaterialParameters>         &materials,
    const CellPartition                                            &partition,
    const std::string &parameter_file)
  {
    this->kinematics = &kinematics;
    this->curves     = &curves;
    laws.clear();
    elements.clear();
    points.clear();
    recoveries.clear();
    for (const auto &[id, parameters] : curves)
      laws[id] = std::make_unique<InterfaceLaw>(parameters);
    rank = partition.rank;
    for (const FacingSides<dim> &pair : pairs)
      {
        check_stiffness(pair, curves.at(pair.curve), materials, parameter_file);
        // Another rank's element: its points' places along the curve, for
        // the profiles, but no cells (this rank may not hold them).
        const bool own =
          partition.owner.empty() ||
          partition.owner[pair.plus_cell->active_cell_index()] == rank;
        add_element(pair, curves.at(pair.curve), own, dof_handler, mapping);
      }

    coupled_matrices.clear();
    for (Element &element : elements)
      {
        element.coupled_dofs.clear();
        for (unsigned int m = 0; m < kinematics.n_modes(); ++m)
          for (const auto dof : element.dofs)
            element.coupled_dofs.push_back(m * dof_handler.n_dofs() + dof);
        coupled_matrices.emplace_back(element.coupled_dofs.size(),
                                      element.coupled_dofs.size());
      }

    element_owner.clear();
    point_owner.clear();
    if (!partition.owner.empty())
      {
        for (const Element &element : elements)
          element_owner.push_back(partition.owner[element.plus_cell]);
        for (const IntegrationPoint &point : points)
          point_owner.push_back(element_owner[point.element]);
      }

    states.assign(points.size() * kinematics.n_stations(),
                  InterfacePointState());
    tangents.assign(states.size(), Tensor<2, 3>());
    for (unsigned int p = 0; p < points.size(); ++p)
      for (unsigned int s = 0; s < kinematics.n_stations(); ++s)
        tangents[p * kinematics.n_stations() + s] =
          elements[points[p].element].law->elasticity();
  }


  template <int dim>
  void
  InterfaceElements<dim>::reduce_strength(
    const StrengthReductionParameters &reduced,
    const double                       factor)
  {
    for (const types::boundary_id id : reduced.interfaces)
      {
        InterfaceElementParameters curve = curves->at(id);
        const auto r   = StrengthReductionParameters::reduce(curve.adhesion,
                                                           curve.friction_angle,
                                                           curve.dilation_angle,
                                                           factor);
        curve.adhesion = r.cohesion;
        curve.friction_angle = r.friction_angle;
        curve.dilation_angle = r.dilation_angle;
        laws[id]             = std::make_unique<InterfaceLaw>(curve);
      }
    for (Element &element : elements)
      element.law = laws.at(element.curve).get();
  }


  template <int dim>
  typename InterfaceElements<dim>::InitialTractions
  InterfaceElements<dim>::set_initial_tractions(
    const std::function<SymmetricTensor<2, 3>(const dealii::Point<dim> &,
                                              types::material_id)> &initial)
  {
    InitialTractions found;
    for (unsigned int p = 0; p < points.size(); ++p)
      {
        if (!owns_point(p))
          continue;
        const IntegrationPoint &point   = points[p];
        const Element          &element = elements[point.element];
        // sigma n in the local frame (s, n, t), from either side's stress.
        std::array<Tensor<1, 3>, 2> sides;
        for (unsigned int side = 0; side < 2; ++side)
          sides[side] =
            point.frame *
            (initial(point.position, element.materials[side]) * point.frame[1]);
        const double larger = std::max(sides[0].norm(), sides[1].norm());
        const double mismatch =
          larger > 0 ? (sides[0] - sides[1]).norm() / larger : 0.;
        // Along a straight interface in a linear at-rest state the ratios
        // tie; a margin keeps the first point of the tie, whatever the
        // round-off of the points' places.
        if (mismatch > found.mismatch * (1 + 1e-9))
          {
            found.mismatch           = mismatch;
            found.mismatch_at        = point.position;
            found.mismatch_curve     = point.curve;
            found.mismatch_materials = element.materials;
          }
        const Tensor<1, 3> traction = 0.5 * (sides[0] + sides[1]);
        if (element.law->can_yield())
          {
            // Against the traction's size: the law's own yield ratio is
            // scaled by its stiffness where there is no adhesion.
            const double size = traction.norm();
            const double ratio =
              element.law->yield_function(traction) / (size > 0 ? size : 1.);
            if (ratio > found.yield_ratio * (1 + 1e-9))
              {
                found.yield_ratio = ratio;
                found.yield_at    = point.position;
                found.yield_curve = point.curve;
              }
          }
        for (unsigned int s = 0; s < kinematics->n_stations(); ++s)
          {
            InterfacePointState &state =
              states[p * kinematics->n_stations() + s];
            state                    = InterfacePointState();
            state.traction           = traction;
            state.converged_traction = traction;
          }
      }
    return found;
  }


  template <int dim>
  void
  InterfaceElements<dim>::check_stiffness(
    const FacingSides<dim>                                 &pair,
    const InterfaceElementParameters                       &curve,
    const std::map<types::material_id, MaterialParameters> &materials,
    const std::string                                      &parameter_file)
  {
    const auto   face = pair.plus_cell->face(pair.plus_face);
    const double h =
      dim == 2 ? pair.entry.distance(pair.exit) : std::sqrt(face->measure());
    const double E =
      std::min(materials.at(pair.plus_cell->material_id()).youngs_modulus,
               materials.at(pair.minus_cell->material_id()).youngs_modulus);
    const double limit = max_stiffness_ratio * E / h;
    for (const auto &[entry, stiffness] :
         {std::pair<const char *, double>{"Normal stiffness",
                                          curve.normal_stiffness},
          {"Shear stiffness", curve.shear_stiffness}})
      if (stiffness > limit)
        {
          std::ostringstream message;
          message << "expected at most " << max_stiffness_ratio
                  << " E / h = " << limit << " for the element at ("
                  << face->center() << ") (E = " << E
                  << " of the cells beside it, side h = " << h << "), got "
                  << stiffness
                  << ": a stiffer interface adds no accuracy, and round-off "
                     "takes its tractions";
          throw InputError(parameter_file,
                           InterfaceElementParameters::section(pair.curve) +
                             "/" + entry,
                           message.str());
        }
  }


  template <int dim>
  void
  InterfaceElements<dim>::add_element(const FacingSides<dim>           &pair,
                                      const InterfaceElementParameters &curve,
                                      const bool                        own,
                                      const DoFHandler<dim> &dof_handler,
                                      const Mapping<dim>    &mapping)
  {
    const FiniteElement<dim>            &fe = dof_handler.get_fe();
    std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
    Element                              element{laws.at(pair.curve).get(),
                    pair.curve,
                    pair.plus_cell->active_cell_index(),
                    {{pair.plus_cell->material_id(),
                                                   pair.minus_cell->material_id()}},
                    {},
                    {}};
    std::map<types::global_dof_index, unsigned int> local;
    const std::vector<InterfacePointPlace<dim>>     places =
      interface_point_places(pair, curve, mapping, *kinematics);
    add_to_recovery(pair, places);
    for (const InterfacePointPlace<dim> &place : places)
      {
        IntegrationPoint point;
        point.element    = elements.size();
        point.curve      = pair.curve;
        point.run        = pair.run;
        point.position   = place.position;
        point.arc_length = place.arc_length;
        point.frame      = place.frame;
        point.weight     = place.weight;
        point.patch      = place.patch;
        // The jump: shape values on the plus side less those on the minus
        // side, at the point's place in each cell (the pair's cells as
        // @p dof_handler holds them).
        for (const auto &[serial_cell, sign] :
             {std::pair<typename DoFHandler<dim>::active_cell_iterator, double>{
                pair.plus_cell, 1.},
              {pair.minus_cell, -1.}})
          if (own)
            {
              const auto cell = cell_of(dof_handler, serial_cell->id());
              const dealii::Point<dim> unit =
                (sign > 0 && std::isfinite(place.unit_plus[0]))
                  ? place.unit_plus
                  : mapping.transform_real_to_unit_cell(cell, point.position);
              cell->get_dof_indices(cell_dofs);
              for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                {
                  const double value = fe.shape_value(i, unit);
                  if (std::abs(value) < 1e-12)
                    continue;
                  const auto [it, inserted] =
                    local.emplace(cell_dofs[i], element.dofs.size());
                  if (inserted)
                    element.dofs.push_back(cell_dofs[i]);
                  point.entries.push_back(
                    {it->second,
                     fe.system_to_component_index(i).first,
                     sign * value});
                }
            }
        points.push_back(point);
      }
    elements.push_back(element);
  }


  template <int dim>
  void
  InterfaceElements<dim>::add_to_recovery(
    const FacingSides<dim>                      &pair,
    const std::vector<InterfacePointPlace<dim>> &places)
  {
    // The profile of the pair's curve lists its points in the order they
    // are added: the element's samples follow those already there.
    const unsigned int        first = recoveries[pair.curve].n_samples();
    std::vector<unsigned int> samples;
    std::vector<std::array<double, 2>> rule_places;
    std::vector<double>                weights;
    for (const InterfacePointPlace<dim> &place : places)
      {
        samples.push_back(first + samples.size());
        rule_places.push_back(place.rule_place);
        weights.push_back(place.weight);
      }
    const auto cell = pair.plus_cell;
    const auto face = cell->face(pair.plus_face);
    std::function<std::vector<unsigned int>(double, double)> key;
    if constexpr (dim == 2)
      {
        // A side's nodes from its entry: the entry's vertex, both, the
        // exit's.
        const bool entry_first = face->vertex(0).distance(pair.entry) <=
                                 face->vertex(1).distance(pair.entry);
        const unsigned int entry = face->vertex_index(entry_first ? 0 : 1);
        const unsigned int exit  = face->vertex_index(entry_first ? 1 : 0);
        key                      = [entry, exit](const double x, double) {
          if (x == 0)
            return std::vector<unsigned int>{entry};
          if (x == 1)
            return std::vector<unsigned int>{exit};
          return std::vector<unsigned int>{std::min(entry, exit),
                                           std::max(entry, exit)};
        };
      }
    else
      {
        // The face's nodes in the plus cell's unit coordinates, as
        // interface_point_places() lays its rule out.
        const unsigned int d           = pair.plus_face / 2;
        const double       across      = pair.plus_face % 2;
        const unsigned int first_axis  = d == 0 ? 1 : 0;
        const unsigned int second_axis = d == 2 ? 1 : 2;
        key                            = [=](const double a, const double b) {
          Point<dim> unit;
          unit[first_axis]  = a;
          unit[second_axis] = b;
          unit[d]           = across;
          return TractionRecovery::node_key(cell, unit);
        };
      }
    recoveries[pair.curve].add_element(
      samples, rule_places, weights, dim == 3, key);
  }


  // The class is instantiated in interface_elements.cc; these are the
  // members defined here, for each dimension.
#define THINLAYER_INSTANTIATE_SETUP(d)                                    \
  template void InterfaceElements<d>::reinit(                             \
    const std::vector<FacingSides<d>> &,                                  \
    const DoFHandler<d> &,                                                \
    const Mapping<d> &,                                                   \
    const Kinematics &,                                                   \
    const std::map<types::boundary_id, InterfaceElementParameters> &,     \
    const std::map<types::material_id, MaterialParameters> &,             \
    const CellPartition &,                                                \
    const std::string &);                                                 \
  template void InterfaceElements<d>::reduce_strength(                    \
    const StrengthReductionParameters &, const double);                   \
  template InterfaceElements<d>::InitialTractions                         \
  InterfaceElements<d>::set_initial_tractions(                            \
    const std::function<SymmetricTensor<2, 3>(const dealii::Point<d> &,   \
                                              types::material_id)> &);    \
  template void InterfaceElements<d>::check_stiffness(                    \
    const FacingSides<d> &,                                               \
    const InterfaceElementParameters &,                                   \
    const std::map<types::material_id, MaterialParameters> &,             \
    const std::string &);                                                 \
  template void InterfaceElements<d>::add_to_recovery(                    \
    const FacingSides<d> &, const std::vector<InterfacePointPlace<d>> &); \
  template void InterfaceElements<d>::add_element(                        \
    const FacingSides<d> &,                                               \
    const InterfaceElementParameters &,                                   \
    const bool,                                                           \
    const DoFHandler<d> &,                                                \
    const Mapping<d> &);

  THINLAYER_INSTANTIATE_SETUP(2)
  THINLAYER_INSTANTIATE_SETUP(3)
#undef THINLAYER_INSTANTIATE_SETUP
} // namespace thinlayer
