#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <thinlayer/analysis/rigid_body_modes.h>
#include <thinlayer/base/text_format.h>
#include <thinlayer/parallel/mpi.h>

#include <algorithm>
#include <array>
#include <cmath>

#include <petscmat.h>

namespace thinlayer
{
  namespace
  {
    using Motions = std::array<Vector<double>, 3>;

    /// The centre of the bounding box of @p points, and half its diagonal
    /// (at least 1e-300).
    void
    bounding_box_centre(const std::vector<Point<2>> &points,
                        Point<2>                    &centre,
                        double                      &size)
    {
      Point<2> low = points[0], high = points[0];
      for (const auto &p : points)
        for (unsigned int d = 0; d < 2; ++d)
          {
            low[d]  = std::min(low[d], p[d]);
            high[d] = std::max(high[d], p[d]);
          }
      centre = (low + high) / 2;
      size   = std::max((high - low).norm() / 2, 1e-300);
    }

    /**
     * The check itself, given the three motions and what the stiffness
     * makes of them: @p image = K r and @p scale = |K| |r| on the
     * unconstrained rows.
     */
    std::string
    free_motion(const Point<2>                  &centre,
                const double                     size,
                const AffineConstraints<double> &constraints,
                Motions                         &image,
                const Motions                   &scale);


    /// The two translations and the rotation about the centre of the
    /// bounding box of @p support_points, scaled by its size, their
    /// supported values 0; @p image and @p scale sized for them, zero.
    Motions
    rigid_motions(const std::vector<Point<2>>     &support_points,
                  const std::vector<unsigned int> &dof_component,
                  const AffineConstraints<double> &constraints,
                  Point<2>                        &centre,
                  double                          &size,
                  Motions                         &image,
                  Motions                         &scale)
    {
      const unsigned int n = support_points.size();
      bounding_box_centre(support_points, centre, size);
      const std::vector<Vector<double>> motions =
        rigid_body_motions(support_points, dof_component, 2);
      Motions motion;
      for (unsigned int k = 0; k < 3; ++k)
        {
          motion[k] = motions[k];
          image[k].reinit(n);
          scale[k].reinit(n);
          for (unsigned int i = 0; i < n; ++i)
            // Held by a support: a line without entries.
            if (constraints.is_constrained(i))
              {
                const auto *entries = constraints.get_constraint_entries(i);
                if (entries == nullptr || entries->empty())
                  motion[k][i] = 0;
              }
        }
      return motion;
    }


    std::string
    free_motion(const Point<2>                  &centre,
                const double                     size,
                const AffineConstraints<double> &constraints,
                Motions                         &image,
                const Motions                   &scale)
    {
      const unsigned int n = image[0].size();

      // K R over the unconstrained rows, each column scaled by the largest
      // |K| |r| of a row, reduced by modified Gram-Schmidt to a 3x3 R with
      // the same singular values (squaring into a Gram matrix would lose the
      // small ones to rounding).
      std::array<double, 3> norm;
      for (unsigned int k = 0; k < 3; ++k)
        {
          norm[k] = std::max(scale[k].linfty_norm(), 1e-300);
          for (unsigned int i = 0; i < n; ++i)
            image[k][i] =
              constraints.is_constrained(i) ? 0. : image[k][i] / norm[k];
        }
      LAPACKFullMatrix<double> r(3, 3);
      for (unsigned int k = 0; k < 3; ++k)
        {
          for (unsigned int l = 0; l < k; ++l)
            {
              r(l, k) = image[l] * image[k];
              image[k].add(-r(l, k), image[l]);
            }
          r(k, k) = image[k].l2_norm();
          if (r(k, k) > 0)
            image[k] /= r(k, k);
        }
      r.compute_svd();
      if (!(r.singular_value(2) < 1e-9))
        return "";

      // The free motion, in the motions' own units.
      const LAPACKFullMatrix<double> &vt = r.get_svd_vt();
      std::array<double, 3>           c;
      for (unsigned int k = 0; k < 3; ++k)
        c[k] = vt(2, k) / norm[k];
      // A coordinate, rounding noise below 1e-9 of the body's size shown as 0.
      const auto coordinate = [size](const double x) {
        return text_format::printf("%.6g", std::abs(x) < 1e-9 * size ? 0. : x);
      };
      if (std::abs(c[2]) > 1e-6 * std::max(std::abs(c[0]), std::abs(c[1])))
        return "a rotation about (" +
               coordinate(centre[0] - c[1] * size / c[2]) + ", " +
               coordinate(centre[1] + c[0] * size / c[2]) + ")";
      using text_format::printf;
      const double length = std::hypot(c[0], c[1]);
      return "a translation in the direction (" +
             printf("%.3g", c[0] / length) + ", " +
             printf("%.3g", c[1] / length) + ")";
    }
  } // namespace


  std::vector<Vector<double>>
  rigid_body_motions(const std::vector<Point<2>>     &support_points,
                     const std::vector<unsigned int> &dof_component,
                     const unsigned int               n_components)
  {
    const unsigned int          n = support_points.size();
    std::vector<Vector<double>> motions;
    if (n_components != 2)
      {
        for (unsigned int k = 0; k < n_components; ++k)
          {
            motions.emplace_back(n);
            for (unsigned int i = 0; i < n; ++i)
              motions[k][i] = dof_component[i] == k ? 1. : 0.;
          }
        return motions;
      }
    // The rotation about the centre of the bounding box, scaled by its
    // size, so that the three motions have displacements of one size.
    Point<2> centre;
    double   size;
    bounding_box_centre(support_points, centre, size);
    for (unsigned int k = 0; k < 3; ++k)
      {
        motions.emplace_back(n);
        for (unsigned int i = 0; i < n; ++i)
          {
            const Tensor<1, 2> x = (support_points[i] - centre) / size;
            const unsigned int c = dof_component[i];
            motions[k][i] =
              k < 2 ? (c == k ? 1. : 0.) : (c == 0 ? -x[1] : x[0]);
          }
      }
    return motions;
  }


  std::string
  free_rigid_body_motion(const std::vector<Point<2>>     &support_points,
                         const std::vector<unsigned int> &dof_component,
                         const AffineConstraints<double> &constraints,
                         const SparseMatrix<double>      &condensed_stiffness)
  {
    Point<2>      centre;
    double        size;
    Motions       image, scale;
    const Motions motion = rigid_motions(
      support_points, dof_component, constraints, centre, size, image, scale);
    const unsigned int n = support_points.size();
    for (unsigned int k = 0; k < 3; ++k)
      condensed_stiffness.vmult(image[k], motion[k]);
    // |K| |r|, row by row: what rounding is measured against.
    for (unsigned int i = 0; i < n; ++i)
      if (!constraints.is_constrained(i))
        for (auto e = condensed_stiffness.begin(i);
             e != condensed_stiffness.end(i);
             ++e)
          for (unsigned int k = 0; k < 3; ++k)
            scale[k][i] += std::abs(e->value() * motion[k][e->column()]);
    return free_motion(centre, size, constraints, image, scale);
  }


  std::string
  free_rigid_body_motion(
    const std::vector<Point<2>>            &support_points,
    const std::vector<unsigned int>        &dof_component,
    const AffineConstraints<double>        &constraints,
    const PETScWrappers::MPI::SparseMatrix &condensed_stiffness)
  {
    Point<2>      centre;
    double        size;
    Motions       image, scale;
    const Motions motion = rigid_motions(
      support_points, dof_component, constraints, centre, size, image, scale);
    // Each rank its rows, then the sums: every rank has both whole.
    const auto [first, last] = condensed_stiffness.local_range();
    for (auto i = first; i < last; ++i)
      {
        PetscInt           n_entries;
        const PetscInt    *columns;
        const PetscScalar *values;
        MatGetRow(condensed_stiffness, i, &n_entries, &columns, &values);
        for (PetscInt e = 0; e < n_entries; ++e)
          for (unsigned int k = 0; k < 3; ++k)
            {
              const double product = values[e] * motion[k][columns[e]];
              image[k][i] += product;
              if (!constraints.is_constrained(i))
                scale[k][i] += std::abs(product);
            }
        MatRestoreRow(condensed_stiffness, i, &n_entries, &columns, &values);
      }
    for (unsigned int k = 0; k < 3; ++k)
      {
        mpi::sum(image[k]);
        mpi::sum(scale[k]);
      }
    return free_motion(centre, size, constraints, image, scale);
  }
} // namespace thinlayer
