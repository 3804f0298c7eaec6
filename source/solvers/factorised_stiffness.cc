#include <thinlayer/base/work_counts.h>
#include <thinlayer/solvers/factorised_stiffness.h>
#include <thinlayer/solvers/linear_solver_failure.h>
#include <thinlayer/solvers/singular_matrix.h>

#include <mutex>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <dlfcn.h>
#include <suitesparse/cholmod.h>
#include <suitesparse/umfpack.h>

namespace thinlayer
{
  namespace
  {
    /**
     * Debian's CHOLMOD (SuiteSparse 5) runs the copy loops of its
     * supernodal factorisation as OpenMP regions with a thread count fixed
     * when it was compiled (4), which neither OMP_NUM_THREADS nor any
     * CHOLMOD setting lowers. On a machine with fewer cores, or under
     * mpirun with a rank per core, those threads contend for the cores at
     * every supernode, and a factorisation spends much of its time in the
     * kernel's scheduler (benchmarks/linear_solvers.py shows the cost of
     * a factorisation). The work itself is BLAS's (serial here) and
     * thinlayer's; so OpenMP regions are made inactive (one thread each)
     * for the whole process, by the runtime's maximum of active levels,
     * which bounds the thread count of every region whatever its clause.
     * The runtime is found in the process (CHOLMOD loaded it) rather than
     * linked, so that no OpenMP flag changes how thinlayer is compiled;
     * without one there is nothing to do.
     */
    void
    make_openmp_serial()
    {
      static std::once_flag once;
      std::call_once(once, [] {
        using SetLevels = void (*)(int);
        if (const auto set_levels = reinterpret_cast<SetLevels>(
              dlsym(RTLD_DEFAULT, "omp_set_max_active_levels")))
          set_levels(0);
      });
    }
  } // namespace


  struct FactorisedStiffness::Cholmod
  {
    Cholmod()
    {
      make_openmp_serial();
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
    /// Its size: a pattern at the address of a freed one (a new run in the
    /// same process) is another pattern.
    std::size_t analysed_entries = 0;
    std::size_t analysed_rows    = 0;
    // Reused by every solve, so that it allocates nothing.
    cholmod_dense *x = nullptr, *y = nullptr, *e = nullptr;
  };


  struct FactorisedStiffness::Umfpack
  {
    Umfpack()
    {
      umfpack_dl_defaults(control);
    }

    ~Umfpack()
    {
      clear();
    }

    void
    clear()
    {
      if (symbolic)
        umfpack_dl_free_symbolic(&symbolic);
      if (numeric)
        umfpack_dl_free_numeric(&numeric);
    }

    double control[UMFPACK_CONTROL];
    double info[UMFPACK_INFO];
    void  *symbolic = nullptr;
    void  *numeric  = nullptr;
    /// The matrix's rows as UMFPACK's compressed columns (so that UMFPACK
    /// factorises its transpose), each sorted by column.
    std::vector<SuiteSparse_long> start, column;
    std::vector<double>           value;
    // Reused by every solve, so that it allocates nothing.
    std::vector<double> solution;
  };


  namespace
  {
    /// The SingularMatrix for a factor whose pivots show it singular up to
    /// round-off.
    SingularMatrix
    singular(const std::string &solver,
             const double       pivot_ratio,
             const double       minimum_pivot_ratio)
    {
      std::ostringstream text;
      text << solver
           << " found the stiffness matrix singular: its smallest pivot is "
           << pivot_ratio << " of its largest, below " << minimum_pivot_ratio;
      return SingularMatrix(text.str());
    }
  } // namespace


  FactorisedStiffness::FactorisedStiffness(const Method method,
                                           const double minimum_pivot_ratio)
    : method(method)
    , minimum_pivot_ratio(minimum_pivot_ratio)
    , cholmod(method == Method::cholmod ? std::make_unique<Cholmod>() : nullptr)
    , umfpack(method == Method::umfpack ? std::make_unique<Umfpack>() : nullptr)
  {}


  FactorisedStiffness::~FactorisedStiffness() = default;


  void
  FactorisedStiffness::factorize(const SparseMatrix<double> &matrix)
  {
    ++work_counts().factorisations;
    const WorkTimer timer(work_counts().factorisation_seconds);
    last_cost = FactorCost();
    if (method == Method::umfpack)
      {
        factorize_umfpack(matrix);
        return;
      }

    const SparsityPattern *pattern = &matrix.get_sparsity_pattern();
    if (cholmod->analysed_pattern != pattern ||
        cholmod->analysed_entries != pattern->n_nonzero_elements() ||
        cholmod->analysed_rows != pattern->n_rows())
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
        cholmod->analysed_entries = pattern->n_nonzero_elements();
        cholmod->analysed_rows    = pattern->n_rows();
      }
    const bool ok = cholmod->factor != nullptr &&
                    cholmod_l_factorize(A, cholmod->factor, &c) &&
                    c.status == CHOLMOD_OK;
    const int status = c.status;
    cholmod_l_free_sparse(&A, &c);
    // The symbolic analysis's counts: fl for L L^T, and a multiply-add per
    // entry of L in each of the two triangular solves.
    last_cost = ok ? FactorCost{c.fl, 4 * c.lnz} : FactorCost();
    // (min L_jj / max L_jj)^2 of L L^T: the pivot ratio of L D L^T, a pass
    // over the factor's diagonal that a tangent (no minimum) is spared.
    const double pivot_ratio =
      ok && minimum_pivot_ratio > 0 ? cholmod_l_rcond(cholmod->factor, &c) : 1;
    if (pivot_ratio < minimum_pivot_ratio)
      {
        cholmod->clear();
        throw singular("CHOLMOD", pivot_ratio, minimum_pivot_ratio);
      }
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
  FactorisedStiffness::factorize_umfpack(const SparseMatrix<double> &matrix)
  {
    Umfpack               &u = *umfpack;
    const SuiteSparse_long n = matrix.m();
    u.clear();

    // deal.II stores each row's diagonal first: UMFPACK wants the columns
    // in order.
    u.start.resize(n + 1);
    u.column.resize(matrix.n_nonzero_elements());
    u.value.resize(matrix.n_nonzero_elements());
    SuiteSparse_long k = 0;
    for (SuiteSparse_long i = 0; i < n; ++i)
      {
        u.start[i] = k;
        for (auto entry = matrix.begin(i); entry != matrix.end(i); ++entry)
          {
            SuiteSparse_long j = k++;
            for (; j > u.start[i] &&
                   u.column[j - 1] > SuiteSparse_long(entry->column());
                 --j)
              {
                u.column[j] = u.column[j - 1];
                u.value[j]  = u.value[j - 1];
              }
            u.column[j] = entry->column();
            u.value[j]  = entry->value();
          }
      }
    u.start[n] = k;

    // The symbolic analysis afresh for every matrix, as deal.II's wrapper
    // did: UMFPACK chooses its strategy from the values as well.
    int status = umfpack_dl_symbolic(n,
                                     n,
                                     u.start.data(),
                                     u.column.data(),
                                     u.value.data(),
                                     &u.symbolic,
                                     u.control,
                                     u.info);
    if (status == UMFPACK_OK)
      status = umfpack_dl_numeric(u.start.data(),
                                  u.column.data(),
                                  u.value.data(),
                                  u.symbolic,
                                  &u.numeric,
                                  u.control,
                                  u.info);
    if (status == UMFPACK_WARNING_singular_matrix)
      {
        u.clear();
        throw SingularMatrix("UMFPACK found the stiffness matrix singular: "
                             "a pivot is zero");
      }
    if (status != UMFPACK_OK)
      {
        u.clear();
        throw LinearSolverFailure(
          "UMFPACK could not factorise the stiffness matrix (its status " +
          std::to_string(status) +
          (status == UMFPACK_ERROR_out_of_memory ? ": out of memory)" : ")"));
      }
    last_cost = {u.info[UMFPACK_FLOPS],
                 2 * (u.info[UMFPACK_LNZ] + u.info[UMFPACK_UNZ])};
    // min |U_ii| / max |U_ii|.
    const double pivot_ratio = u.info[UMFPACK_RCOND];
    if (pivot_ratio < minimum_pivot_ratio)
      {
        u.clear();
        throw singular("UMFPACK", pivot_ratio, minimum_pivot_ratio);
      }
  }


  FactorCost
  FactorisedStiffness::cost() const
  {
    return last_cost;
  }


  void
  FactorisedStiffness::solve(const ArrayView<double> &rhs)
  {
    ++work_counts().substitutions;
    if (method == Method::umfpack)
      {
        Umfpack &u = *umfpack;
        u.solution.resize(rhs.size());
        // UMFPACK holds the transpose's factors (its columns are the
        // matrix's rows): A x = b is its transposed solve.
        const int status = umfpack_dl_solve(UMFPACK_At,
                                            u.start.data(),
                                            u.column.data(),
                                            u.value.data(),
                                            u.solution.data(),
                                            rhs.data(),
                                            u.numeric,
                                            u.control,
                                            u.info);
        if (status != UMFPACK_OK)
          throw LinearSolverFailure("UMFPACK could not solve with its factor "
                                    "(its status " +
                                    std::to_string(status) + ")");
        std::copy(u.solution.begin(), u.solution.end(), rhs.begin());
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
