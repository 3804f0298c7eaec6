#include <thinlayer/solvers/factorised_stiffness.h>
#include <thinlayer/solvers/linear_solver_failure.h>
#include <thinlayer/solvers/singular_matrix.h>

#include <stdexcept>
#include <vector>

#include <suitesparse/cholmod.h>

namespace thinlayer
{
  struct FactorisedStiffness::Cholmod
  {
    Cholmod()
    {
      cholmod_l_start(&common);
      common.supernodal = CHOLMOD_SUPERNODAL;
      // A tangent that is not positive definite is reported to the caller
      // (Newton then cuts the step back), not printed.
      common.print         = 0;
      common.error_handler = nullptr;
    }

    ~Cholmod()
    {
      clear();
      cholmod_l_finish(&common);
    }

    void
    clear()
    {
      for (cholmod_dense **d : {&x, &y, &e})
        if (*d)
          cholmod_l_free_dense(d, &common);
      if (factor)
        cholmod_l_free_factor(&factor, &common);
      analysed_pattern = nullptr;
    }

    cholmod_common  common;
    cholmod_factor *factor = nullptr;
    /// The sparsity pattern the symbolic analysis in factor was made for:
    /// refactorising a matrix on the same pattern (Newton's tangent, every
    /// iteration) reuses it and only redoes the numbers.
    const SparsityPattern *analysed_pattern = nullptr;
    // Reused by every solve, so that it allocates nothing.
    cholmod_dense *x = nullptr, *y = nullptr, *e = nullptr;
  };


  FactorisedStiffness::FactorisedStiffness(const Method method)
    : method(method)
    , cholmod(method == Method::cholmod ? std::make_unique<Cholmod>() : nullptr)
  {}


  FactorisedStiffness::~FactorisedStiffness() = default;


  void
  FactorisedStiffness::factorize(const SparseMatrix<double> &matrix)
  {
    if (method == Method::umfpack)
      {
        // UMFPACK's failure on these matrices is their singularity.
        try
          {
            umfpack.factorize(matrix);
          }
        catch (const ExceptionBase &e)
          {
            throw SingularMatrix(e.what());
          }
        return;
      }

    const SparsityPattern *pattern = &matrix.get_sparsity_pattern();
    if (cholmod->analysed_pattern != pattern)
      cholmod->clear();
    cholmod_common &c = cholmod->common;
    const auto      n = matrix.m();

    // The matrix is symmetric, so its rows are its columns: the CSR arrays
    // of deal.II serve as CSC, of which CHOLMOD reads the upper triangle.
    cholmod_sparse *A            = cholmod_l_allocate_sparse(n,
                                                  n,
                                                  matrix.n_nonzero_elements(),
                                                  /*sorted=*/0,
                                                  /*packed=*/1,
                                                  /*stype=*/1,
                                                  CHOLMOD_REAL,
                                                  &c);
    auto           *column_start = static_cast<SuiteSparse_long *>(A->p);
    auto           *row          = static_cast<SuiteSparse_long *>(A->i);
    auto           *value        = static_cast<double *>(A->x);
    std::size_t     k            = 0;
    for (types::global_dof_index i = 0; i < n; ++i)
      {
        column_start[i] = k;
        for (auto entry = matrix.begin(i); entry != matrix.end(i); ++entry)
          {
            row[k]   = entry->column();
            value[k] = entry->value();
            ++k;
          }
      }
    column_start[n] = k;

    if (cholmod->factor == nullptr)
      {
        cholmod->factor           = cholmod_l_analyze(A, &c);
        cholmod->analysed_pattern = pattern;
      }
    const bool ok = cholmod->factor != nullptr &&
                    cholmod_l_factorize(A, cholmod->factor, &c) &&
                    c.status == CHOLMOD_OK;
    const int status = c.status;
    cholmod_l_free_sparse(&A, &c);
    if (!ok)
      {
        cholmod->clear(); // a failed factor is analysed afresh next time
        if (status == CHOLMOD_NOT_POSDEF)
          throw SingularMatrix("CHOLMOD could not factorise the stiffness "
                               "matrix: it is singular or not positive "
                               "definite");
        throw LinearSolverFailure(
          "CHOLMOD could not factorise the stiffness matrix (its status " +
          std::to_string(status) +
          (status == CHOLMOD_OUT_OF_MEMORY ? ": out of memory)" : ")"));
      }
  }


  void
  FactorisedStiffness::solve(const ArrayView<double> &rhs)
  {
    if (method == Method::umfpack)
      {
        // deal.II's UMFPACK takes its own vector type.
        Vector<double> v(rhs.begin(), rhs.end());
        umfpack.solve(v);
        std::copy(v.begin(), v.end(), rhs.begin());
        return;
      }

    cholmod_common &c = cholmod->common;
    cholmod_dense   b;
    b.nrow  = rhs.size();
    b.ncol  = 1;
    b.nzmax = rhs.size();
    b.d     = rhs.size();
    b.x     = rhs.data();
    b.z     = nullptr;
    b.xtype = CHOLMOD_REAL;
    b.dtype = CHOLMOD_DOUBLE;
    cholmod_l_solve2(CHOLMOD_A,
                     cholmod->factor,
                     &b,
                     nullptr,
                     &cholmod->x,
                     nullptr,
                     &cholmod->y,
                     &cholmod->e,
                     &c);
    const double *x = static_cast<const double *>(cholmod->x->x);
    std::copy(x, x + rhs.size(), rhs.begin());
  }
} // namespace thinlayer
