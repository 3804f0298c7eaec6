#include <deal.II/dofs/dof_tools.h>

#include <thinlayer/discretisation/mode_constraints.h>

#include <array>
#include <map>

namespace thinlayer
{
  template <int dim>
  void
  make_mode_constraints(const DoFHandler<dim>           &dof_handler,
                        const Kinematics                &kinematics,
                        const unsigned int               m,
                        const int                        axis,
                        const AffineConstraints<double> &element_constraints,
                        const BoundaryData              &boundary_data,
                        AffineConstraints<double>       &structural,
                        AffineConstraints<double>       &constraints)
  {
    const auto &fe = dof_handler.get_fe();
    // The lines of the DoFs this rank holds, as the element constraints'.
    structural.reinit(element_constraints.get_local_lines());
    structural.merge(element_constraints);

    // Components that play no part in this mode (u_theta for n = 0).
    std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        {
          cell->get_dof_indices(cell_dofs);
          for (unsigned int i = 0; i < cell_dofs.size(); ++i)
            if (kinematics.is_dead_component(
                  m, fe.system_to_component_index(i).first) &&
                !structural.is_constrained(cell_dofs[i]))
              structural.add_line(cell_dofs[i]);
        }

    // On the axis r = 0 the field must be single-valued: harmonic 0 has no
    // radial (symmetric) or circumferential (antisymmetric) movement there,
    // harmonic 1 moves sideways rigidly (u_z = 0, u_theta = -+ u_r) and
    // higher harmonics not at all.
    if (kinematics.is_fourier() && axis >= 0)
      {
        const unsigned int n    = kinematics.harmonic(m);
        const double       sign = kinematics.is_antisymmetric() ? 1. : -1.;
        std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
        const auto zero = [&](const types::global_dof_index dof) {
          if (!structural.is_constrained(dof))
            structural.add_line(dof);
        };
        for (const auto &cell : dof_handler.active_cell_iterators())
          for (const auto f : cell->face_indices())
            if (!cell->is_artificial() && cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() ==
                  static_cast<types::boundary_id>(axis))
              {
                cell->face(f)->get_dof_indices(face_dofs);
                // node[b][c]: the DoF of component c at the face's node b.
                std::map<unsigned int, std::array<types::global_dof_index, 3>>
                  node;
                for (unsigned int k = 0; k < face_dofs.size(); ++k)
                  {
                    const auto c_b = fe.face_system_to_component_index(k);
                    node[c_b.second][c_b.first] = face_dofs[k];
                  }
                for (const auto &[b, d] : node)
                  {
                    const auto r = d[0], z = d[1], theta = d[2];
                    if (n == 0)
                      zero(kinematics.is_antisymmetric() ? theta : r);
                    else if (n == 1)
                      {
                        zero(z);
                        if (!structural.is_constrained(theta))
                          {
                            structural.add_line(theta);
                            structural.add_entry(theta, r, sign);
                          }
                      }
                    else
                      {
                        zero(r);
                        zero(z);
                        zero(theta);
                      }
                  }
              }
      }
    structural.close();

    constraints.reinit(element_constraints.get_local_lines());
    constraints.merge(structural);
    boundary_data.make_zero_constraints(dof_handler, constraints);
    constraints.close();
  }


  template void
  make_mode_constraints(const DoFHandler<2> &,
                        const Kinematics &,
                        const unsigned int,
                        const int,
                        const AffineConstraints<double> &,
                        const BoundaryData &,
                        AffineConstraints<double> &,
                        AffineConstraints<double> &);
  template void
  make_mode_constraints(const DoFHandler<3> &,
                        const Kinematics &,
                        const unsigned int,
                        const int,
                        const AffineConstraints<double> &,
                        const BoundaryData &,
                        AffineConstraints<double> &,
                        AffineConstraints<double> &);
} // namespace thinlayer
