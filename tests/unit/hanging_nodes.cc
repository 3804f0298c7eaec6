// Truth checked: on a locally refined mesh, make_element_constraints() gives
// a conforming space that is the serendipity space on every cell.
// - Conformity: a function of the constrained space (random nodal values,
//   the constraints distributed) takes the same values from both sides of
//   every face between a refined cell and its coarser neighbour, to
//   round-off, at points spread over the face; the unconstrained values
//   jump there (so the check can fail).
// - Serendipity: the constrained interpolant of x^2 y (in the 8/20-node
//   space) is exact on the refined mesh; that of x^2 y^2 (in Q9/Q27 only)
//   is not.
// In 2D one cell of a 3x2 grid is refined; in 3D one cell of a 2x2x2 box,
// so that hanging faces (with a hanging face centre) and hanging edges
// both occur.
#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <thinlayer/discretisation/serendipity_constraints.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <random>

using namespace dealii;

// The finite-element function @p u on @p cell at the real point @p p.
template <int dim>
double
value_at(const MappingQ<dim>                                  &mapping,
         const typename DoFHandler<dim>::active_cell_iterator &cell,
         const Vector<double>                                 &u,
         const Point<dim>                                     &p)
{
  const Point<dim> unit = mapping.transform_real_to_unit_cell(cell, p);
  std::vector<types::global_dof_index> dofs(cell->get_fe().n_dofs_per_cell());
  cell->get_dof_indices(dofs);
  double value = 0;
  for (unsigned int i = 0; i < dofs.size(); ++i)
    value += u[dofs[i]] * cell->get_fe().shape_value(i, unit);
  return value;
}

// The largest jump of @p u across the faces between refined cells and
// their coarser neighbours.
template <int dim>
double
largest_jump(const MappingQ<dim>   &mapping,
             const DoFHandler<dim> &dof_handler,
             const Vector<double>  &u,
             unsigned int          &n_faces)
{
  const QGauss<dim - 1> points(4);
  double                jump = 0;
  n_faces                    = 0;
  for (const auto &cell : dof_handler.active_cell_iterators())
    for (const unsigned int f : cell->face_indices())
      if (!cell->at_boundary(f) && cell->neighbor_is_coarser(f))
        {
          ++n_faces;
          const auto coarse = cell->neighbor(f);
          for (const auto &q : points.get_points())
            {
              // The point on the fine face, from its corners (the cells
              // are affine).
              const auto face = cell->face(f);
              Point<dim> p    = face->vertex(0);
              p += q[0] * (face->vertex(1) - face->vertex(0));
              if constexpr (dim == 3)
                p += q[1] * (face->vertex(2) - face->vertex(0));
              jump = std::max(jump,
                              std::abs(value_at(mapping, cell, u, p) -
                                       value_at(mapping, coarse, u, p)));
            }
        }
  return jump;
}

template <int dim>
double
interpolation_error(const MappingQ<dim>             &mapping,
                    const DoFHandler<dim>           &dof_handler,
                    const AffineConstraints<double> &constraints,
                    const Function<dim>             &f)
{
  Vector<double> u(dof_handler.n_dofs());
  VectorTools::interpolate(mapping, dof_handler, f, u);
  constraints.distribute(u);
  Vector<double> cell_errors(dof_handler.get_triangulation().n_active_cells());
  const QGauss<dim> quadrature(5);
  VectorTools::integrate_difference(
    mapping, dof_handler, u, f, cell_errors, quadrature, VectorTools::L2_norm);
  return VectorTools::compute_global_error(dof_handler.get_triangulation(),
                                           cell_errors,
                                           VectorTools::L2_norm);
}

template <int dim>
void
check(Triangulation<dim> &tria)
{
  tria.begin_active()->set_refine_flag();
  tria.execute_coarsening_and_refinement();

  const FE_Q<dim>     fe(2);
  DoFHandler<dim>     dof_handler(tria);
  const MappingQ<dim> mapping(1);
  dof_handler.distribute_dofs(fe);
  AffineConstraints<double> constraints;
  thinlayer::make_element_constraints(dof_handler, true, constraints);
  constraints.close();

  std::mt19937                           random(7);
  std::uniform_real_distribution<double> uniform(-1, 1);
  Vector<double>                         u(dof_handler.n_dofs());
  for (auto &value : u)
    value = uniform(random);
  unsigned int n_faces  = 0;
  const double raw_jump = largest_jump(mapping, dof_handler, u, n_faces);
  constraints.distribute(u);
  const double jump = largest_jump(mapping, dof_handler, u, n_faces);
  std::printf("%dD: %u faces on a coarser neighbour; random nodal values "
              "jump there %s unconstrained, %s constrained\n",
              dim,
              n_faces,
              raw_jump > 1e-3 ? "yes" : "NO",
              jump < 1e-12 ? "not (round-off)" : "YES");

  const ScalarFunctionFromFunctionObject<dim> serendipity(
    [](const Point<dim> &p) {
      return p[0] * p[0] * p[1] + 0.5 * p[dim - 1] - 0.3 * p[0] * p[1];
    });
  const ScalarFunctionFromFunctionObject<dim> biquadratic(
    [](const Point<dim> &p) { return p[0] * p[0] * p[1] * p[1]; });
  std::printf(
    "%dD: x^2 y interpolated %s; x^2 y^2 %s\n",
    dim,
    interpolation_error(mapping, dof_handler, constraints, serendipity) < 1e-12
      ? "exactly"
      : "NOT exactly",
    interpolation_error(mapping, dof_handler, constraints, biquadratic) > 1e-6
      ? "with an error (outside the space)"
      : "EXACTLY (the constraints are missing)");
}

int
main()
{
  Triangulation<2> plane;
  GridGenerator::subdivided_hyper_rectangle(plane,
                                            {3, 2},
                                            Point<2>(0.2, -0.3),
                                            Point<2>(1.4, 0.9));
  check(plane);
  Triangulation<3> box;
  GridGenerator::subdivided_hyper_rectangle(box,
                                            {2, 2, 2},
                                            Point<3>(0.1, -0.2, 0.3),
                                            Point<3>(1.3, 0.8, 1.1));
  check(box);
}
