#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/filtered_iterator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <thinlayer/base/input_error.h>
#include <thinlayer/parallel/mpi.h>
#include <thinlayer/postprocess/monitors.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace thinlayer
{
  template <int dim>
  Monitors<dim>::Monitors(const MonitorParameters &parameters,
                          const AnalysisView<dim> &analysis,
                          const std::string       &parameter_file)
    : parameters(parameters)
    , analysis(analysis)
  {
    if (parameters.displacement_measure ==
        MonitorParameters::DisplacementMeasure::point)
      {
        Point<dim> x;
        for (unsigned int d = 0; d < dim; ++d)
          x[d] = parameters.displacement_point[d];
        // The cell this rank evaluates the point in, if it owns one that
        // holds it; the lowest such rank reports it.
        try
          {
            const auto found = GridTools::find_active_cell_around_point(
              analysis.get_mapping(), analysis.get_dof_handler(), x);
            if (found.first.state() == IteratorState::valid)
              {
                if (found.first->is_locally_owned())
                  point_cell = found;
                else
                  for (const auto &other :
                       GridTools::find_all_active_cells_around_point(
                         analysis.get_mapping(),
                         analysis.get_dof_handler(),
                         x,
                         1e-10,
                         found))
                    if (other.first->is_locally_owned())
                      {
                        point_cell = other;
                        break;
                      }
              }
          }
        catch (const std::exception &)
          {
            // Not in this rank's part of the mesh.
          }
        const unsigned int holder =
          Utilities::MPI::min(point_cell.first.state() == IteratorState::valid
                                ? mpi::rank()
                                : mpi::n_ranks(),
                              mpi::communicator());
        if (holder != mpi::rank())
          point_cell.first = typename DoFHandler<dim>::active_cell_iterator();
        const bool inside = holder < mpi::n_ranks();
        if (!inside)
          {
            std::ostringstream point;
            for (unsigned int d = 0; d < dim; ++d)
              point << (d > 0 ? ", " : "") << x[d];
            throw InputError(parameter_file,
                             "Monitors/Displacement point",
                             "(" + point.str() +
                               ") lies outside the mesh; expected a point "
                               "of the body");
          }
      }
    if (parameters.load_measure != MonitorParameters::LoadMeasure::reaction)
      return;
    const auto        &dof_handler  = analysis.get_dof_handler();
    const unsigned int n_components = analysis.get_kinematics().n_components();
    const OwnedDofPlaces places     = analysis.owned_dof_places();
    reaction_dofs.resize(n_components);
    for (unsigned int c = 0; c < n_components; ++c)
      {
        std::vector<bool> mask(n_components, false);
        mask[c] = true;
        for (const auto dof : DoFTools::extract_boundary_dofs(
               dof_handler, ComponentMask(mask), {parameters.load_boundary_id}))
          if (places.owned.is_element(dof))
            reaction_dofs[c].emplace_back(
              dof, places.points[places.owned.index_within_set(dof)]);
      }
  }


  template <int dim>
  double
  Monitors<dim>::load() const
  {
    switch (parameters.load_measure)
      {
        case MonitorParameters::LoadMeasure::load_factor:
          return parameters.load_scale * analysis.load_factor();
          case MonitorParameters::LoadMeasure::stress_average: {
            const auto [integral, area] = stress_integral();
            return parameters.load_scale * integral / area;
          }
        case MonitorParameters::LoadMeasure::reaction:
          return parameters.load_scale * reaction();
      }
    return std::numeric_limits<double>::quiet_NaN();
  }


  template <int dim>
  std::pair<double, double>
  Monitors<dim>::stress_integral() const
  {
    const auto [i, j]           = parameters.load_stress_component;
    const unsigned int n_q      = analysis.n_quadrature_points();
    const auto        &B        = analysis.get_cells().get_strain_operator();
    double             integral = 0, area = 0;
    for (const auto &cell :
         analysis.get_dof_handler().get_triangulation().active_cell_iterators())
      if (cell->material_id() == parameters.load_material_id &&
          analysis.get_cells().owns(cell->active_cell_index()))
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const unsigned int c = cell->active_cell_index();
            const double       w = B.point_weight(c * n_q + q);
            integral += analysis.get_point_state(c, q).stress[i][j] * w;
            area += w;
          }
    // Each rank's cells' share.
    if (mpi::n_ranks() > 1)
      {
        Vector<double> sums(2);
        sums[0] = integral;
        sums[1] = area;
        mpi::sum(sums);
        return {sums[0], sums[1]};
      }
    return {integral, area};
  }


  template <int dim>
  double
  Monitors<dim>::boundary_sum(const ModeVector  &forces,
                              const unsigned int component,
                              const int          weight_by) const
  {
    // Each rank's own DoFs.
    double sum = 0;
    for (const auto &[dof, point] : reaction_dofs[component])
      sum += forces[dof] * (weight_by < 0 ? 1. : point[weight_by]);
    return mpi::sum(sum);
  }


  template <int dim>
  double
  Monitors<dim>::reaction() const
  {
    using Component              = MonitorParameters::LoadComponent;
    const Kinematics &kinematics = analysis.get_kinematics();
    const Component   component  = parameters.load_component;
    // The mode the resultant comes from (checked to exist when reading).
    const unsigned int harmonic =
      (component == Component::x || component == Component::moment) &&
          kinematics.is_fourier()
        ? 1
        : 0;
    unsigned int m = 0;
    while (kinematics.harmonic(m) != harmonic)
      ++m;
    ModeVector f(analysis.get_internal_forces()[m]);
    f.add(-analysis.load_factor(), analysis.get_mode_system(m).unit_load);
    f -= analysis.get_mode_system(m).held_load;
    condense(analysis.get_element_constraints(), f);

    // Components: 0 x or r, 1 y or z, 2 theta or z; coordinates likewise.
    if (!kinematics.is_fourier())
      switch (component)
        {
          case Component::x:
            return boundary_sum(f, 0);
          case Component::y:
            return boundary_sum(f, 1);
          case Component::z:
            return boundary_sum(f, 2);
          case Component::moment:
            return boundary_sum(f, 1, 0) - boundary_sum(f, 0, 1);
          case Component::torque:
            return boundary_sum(f, 0, 2) - boundary_sum(f, 2, 0);
        }
    switch (component)
      {
        case Component::x:
          return boundary_sum(f, 0) - boundary_sum(f, 2);
        case Component::y:
          return boundary_sum(f, 1);
        case Component::z:
          break; // refused when reading
        case Component::moment:
          return boundary_sum(f, 0, 1) - boundary_sum(f, 2, 1) -
                 boundary_sum(f, 1, 0);
        case Component::torque:
          return boundary_sum(f, 2, 0);
      }
    return std::numeric_limits<double>::quiet_NaN();
  }


  template <int dim>
  DisplacementMeasure
  Monitors<dim>::displacement() const
  {
    return displacement_of(analysis.displacements());
  }


  template <int dim>
  DisplacementMeasure
  Monitors<dim>::displacement_of(const ModeVectors &modes) const
  {
    const double      s          = parameters.displacement_scale;
    const double      theta      = parameters.displacement_angle;
    const Kinematics &kinematics = analysis.get_kinematics();
    const auto       &fe         = analysis.get_dof_handler().get_fe();
    const ModeVector  u          = analysis.displacement_at(theta, modes);
    // The monitored Cartesian component from the nodal components: for
    // Fourier x = u_r cos(theta) - u_theta sin(theta), y = u_z.
    // In 3D the third is u_z.
    const auto component =
      [&](const double r_or_x, const double z_or_y, const double third) {
        if (parameters.displacement_component == 1)
          return z_or_y;
        if (parameters.displacement_component == 2)
          return third;
        return kinematics.is_fourier()
                 ? r_or_x * std::cos(theta) - third * std::sin(theta)
                 : r_or_x;
      };

    if (parameters.displacement_measure ==
        MonitorParameters::DisplacementMeasure::point)
      {
        // As VectorTools::point_value() evaluates, on the rank that holds
        // the point.
        Vector<double> value(kinematics.n_components());
        if (point_cell.first.state() == IteratorState::valid)
          {
            FEValues<dim> fe_values(analysis.get_mapping(),
                                    fe,
                                    Quadrature<dim>(
                                      GeometryInfo<dim>::project_to_unit_cell(
                                        point_cell.second)),
                                    update_values);
            fe_values.reinit(point_cell.first);
            std::vector<Vector<double>> values(1, value);
            fe_values.get_function_values(u, values);
            value = values[0];
          }
        mpi::sum(value);
        const double v =
          component(value[0], value[1], value.size() > 2 ? value[2] : 0.);
        return {s * v, s * v, s * v};
      }

    const QGauss<dim - 1>       face_quadrature(3);
    FEFaceValues<dim>           fe_face(analysis.get_mapping(),
                              fe,
                              face_quadrature,
                              update_values | update_JxW_values);
    std::vector<Vector<double>> values(
      face_quadrature.size(), Vector<double>(kinematics.n_components()));
    std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
    double                               integral = 0, length = 0;
    double min        = std::numeric_limits<double>::max();
    double max        = std::numeric_limits<double>::lowest();
    bool   non_finite = false;
    for (const auto &cell : analysis.get_dof_handler().active_cell_iterators() |
                              IteratorFilters::LocallyOwnedCell())
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary() &&
            cell->face(f)->boundary_id() == parameters.displacement_boundary_id)
          {
            fe_face.reinit(cell, f);
            fe_face.get_function_values(u, values);
            for (const unsigned int q : fe_face.quadrature_point_indices())
              {
                const Vector<double> &v = values[q];
                integral += component(v[0], v[1], v.size() > 2 ? v[2] : 0.) *
                            fe_face.JxW(q);
                length += fe_face.JxW(q);
              }
            // Extremes over the face's nodes.
            cell->face(f)->get_dof_indices(face_dofs);
            std::map<unsigned int, std::array<double, 3>> node;
            for (unsigned int k = 0; k < face_dofs.size(); ++k)
              {
                const auto c_b = fe.face_system_to_component_index(k);
                node[c_b.second][c_b.first] = u[face_dofs[k]];
              }
            for (const auto &[b, v] : node)
              {
                const double value =
                  component(v[0],
                            v[1],
                            kinematics.n_components() > 2 ? v[2] : 0.);
                min        = std::min(min, value);
                max        = std::max(max, value);
                non_finite = non_finite || !std::isfinite(value);
              }
          }
    // Each rank's faces.
    if (mpi::n_ranks() > 1)
      {
        integral   = mpi::sum(integral);
        length     = mpi::sum(length);
        min        = -mpi::max(-min);
        max        = mpi::max(max);
        non_finite = mpi::sum(non_finite ? 1u : 0u) > 0;
      }
    // std::min and std::max pass a NaN by: say so, rather than report the
    // starting values as extremes.
    if (non_finite || !(min <= max))
      min = max = std::numeric_limits<double>::quiet_NaN();
    return {s * integral / length,
            std::min(s * min, s * max),
            std::max(s * min, s * max)};
  }


  template class Monitors<2>;
  template class Monitors<3>;
} // namespace thinlayer
