#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/vector_tools.h>

#include <thinlayer/base/input_error.h>
#include <thinlayer/discretisation/boundary_data.h>

#include <cmath>
#include <sstream>

namespace thinlayer
{
  namespace
  {
    /**
     * Points of the trapezoidal rule over the circle: exact for the
     * trigonometric polynomials of the harmonics in use (degree < 64).
     */
    constexpr unsigned int n_circle_points = 64;

    /**
     * A vector-valued FunctionParser from ';'-separated expressions; a
     * single expression stands for every component.
     */
    std::unique_ptr<FunctionParser<3>>
    make_function(const std::string                   &expressions,
                  const unsigned int                   n_components,
                  const std::string                   &variables,
                  const std::map<std::string, double> &geometry_parameters)
    {
      auto parts = Utilities::split_string_list(expressions, ';');
      if (parts.size() == 1 && n_components > 1)
        parts.assign(n_components, parts[0]);
      auto constants  = geometry_parameters;
      constants["pi"] = numbers::PI;
      auto f          = std::make_unique<FunctionParser<3>>(n_components);
      f->initialize(variables, parts, constants);
      return f;
    }

    bool
    is_zero(const std::string &expressions)
    {
      for (const auto &e : Utilities::split_string_list(expressions, ';'))
        if (e != "0")
          return false;
      return true;
    }

    /**
     * The amplitudes of a mode of the prescribed displacement, as a
     * function on the mesh (for interpolate_boundary_values).
     */
    template <int dim>
    class ModeAmplitude : public Function<dim>
    {
    public:
      /// As many components as the element has (2 in plane strain, 3 for
      /// Fourier and 3D): deal.II writes that many values per point.
      ModeAmplitude(const unsigned int n_components,
                    const std::function<Tensor<1, 3>(const Point<dim> &)> &f)
        : Function<dim>(n_components)
        , f(f)
      {}

      double
      value(const Point<dim> &x, const unsigned int c) const override
      {
        return f(x)[c];
      }

    private:
      std::function<Tensor<1, 3>(const Point<dim> &)> f;
    };


    /// The point the parsed functions take: (x, y, z) of a 3D mesh, and
    /// (x, y) or (r, z) of a 2D mesh with the angle @p theta third.
    template <int dim>
    Point<3>
    parser_point(const Point<dim> &x, const double theta)
    {
      return dim == 3 ? Point<3>(x[0], x[1], x[dim - 1])
                      : Point<3>(x[0], x[1], theta);
    }
  } // namespace


  BoundaryData::BoundaryData(
    const std::map<types::boundary_id, BoundaryParameters> &boundaries,
    const std::map<std::string, double>                    &constants,
    const Kinematics                                       &kinematics,
    const std::string                                      &parameter_file)
    : kinematics(kinematics)
    , parameter_file(parameter_file)
  {
    const unsigned int n         = kinematics.n_components();
    const std::string  variables = kinematics.is_fourier() ? "r,z,theta"
                                   : kinematics.mesh_dimension() == 3
                                     ? "x,y,z"
                                     : "x,y,unused_z";
    for (const auto &[id, b] : boundaries)
      {
        Condition        &c = conditions[id];
        std::vector<bool> mask(b.constrained_components);
        mask.resize(n, false);
        c.constrained  = ComponentMask(mask);
        c.displacement = make_function(b.displacement, n, variables, constants);
        c.traction     = make_function(b.traction, n, variables, constants);
        c.pressure     = make_function(b.pressure, 1, variables, constants);
        c.loaded       = !(is_zero(b.traction) && is_zero(b.pressure));
        c.section      = BoundaryParameters::section(id);
      }
  }


  template <int dim>
  void
  BoundaryData::check_finite(const Vector<double> &v,
                             const Point<dim>     &x,
                             const double          theta,
                             const std::string    &entry) const
  {
    for (const double value : v)
      if (!std::isfinite(value))
        {
          std::ostringstream where;
          where.precision(6);
          if (kinematics.is_fourier())
            where << "r = " << x[0] << ", z = " << x[1]
                  << ", theta = " << theta;
          else
            where << "x = " << x[0] << ", y = " << x[1]
                  << (dim == 3 ? ", z = " + std::to_string(x[dim - 1]) : "");
          throw InputError(parameter_file,
                           entry,
                           std::string("gives ") +
                             (std::isnan(value) ? "nan"
                              : value > 0       ? "inf"
                                                : "-inf") +
                             " at " + where.str() +
                             " on the boundary; expected finite numbers");
        }
  }


  template <int dim>
  double
  BoundaryData::pressure(const Condition  &c,
                         const Point<dim> &x,
                         const double      theta) const
  {
    Vector<double> v(1);
    v[0] = c.pressure->value(parser_point(x, theta));
    check_finite(v, x, theta, c.section + "/Pressure");
    return v[0];
  }


  template <int dim>
  Tensor<1, 3>
  BoundaryData::evaluate(const FunctionParser<3> &f,
                         const Point<dim>        &x,
                         const double             theta,
                         const std::string       &entry) const
  {
    Vector<double> v(f.n_components);
    f.vector_value(parser_point(x, theta), v);
    check_finite(v, x, theta, entry);
    Tensor<1, 3> result;
    if (!kinematics.is_fourier())
      {
        for (unsigned int c = 0; c < v.size(); ++c)
          result[c] = v[c];
        return result;
      }
    // Cartesian (x, y, z) to cylindrical (r, z, theta).
    const double cos_t = std::cos(theta), sin_t = std::sin(theta);
    result[0] = v[0] * cos_t + v[1] * sin_t;
    result[1] = v[2];
    result[2] = -v[0] * sin_t + v[1] * cos_t;
    return result;
  }


  template <int dim>
  void
  BoundaryData::make_zero_constraints(
    const DoFHandler<dim>     &dof_handler,
    AffineConstraints<double> &constraints) const
  {
    const unsigned int n = kinematics.n_components();
    for (const auto &[id, c] : conditions)
      if (c.constrained.n_selected_components(n) > 0)
        VectorTools::interpolate_boundary_values(dof_handler,
                                                 id,
                                                 Functions::ZeroFunction<dim>(
                                                   n),
                                                 constraints,
                                                 c.constrained);
  }


  template <int dim>
  std::map<types::global_dof_index, double>
  BoundaryData::prescribed_values(const Mapping<dim>    &mapping,
                                  const DoFHandler<dim> &dof_handler,
                                  const unsigned int     m) const
  {
    const unsigned int n = kinematics.n_components();
    // Later ids overwrite earlier ones at shared nodes: going from the
    // highest id down makes the lowest id win, the documented rule.
    std::map<types::global_dof_index, double>             values;
    std::map<types::global_dof_index, types::boundary_id> set_by;
    for (auto c = conditions.rbegin(); c != conditions.rend(); ++c)
      {
        if (c->second.constrained.n_selected_components(n) == 0)
          continue;
        std::map<types::global_dof_index, double> own;
        const FunctionParser<3>                  &u = *c->second.displacement;
        const std::string        entry = c->second.section + "/Displacement";
        const ModeAmplitude<dim> amplitude(
          kinematics.n_components(), [&](const Point<dim> &x) {
            if (!kinematics.is_fourier())
              return evaluate(u, x, 0, entry);
            Tensor<1, 3> a;
            const double d = 2 * numbers::PI / n_circle_points;
            for (unsigned int j = 0; j < n_circle_points; ++j)
              {
                const double       theta = j * d;
                const Tensor<1, 3> g     = evaluate(u, x, theta, entry);
                a[0] += g[0] * kinematics.T1_at(m, theta) * d;
                a[1] += g[1] * kinematics.T1_at(m, theta) * d;
                a[2] += g[2] * kinematics.T2_at(m, theta) * d;
              }
            const double c1 = kinematics.c1(m), c2 = kinematics.c2(m);
            a[0] = (c1 > 0) ? a[0] / c1 : 0.;
            a[1] = (c1 > 0) ? a[1] / c1 : 0.;
            a[2] = (c2 > 0) ? a[2] / c2 : 0.;
            return a;
          });
        VectorTools::interpolate_boundary_values(mapping,
                                                 dof_handler,
                                                 c->first,
                                                 amplitude,
                                                 own,
                                                 c->second.constrained);
        for (const auto &[dof, value] : own)
          {
            const auto earlier = values.find(dof);
            if (earlier != values.end() &&
                std::abs(earlier->second - value) >
                  1e-12 * std::max(std::abs(earlier->second), std::abs(value)))
              note_conflict(mapping, dof_handler, dof, c->first, set_by[dof]);
            values[dof] = value;
            set_by[dof] = c->first;
          }
      }
    return values;
  }


  template <int dim>
  void
  BoundaryData::assemble_load_vector(const Mapping<dim>    &mapping,
                                     const DoFHandler<dim> &dof_handler,
                                     const unsigned int     m,
                                     ModeVector            &load) const
  {
    load                                    = 0;
    const FiniteElement<dim>            &fe = dof_handler.get_fe();
    const QGauss<dim - 1>                quadrature(fe.degree + 2);
    FEFaceValues<dim>                    fe_face(mapping,
                              fe,
                              quadrature,
                              update_values | update_normal_vectors |
                                update_quadrature_points | update_JxW_values);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    Vector<double>                       cell_load(fe.n_dofs_per_cell());

    // Angles and trigonometric weights of the circle integral (a single
    // angle, weight 1, in plane strain).
    std::vector<double> thetas = {0}, weights = {1};
    if (kinematics.is_fourier())
      {
        thetas.resize(n_circle_points);
        weights.assign(n_circle_points, 2 * numbers::PI / n_circle_points);
        for (unsigned int j = 0; j < n_circle_points; ++j)
          thetas[j] = j * 2 * numbers::PI / n_circle_points;
      }

    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const auto f : cell->face_indices())
        {
          if (!cell->is_locally_owned() || !cell->face(f)->at_boundary())
            continue;
          const auto c = conditions.find(cell->face(f)->boundary_id());
          if (c == conditions.end() || !c->second.loaded)
            continue;
          fe_face.reinit(cell, f);
          cell_load = 0;
          for (const unsigned int q : fe_face.quadrature_point_indices())
            {
              const Point<dim> &x  = fe_face.quadrature_point(q);
              const double      dA = kinematics.area_factor(x) * fe_face.JxW(q);
              // The mode's share of the traction, component by component.
              Tensor<1, 3> t;
              for (unsigned int j = 0; j < thetas.size(); ++j)
                {
                  Tensor<1, 3> g = evaluate(*c->second.traction,
                                            x,
                                            thetas[j],
                                            c->second.section + "/Traction");
                  const double p = pressure(c->second, x, thetas[j]);
                  for (unsigned int d = 0; d < dim; ++d)
                    g[d] -= p * fe_face.normal_vector(q)[d];
                  for (unsigned int k = 0; k < 3; ++k)
                    t[k] +=
                      g[k] * kinematics.T_at(k, m, thetas[j]) * weights[j];
                }
              for (const unsigned int i : fe_face.dof_indices())
                {
                  const unsigned int k = fe.system_to_component_index(i).first;
                  cell_load[i] += t[k] * fe_face.shape_value(i, q) * dA;
                }
            }
          cell->get_dof_indices(dofs);
          for (const unsigned int i : fe_face.dof_indices())
            load(dofs[i]) += cell_load[i];
        }
    load.compress(VectorOperation::add);
  }


  template <int dim>
  void
  BoundaryData::note_conflict(const Mapping<dim>           &mapping,
                              const DoFHandler<dim>        &dof_handler,
                              const types::global_dof_index dof,
                              const types::boundary_id      winner,
                              const types::boundary_id      loser) const
  {
    // One warning per pair of ids, naming the first node where they
    // disagree.
    const std::string ids = "Boundary " + std::to_string(winner) +
                            " and Boundary " + std::to_string(loser);
    for (const auto &w : warnings)
      if (w.find(ids) != std::string::npos)
        return;
    // The points of the DoFs this rank holds (all, on one rank).
    std::map<types::global_dof_index, Point<dim>> points;
    DoFTools::map_dofs_to_support_points(mapping, dof_handler, points);
    std::ostringstream where;
    for (unsigned int d = 0; d < dim; ++d)
      where << (d > 0 ? ", " : "") << points[dof][d];
    warnings.push_back("warning: " + ids +
                       " prescribe different displacements at the node (" +
                       where.str() + "); the lower id's value is used");
  }


  const std::vector<std::string> &
  BoundaryData::get_warnings() const
  {
    return warnings;
  }


  bool
  BoundaryData::has_constraints() const
  {
    for (const auto &[id, c] : conditions)
      if (c.constrained.n_selected_components(kinematics.n_components()) > 0)
        return true;
    return false;
  }

  // The members for the mesh's dimension.
#define THINLAYER_INSTANTIATE(dim)                                          \
  template void BoundaryData::make_zero_constraints(                        \
    const DoFHandler<dim> &, AffineConstraints<double> &) const;            \
  template std::map<types::global_dof_index, double>                        \
                BoundaryData::prescribed_values(const Mapping<dim> &,       \
                                  const DoFHandler<dim> &,    \
                                  const unsigned int) const;  \
  template void BoundaryData::assemble_load_vector(const Mapping<dim> &,    \
                                                   const DoFHandler<dim> &, \
                                                   const unsigned int,      \
                                                   ModeVector &) const;
  THINLAYER_INSTANTIATE(2)
  THINLAYER_INSTANTIATE(3)
#undef THINLAYER_INSTANTIATE
} // namespace thinlayer
