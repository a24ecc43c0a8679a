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
    /**
     * A = U Sigma V^T: its pseudo-inverse, its null space N and its left
     * null space U_0 (A x - c = (A A^+ - I) c = -U_0 U_0^T c: what of the
     * data no admissible field can meet).
     */
    void
    pseudo_inverse_and_null_spaces(const FullMatrix<double> &A,
                                   FullMatrix<double>       &pinv,
                                   FullMatrix<double>       &N,
                                   FullMatrix<double>       &left_null)
    {
      const unsigned int       n_rows = A.m(), n = A.n();
      LAPACKFullMatrix<double> svd(n_rows, n);
      svd = A;
      svd.compute_svd();
      const auto  &U    = svd.get_svd_u();
      const auto  &VT   = svd.get_svd_vt();
      unsigned int rank = 0;
      while (rank < std::min(n_rows, n) &&
             svd.singular_value(rank) > 1e-11 * svd.singular_value(0))
        ++rank;
      // A^+ = V_r Sigma_r^-1 U_r^T (one BLAS product).
      FullMatrix<double> VS(n, rank), Ur(n_rows, rank);
      for (unsigned int l = 0; l < rank; ++l)
        {
          for (unsigned int i = 0; i < n; ++i)
            VS(i, l) = VT(l, i) / svd.singular_value(l);
          for (unsigned int j = 0; j < n_rows; ++j)
            Ur(j, l) = U(j, l);
        }
      pinv.reinit(n, n_rows);
      VS.mTmult(pinv, Ur);
      N.reinit(n, n - rank);
      for (unsigned int l = rank; l < n; ++l)
        for (unsigned int i = 0; i < n; ++i)
          N(i, l - rank) = VT(l, i);
      left_null.reinit(n_rows, n_rows - rank);
      for (unsigned int l = rank; l < n_rows; ++l)
        for (unsigned int j = 0; j < n_rows; ++j)
          left_null(j, l - rank) = U(j, l);
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

  std::vector<long long>
  CellEquilibration::shape_key(const TriangleSplit     &split,
                               const types::material_id body) const
  {
    std::vector<long long> key{(long long)body, (long long)split.n_triangles()};
    for (unsigned int k = 1; k < split.n_triangles(); ++k)
      for (unsigned int d = 0; d < 2; ++d)
        key.push_back(
          std::llround((split.P[k][d] - split.P[0][d]) / split.h * 1e10));
    return key;
  }

  void
  CellEquilibration::tabulate(const TriangleSplit         &split,
                              const std::vector<Point<2>> &points,
                              Factors                     &F) const
  {
    const TrianglePolynomials &P = polynomials;
    F.h                          = split.h;
    F.values.reinit(points.size(), P.monomials.size());
    F.lower_values.reinit(points.size(), lower.monomials.size());
    for (unsigned int q = 0; q < points.size(); ++q)
      {
        for (unsigned int m = 0; m < P.monomials.size(); ++m)
          F.values(q, m) = P.value(split, points[q], m);
        for (unsigned int l = 0; l < lower.monomials.size(); ++l)
          F.lower_values(q, l) = lower.value(split, points[q], l);
      }
  }

  void
  CellEquilibration::hessian(const Factors             &F,
                             const types::material_id   body,
                             const std::vector<double> &weights,
                             const unsigned int         n_triangles,
                             FullMatrix<double>        &H)
  {
    // Block diagonal, one block per triangle and pair of components: the
    // monomials' mass matrix times the compliance.
    const TrianglePolynomials &P   = polynomials;
    const unsigned int         n_m = P.monomials.size();
    const unsigned int         n_k = weights.size() / n_triangles;
    const FullMatrix<double>  &S   = compliances(body).first;
    H.reinit(P.n_unknowns(n_triangles), P.n_unknowns(n_triangles));
    FullMatrix<double> mass(n_m, n_m);
    for (unsigned int k = 0; k < n_triangles; ++k)
      {
        mass = 0;
        for (unsigned int q = k * n_k; q < (k + 1) * n_k; ++q)
          for (unsigned int m1 = 0; m1 < n_m; ++m1)
            for (unsigned int m2 = 0; m2 < n_m; ++m2)
              mass(m1, m2) += weights[q] * F.values(q, m1) * F.values(q, m2);
        for (unsigned int c1 = 0; c1 < 3; ++c1)
          for (unsigned int c2 = 0; c2 < 3; ++c2)
            for (unsigned int m1 = 0; m1 < n_m; ++m1)
              for (unsigned int m2 = 0; m2 < n_m; ++m2)
                H(P.index(k, c1, m1), P.index(k, c2, m2)) =
                  S(c1, c2) * mass(m1, m2);
      }
  }

  const CellEquilibration::Factors &
  CellEquilibration::factors(const TriangleSplit         &split,
                             const types::material_id     body,
                             const std::vector<Point<2>> &points,
                             const std::vector<double>   &weights)
  {
    const auto key = shape_key(split, body);
    if (const auto it = cache.find(key); it != cache.end())
      return it->second;
    // A mesh of distinct shapes (curved, graded) would keep one set per
    // cell (some 100 kB each): past 512 sets the cache starts over.
    if (cache.size() >= 512)
      cache.clear();

    const TrianglePolynomials &P      = polynomials;
    const unsigned int         n_tri  = split.n_triangles();
    const unsigned int         n      = P.n_unknowns(n_tri);
    const unsigned int         n_k    = points.size() / n_tri;
    const unsigned int         n_rows = this->n_rows(split);
    Factors                    F;
    // The monomials at the rule's points: the same local coordinates on
    // every similar cell.
    tabulate(split, points, F);
    FullMatrix<double> A, H;
    constraint_matrix(split, points, weights, A);
    hessian(F, body, weights, n_tri, H);
    FullMatrix<double> pinv, N;
    pseudo_inverse_and_null_spaces(A, pinv, N, F.left_null);
    const unsigned int rank = n - N.n();
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
    // On a parallelogram eps(u_h) is linear, e = sum_a e_a b_a with b = (1,
    // xi, eta): g = G e_a and M_g g = (M_g G) e_a; e_a from three points.
    if (split.parallelogram())
      {
        FullMatrix<double> G(n, 9), B(3, 3);
        const auto basis = [&](const unsigned int q, const unsigned int a) {
          const Tensor<1, 2> xi = (points[q] - split.centre) / split.h;
          return a == 0 ? 1. : xi[a - 1];
        };
        for (unsigned int q = 0; q < points.size(); ++q)
          for (unsigned int m = 0; m < P.monomials.size(); ++m)
            for (unsigned int cc = 0; cc < 3; ++cc)
              for (unsigned int a = 0; a < 3; ++a)
                G(P.index(q / n_k, cc, m), 3 * cc + a) +=
                  weights[q] * F.values(q, m) * basis(q, a);
        F.M_g_G.reinit(n, 9);
        F.M_g.mmult(F.M_g_G, G);
        const unsigned int n_1d = std::lround(std::sqrt(n_k));
        F.fit_points            = {{0, 1, n_1d}};
        for (unsigned int j = 0; j < 3; ++j)
          for (unsigned int a = 0; a < 3; ++a)
            B(j, a) = basis(F.fit_points[j], a);
        F.fit.reinit(3, 3);
        F.fit.invert(B);
      }
    return cache.emplace(key, std::move(F)).first->second;
  }

  void
  CellEquilibration::constraint_data(
    const DoFHandler<2>::active_cell_iterator &cell,
    const TriangleSplit                       &split,
    const std::vector<Point<2>>               &points,
    const std::vector<double>                 &weights,
    const Factors                             &F,
    Vector<double>                            &c) const
  {
    c.reinit(n_rows(split));
    unsigned int       r     = 0;
    const auto        &f     = results.scene.body_force;
    const unsigned int n_tri = split.n_triangles();
    const unsigned int n_k   = points.size() / n_tri;
    // -f against P_{p-1} on each triangle.
    Vector<double> value(2);
    for (unsigned int k = 0; k < n_tri; ++k)
      {
        for (unsigned int q = k * n_k; f && q < (k + 1) * n_k; ++q)
          {
            f->vector_value(points[q], value);
            for (unsigned int i = 0; i < 2; ++i)
              for (unsigned int l = 0; l < lower.monomials.size(); ++l)
                c(r + i * lower.monomials.size() + l) -=
                  weights[q] * value[i] * F.lower_values(q, l);
          }
        r += 2 * lower.monomials.size();
      }
    // The face tractions on the outer edges (the inner rows' data are 0).
    static const QGauss<1> edge_rule(degree + 3);
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
    const TriangleSplit   split(cell);
    const MaterialLaw<2> &law = results.scene.material_of(cell->material_id());
    const bool            nonlinear = !law.is_linear();
    // Exact for the energy's degree 2p on a parallelogram (eps(u_h)
    // linear); more points where eps(u_h) is rational, and where the law
    // is not quadratic (on the Ramberg-Osgood beam 5 x 5 a triangle give
    // the bound of 7 x 7 to 6e-9, at half the cost).
    const unsigned int n_tri = !split.parallelogram() ? degree + 5 :
                               nonlinear              ? degree + 3 :
                                                        degree + 1;
    points.clear();
    weights.clear();
    split.rule(n_tri, points, weights);
    sampler(cell, split, points, eps, sigma_h);
    // A nonlinear law: tau nearest (in the elastic compliance S) to the
    // stress of u_h's strain, whose S-strain takes eps's place below
    // (found from sigma_h, which is near it).
    target.resize(points.size());
    if (nonlinear)
      for (unsigned int q = 0; q < points.size(); ++q)
        target[q] = stress_at_strain(law, eps[q], points[q], &sigma_h[q]);
    // A shape that repeats (every parallelogram, and a shape met before)
    // keeps its factors; one met for the first time is solved directly.
    const types::material_id body = cell->material_id();
    if (!split.parallelogram() &&
        cache.find(shape_key(split, body)) == cache.end())
      {
        if (seen.size() >= 100000)
          seen.clear();
        if (seen.insert(shape_key(split, body)).second)
          {
            solve_directly(cell, split, body, nonlinear, x);
            finish(cell, law, direct, x, bound_squared, energy_squared);
            return;
          }
      }
    const Factors &F = factors(split, body, points, weights);
    constraint_data(cell, split, points, weights, F, c);
    x.reinit(polynomials.n_unknowns(split.n_triangles()));
    // The factors of a similar cell of size F.h: A scales as h, the
    // energy's Hessian as h^2 (the unknowns are stresses, dimensionless in
    // h), so M_c as 1/h and M_g as 1/h^2.
    const double scale = F.h / split.h;
    xg.reinit(x.size());
    F.M_c.vmult(x, c);
    if (F.M_g_G.m() > 0 && !nonlinear)
      {
        // The strain's linear coefficients (xx, yy, 2 xy; 1, xi, eta).
        Vector<double> e_a(9);
        for (unsigned int j = 0; j < 3; ++j)
          {
            const auto  &e    = eps[F.fit_points[j]];
            const double v[3] = {e[0][0], e[1][1], 2 * e[0][1]};
            for (unsigned int cc = 0; cc < 3; ++cc)
              for (unsigned int a = 0; a < 3; ++a)
                e_a(3 * cc + a) += F.fit(a, j) * v[cc];
          }
        F.M_g_G.vmult(xg, e_a);
        x.sadd(scale, 1., xg);
      }
    else
      {
        energy_gradient(F, body, nonlinear, split.n_triangles(), g);
        F.M_g.vmult(xg, g);
        x.sadd(scale, scale * scale, xg);
      }
    // A x - c = -U_0 U_0^T c.
    Vector<double> projection(F.left_null.n());
    F.left_null.Tvmult(projection, c);
    Ax.reinit(c.size());
    F.left_null.vmult(Ax, projection);
    if (sigma_max > 0)
      residual = std::max(residual, Ax.linfty_norm() / (sigma_max * split.h));
    finish(cell, law, F, x, bound_squared, energy_squared);
  }

  void
  CellEquilibration::energy_gradient(const Factors           &F,
                                     const types::material_id body,
                                     const bool               nonlinear,
                                     const unsigned int       n_triangles,
                                     Vector<double>          &g) const
  {
    const unsigned int n_k = points.size() / n_triangles;
    const unsigned int n_m = polynomials.monomials.size();
    g.reinit(polynomials.n_unknowns(n_triangles));
    const FullMatrix<double> &S = compliance.at(body).first;
    for (unsigned int q = 0; q < points.size(); ++q)
      {
        double e[3] = {eps[q][0][0], eps[q][1][1], 2 * eps[q][0][1]};
        if (nonlinear)
          for (unsigned int cc = 0; cc < 3; ++cc)
            e[cc] = S(cc, 0) * target[q][0][0] + S(cc, 1) * target[q][1][1] +
                    S(cc, 2) * target[q][0][1];
        for (unsigned int m = 0; m < n_m; ++m)
          {
            const double v = weights[q] * F.values(q, m);
            for (unsigned int cc = 0; cc < 3; ++cc)
              g(polynomials.index(q / n_k, cc, m)) += v * e[cc];
          }
      }
  }

  void
  CellEquilibration::solve_directly(
    const DoFHandler<2>::active_cell_iterator &cell,
    const TriangleSplit                       &split,
    const types::material_id                   body,
    const bool                                 nonlinear,
    Vector<double>                            &x)
  {
    const unsigned int n_tri = split.n_triangles();
    // The constraints and the energy are polynomials of degree p and 2p
    // on each triangle: Duffy rules exact for them, not the bound's rule
    // (which integrates the rational eps(u_h) of a general quadrilateral).
    low_points.clear();
    low_weights.clear();
    split.rule(degree, low_points, low_weights);
    constraint_matrix(split, low_points, low_weights, A_direct);
    low_points.clear();
    low_weights.clear();
    split.rule(degree + 1, low_points, low_weights);
    tabulate(split, low_points, low);
    hessian(low, body, low_weights, n_tri, H_direct);
    tabulate(split, points, direct);
    constraint_data(cell, split, points, weights, direct, c);
    energy_gradient(direct, body, nonlinear, n_tri, g);
    // Each triangle's own rows (its equilibrium, its outer edge's
    // traction) first, then the inner edges' jumps (BlockNullSpace).
    block_solve.solve(A_direct,
                      H_direct,
                      g,
                      c,
                      BlockNullSpace::own_rows(n_tri,
                                               2 * lower.monomials.size(),
                                               2 * (degree + 1)),
                      x);
    Ax.reinit(c.size());
    A_direct.vmult(Ax, x);
    Ax -= c;
    if (sigma_max > 0)
      residual = std::max(residual, Ax.linfty_norm() / (sigma_max * split.h));
  }

  void
  CellEquilibration::finish(const DoFHandler<2>::active_cell_iterator &cell,
                            const MaterialLaw<2>                      &law,
                            const Factors                             &F,
                            const Vector<double>                      &x,
                            double &bound_squared,
                            double &energy_squared)
  {
    const unsigned int n_k = points.size() / (x.size() / (3 * F.values.n()));
    const unsigned int n_m = polynomials.monomials.size();
    if (!law.is_linear())
      {
        fenchel_young(law, F, x, bound_squared, energy_squared);
        return;
      }
    // This cell's share of eta^2 (tau - C eps(u_h), with C eps = S^-1 e)
    // and of the computed stresses' energy.
    const auto &[S, S_inv] = compliances(cell->material_id());
    const auto energy      = [&S](const double(&v)[3]) {
      double sum = 0;
      for (unsigned int a = 0; a < 3; ++a)
        for (unsigned int b = 0; b < 3; ++b)
          sum += v[a] * S(a, b) * v[b];
      return sum;
    };
    bound_squared = energy_squared = 0;
    for (unsigned int q = 0; q < points.size(); ++q)
      {
        // tau - C eps(u_h) (xx, yy, xy).
        const unsigned int k = q / n_k;
        const double e[3]    = {eps[q][0][0], eps[q][1][1], 2 * eps[q][0][1]};
        double       v[3]    = {0, 0, 0};
        for (unsigned int cc = 0; cc < 3; ++cc)
          {
            for (unsigned int m = 0; m < n_m; ++m)
              v[cc] += x(polynomials.index(k, cc, m)) * F.values(q, m);
            for (unsigned int b = 0; b < 3; ++b)
              v[cc] -= S_inv(cc, b) * e[b];
          }
        bound_squared += weights[q] * energy(v);
        const double s[3] = {sigma_h[q][0][0],
                             sigma_h[q][1][1],
                             sigma_h[q][0][1]};
        energy_squared += weights[q] * energy(s);
      }
  }

  void
  CellEquilibration::fenchel_young(const MaterialLaw<2> &law,
                                   const Factors        &F,
                                   const Vector<double> &x,
                                   double               &bound_squared,
                                   double               &energy_squared) const
  {
    const unsigned int n_k = points.size() / (x.size() / (3 * F.values.n()));
    bound_squared = energy_squared = 0;
    for (unsigned int q = 0; q < points.size(); ++q)
      {
        const unsigned int    k = q / n_k;
        SymmetricTensor<2, 2> tau;
        for (unsigned int m = 0; m < F.values.n(); ++m)
          {
            tau[0][0] += x(polynomials.index(k, 0, m)) * F.values(q, m);
            tau[1][1] += x(polynomials.index(k, 1, m)) * F.values(q, m);
            tau[0][1] += x(polynomials.index(k, 2, m)) * F.values(q, m);
          }
        const Point<2> &p = points[q];
        // phi^c(tau) + W(eps) - tau : eps, W(eps) = s : eps - phi^c(s).
        const double gap = law.complementary_energy(tau, p) -
                           law.complementary_energy(target[q], p) -
                           (tau - target[q]) * eps[q];
        bound_squared += weights[q] * 2 * gap;
        energy_squared +=
          weights[q] * 2 * law.complementary_energy(sigma_h[q], p);
      }
  }
} // namespace hrcontact
