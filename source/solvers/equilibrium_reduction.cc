#include <deal.II/base/exceptions.h>

#include <hrcontact/core/blas_lapack.h>
#include <hrcontact/core/input.h>
#include <hrcontact/solvers/equilibrium_reduction.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <numeric>
#include <sstream>

namespace hrcontact
{
  using namespace dealii;

  void
  EquilibriumReduction::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Equilibrium reduction");
    prm.declare_entry(
      "Pivot tolerance",
      "1e-9",
      Patterns::Double(0, 1e-2),
      "A pivot of the Gaussian reduction of C^T smaller than this times the "
      "norm of its row of C counts as zero: C is then rank deficient (a "
      "mechanism) and the run stops naming the nodes the mode moves.");
    prm.leave_subsection();
  }

  void
  EquilibriumReduction::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Equilibrium reduction");
    pivot_tolerance = prm.get_double("Pivot tolerance");
    prm.leave_subsection();
  }

  namespace
  {
    /** C^T of the free rows, tau x n, column-major (column i is free row i
     * of B~), and the rows' norms; a row no cell touches is an error. */
    std::vector<double>
    free_rows_transposed(const EquilibriumSystem &sys,
                         const unsigned int       tau,
                         std::vector<double>     &row_norm)
    {
      const unsigned int n = sys.free_rows.size();
      row_norm.assign(n, 0.);
      std::vector<double> A(static_cast<std::size_t>(tau) * n, 0.);
      for (unsigned int i = 0; i < n; ++i)
        {
          const EquilibriumRow &row = sys.rows[sys.free_rows[i]];
          double *const col = A.data() + static_cast<std::size_t>(i) * tau;
          for (const auto &[dof, c] : row.combination)
            if (c != 0)
              for (auto it = sys.B.begin(sys.b_row(dof));
                   it != sys.B.end(sys.b_row(dof));
                   ++it)
                col[it->column()] += c * it->value();
          for (unsigned int j = 0; j < tau; ++j)
            row_norm[i] += col[j] * col[j];
          row_norm[i] = std::sqrt(row_norm[i]);
          if (row_norm[i] == 0)
            throw InputError(
              "Equilibrium reduction: " + sys.describe_row(sys.free_rows[i]) +
              " is touched by no cell: a node without stiffness.");
        }

      return A;
    }

    /**
     * The error for a rank-deficient C: the null vector of the first
     * vanishing pivot of U (the LU factor of C^T in A) is a displacement of
     * the free rows that no stress in the space resists; the nodes it moves
     * most are named.
     */
    InputError
    mechanism_error(const EquilibriumSystem         &sys,
                    const std::vector<double>       &A,
                    const unsigned int               tau,
                    const std::vector<unsigned int> &zero_pivots)
    {
      const unsigned int n = sys.free_rows.size();
      // Null vector y of U (hence of C^T): y_k = 1, y_{>k} = 0,
      // U[0:k,0:k] y[0:k] = -U[0:k,k]. It is the mode: a displacement of
      // the free rows that no stress in the space resists.
      const unsigned int  k = zero_pivots.front();
      std::vector<double> y(n, 0.);
      y[k] = 1.;
      for (unsigned int i = 0; i < k; ++i)
        y[i] = -A[i + static_cast<std::size_t>(k) * tau];
      if (k > 0)
        {
          const int ik = k, itau = tau, one = 1;
          dtrsv_("U", "N", "N", &ik, A.data(), &itau, y.data(), &one);
        }
      // Nodes ranked by how much the mode moves them.
      std::vector<std::pair<double, unsigned int>> node_motion;
      std::vector<double> per_node(sys.node_coordinates.size(), 0.);
      for (unsigned int i = 0; i < n; ++i)
        per_node[sys.rows[sys.free_rows[i]].node] += y[i] * y[i];
      for (unsigned int node = 0; node < per_node.size(); ++node)
        if (per_node[node] > 0)
          node_motion.emplace_back(std::sqrt(per_node[node]), node);
      std::sort(node_motion.rbegin(), node_motion.rend());
      const double largest =
        node_motion.empty() ? 1. : node_motion.front().first;
      std::ostringstream s;
      s << "Equilibrium reduction: the equilibrium matrix C of the free rows "
           "is rank deficient ("
        << zero_pivots.size() << " of " << n
        << " pivots vanish): the body has a zero-energy mode, i.e. a "
           "mechanism, an unsupported (floating) body, or a stress space too "
           "poor for this mesh. Add supports that stop rigid motions, or use "
           "a richer stress element. First vanishing pivot at "
        << sys.describe_row(sys.free_rows[k]) << ". The mode moves "
        << node_motion.size() << " node(s); the largest motions are at:";
      for (unsigned int i = 0; i < std::min<std::size_t>(4, node_motion.size());
           ++i)
        s << (i ? "," : "") << " " << sys.describe_node(node_motion[i].second)
          << " [" << std::setprecision(2) << node_motion[i].first / largest
          << "]";
      s << ".";
      return InputError(s.str());
    }
  } // namespace

  void
  EquilibriumReduction::initialize(const EquilibriumSystem &sys,
                                   std::ostream            *log)
  {
    AssertThrow(!sys.lean_rows,
                ExcMessage("the null-space reduction needs every free row "
                           "(a system classified with lean rows)"));
    system = &sys;
    tau    = sys.n_stress_dofs;
    n      = sys.free_rows.size();

    if (n > tau)
      throw InputError(
        "Equilibrium reduction: there are " + std::to_string(n) +
        " free displacement rows but only " + std::to_string(tau) +
        " stress unknowns, so C cannot have full row rank: the body has at "
        "least " +
        std::to_string(n - tau) +
        " zero-energy modes (a mechanism, an unsupported body, or a stress "
        "space too poor for this mesh; try Stress element = DGQ1).");
    m = tau - n;

    // A = C^T, tau x n, column-major: column i is free row i of B~.
    std::vector<double> row_norm;
    std::vector<double> A = free_rows_transposed(sys, tau, row_norm);

    // Gaussian reduction with row pivoting of C^T = column choice of C.
    std::vector<int> ipiv(n);
    if (n > 0)
      {
        const int itau = tau, in = n;
        int       info = 0;
        dgetrf_(&itau, &in, A.data(), &itau, ipiv.data(), &info);
        AssertThrow(info >= 0, ExcMessage("dgetrf: illegal argument"));
      }
    perm.resize(tau);
    std::iota(perm.begin(), perm.end(), 0u);
    for (unsigned int k = 0; k < n; ++k)
      std::swap(perm[k], perm[ipiv[k] - 1]);
    position.resize(tau);
    for (unsigned int i = 0; i < tau; ++i)
      position[perm[i]] = i;

    // Rank check: a vanishing pivot is a zero-energy mode of C.
    std::vector<unsigned int> zero_pivots;
    for (unsigned int k = 0; k < n; ++k)
      if (!(std::abs(A[k + static_cast<std::size_t>(k) * tau]) >
            pivot_tolerance * row_norm[k]))
        zero_pivots.push_back(k);
    if (!zero_pivots.empty())
      throw mechanism_error(sys, A, tau, zero_pivots);

    if (log)
      *log << "  equilibrium reduction: rank(C) = " << n << " of " << n
           << " free rows, " << tau << " stresses, dim(s0) = " << m
           << std::endl;

    // Keep L11 \ U (n x n); X = L11^{-T} L21^T (n x m).
    LU11.assign(static_cast<std::size_t>(n) * n, 0.);
    for (unsigned int j = 0; j < n; ++j)
      for (unsigned int i = 0; i < n; ++i)
        LU11[i + static_cast<std::size_t>(j) * n] =
          A[i + static_cast<std::size_t>(j) * tau];
    X.assign(static_cast<std::size_t>(n) * m, 0.);
    for (unsigned int j = 0; j < m; ++j)
      for (unsigned int i = 0; i < n; ++i)
        X[i + static_cast<std::size_t>(j) * n] =
          A[(n + j) + static_cast<std::size_t>(i) * tau];
    std::vector<double>().swap(A);
    if (n > 0 && m > 0)
      {
        const int    in = n, im = m;
        const double one = 1.;
        dtrsm_(
          "L", "L", "T", "U", &in, &im, &one, LU11.data(), &in, X.data(), &in);
      }

    // Particular stress t: C1 t1 = f_C, C1 = U^T L11^T.
    t.reinit(tau);
    if (n > 0)
      {
        std::vector<double> t1(n);
        for (unsigned int i = 0; i < n; ++i)
          t1[i] = sys.row_load(sys.rows[sys.free_rows[i]]);
        const int in = n, one = 1;
        dtrsv_("U", "T", "N", &in, LU11.data(), &in, t1.data(), &one);
        dtrsv_("L", "T", "U", &in, LU11.data(), &in, t1.data(), &one);
        for (unsigned int i = 0; i < n; ++i)
          t[perm[i]] = t1[i];
      }

    // Q R (eq. 42), row by row: (Q R)_i = sum_k Q_ik R[k, :], R[k, :] being a
    // unit vector for s0 columns and -X[pos(k), :] for s1 columns.
    n_q = sys.contact_rows.size();
    QR.assign(static_cast<std::size_t>(n_q) * m, 0.);
    a.assign(n_q, 0.);
    for (unsigned int i = 0; i < n_q; ++i)
      {
        const EquilibriumRow &row = sys.rows[sys.contact_rows[i]];
        double *const         QRi = QR.data() + static_cast<std::size_t>(i) * m;
        for (const auto &[dof, c] : row.combination)
          if (c != 0)
            for (auto it = sys.B.begin(sys.b_row(dof));
                 it != sys.B.end(sys.b_row(dof));
                 ++it)
              {
                const unsigned int k = position[it->column()];
                const double       v = c * it->value();
                if (k >= n)
                  QRi[k - n] += v;
                else
                  for (unsigned int j = 0; j < m; ++j)
                    QRi[j] -= v * X[k + static_cast<std::size_t>(j) * n];
              }
        a[i] = sys.row_times(row, t) - sys.row_load(row);
      }

    flexibility_changed();
  }

  void
  EquilibriumReduction::flexibility_changed()
  {
    const EquilibriumSystem &sys = *system;
    // M0 = R^T F R = G0 - X^T G1 with G = F R, computed column by column
    // (F is block diagonal: one small product per cell).
    std::vector<double> G0(static_cast<std::size_t>(m) * m, 0.);
    std::vector<double> G1(static_cast<std::size_t>(n) * m, 0.);
    {
      std::vector<double> Rcol(tau), Gcol(tau);
      for (unsigned int j = 0; j < m; ++j)
        {
          const double *Xj = X.data() + static_cast<std::size_t>(j) * n;
          for (unsigned int i = 0; i < n; ++i)
            Rcol[perm[i]] = -Xj[i];
          for (unsigned int i = n; i < tau; ++i)
            Rcol[perm[i]] = (i - n == j) ? 1. : 0.;
          for (unsigned int c = 0; c < sys.cell_stress_dofs.size(); ++c)
            {
              const auto &dofs = sys.cell_stress_dofs[c];
              const auto &Fc   = sys.cell_flexibility[c];
              for (unsigned int a = 0; a < dofs.size(); ++a)
                {
                  double sum = 0;
                  for (unsigned int b = 0; b < dofs.size(); ++b)
                    sum += Fc(a, b) * Rcol[dofs[b]];
                  Gcol[dofs[a]] = sum;
                }
            }
          for (unsigned int i = 0; i < n; ++i)
            G1[i + static_cast<std::size_t>(j) * n] = Gcol[perm[i]];
          for (unsigned int i = n; i < tau; ++i)
            G0[(i - n) + static_cast<std::size_t>(j) * m] = Gcol[perm[i]];
        }
    }
    if (n > 0 && m > 0)
      {
        const int    in = n, im = m;
        const double minus_one = -1., one = 1.;
        dgemm_("T",
               "N",
               &im,
               &im,
               &in,
               &minus_one,
               X.data(),
               &in,
               G1.data(),
               &in,
               &one,
               G0.data(),
               &im);
      }
    std::vector<double>().swap(G1);
    // Symmetrise against round-off, then factorise (R^T F R is SPD: F is SPD
    // and R has full column rank).
    for (unsigned int j = 0; j < m; ++j)
      for (unsigned int i = j + 1; i < m; ++i)
        {
          const double avg = 0.5 * (G0[i + static_cast<std::size_t>(j) * m] +
                                    G0[j + static_cast<std::size_t>(i) * m]);
          G0[i + static_cast<std::size_t>(j) * m] = avg;
          G0[j + static_cast<std::size_t>(i) * m] = avg;
        }
    M0_factor.swap(G0);

    // b0 = R^T v, v = -F t + H^T u-hat + Q^T g, and -d for a material
    // Newton step (the energy's linear term d^T s).
    {
      Vector<double> v;
      sys.multiply_flexibility(t, v);
      sys.add_strain_terms(v);
      v *= -1.;
      for (const unsigned int r : sys.prescribed_rows)
        sys.add_row_transpose(sys.rows[r], sys.rows[r].value, v);
      for (const unsigned int r : sys.contact_rows)
        sys.add_row_transpose(sys.rows[r], sys.rows[r].value, v);
      b0.reinit(m);
      std::vector<double> v1(n);
      for (unsigned int i = 0; i < n; ++i)
        v1[i] = v[perm[i]];
      for (unsigned int j = 0; j < m; ++j)
        b0[j] = v[perm[n + j]];
      if (n > 0 && m > 0)
        {
          const int    in = n, im = m, one_i = 1;
          const double minus_one = -1., one = 1.;
          dgemv_("T",
                 &in,
                 &im,
                 &minus_one,
                 X.data(),
                 &in,
                 v1.data(),
                 &one_i,
                 &one,
                 b0.data(),
                 &one_i);
        }
    }
    if (m > 0)
      {
        const int im   = m;
        int       info = 0;
        dpotrf_("L", &im, M0_factor.data(), &im, &info);
        if (info != 0)
          throw InputError(
            "Equilibrium reduction: R^T F R is not positive definite (Cholesky "
            "failed at column " +
            std::to_string(info) +
            "); the flexibility is singular. Check the material parameters.");
      }
  }

  void
  EquilibriumReduction::apply_R(const Vector<double> &s0,
                                Vector<double>       &s) const
  {
    AssertDimension(s0.size(), m);
    s.reinit(tau);
    std::vector<double> xs(n, 0.);
    if (n > 0 && m > 0)
      {
        const int    in = n, im = m, one_i = 1;
        const double one = 1., zero = 0.;
        dgemv_("N",
               &in,
               &im,
               &one,
               X.data(),
               &in,
               s0.data(),
               &one_i,
               &zero,
               xs.data(),
               &one_i);
      }
    for (unsigned int i = 0; i < n; ++i)
      s[perm[i]] = -xs[i];
    for (unsigned int j = 0; j < m; ++j)
      s[perm[n + j]] = s0[j];
  }

  void
  EquilibriumReduction::solve_M0(double *x, const unsigned int n_rhs) const
  {
    if (m == 0)
      return;
    const int im = m, nr = n_rhs;
    int       info = 0;
    dpotrs_("L", &im, &nr, M0_factor.data(), &im, x, &im, &info);
    AssertThrow(info == 0, ExcMessage("dpotrs failed"));
  }

  void
  EquilibriumReduction::multiply_M0(const Vector<double> &x,
                                    Vector<double>       &y) const
  {
    // M0 = L L^T: y = L (L^T x).
    y = x;
    if (m == 0)
      return;
    const int im = m, one = 1;
    dtrmv_("L", "T", "N", &im, M0_factor.data(), &im, y.data(), &one);
    dtrmv_("L", "N", "N", &im, M0_factor.data(), &im, y.data(), &one);
  }

  void
  EquilibriumReduction::stress_from_s0(const Vector<double> &s0,
                                       Vector<double>       &s) const
  {
    apply_R(s0, s);
    s += t;
  }

  std::vector<double>
  EquilibriumReduction::row_displacements(
    const Vector<double>      &s,
    const std::vector<double> &contact_w) const
  {
    const EquilibriumSystem &sys = *system;
    AssertDimension(contact_w.size(), sys.contact_rows.size());
    // The strains F s (+ d for a material Newton step: the law's strain
    // linearised at the last state).
    Vector<double> rhs;
    sys.multiply_flexibility(s, rhs);
    sys.add_strain_terms(rhs);
    for (const unsigned int r : sys.prescribed_rows)
      sys.add_row_transpose(sys.rows[r], -sys.rows[r].value, rhs);
    for (unsigned int k = 0; k < sys.contact_rows.size(); ++k)
      sys.add_row_transpose(sys.rows[sys.contact_rows[k]], -contact_w[k], rhs);

    // Eq. 51, second line: C1^T u_C = rhs_1 with C1^T = L11 U.
    std::vector<double> uC(n);
    for (unsigned int i = 0; i < n; ++i)
      uC[i] = rhs[perm[i]];
    if (n > 0)
      {
        const int in = n, one = 1;
        dtrsv_("L", "N", "U", &in, LU11.data(), &in, uC.data(), &one);
        dtrsv_("U", "N", "N", &in, LU11.data(), &in, uC.data(), &one);
      }
    std::vector<double> values(sys.rows.size(), 0.);
    for (unsigned int i = 0; i < n; ++i)
      values[sys.free_rows[i]] = uC[i];
    for (unsigned int k = 0; k < sys.contact_rows.size(); ++k)
      values[sys.contact_rows[k]] = contact_w[k];
    for (const unsigned int r : sys.prescribed_rows)
      values[r] = sys.rows[r].value;
    return values;
  }
} // namespace hrcontact
