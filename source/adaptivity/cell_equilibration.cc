#include <deal.II/base/quadrature_lib.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <hrcontact/adaptivity/cell_equilibration.h>

#include <algorithm>
#include <cmath>

namespace hrcontact
{
  using namespace dealii;

  namespace
  {
    /** The Legendre-like test functions s^j, s in [-1, 1], on an edge. */
    double
    edge_test(const double s, const unsigned int j)
    {
      double r = 1;
      for (unsigned int i = 0; i < j; ++i)
        r *= 2 * s - 1;
      return r;
    }
  } // namespace

  CellEquilibration::CellEquilibration(const Results<2>    &results,
                                       const FaceTractions &faces)
    : polynomials(degree)
    , results(results)
    , faces(faces)
    , lower(degree - 1)
    , sampler(results)
  {
    // The largest stress dof over every process.
    sigma_max = results.stress.linfty_norm();
  }

  unsigned int
  CellEquilibration::n_rows(const TriangleSplit &split) const
  {
    // Equilibrium per triangle, two traction components per outer and
    // inner edge.
    return split.n_triangles() *
           (2 * lower.monomials.size() + 2 * 2 * (degree + 1));
  }

  const std::pair<FullMatrix<double>, FullMatrix<double>> &
  CellEquilibration::compliances(const types::material_id body)
  {
    auto it = compliance.find(body);
    if (it == compliance.end())
      {
        FullMatrix<double> S = component_compliance(
                             results.scene.material_of(body)),
                           S_inv(3, 3);
        S_inv.invert(S);
        it = compliance.emplace(body, std::make_pair(S, S_inv)).first;
      }
    return it->second;
  }

  void
  CellEquilibration::constraint_matrix(const TriangleSplit         &split,
                                       const std::vector<Point<2>> &points,
                                       const std::vector<double>   &weights,
                                       FullMatrix<double>          &A) const
  {
    const TrianglePolynomials &P     = polynomials;
    const unsigned int         n_tri = split.n_triangles();
    const unsigned int         n_k   = points.size() / n_tri;
    A.reinit(n_rows(split), P.n_unknowns(n_tri));
    unsigned int r = 0;
    // div tau against P_{p-1} on each triangle (x: d/dx sxx + d/dy sxy; y:
    // d/dx sxy + d/dy syy).
    for (unsigned int k = 0; k < n_tri; ++k)
      for (unsigned int i = 0; i < 2; ++i)
        for (unsigned int l = 0; l < lower.monomials.size(); ++l, ++r)
          for (unsigned int q = k * n_k; q < (k + 1) * n_k; ++q)
            {
              const double t = weights[q] * lower.value(split, points[q], l);
              for (unsigned int m = 0; m < P.monomials.size(); ++m)
                {
                  const Tensor<1, 2> g = P.gradient(split, points[q], m);
                  A(r, P.index(k, i, m)) += t * g[i];
                  A(r, P.index(k, 2, m)) += t * g[1 - i];
                }
            }
    // tau n on the outer edges, its jump on the inner ones (between
    // triangles k - 1 and k), against P_p on each edge.
    const QGauss<1> edge_rule(degree + 3);
    for (unsigned int e = 0; e < 2 * n_tri; ++e)
      {
        const bool         outer = e < n_tri;
        const unsigned int k     = e % n_tri;
        const Point<2>     a     = outer ? split.P[k] : split.centre;
        const Tensor<1, 2> d     = split.P[outer ? k + 1 : k] - a;
        const double       L     = d.norm();
        const Tensor<1, 2> n({d[1] / L, -d[0] / L});
        for (unsigned int i = 0; i < 2; ++i)
          for (unsigned int j = 0; j <= degree; ++j, ++r)
            for (unsigned int q = 0; q < edge_rule.size(); ++q)
              {
                const double   s = edge_rule.point(q)[0];
                const Point<2> x = a + s * d;
                const double   w = edge_rule.weight(q) * L * edge_test(s, j);
                for (unsigned int m = 0; m < P.monomials.size(); ++m)
                  {
                    // (tau n)_i = tau_ii n_i + tau_xy n_(1-i)
                    const double v = w * P.value(split, x, m);
                    A(r, P.index(k, i, m)) += v * n[i];
                    A(r, P.index(k, 2, m)) += v * n[1 - i];
                    if (!outer)
                      {
                        const unsigned int before = (k + n_tri - 1) % n_tri;
                        A(r, P.index(before, i, m)) -= v * n[i];
                        A(r, P.index(before, 2, m)) -= v * n[1 - i];
                      }
                  }
              }
      }
    Assert(r == A.m(), ExcInternalError());
  }

  const CellEquilibration::Factors &
  CellEquilibration::factors(const TriangleSplit         &split,
                             const types::material_id     body,
                             const std::vector<Point<2>> &points,
                             const std::vector<double>   &weights)
  {
    // The shape up to translation (with its hanging nodes), and the body.
    std::vector<long long> key{(long long)body, (long long)split.n_triangles()};
    for (unsigned int k = 1; k < split.n_triangles(); ++k)
      for (unsigned int d = 0; d < 2; ++d)
        key.push_back(
          std::llround((split.P[k][d] - split.P[0][d]) / split.h * 1e10));
    key.push_back(std::llround(std::log(split.h) * 1e10));
    if (const auto it = cache.find(key); it != cache.end())
      return it->second;

    const TrianglePolynomials &P      = polynomials;
    const unsigned int         n_tri  = split.n_triangles();
    const unsigned int         n      = P.n_unknowns(n_tri);
    const unsigned int         n_k    = points.size() / n_tri;
    const unsigned int         n_rows = this->n_rows(split);
    Factors                    F;
    constraint_matrix(split, points, weights, F.A);
    // The energy's Hessian H = sum_q w_q B_q^T S B_q.
    const FullMatrix<double> &S = compliances(body).first;
    FullMatrix<double>        H(n, n);
    for (unsigned int q = 0; q < points.size(); ++q)
      for (unsigned int m1 = 0; m1 < P.monomials.size(); ++m1)
        for (unsigned int m2 = 0; m2 < P.monomials.size(); ++m2)
          {
            const double v = weights[q] * P.value(split, points[q], m1) *
                             P.value(split, points[q], m2);
            for (unsigned int c1 = 0; c1 < 3; ++c1)
              for (unsigned int c2 = 0; c2 < 3; ++c2)
                H(P.index(q / n_k, c1, m1), P.index(q / n_k, c2, m2)) +=
                  v * S(c1, c2);
          }
    // A = U Sigma V^T: the pseudo-inverse and the null space N.
    LAPACKFullMatrix<double> svd(n_rows, n);
    svd = F.A;
    svd.compute_svd();
    const auto  &U    = svd.get_svd_u();
    const auto  &VT   = svd.get_svd_vt();
    unsigned int rank = 0;
    while (rank < std::min(n_rows, n) &&
           svd.singular_value(rank) > 1e-11 * svd.singular_value(0))
      ++rank;
    FullMatrix<double> pinv(n, n_rows), N(n, n - rank);
    for (unsigned int l = 0; l < rank; ++l)
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n_rows; ++j)
          pinv(i, j) += VT(l, i) * U(j, l) / svd.singular_value(l);
    for (unsigned int l = rank; l < n; ++l)
      for (unsigned int i = 0; i < n; ++i)
        N(i, l - rank) = VT(l, i);
    // M_g = N (N^T H N)^{-1} N^T, M_c = A^+ - M_g H A^+.
    FullMatrix<double> HN(n, n - rank), K(n - rank, n - rank), NK(n, n - rank),
      HP(n, n_rows), MHP(n, n_rows);
    H.mmult(HN, N);
    N.Tmmult(K, HN);
    K.gauss_jordan();
    N.mmult(NK, K);
    F.M_g.reinit(n, n);
    NK.mTmult(F.M_g, N);
    H.mmult(HP, pinv);
    F.M_g.mmult(MHP, HP);
    F.M_c = pinv;
    F.M_c.add(-1., MHP);
    return cache.emplace(key, std::move(F)).first->second;
  }

  void
  CellEquilibration::constraint_data(
    const DoFHandler<2>::active_cell_iterator &cell,
    const TriangleSplit                       &split,
    const std::vector<Point<2>>               &points,
    const std::vector<double>                 &weights,
    Vector<double>                            &c) const
  {
    c.reinit(n_rows(split));
    unsigned int       r     = 0;
    const auto        &f     = results.scene.body_force;
    const unsigned int n_tri = split.n_triangles();
    const unsigned int n_k   = points.size() / n_tri;
    // -f against P_{p-1} on each triangle.
    std::vector<Tensor<1, 2>> body(points.size());
    Vector<double>            value(2);
    for (unsigned int q = 0; f && q < points.size(); ++q)
      {
        f->vector_value(points[q], value);
        body[q] = Tensor<1, 2>({value[0], value[1]});
      }
    for (unsigned int k = 0; k < n_tri; ++k)
      for (unsigned int i = 0; i < 2; ++i)
        for (unsigned int l = 0; l < lower.monomials.size(); ++l, ++r)
          for (unsigned int q = k * n_k; f && q < (k + 1) * n_k; ++q)
            c(r) -= weights[q] * body[q][i] * lower.value(split, points[q], l);
    // The face tractions on the outer edges (the inner rows' data are 0).
    const QGauss<1> edge_rule(degree + 3);
    for (unsigned int k = 0; k < n_tri; ++k)
      {
        const unsigned int face = split.segment[k];
        const Point<2>     a    = split.P[k];
        const Tensor<1, 2> d    = split.P[k + 1] - a;
        const double       L    = d.norm();
        const Tensor<1, 2> n({d[1] / L, -d[0] / L});
        for (unsigned int q = 0; q < edge_rule.size(); ++q)
          {
            const double       s = edge_rule.point(q)[0];
            const Tensor<1, 2> t =
              faces.traction(face, cell->active_cell_index(), a + s * d, n);
            for (unsigned int i = 0; i < 2; ++i)
              for (unsigned int j = 0; j <= degree; ++j)
                c(r + i * (degree + 1) + j) +=
                  edge_rule.weight(q) * L * edge_test(s, j) * t[i];
          }
        r += 2 * (degree + 1);
      }
  }

  void
  CellEquilibration::solve(const DoFHandler<2>::active_cell_iterator &cell,
                           Vector<double>                            &x,
                           double &bound_squared,
                           double &energy_squared)
  {
    const TriangleSplit split(cell);
    // Exact for the energy's degree 2p on a parallelogram (eps(u_h)
    // linear); more points where eps(u_h) is rational.
    const unsigned int n_tri = split.parallelogram() ? degree + 1 : degree + 5;
    std::vector<Point<2>> points;
    std::vector<double>   weights;
    split.rule(n_tri, points, weights);
    std::vector<SymmetricTensor<2, 2>> eps, sigma_h;
    sampler(cell, split, points, eps, sigma_h);
    const Factors &F = factors(split, cell->material_id(), points, weights);

    const unsigned int n_k = points.size() / split.n_triangles();
    Vector<double>     c, g(polynomials.n_unknowns(split.n_triangles()));
    constraint_data(cell, split, points, weights, c);
    for (unsigned int q = 0; q < points.size(); ++q)
      {
        const double e[3] = {eps[q][0][0], eps[q][1][1], 2 * eps[q][0][1]};
        for (unsigned int m = 0; m < polynomials.monomials.size(); ++m)
          {
            const double v =
              weights[q] * polynomials.value(split, points[q], m);
            for (unsigned int cc = 0; cc < 3; ++cc)
              g(polynomials.index(q / n_k, cc, m)) += v * e[cc];
          }
      }
    x.reinit(polynomials.n_unknowns(split.n_triangles()));
    F.M_c.vmult(x, c);
    F.M_g.vmult_add(x, g);
    Vector<double> Ax(c.size());
    F.A.vmult(Ax, x);
    Ax -= c;
    if (sigma_max > 0)
      residual = std::max(residual, Ax.linfty_norm() / (sigma_max * split.h));

    // This cell's share of eta^2 (tau - C eps(u_h), with C eps = S^-1 e)
    // and of the computed stresses' energy.
    const auto &[S, S_inv] = compliances(cell->material_id());
    Vector<double> e(3), Ce(3), v(3), Sv(3);
    bound_squared = energy_squared = 0;
    for (unsigned int q = 0; q < points.size(); ++q)
      {
        const auto tau = polynomials.stress(x, split, q / n_k, points[q]);
        e(0)           = eps[q][0][0];
        e(1)           = eps[q][1][1];
        e(2)           = 2 * eps[q][0][1];
        S_inv.vmult(Ce, e);
        v(0) = tau[0][0] - Ce(0);
        v(1) = tau[1][1] - Ce(1);
        v(2) = tau[0][1] - Ce(2);
        S.vmult(Sv, v);
        bound_squared += weights[q] * (v * Sv);
        v(0) = sigma_h[q][0][0];
        v(1) = sigma_h[q][1][1];
        v(2) = sigma_h[q][0][1];
        S.vmult(Sv, v);
        energy_squared += weights[q] * (v * Sv);
      }
  }
} // namespace hrcontact
