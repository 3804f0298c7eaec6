#include <deal.II/base/partitioner.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <thinlayer/analysis/rigid_body_modes.h>
#include <thinlayer/base/text_format.h>
#include <thinlayer/parallel/mpi.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include <petscmat.h>

namespace thinlayer
{
  namespace
  {
    using Motions = std::vector<Vector<double>>;

    /// The number of rigid motions of a body on a mesh of dimension
    /// @p dimension: two translations and a rotation, or three of each.
    unsigned int
    n_rigid_motions(const unsigned int dimension)
    {
      return dimension == 3 ? 6 : 3;
    }


    /// The centre of the bounding box of every rank's @p points, and half
    /// its diagonal (at least 1e-300).
    void
    bounding_box_centre(const std::vector<Point<3>> &points,
                        Point<3>                    &centre,
                        double                      &size)
    {
      const double infinity = std::numeric_limits<double>::infinity();
      Point<3>     low(infinity, infinity, infinity), high(-low);
      for (const auto &p : points)
        for (unsigned int d = 0; d < 3; ++d)
          {
            low[d]  = std::min(low[d], p[d]);
            high[d] = std::max(high[d], p[d]);
          }
      for (unsigned int d = 0; d < 3; ++d)
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
                  const Point<3>       &centre,
                  const double          size)
    {
      // Rigid motions where the components are Cartesian: translations,
      // then rotations (about z in the plane; about x, y, z in space).
      const bool cartesian =
        n_components == places.dimension && n_components >= 2;
      const unsigned int n_motions =
        cartesian ? n_rigid_motions(places.dimension) : n_components;
      const unsigned int          n = places.points.size();
      std::vector<Vector<double>> motions;
      for (unsigned int k = 0; k < n_motions; ++k)
        {
          motions.emplace_back(n);
          for (unsigned int i = 0; i < n; ++i)
            {
              const unsigned int c = places.components[i];
              if (!cartesian || k < n_components)
                motions[k][i] = c == k ? 1. : 0.;
              else
                {
                  const Tensor<1, 3> x = (places.points[i] - centre) / size;
                  Tensor<1, 3>       axis;
                  axis[n_components == 2 ? 2 : k - n_components] = 1;
                  motions[k][i] = cross_product_3d(axis, x)[c];
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
    FreeMotion
    free_motion(const Point<3>    &centre,
                const double       size,
                const unsigned int dimension,
                Motions           &image,
                const Motions     &scale)
    {
      // K R, each column scaled by the largest |K| |r| of a row, reduced
      // by modified Gram-Schmidt to a square R with the same singular
      // values (squaring into a Gram matrix would lose the small ones to
      // rounding).
      // deal.II's vector operations refuse empty vectors: a rank may own
      // no rows.
      const unsigned int  n_motions = image.size();
      const bool          rows      = image[0].size() > 0;
      std::vector<double> norm(n_motions);
      for (unsigned int k = 0; k < n_motions; ++k)
        {
          norm[k] =
            std::max(mpi::max(rows ? scale[k].linfty_norm() : 0.), 1e-300);
          if (rows)
            image[k] /= norm[k];
        }
      LAPACKFullMatrix<double> r(n_motions, n_motions);
      for (unsigned int k = 0; k < n_motions; ++k)
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
      const double resistance = r.singular_value(n_motions - 1);
      if (!(resistance < 1e-9))
        return {"", resistance};

      // The free motion, in the motions' own units: a translation t and a
      // rotation w (about z in the plane), u(x) = t + w x (x - centre) /
      // size.
      const LAPACKFullMatrix<double> &vt = r.get_svd_vt();
      Tensor<1, 3>                    t, w;
      for (unsigned int k = 0; k < n_motions; ++k)
        {
          const double c = vt(n_motions - 1, k) / norm[k];
          if (k < dimension)
            t[k] = c;
          else
            w[dimension == 2 ? 2 : k - dimension] = c;
        }
      // A coordinate, rounding noise below 1e-9 of the body's size shown as 0.
      const auto coordinate = [size](const double x) {
        return text_format::printf("%.6g", std::abs(x) < 1e-9 * size ? 0. : x);
      };
      using text_format::printf;
      // A unit vector, rounding noise below 1e-9 shown as 0.
      const auto direction = [&](const Tensor<1, 3> &v) {
        std::string text;
        for (unsigned int d = 0; d < dimension; ++d)
          {
            const double x = v[d] / v.norm();
            text += (d == 0 ? "(" : ", ") +
                    printf("%.3g", std::abs(x) < 1e-9 ? 0. : x);
          }
        return text + ")";
      };
      if (w.norm() > 1e-6 * t.norm())
        {
          // The axis: the points that only move along w.
          const Point<3> through =
            centre + size * cross_product_3d(w, t) / w.norm_square();
          std::string point;
          for (unsigned int d = 0; d < dimension; ++d)
            point += (d == 0 ? "(" : ", ") + coordinate(through[d]);
          point += ")";
          return {dimension == 2 ? "a rotation about " + point
                                 : "a rotation about the axis " + direction(w) +
                                     " through " + point,
                  resistance};
        }
      return {"a translation in the direction " + direction(t), resistance};
    }


    /**
     * free_rigid_body_motion() on the rows that @p for_each_entry(i, f)
     * walks (calling f(column, value) for each entry of row i), whose
     * columns are @p columns.
     */
    template <typename EntryWalk>
    FreeMotion
    check_rows(const OwnedDofPlaces            &places,
               const AffineConstraints<double> &constraints,
               const IndexSet                  &columns,
               const EntryWalk                 &for_each_entry)
    {
      const IndexSet &owned = places.owned;
      const auto      n     = owned.n_elements();
      Point<3>        centre;
      double          size;
      bounding_box_centre(places.points, centre, size);
      const std::vector<Vector<double>> motions =
        motions_about(places, places.dimension, centre, size);
      const unsigned int n_motions = motions.size();

      // The motions with the supports held, the columns' imported from
      // their owners.
      IndexSet ghosts = columns;
      ghosts.subtract_set(owned);
      std::vector<LinearAlgebra::distributed::Vector<double>> motion(n_motions);
      const auto                                              partitioner =
        std::make_shared<Utilities::MPI::Partitioner>(owned,
                                                      ghosts,
                                                      mpi::n_ranks() > 1
                                                        ? mpi::communicator()
                                                        : MPI_COMM_SELF);
      for (unsigned int k = 0; k < n_motions; ++k)
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

      Motions image(n_motions), scale(n_motions);
      for (unsigned int k = 0; k < n_motions; ++k)
        {
          image[k].reinit(n);
          scale[k].reinit(n);
        }
      for (unsigned int r = 0; r < n; ++r)
        {
          const auto i           = owned.nth_index_in_set(r);
          const bool constrained = constraints.is_constrained(i);
          for_each_entry(i, [&](const types::global_dof_index j, double value) {
            for (unsigned int k = 0; k < n_motions; ++k)
              {
                const double product = value * motion[k](j);
                image[k][r] += product;
                // |K| |r|, row by row: what rounding is measured against.
                if (!constrained)
                  scale[k][r] += std::abs(product);
              }
          });
          if (constrained)
            for (unsigned int k = 0; k < n_motions; ++k)
              image[k][r] = 0;
        }
      return free_motion(centre, size, places.dimension, image, scale);
    }
  } // namespace


  std::vector<Vector<double>>
  rigid_body_motions(const OwnedDofPlaces &places,
                     const unsigned int    n_components)
  {
    // The rotations about the centre of the bounding box, scaled by its
    // size, so that all motions have displacements of one size.
    Point<3> centre;
    double   size = 1;
    if (n_components == places.dimension)
      bounding_box_centre(places.points, centre, size);
    return motions_about(places, n_components, centre, size);
  }


  FreeMotion
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


  FreeMotion
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
