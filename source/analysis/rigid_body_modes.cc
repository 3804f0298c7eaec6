#include <deal.II/base/partitioner.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <thinlayer/analysis/rigid_body_modes.h>
#include <thinlayer/base/text_format.h>
#include <thinlayer/parallel/mpi.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>

#include <petscmat.h>

namespace thinlayer
{
  namespace
  {
    using Motions = std::array<Vector<double>, 3>;

    /// The centre of the bounding box of every rank's @p points, and half
    /// its diagonal (at least 1e-300).
    void
    bounding_box_centre(const std::vector<Point<2>> &points,
                        Point<2>                    &centre,
                        double                      &size)
    {
      const double infinity = std::numeric_limits<double>::infinity();
      Point<2>     low(infinity, infinity), high(-infinity, -infinity);
      for (const auto &p : points)
        for (unsigned int d = 0; d < 2; ++d)
          {
            low[d]  = std::min(low[d], p[d]);
            high[d] = std::max(high[d], p[d]);
          }
      for (unsigned int d = 0; d < 2; ++d)
        {
          low[d]  = -mpi::max(-low[d]);
          high[d] = mpi::max(high[d]);
        }
      centre = (low + high) / 2;
      size   = std::max((high - low).norm() / 2, 1e-300);
    }


    /// The motions about @p centre, scaled by @p size (see
    /// rigid_body_motions()).
    std::vector<Vector<double>>
    motions_about(const OwnedDofPlaces &places,
                  const unsigned int    n_components,
                  const Point<2>       &centre,
                  const double          size)
    {
      const unsigned int          n = places.points.size();
      std::vector<Vector<double>> motions;
      for (unsigned int k = 0; k < (n_components == 2 ? 3 : n_components); ++k)
        {
          motions.emplace_back(n);
          for (unsigned int i = 0; i < n; ++i)
            {
              const unsigned int c = places.components[i];
              if (n_components != 2 || k < 2)
                motions[k][i] = c == k ? 1. : 0.;
              else
                {
                  const Tensor<1, 2> x = (places.points[i] - centre) / size;
                  motions[k][i]        = c == 0 ? -x[1] : x[0];
                }
            }
        }
      return motions;
    }


    /**
     * The check itself, given the three motions and what the stiffness
     * makes of them: @p image = K r and @p scale = |K| |r| on this rank's
     * rows, zero on the constrained ones.
     */
    std::string
    free_motion(const Point<2> &centre,
                const double    size,
                Motions        &image,
                const Motions  &scale)
    {
      // K R, each column scaled by the largest |K| |r| of a row, reduced
      // by modified Gram-Schmidt to a 3x3 R with the same singular values
      // (squaring into a Gram matrix would lose the small ones to
      // rounding).
      // deal.II's vector operations refuse empty vectors: a rank may own
      // no rows.
      const bool            rows = image[0].size() > 0;
      std::array<double, 3> norm;
      for (unsigned int k = 0; k < 3; ++k)
        {
          norm[k] =
            std::max(mpi::max(rows ? scale[k].linfty_norm() : 0.), 1e-300);
          if (rows)
            image[k] /= norm[k];
        }
      LAPACKFullMatrix<double> r(3, 3);
      for (unsigned int k = 0; k < 3; ++k)
        {
          for (unsigned int l = 0; l < k; ++l)
            {
              r(l, k) = mpi::sum(rows ? image[l] * image[k] : 0.);
              if (rows)
                image[k].add(-r(l, k), image[l]);
            }
          r(k, k) = std::sqrt(mpi::sum(rows ? image[k].norm_sqr() : 0.));
          if (r(k, k) > 0 && rows)
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


    /**
     * free_rigid_body_motion() on the rows that @p for_each_entry(i, f)
     * walks (calling f(column, value) for each entry of row i), whose
     * columns are @p columns.
     */
    template <typename EntryWalk>
    std::string
    check_rows(const OwnedDofPlaces            &places,
               const AffineConstraints<double> &constraints,
               const IndexSet                  &columns,
               const EntryWalk                 &for_each_entry)
    {
      const IndexSet &owned = places.owned;
      const auto      n     = owned.n_elements();
      Point<2>        centre;
      double          size;
      bounding_box_centre(places.points, centre, size);
      const std::vector<Vector<double>> motions =
        motions_about(places, 2, centre, size);

      // The motions with the supports held, the columns' imported from
      // their owners.
      IndexSet ghosts = columns;
      ghosts.subtract_set(owned);
      std::array<LinearAlgebra::distributed::Vector<double>, 3> motion;
      const auto                                                partitioner =
        std::make_shared<Utilities::MPI::Partitioner>(owned,
                                                      ghosts,
                                                      mpi::n_ranks() > 1
                                                        ? mpi::communicator()
                                                        : MPI_COMM_SELF);
      for (unsigned int k = 0; k < 3; ++k)
        {
          motion[k].reinit(partitioner);
          for (unsigned int r = 0; r < n; ++r)
            {
              const auto  i       = owned.nth_index_in_set(r);
              const auto *entries = constraints.get_constraint_entries(i);
              const bool  held    = constraints.is_constrained(i) &&
                                (entries == nullptr || entries->empty());
              motion[k].local_element(r) = held ? 0. : motions[k][r];
            }
          if (mpi::n_ranks() > 1)
            motion[k].update_ghost_values();
        }

      Motions image, scale;
      for (unsigned int k = 0; k < 3; ++k)
        {
          image[k].reinit(n);
          scale[k].reinit(n);
        }
      for (unsigned int r = 0; r < n; ++r)
        {
          const auto i           = owned.nth_index_in_set(r);
          const bool constrained = constraints.is_constrained(i);
          for_each_entry(i, [&](const types::global_dof_index j, double value) {
            for (unsigned int k = 0; k < 3; ++k)
              {
                const double product = value * motion[k](j);
                image[k][r] += product;
                // |K| |r|, row by row: what rounding is measured against.
                if (!constrained)
                  scale[k][r] += std::abs(product);
              }
          });
          if (constrained)
            for (unsigned int k = 0; k < 3; ++k)
              image[k][r] = 0;
        }
      return free_motion(centre, size, image, scale);
    }
  } // namespace


  std::vector<Vector<double>>
  rigid_body_motions(const OwnedDofPlaces &places,
                     const unsigned int    n_components)
  {
    // The rotation about the centre of the bounding box, scaled by its
    // size, so that the three motions have displacements of one size.
    Point<2> centre;
    double   size = 1;
    if (n_components == 2)
      bounding_box_centre(places.points, centre, size);
    return motions_about(places, n_components, centre, size);
  }


  std::string
  free_rigid_body_motion(const OwnedDofPlaces            &places,
                         const AffineConstraints<double> &constraints,
                         const SparseMatrix<double>      &condensed_stiffness)
  {
    return check_rows(places,
                      constraints,
                      complete_index_set(condensed_stiffness.n()),
                      [&](const types::global_dof_index i, const auto &f) {
                        for (auto e = condensed_stiffness.begin(i);
                             e != condensed_stiffness.end(i);
                             ++e)
                          f(e->column(), e->value());
                      });
  }


  std::string
  free_rigid_body_motion(
    const OwnedDofPlaces                   &places,
    const AffineConstraints<double>        &constraints,
    const PETScWrappers::MPI::SparseMatrix &condensed_stiffness)
  {
    const auto walk = [&](const types::global_dof_index i, const auto &f) {
      PetscInt           n_entries;
      const PetscInt    *columns;
      const PetscScalar *values;
      MatGetRow(condensed_stiffness, i, &n_entries, &columns, &values);
      for (PetscInt e = 0; e < n_entries; ++e)
        f(columns[e], values[e]);
      MatRestoreRow(condensed_stiffness, i, &n_entries, &columns, &values);
    };
    // The columns this rank's rows name.
    IndexSet                             columns(condensed_stiffness.n());
    std::vector<types::global_dof_index> named;
    for (const auto i : places.owned)
      walk(i, [&](const types::global_dof_index j, double) {
        named.push_back(j);
      });
    std::sort(named.begin(), named.end());
    named.erase(std::unique(named.begin(), named.end()), named.end());
    columns.add_indices(named.begin(), named.end());
    return check_rows(places, constraints, columns, walk);
  }
} // namespace thinlayer
