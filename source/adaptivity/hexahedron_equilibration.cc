#include <deal.II/base/geometry_info.h>
#include <deal.II/base/quadrature_lib.h>

#include <hrcontact/adaptivity/hexahedron_equilibration.h>

#include <algorithm>
#include <cmath>

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

    /** The unit normal of a triangle pointing away from @p inside. */
    Tensor<1, 3>
    unit_normal(const std::array<Point<3>, 3> &tri, const Point<3> &inside)
    {
      Tensor<1, 3> n = cross_product_3d(tri[1] - tri[0], tri[2] - tri[0]);
      if (n * (tri[0] - inside) < 0)
        n = -n;
      return n / n.norm();
    }
  } // namespace

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
    static_assert(degree == 2,
                  "the monomials' values are kept in arrays of 10 and 4");
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
            g[d] *= std::pow(xi[i], int(i == d ? e[i] - 1 : e[i]));
        }
    return g;
  }

  void
  HexahedronEquilibration::monomial_values(
    const Point<3>                                 &x,
    const std::vector<std::array<unsigned int, 3>> &exps,
    double                                         *values) const
  {
    const Tensor<1, 3> xi = (x - geometry.P[14]) / geometry.h;
    double             p[3][3];
    for (unsigned int d = 0; d < 3; ++d)
      {
        p[d][0] = 1;
        p[d][1] = xi[d];
        p[d][2] = xi[d] * xi[d];
      }
    for (unsigned int m = 0; m < exps.size(); ++m)
      values[m] = p[0][exps[m][0]] * p[1][exps[m][1]] * p[2][exps[m][2]];
  }

  SymmetricTensor<2, 3>
  HexahedronEquilibration::stress(const Vector<double> &x,
                                  const unsigned int    k,
                                  const Point<3>       &point) const
  {
    SymmetricTensor<2, 3> s;
    double                values[10];
    monomial_values(point, monomials, values);
    for (unsigned int m = 0; m < monomials.size(); ++m)
      {
        const double v = values[m];
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
        // No body force: these rows' data are zero.
        if (!A && !body_force)
          continue;
        tetrahedron_rule(k, points, weights);
        for (unsigned int q = 0; q < points.size(); ++q)
          {
            const Tensor<1, 3> f =
              body_force ? body_force(points[q]) : Tensor<1, 3>();
            double lower_values[4];
            monomial_values(points[q], lower, lower_values);
            for (unsigned int l = 0; l < n_l; ++l)
              {
                const double t = weights[q] * lower_values[l];
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
          double values[10];
          if (A)
            monomial_values(points[q], monomials, values);
          for (unsigned int j = 0; j < n_t; ++j)
            {
              const double w = weights[q] * test[j];
              for (unsigned int i = 0; i < 3; ++i)
                c(r + i * n_t + j) += w * data[i];
              if (A)
                for (unsigned int m = 0; m < monomials.size(); ++m)
                  {
                    const double v = w * values[m];
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
        triangle_rows(
          tri, unit_normal(tri, geometry.P[14]), k, -1, face_of_tet[k]);
      }
    // The inner rows' data are zero: only their matrix needs the rules.
    if (!A)
      r += inner.size() * 3 * n_t;
    for (const InnerFace &f : inner)
      if (A)
        {
          const std::array<Point<3>, 3> tri = {{geometry.P[f.points[0]],
                                                geometry.P[f.points[1]],
                                                geometry.P[f.points[2]]}};
          // From tetrahedron a to b: away from a's centroid.
          Point<3> centroid_a;
          for (unsigned int i = 0; i < 4; ++i)
            centroid_a += geometry.P[tets[f.a][i]] / 4.;
          triangle_rows(tri, unit_normal(tri, centroid_a), f.a, f.b, -1);
        }
    AssertDimension(r, n_rows);
  }

  void
  HexahedronEquilibration::energy(
    const StressField                  &target,
    FullMatrix<double>                 *H,
    Vector<double>                     &g,
    std::vector<SymmetricTensor<2, 3>> &targets) const
  {
    targets.clear();
    const unsigned int n_m = monomials.size();
    if (H)
      H->reinit(n_tetrahedra * 6 * n_m, n_tetrahedra * 6 * n_m);
    g.reinit(n_tetrahedra * 6 * n_m);
    std::vector<Point<3>> points;
    std::vector<double>   weights;
    std::vector<double>   values(n_m);
    for (unsigned int k = 0; k < n_tetrahedra; ++k)
      {
        // Exact for degree 5: the energy's 4, and eps(u_h) of a
        // parallelepiped (degree 2) against the quadratics.
        tetrahedron_rule(k, points, weights);
        for (unsigned int q = 0; q < points.size(); ++q)
          {
            monomial_values(points[q], monomials, values.data());
            targets.push_back(target(points[q]));
            const SymmetricTensor<2, 3> s    = targets.back();
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
  HexahedronEquilibration::distance(
    const Vector<double>                     &x,
    const std::vector<SymmetricTensor<2, 3>> &targets) const
  {
    unsigned int          point = 0;
    std::vector<Point<3>> points;
    std::vector<double>   weights;
    double                sum = 0;
    for (unsigned int k = 0; k < n_tetrahedra; ++k)
      {
        tetrahedron_rule(k, points, weights);
        for (unsigned int q = 0; q < points.size(); ++q)
          {
            const SymmetricTensor<2, 3> d =
              stress(x, k, points[q]) - targets[point++];
            const double v[6] = {
              d[0][0], d[1][1], d[2][2], d[0][1], d[0][2], d[1][2]};
            for (unsigned int a = 0; a < 6; ++a)
              for (unsigned int b = 0; b < 6; ++b)
                sum += weights[q] * v[a] * S(a, b) * v[b];
          }
      }
    return sum;
  }

  std::vector<long long>
  HexahedronEquilibration::shape_key(const std::array<Point<3>, 8> &v)
  {
    const double           h = v[0].distance(v[7]);
    std::vector<long long> key;
    for (unsigned int i = 1; i < 8; ++i)
      for (unsigned int d = 0; d < 3; ++d)
        key.push_back(std::llround((v[i][d] - v[0][d]) / h * 1e10));
    return key;
  }

  void
  HexahedronEquilibration::data(const std::array<Point<3>, 8> &vertices,
                                const Traction                &traction,
                                const VectorField             &body_force,
                                const StressField             &target,
                                CellData                      &cell)
  {
    set_cell(vertices);
    const Geometry &G  = geometry;
    auto            it = shapes.find(shape_key(vertices));
    if (it == shapes.end())
      {
        FullMatrix<double> A, H;
        constraints(traction, body_force, &A, cell.c0);
        energy(target, &H, cell.g0, cell.targets);
        // Each tetrahedron's own rows: its equilibrium, its outer
        // triangle's traction (constraints()' order).
        it = shapes
               .emplace(shape_key(vertices),
                        ShapeFactors(std::move(A),
                                     H,
                                     G.h,
                                     BlockNullSpace::own_rows(n_tetrahedra,
                                                              3 * lower.size(),
                                                              3 * 6)))
               .first;
      }
    else
      {
        constraints(traction, body_force, nullptr, cell.c0);
        energy(target, nullptr, cell.g0, cell.targets);
      }
    ShapeFactors &shape = it->second;
    rank                = shape.rank();
    n_unknowns          = shape.n_unknowns();
    // A similar cell of size h: A scales as (h / h_0)^2, the energy as
    // (h / h_0)^3 (the unknowns are stresses).
    cell.shape = &shape;
    cell.s     = G.h / shape.h;
    cell.c0 /= cell.s * cell.s;
    cell.g0 /= cell.s * cell.s * cell.s;
  }

  void
  HexahedronEquilibration::solve(const std::vector<const CellData *> &batch,
                                 std::vector<Vector<double>>         &x,
                                 std::vector<double>                 &residuals,
                                 std::vector<Vector<double>>         *defects)
  {
    x.resize(batch.size());
    if (defects)
      defects->resize(batch.size());
    residuals.assign(batch.size(), 0.);
    std::vector<bool> done(batch.size(), false);
    for (unsigned int first = 0; first < batch.size(); ++first)
      if (!done[first])
        {
          // This shape's cells, as columns.
          ShapeFactors &shape = *const_cast<ShapeFactors *>(
            static_cast<const ShapeFactors *>(batch[first]->shape));
          std::vector<unsigned int> cells;
          for (unsigned int i = first; i < batch.size(); ++i)
            if (batch[i]->shape == batch[first]->shape)
              {
                cells.push_back(i);
                done[i] = true;
              }
          const int m = batch[first]->c0.size(), n = shape.n_unknowns(),
                    k = cells.size();
          std::vector<double> G(n * k), C(m * k), X, defect, D;
          for (int j = 0; j < k; ++j)
            {
              const CellData &cell = *batch[cells[j]];
              std::copy(cell.g0.begin(), cell.g0.end(), G.begin() + j * n);
              std::copy(cell.c0.begin(), cell.c0.end(), C.begin() + j * m);
            }
          shape.solve(G, C, k, X, defect, defects ? &D : nullptr);
          // Back in each cell's units (A = s^2 A_0).
          for (int j = 0; j < k; ++j)
            {
              const double s = batch[cells[j]]->s;
              x[cells[j]].reinit(n);
              std::copy(X.begin() + j * n,
                        X.begin() + (j + 1) * n,
                        x[cells[j]].begin());
              residuals[cells[j]] = s * s * defect[j];
              if (defects)
                {
                  (*defects)[cells[j]] =
                    Vector<double>(D.begin() + j * m, D.begin() + (j + 1) * m);
                  (*defects)[cells[j]] *= s * s;
                }
            }
        }
  }

  double
  HexahedronEquilibration::solve(const std::array<Point<3>, 8> &vertices,
                                 const Traction                &traction,
                                 const VectorField             &body_force,
                                 const StressField             &target,
                                 Vector<double>                &x)
  {
    CellData cell;
    data(vertices, traction, body_force, target, cell);
    std::vector<Vector<double>> xs;
    std::vector<double>         residuals;
    solve({&cell}, xs, residuals);
    x        = xs[0];
    residual = residuals[0];
    return distance(x, cell.targets);
  }
} // namespace hrcontact
