#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/sparse_direct.h>

#include <hrcontact/input.h>
#include <hrcontact/newton_step.h>

#include <cmath>

namespace hrcontact
{
  using namespace dealii;

  // ------------------------------------------------------------------------
  // Null-space path

  NullSpaceStep::NullSpaceStep(const EquilibriumReduction &reduction)
    : reduction(reduction)
  {
    const unsigned int nq = reduction.n_contact_rows();
    const unsigned int m  = reduction.n_self_equilibrated();
    Z.resize(static_cast<std::size_t>(m) * nq);
    for (unsigned int i = 0; i < nq; ++i)
      std::copy(reduction.QR_row(i),
                reduction.QR_row(i) + m,
                Z.begin() + static_cast<std::size_t>(i) * m);
    reduction.solve_M0(Z.data(), nq);
    S.reinit(nq, nq);
    for (unsigned int i = 0; i < nq; ++i)
      for (unsigned int j = 0; j < nq; ++j)
        {
          const double *q   = reduction.QR_row(i);
          const double *z   = Z.data() + static_cast<std::size_t>(j) * m;
          double        sum = 0;
          for (unsigned int k = 0; k < m; ++k)
            sum += q[k] * z[k];
          S(i, j) = sum;
        }
  }

  void
  NullSpaceStep::solve(const std::vector<bool>   &released,
                       const std::vector<double> &mu,
                       const std::vector<double> &alpha,
                       std::vector<double>       &p)
  {
    const unsigned int        nq = reduction.n_contact_rows();
    const unsigned int        m  = reduction.n_self_equilibrated();
    const auto               &a  = reduction.contact_offset();
    std::vector<unsigned int> active;
    for (unsigned int i = 0; i < nq; ++i)
      if (released[i])
        active.push_back(i);

    // H s0 = r, H = M0 + sum_A alpha_i q_i q_i^T,
    // r = b0 + sum_A q_i (mu_i - alpha_i a_i).
    Vector<double> r = reduction.linear_term();
    for (const unsigned int i : active)
      {
        const double  c = mu[i] - alpha[i] * a[i];
        const double *q = reduction.QR_row(i);
        for (unsigned int j = 0; j < m; ++j)
          r[j] += c * q[j];
      }
    auto q_dot = [&](const unsigned int i, const Vector<double> &x) {
      const double *q   = reduction.QR_row(i);
      double        sum = 0;
      for (unsigned int j = 0; j < m; ++j)
        sum += q[j] * x[j];
      return sum;
    };
    // Woodbury: H^{-1} v = y - Z_A (alpha_A^{-1} + S_AA)^{-1} (QR_A y),
    // y = M0^{-1} v; W is factorised once per solve.
    const unsigned int       na = active.size();
    LAPACKFullMatrix<double> W(na, na);
    if (na > 0)
      {
        for (unsigned int i = 0; i < na; ++i)
          {
            for (unsigned int j = 0; j < na; ++j)
              W(i, j) = S(active[i], active[j]);
            W(i, i) += 1. / alpha[active[i]];
          }
        W.set_property(LAPACKSupport::symmetric);
        W.compute_cholesky_factorization();
      }
    auto apply_H_inverse = [&](Vector<double> &x) {
      reduction.solve_M0(x.data());
      if (na == 0)
        return;
      Vector<double> t(na);
      for (unsigned int i = 0; i < na; ++i)
        t[i] = q_dot(active[i], x);
      W.solve(t);
      for (unsigned int i = 0; i < na; ++i)
        {
          const double *z = Z.data() + static_cast<std::size_t>(active[i]) * m;
          for (unsigned int j = 0; j < m; ++j)
            x[j] -= t[i] * z[j];
        }
    };
    s0 = r;
    apply_H_inverse(s0);
    // Iterative refinement: compliant springs (large alpha against the
    // nodal compliance) make p a small difference of large numbers; two
    // corrections with the residual r - H s0 bring it to round-off.
    for (unsigned int refinement = 0; refinement < 2; ++refinement)
      {
        Vector<double> residual(m), Hs0(m);
        reduction.multiply_M0(s0, Hs0);
        for (const unsigned int i : active)
          {
            const double  c = alpha[i] * q_dot(i, s0);
            const double *q = reduction.QR_row(i);
            for (unsigned int j = 0; j < m; ++j)
              Hs0[j] += c * q[j];
          }
        residual = r;
        residual -= Hs0;
        apply_H_inverse(residual);
        s0 += residual;
      }
    p.resize(nq);
    for (unsigned int i = 0; i < nq; ++i)
      {
        const double *q   = reduction.QR_row(i);
        double        sum = a[i];
        for (unsigned int j = 0; j < m; ++j)
          sum += q[j] * s0[j];
        p[i] = sum;
      }
  }

  void
  NullSpaceStep::stresses(Vector<double> &s) const
  {
    reduction.stress_from_s0(s0, s);
  }

  void
  NullSpaceStep::displacements(const std::vector<double> &contact_w,
                               Vector<double>            &u) const
  {
    Vector<double> s;
    stresses(s);
    // Eq. 50-51.
    reduction.system_displacements(s, contact_w, u);
  }

  // ------------------------------------------------------------------------
  // Condensed path

  CondensedStep::CondensedStep(const EquilibriumSystem &system)
    : system(system)
  {
    const unsigned int     n_u = system.n_displacement_dofs;
    DynamicSparsityPattern dsp(n_u, n_u);
    for (const auto &dofs : system.cell_displacement_dofs)
      for (const auto i : dofs)
        for (const auto j : dofs)
          dsp.add(i, j);
    sparsity.copy_from(dsp);
    K.reinit(sparsity);

    // K_c = B_c F_c^{-1} B_c^T, and F_c^{-1} B_c^T kept for the stresses.
    recovery.resize(system.cell_stress_dofs.size());
    for (unsigned int c = 0; c < system.cell_stress_dofs.size(); ++c)
      {
        const auto        &du = system.cell_displacement_dofs[c];
        const auto        &ds = system.cell_stress_dofs[c];
        FullMatrix<double> Bc(du.size(), ds.size());
        for (unsigned int i = 0; i < du.size(); ++i)
          for (unsigned int j = 0; j < ds.size(); ++j)
            Bc(i, j) = system.B.el(du[i], ds[j]);
        FullMatrix<double> Finv(ds.size(), ds.size());
        Finv.invert(system.cell_flexibility[c]);
        recovery[c].reinit(ds.size(), du.size());
        Finv.mTmult(recovery[c], Bc); // F^{-1} B^T
        FullMatrix<double> Kc(du.size(), du.size());
        Bc.mmult(Kc, recovery[c]);
        for (unsigned int i = 0; i < du.size(); ++i)
          for (unsigned int j = 0; j < du.size(); ++j)
            K.add(du[i], du[j], Kc(i, j));
      }
  }

  void
  CondensedStep::solve(const std::vector<bool>   &released,
                       const std::vector<double> &mu,
                       const std::vector<double> &alpha,
                       std::vector<double>       &p)
  {
    const unsigned int n_u = system.n_displacement_dofs;
    // Constraints d . u = value for prescribed and pressed rows: the dof
    // with the largest |d_k| is expressed by the others of its node.
    AffineConstraints<double> constraints;
    auto constrain = [&](const EquilibriumRow &row, const double value) {
      unsigned int k_max = 0;
      for (unsigned int k = 1; k < row.combination.size(); ++k)
        if (std::abs(row.combination[k].second) >
            std::abs(row.combination[k_max].second))
          k_max = k;
      const auto   dof = row.combination[k_max].first;
      const double d   = row.combination[k_max].second;
      constraints.add_line(dof);
      for (unsigned int k = 0; k < row.combination.size(); ++k)
        if (k != k_max && row.combination[k].second != 0)
          constraints.add_entry(dof,
                                row.combination[k].first,
                                -row.combination[k].second / d);
      constraints.set_inhomogeneity(dof, value / d);
    };
    for (const unsigned int r : system.prescribed_rows)
      constrain(system.rows[r], system.rows[r].value);

    SparseMatrix<double> A(sparsity);
    A.copy_from(K);
    Vector<double> rhs = system.load;
    for (unsigned int i = 0; i < system.contact_rows.size(); ++i)
      {
        const EquilibriumRow &row = system.rows[system.contact_rows[i]];
        if (!released[i])
          constrain(row, row.value);
        else
          {
            // Spring 1/alpha along d anchored at g + mu.
            const double k_s = 1. / alpha[i];
            for (const auto &[a, ca] : row.combination)
              {
                rhs[a] += ca * k_s * (row.value + mu[i]);
                for (const auto &[b, cb] : row.combination)
                  A.add(a, b, k_s * ca * cb);
              }
          }
      }
    constraints.close();
    constraints.condense(A, rhs);

    SparseDirectUMFPACK direct;
    try
      {
        direct.initialize(A);
      }
    catch (const std::exception &)
      {
        throw InputError(
          "Condensed path: the stiffness B F^-1 B^T with the current supports "
          "is singular: the body has a zero-energy mode (a mechanism, an "
          "unsupported body, or a stress space too poor for the mesh). The "
          "null-space path (Equilibrium reduction/Path = null-space) names "
          "the nodes the mode moves.");
      }
    u.reinit(n_u);
    direct.vmult(u, rhs);
    constraints.distribute(u);

    s.reinit(system.n_stress_dofs);
    for (unsigned int c = 0; c < recovery.size(); ++c)
      {
        const auto &du = system.cell_displacement_dofs[c];
        const auto &ds = system.cell_stress_dofs[c];
        for (unsigned int i = 0; i < ds.size(); ++i)
          {
            double sum = 0;
            for (unsigned int j = 0; j < du.size(); ++j)
              sum += recovery[c](i, j) * u[du[j]];
            s[ds[i]] = sum;
          }
      }
    p.resize(system.contact_rows.size());
    for (unsigned int i = 0; i < system.contact_rows.size(); ++i)
      {
        const EquilibriumRow &row = system.rows[system.contact_rows[i]];
        p[i] = system.row_times(row, s) - system.row_load(row);
      }
  }

  void
  CondensedStep::stresses(Vector<double> &stress) const
  {
    stress = s;
  }

  void
  CondensedStep::displacements(const std::vector<double> &,
                               Vector<double> &displacement) const
  {
    displacement = u;
  }
} // namespace hrcontact
