#include <deal.II/lac/lapack_full_matrix.h>

#include <hrcontact/core/input.h>
#include <hrcontact/solvers/null_space_step.h>

#include <algorithm>
#include <cmath>

namespace hrcontact
{
  using namespace dealii;

  NullSpaceStep::NullSpaceStep(EquilibriumReduction &reduction)
    : reduction(reduction)
  {
    // The dense path runs whole on every process: every row is its own.
    row_ownership = ContactRowPartition(reduction.n_contact_rows());
    prepare();
  }

  void
  NullSpaceStep::flexibility_changed()
  {
    reduction.flexibility_changed();
    prepare();
  }

  void
  NullSpaceStep::prepare()
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
  NullSpaceStep::solve(const std::vector<ContactPiece> &pieces,
                       std::vector<double>             &p)
  {
    const unsigned int        nq = reduction.n_contact_rows();
    const unsigned int        m  = reduction.n_self_equilibrated();
    const auto               &a  = reduction.contact_offset();
    std::vector<unsigned int> active;
    std::vector<double>       alpha(nq, 0.);
    for (unsigned int i = 0; i < nq; ++i)
      if (pieces[i].spring)
        {
          if (!std::isfinite(pieces[i].compliance))
            throw InputError(
              "the null-space path cannot solve a row without stiffness "
              "(an infinite compliance); take Equilibrium reduction/Path = "
              "condensed.");
          active.push_back(i);
          alpha[i] = pieces[i].compliance;
        }

    // H s0 = r, H = M0 + sum_A alpha_i q_i q_i^T,
    // r = b0 + sum_A q_i (offset_i - alpha_i a_i) + sum_held q_i offset_i:
    // the row's term of the functional is offset p - alpha/2 p^2 (a held
    // row: offset p, which moves its w_n from g to g + offset).
    Vector<double> r = reduction.linear_term();
    for (unsigned int i = 0; i < nq; ++i)
      if (pieces[i].spring || pieces[i].offset != 0)
        {
          const double  c = pieces[i].offset - alpha[i] * a[i];
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
  NullSpaceStep::stresses(FieldVector &s) const
  {
    AssertThrow(is_complete(s),
                ExcMessage("the null-space path runs on a serial mesh"));
    Vector<double> complete;
    reduction.stress_from_s0(s0, complete);
    AssertDimension(complete.size(), s.size());
    std::copy(complete.begin(), complete.end(), s.begin());
  }

  void
  NullSpaceStep::displacements(const std::vector<double> &contact_w,
                               FieldVector               &u) const
  {
    AssertThrow(is_complete(u),
                ExcMessage("the null-space path runs on a serial mesh"));
    Vector<double> s, complete;
    reduction.stress_from_s0(s0, s);
    // Eq. 50-51.
    reduction.system_displacements(s, contact_w, complete);
    AssertDimension(complete.size(), u.size());
    std::copy(complete.begin(), complete.end(), u.begin());
  }

  void
  NullSpaceStep::rows_changed()
  {
    throw InputError(
      "the null-space path cannot follow constraint rows that change during "
      "the solve (curved obstacles updated between multiplier updates need "
      "Equilibrium reduction/Path = condensed).");
  }
} // namespace hrcontact
