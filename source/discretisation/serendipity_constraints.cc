#include <deal.II/base/geometry_info.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe.h>

#include <thinlayer/discretisation/serendipity_constraints.h>

#include <array>

namespace thinlayer
{
  namespace
  {
    /**
     * Local DoF layout of one component of a Q2 cell: the index within the
     * base element of the DoF on each vertex, line, quad and hex.
     */
    template <int dim>
    struct Q2Layout
    {
      static constexpr unsigned int n_vertices =
        GeometryInfo<dim>::vertices_per_cell;
      static constexpr unsigned int n_lines = GeometryInfo<dim>::lines_per_cell;

      static unsigned int
      vertex(const unsigned int v)
      {
        return v;
      }

      static unsigned int
      line(const unsigned int l)
      {
        return n_vertices + l;
      }

      /// The quad (face in 3D, the cell itself in 2D) with index @p q.
      static unsigned int
      quad(const unsigned int q)
      {
        return n_vertices + n_lines + q;
      }

      /// The hex (3D cell interior).
      static unsigned int
      hex()
      {
        return n_vertices + n_lines + GeometryInfo<3>::faces_per_cell;
      }
    };

    template <int dim>
    void
    check_element(const FiniteElement<dim> &fe)
    {
      for (unsigned int b = 0; b < fe.n_base_elements(); ++b)
        AssertThrow(fe.base_element(b).n_components() == 1 &&
                      fe.base_element(b).degree == 2 &&
                      fe.base_element(b).n_dofs_per_cell() ==
                        Utilities::pow(3, dim),
                    ExcMessage("Serendipity constraints need FE_Q(2) base "
                               "elements, got " +
                               fe.get_name()));
    }
  } // namespace


  template <int dim>
  void
  make_serendipity_constraints(const DoFHandler<dim>     &dof_handler,
                               AffineConstraints<double> &constraints)
  {
    using Layout                 = Q2Layout<dim>;
    const FiniteElement<dim> &fe = dof_handler.get_fe();
    check_element(fe);

    const unsigned int n_components = fe.n_components();
    const unsigned int n_base_dofs  = Utilities::pow(3, dim);

    // local_of[component][base index] = local DoF index in the system.
    std::vector<std::vector<unsigned int>> local_of(
      n_components, std::vector<unsigned int>(n_base_dofs));
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      {
        const auto c_and_b = fe.system_to_component_index(i);
        local_of[c_and_b.first][c_and_b.second] = i;
      }

    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());

    const auto constrain =
      [&](
        const types::global_dof_index                                  centre,
        const std::vector<std::pair<types::global_dof_index, double>> &terms) {
        if (constraints.is_constrained(centre))
          return;
        constraints.add_line(centre);
        constraints.add_entries(centre, terms);
      };

    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (cell->is_artificial())
          continue;
        cell->get_dof_indices(dofs);
        for (unsigned int c = 0; c < n_components; ++c)
          {
            const auto &local = local_of[c];
            // Each quad (the cell in 2D, each face in 3D): centre from its
            // four corners and four mid-sides.
            const unsigned int n_quads =
              (dim == 2) ? 1 : GeometryInfo<dim>::faces_per_cell;
            for (unsigned int q = 0; q < n_quads; ++q)
              {
                std::vector<std::pair<types::global_dof_index, double>> terms;
                for (unsigned int k = 0; k < 4; ++k)
                  {
                    const unsigned int v =
                      (dim == 2) ? k
                                 : GeometryInfo<3>::face_to_cell_vertices(q, k);
                    const unsigned int l =
                      (dim == 2) ? k
                                 : GeometryInfo<3>::face_to_cell_lines(q, k);
                    terms.emplace_back(dofs[local[Layout::vertex(v)]], -0.25);
                    terms.emplace_back(dofs[local[Layout::line(l)]], 0.5);
                  }
                constrain(dofs[local[Layout::quad(q)]], terms);
              }
            if (dim == 3)
              {
                // The 20-node shape functions at the centre: -1/4 at each
                // corner, +1/4 at each mid-edge.
                std::vector<std::pair<types::global_dof_index, double>> terms;
                for (unsigned int v = 0; v < Layout::n_vertices; ++v)
                  terms.emplace_back(dofs[local[Layout::vertex(v)]], -0.25);
                for (unsigned int l = 0; l < Layout::n_lines; ++l)
                  terms.emplace_back(dofs[local[Layout::line(l)]], 0.25);
                constrain(dofs[local[Layout::hex()]], terms);
              }
          }
      }
  }


  template <int dim>
  void
  make_element_constraints(const DoFHandler<dim>     &dof_handler,
                           const bool                 serendipity,
                           AffineConstraints<double> &constraints)
  {
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    if (serendipity)
      make_serendipity_constraints(dof_handler, constraints);
  }


  template void
  make_serendipity_constraints(const DoFHandler<2> &,
                               AffineConstraints<double> &);
  template void
  make_serendipity_constraints(const DoFHandler<3> &,
                               AffineConstraints<double> &);
  template void
  make_element_constraints(const DoFHandler<2> &,
                           const bool,
                           AffineConstraints<double> &);
  template void
  make_element_constraints(const DoFHandler<3> &,
                           const bool,
                           AffineConstraints<double> &);
} // namespace thinlayer
