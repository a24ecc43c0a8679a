#include <deal.II/base/geometry_info.h>
#include <deal.II/base/quadrature_lib.h>

#include <hrcontact/adaptivity/hexahedron_equilibration.h>
#include <hrcontact/discretisation/mixed_spaces.h>
#include <hrcontact/material/material_law.h>

#include <algorithm>
#include <cmath>

// Reference BLAS (column-major), linked through deal.II.
extern "C"
{
  void
  dgemv_(const char   *trans,
         const int    *m,
         const int    *n,
         const double *alpha,
         const double *a,
         const int    *lda,
         const double *x,
         const int    *incx,
         const double *beta,
         double       *y,
         const int    *incy);
}

namespace hrcontact
{
  using namespace dealii;

  namespace
  {
    /** The component of (i, j) in (xx, yy, zz, xy, xz, yz). */
    unsigned int
    component(const unsigned int i, const unsigned int j)
    {
      return i == j ? i : 2 + i + j;
    }

    /** Exponents of the monomials of degree at most p in 3 variables. */
    std::vector<std::array<unsigned int, 3>>
    exponents(const unsigned int p)
    {
      std::vector<std::array<unsigned int, 3>> e;
      for (unsigned int d = 0; d <= p; ++d)
        for (unsigned int a = 0; a <= d; ++a)
          for (unsigned int b = 0; a + b <= d; ++b)
            e.push_back({{d - a - b, b, a}});
      return e;
    }

    double
    power(const double x, const unsigned int n)
    {
      double r = 1;
      for (unsigned int i = 0; i < n; ++i)
        r *= x;
      return r;
    }

    /** A rule on the triangle or tetrahedron of @p corners (real points and
     * weights), from Witherden-Vincent's rule exact to degree 2n - 1. */
    template <int dim>
    void
    simplex_rule(const std::array<Point<3>, dim + 1> &corners,
                 const unsigned int                   n,
                 std::vector<Point<3>>               &points,
                 std::vector<double>                 &weights)
    {
      static const QWitherdenVincentSimplex<dim> rule(n);
      AssertDimension(rule.size(), QWitherdenVincentSimplex<dim>(n).size());
      std::array<Tensor<1, 3>, dim> d;
      for (unsigned int k = 0; k < dim; ++k)
        d[k] = corners[k + 1] - corners[0];
      const double jacobian = dim == 3 ?
                                std::abs(d[0] * cross_product_3d(d[1], d[2])) :
                                cross_product_3d(d[0], d[1]).norm();
      points.clear();
      weights.clear();
      for (unsigned int q = 0; q < rule.size(); ++q)
        {
          Point<3> x = corners[0];
          for (unsigned int k = 0; k < dim; ++k)
            x += rule.point(q)[k] * d[k];
          points.push_back(x);
          weights.push_back(rule.weight(q) * jacobian);
        }
    }
  } // namespace

  FullMatrix<double>
  component_compliance(const MaterialLaw<3> &law)
  {
    FullMatrix<double> S(6, 6);
    for (unsigned int a = 0; a < 6; ++a)
      {
        const auto e =
          law.strain(MixedSpaces<3>::stress_basis_tensor(a), Point<3>());
        for (unsigned int b = 0; b < 6; ++b)
          S(b, a) = MixedSpaces<3>::stress_basis_tensor(b) * e;
      }
    return S;
  }

  void
  HexahedronEquilibration::tetrahedron_rule(const unsigned int     k,
                                            std::vector<Point<3>> &points,
                                            std::vector<double> &weights) const
  {
    std::array<Point<3>, 4> corners;
    for (unsigned int i = 0; i < 4; ++i)
      corners[i] = geometry.P[tets[k][i]];
    simplex_rule<3>(corners, 3, points, weights);
  }

  void
  HexahedronEquilibration::set_cell(const std::array<Point<3>, 8> &vertices)
  {
    Geometry &G = geometry;
    G.P[14]     = Point<3>();
    for (unsigned int v = 0; v < 8; ++v)
      {
        G.P[v] = vertices[v];
        G.P[14] += vertices[v] / 8.;
      }
    for (unsigned int f = 0; f < 6; ++f)
      {
        G.P[8 + f] = Point<3>();
        for (unsigned int j = 0; j < 4; ++j)
          G.P[8 + f] +=
            vertices[GeometryInfo<3>::face_to_cell_vertices(f, j)] / 4.;
      }
    G.h = vertices[0].distance(vertices[7]);
  }

  HexahedronEquilibration::HexahedronEquilibration(const FullMatrix<double> &S)
    : S(S)
    , monomials(exponents(degree))
    , lower(exponents(degree - 1))
  {
    // Per face, its four edges in cyclic order (deal.II's face vertices
    // 0, 1, 3, 2), each with the face centre and the cell centre.
    unsigned int k = 0;
    for (unsigned int f = 0; f < 6; ++f)
      {
        const unsigned int cycle[4] = {0, 1, 3, 2};
        for (unsigned int e = 0; e < 4; ++e, ++k)
          {
            tets[k] = {
              {14,
               8 + f,
               GeometryInfo<3>::face_to_cell_vertices(f, cycle[e]),
               GeometryInfo<3>::face_to_cell_vertices(f, cycle[(e + 1) % 4])}};
            face_of_tet[k] = f;
          }
      }
    // Inner triangles: the faces through the centre, each shared by two
    // tetrahedra.
    std::map<std::array<unsigned int, 3>, unsigned int> first;
    for (unsigned int t = 0; t < n_tetrahedra; ++t)
      for (unsigned int drop = 1; drop < 4; ++drop)
        {
          std::array<unsigned int, 3> tri;
          unsigned int                j = 0;
          for (unsigned int i = 0; i < 4; ++i)
            if (i != drop)
              tri[j++] = tets[t][i];
          std::array<unsigned int, 3> key = tri;
          std::sort(key.begin(), key.end());
          if (const auto it = first.find(key); it != first.end())
            inner.push_back({it->second, t, tri});
          else
            first.emplace(key, t);
        }
    AssertDimension(inner.size(), 36);
  }

  double
  HexahedronEquilibration::monomial(const std::array<unsigned int, 3> &e,
                                    const Point<3>                    &x) const
  {
    const Tensor<1, 3> xi = (x - geometry.P[14]) / geometry.h;
    return power(xi[0], e[0]) * power(xi[1], e[1]) * power(xi[2], e[2]);
  }

  Tensor<1, 3>
  HexahedronEquilibration::monomial_gradient(
    const std::array<unsigned int, 3> &e,
    const Point<3>                    &x) const
  {
    const Tensor<1, 3> xi = (x - geometry.P[14]) / geometry.h;
    Tensor<1, 3>       g;
    for (unsigned int d = 0; d < 3; ++d)
      if (e[d] > 0)
        {
          g[d] = e[d] / geometry.h;
          for (unsigned int i = 0; i < 3; ++i)
            g[d] *= power(xi[i], i == d ? e[i] - 1 : e[i]);
        }
    return g;
  }

  SymmetricTensor<2, 3>
  HexahedronEquilibration::stress(const Vector<double> &x,
                                  const unsigned int    k,
                                  const Point<3>       &point) const
  {
    SymmetricTensor<2, 3> s;
    for (unsigned int m = 0; m < monomials.size(); ++m)
      {
        const double v = monomial(monomials[m], point);
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = i; j < 3; ++j)
            s[i][j] += x(index(k, component(i, j), m)) * v;
      }
    return s;
  }

  void
  HexahedronEquilibration::constraints(const Traction     &traction,
                                       const VectorField  &body_force,
                                       FullMatrix<double> *A,
                                       Vector<double>     &c)
  {
    const unsigned int n_l = lower.size(), n_t = 6;
    n_rows = n_tetrahedra * 3 * (n_l + n_t) + 36 * 3 * n_t;
    if (A)
      A->reinit(n_rows, n_tetrahedra * 6 * monomials.size());
    c.reinit(n_rows);
    std::vector<Point<3>> points;
    std::vector<double>   weights;
    unsigned int          r = 0;
    // div tau + f = 0 against the linear polynomials on each tetrahedron.
    for (unsigned int k = 0; k < n_tetrahedra; ++k, r += 3 * n_l)
      {
        std::array<Point<3>, 4> corners;
        for (unsigned int i = 0; i < 4; ++i)
          corners[i] = geometry.P[tets[k][i]];
        simplex_rule<3>(corners, 3, points, weights);
        for (unsigned int q = 0; q < points.size(); ++q)
          {
            const Tensor<1, 3> f =
              body_force ? body_force(points[q]) : Tensor<1, 3>();
            for (unsigned int l = 0; l < n_l; ++l)
              {
                const double t = weights[q] * monomial(lower[l], points[q]);
                for (unsigned int i = 0; i < 3; ++i)
                  c(r + i * n_l + l) -= t * f[i];
                if (A)
                  for (unsigned int m = 0; m < monomials.size(); ++m)
                    {
                      const Tensor<1, 3> g =
                        monomial_gradient(monomials[m], points[q]);
                      for (unsigned int i = 0; i < 3; ++i)
                        for (unsigned int j = 0; j < 3; ++j)
                          (*A)(r + i * n_l + l, index(k, component(i, j), m)) +=
                            t * g[j];
                    }
              }
          }
      }
    // tau n on a triangle against the quadratics of its own coordinates:
    // the outer ones (data: the traction), then the jumps across the inner
    // ones (data 0).
    const auto triangle_rows = [&](const std::array<Point<3>, 3> &tri,
                                   const Tensor<1, 3>            &normal,
                                   const unsigned int             k_plus,
                                   const int                      k_minus,
                                   const int                      face) {
      simplex_rule<2>(tri, 3, points, weights);
      const Tensor<1, 3> d1 = tri[1] - tri[0], d2 = tri[2] - tri[0];
      for (unsigned int q = 0; q < points.size(); ++q)
        {
          // The point's coordinates (s, t) on the triangle.
          const Tensor<1, 3> y   = points[q] - tri[0];
          const double       a11 = d1 * d1, a12 = d1 * d2, a22 = d2 * d2;
          const double       det     = a11 * a22 - a12 * a12;
          const double       s       = (a22 * (y * d1) - a12 * (y * d2)) / det;
          const double       t       = (a11 * (y * d2) - a12 * (y * d1)) / det;
          const double       test[6] = {1, s, t, s * s, s * t, t * t};
          const Tensor<1, 3> data =
            face >= 0 ? traction(face, points[q]) : Tensor<1, 3>();
          for (unsigned int j = 0; j < n_t; ++j)
            {
              const double w = weights[q] * test[j];
              for (unsigned int i = 0; i < 3; ++i)
                c(r + i * n_t + j) += w * data[i];
              if (A)
                for (unsigned int m = 0; m < monomials.size(); ++m)
                  {
                    const double v = w * monomial(monomials[m], points[q]);
                    for (unsigned int i = 0; i < 3; ++i)
                      for (unsigned int jj = 0; jj < 3; ++jj)
                        {
                          const unsigned int cc = component(i, jj);
                          (*A)(r + i * n_t + j, index(k_plus, cc, m)) +=
                            v * normal[jj];
                          if (k_minus >= 0)
                            (*A)(r + i * n_t + j, index(k_minus, cc, m)) -=
                              v * normal[jj];
                        }
                  }
            }
        }
      r += 3 * n_t;
    };
    for (unsigned int k = 0; k < n_tetrahedra; ++k)
      {
        const std::array<Point<3>, 3> tri = {{geometry.P[tets[k][1]],
                                              geometry.P[tets[k][2]],
                                              geometry.P[tets[k][3]]}};
        Tensor<1, 3> n = cross_product_3d(tri[1] - tri[0], tri[2] - tri[0]);
        if (n * (tri[0] - geometry.P[14]) < 0)
          n = -n;
        triangle_rows(tri, n / n.norm(), k, -1, face_of_tet[k]);
      }
    for (const InnerFace &f : inner)
      {
        const std::array<Point<3>, 3> tri = {{geometry.P[f.points[0]],
                                              geometry.P[f.points[1]],
                                              geometry.P[f.points[2]]}};
        Tensor<1, 3> n = cross_product_3d(tri[1] - tri[0], tri[2] - tri[0]);
        // From tetrahedron a to b: away from a's centroid.
        Point<3> centroid_a;
        for (unsigned int i = 0; i < 4; ++i)
          centroid_a += geometry.P[tets[f.a][i]] / 4.;
        if (n * (tri[0] - centroid_a) < 0)
          n = -n;
        triangle_rows(tri, n / n.norm(), f.a, f.b, -1);
      }
    AssertDimension(r, n_rows);
  }

  void
  HexahedronEquilibration::energy(const StressField  &target,
                                  FullMatrix<double> *H,
                                  Vector<double>     &g) const
  {
    const unsigned int n_m = monomials.size();
    if (H)
      H->reinit(n_tetrahedra * 6 * n_m, n_tetrahedra * 6 * n_m);
    g.reinit(n_tetrahedra * 6 * n_m);
    std::vector<Point<3>> points;
    std::vector<double>   weights;
    std::vector<double>   values(n_m);
    for (unsigned int k = 0; k < n_tetrahedra; ++k)
      {
        std::array<Point<3>, 4> corners;
        for (unsigned int i = 0; i < 4; ++i)
          corners[i] = geometry.P[tets[k][i]];
        // Exact for degree 5: the energy's 4, and eps(u_h) of a
        // parallelepiped (degree 2) against the quadratics.
        simplex_rule<3>(corners, 3, points, weights);
        for (unsigned int q = 0; q < points.size(); ++q)
          {
            for (unsigned int m = 0; m < n_m; ++m)
              values[m] = monomial(monomials[m], points[q]);
            const SymmetricTensor<2, 3> s    = target(points[q]);
            const double                v[6] = {
                             s[0][0], s[1][1], s[2][2], s[0][1], s[0][2], s[1][2]};
            for (unsigned int c1 = 0; c1 < 6; ++c1)
              {
                double Sv = 0;
                for (unsigned int c2 = 0; c2 < 6; ++c2)
                  Sv += S(c1, c2) * v[c2];
                for (unsigned int m = 0; m < n_m; ++m)
                  g(index(k, c1, m)) += weights[q] * values[m] * Sv;
              }
            if (H)
              for (unsigned int c1 = 0; c1 < 6; ++c1)
                for (unsigned int c2 = 0; c2 < 6; ++c2)
                  for (unsigned int m1 = 0; m1 < n_m; ++m1)
                    for (unsigned int m2 = 0; m2 < n_m; ++m2)
                      (*H)(index(k, c1, m1), index(k, c2, m2)) +=
                        weights[q] * S(c1, c2) * values[m1] * values[m2];
          }
      }
  }

  double
  HexahedronEquilibration::distance(const Vector<double> &x,
                                    const StressField    &target) const
  {
    std::vector<Point<3>> points;
    std::vector<double>   weights;
    double                sum = 0;
    for (unsigned int k = 0; k < n_tetrahedra; ++k)
      {
        std::array<Point<3>, 4> corners;
        for (unsigned int i = 0; i < 4; ++i)
          corners[i] = geometry.P[tets[k][i]];
        simplex_rule<3>(corners, 3, points, weights);
        for (unsigned int q = 0; q < points.size(); ++q)
          {
            const SymmetricTensor<2, 3> d =
              stress(x, k, points[q]) - target(points[q]);
            const double v[6] = {
              d[0][0], d[1][1], d[2][2], d[0][1], d[0][2], d[1][2]};
            for (unsigned int a = 0; a < 6; ++a)
              for (unsigned int b = 0; b < 6; ++b)
                sum += weights[q] * v[a] * S(a, b) * v[b];
          }
      }
    return sum;
  }

  double
  HexahedronEquilibration::solve(const std::array<Point<3>, 8> &vertices,
                                 const Traction                &traction,
                                 const VectorField             &body_force,
                                 const StressField             &target,
                                 Vector<double>                &x)
  {
    set_cell(vertices);
    const Geometry &G = geometry;
    // The shape up to translation and scale.
    std::vector<long long> key;
    for (unsigned int v = 1; v < 8; ++v)
      for (unsigned int d = 0; d < 3; ++d)
        key.push_back(std::llround((G.P[v][d] - G.P[0][d]) / G.h * 1e10));
    auto           it = shapes.find(key);
    Vector<double> c, g;
    if (it == shapes.end())
      {
        Shape              shape;
        FullMatrix<double> H;
        shape.h = G.h;
        constraints(traction, body_force, &shape.A, c);
        energy(target, &H, g);
        shape.least_squares.factor(shape.A);
        shape.least_squares.prepare(H);
        it = shapes.emplace(key, std::move(shape)).first;
      }
    else
      {
        constraints(traction, body_force, nullptr, c);
        energy(target, nullptr, g);
      }
    Shape &shape = it->second;
    // A shape that repeats: the explicit map pays from the second cell on.
    if (++shape.uses == 2)
      shape.least_squares.make_explicit();
    rank       = shape.least_squares.rank();
    n_unknowns = shape.A.n();
    // A similar cell of size h: A scales as (h / h_0)^2, the energy as
    // (h / h_0)^3 (the unknowns are stresses).
    const double   s = G.h / shape.h;
    Vector<double> c0(c), g0(g);
    c0 /= s * s;
    g0 /= s * s * s;
    shape.least_squares.solve(g0, c0, x);
    // A_0 x - c_0 by BLAS (A's row-major entries are A^T column-major).
    Vector<double> r(c.size());
    const auto     defect = [&]() {
      const int    rows = shape.A.m(), columns = shape.A.n(), one = 1;
      const double plus = 1, zero = 0;
      dgemv_("T",
             &columns,
             &rows,
             &plus,
             &shape.A(0, 0),
             &columns,
             x.begin(),
             &one,
             &zero,
             r.begin(),
             &one);
      r -= c0;
      return r.l2_norm() / std::max(c0.l2_norm(), 1e-300);
    };
    double relative = defect();
    // The explicit map loses digits where R_11 is ill conditioned: one
    // step of refinement (the minimiser is linear in the data) brings the
    // constraints back to round-off.
    if (relative > 1e-11)
      {
        Vector<double> zero_g(x.size()), correction;
        r *= -1.;
        shape.least_squares.solve(zero_g, r, correction);
        x += correction;
        relative = defect();
      }
    // In this cell's units (A = s^2 A_0).
    residual = s * s * r.linfty_norm();
    return distance(x, target);
  }
} // namespace hrcontact
