#include <deal.II/base/geometry_info.h>
#include <deal.II/base/quadrature_lib.h>

#include <hrcontact/adaptivity/hexahedron_equilibration.h>
#include <hrcontact/adaptivity/hexahedron_shape_map.h>
#include <hrcontact/core/blas_lapack.h>

#include <cmath>

namespace hrcontact
{
  using namespace dealii;

  namespace
  {
    /** deal.II's Gauss rules on [0, 1]: 3 points on a face, 2 in the cell
     * (the vertex problems' rules). */
    const QGauss<1> &
    gauss(const unsigned int n)
    {
      static const QGauss<1> two(2), three(3);
      return n == 2 ? two : three;
    }

    /** The P2 basis of a face at (a, b), centred. */
    std::array<double, 6>
    face_basis(const double a, const double b)
    {
      const double x = a - 0.5, y = b - 0.5;
      return {{1, x, y, x * x, x * y, y * y}};
    }

    /** The L2 projection on P2 from the values at the 3 x 3 points
     * (a fastest): 6 x 9. */
    const FullMatrix<double> &
    face_projection()
    {
      static const FullMatrix<double> P = [] {
        FullMatrix<double> mass(6, 6), B(6, 9), inverse(6, 6), P(6, 9);
        for (unsigned int j = 0; j < 3; ++j)
          for (unsigned int i = 0; i < 3; ++i)
            {
              const QGauss<1> &g = gauss(3);
              const auto       q = face_basis(g.point(i)[0], g.point(j)[0]);
              const double     w = g.weight(i) * g.weight(j);
              for (unsigned int r = 0; r < 6; ++r)
                {
                  B(r, 3 * j + i) = w * q[r];
                  for (unsigned int c = 0; c < 6; ++c)
                    mass(r, c) += w * q[r] * q[c];
                }
            }
        inverse.invert(mass);
        inverse.mmult(P, B);
        return P;
      }();
      return P;
    }

    /** The frame of a parallelepiped: v0 and the inverse of its edges. */
    struct Frame
    {
      Point<3>     v0;
      Tensor<2, 3> J_inv;
      explicit Frame(const std::array<Point<3>, 8> &v)
        : v0(v[0])
      {
        Tensor<2, 3> J;
        for (unsigned int d = 0; d < 3; ++d)
          for (unsigned int i = 0; i < 3; ++i)
            J[i][d] = v[1u << d][i] - v0[i];
        J_inv = invert(J);
      }
      Tensor<1, 3>
      unit(const Point<3> &x) const
      {
        return J_inv * (x - v0);
      }
    };

    /** The coordinates (a, b) of @p x on face @p f of the cell. */
    std::array<double, 2>
    face_coordinates(const std::array<Point<3>, 8> &v,
                     const unsigned int             f,
                     const Point<3>                &x)
    {
      const Point<3>     p0 = v[GeometryInfo<3>::face_to_cell_vertices(f, 0)];
      const Tensor<1, 3> d1 =
        v[GeometryInfo<3>::face_to_cell_vertices(f, 1)] - p0;
      const Tensor<1, 3> d2 =
        v[GeometryInfo<3>::face_to_cell_vertices(f, 2)] - p0;
      const Tensor<1, 3> y   = x - p0;
      const double       a11 = d1 * d1, a12 = d1 * d2, a22 = d2 * d2;
      const double       det = a11 * a22 - a12 * a12;
      return {{(a22 * (y * d1) - a12 * (y * d2)) / det,
               (a11 * (y * d2) - a12 * (y * d1)) / det}};
    }

    /** The triangular factor of W (m x n, column-major; overwritten) by
     * QR with column pivoting: |W d| = |R P^T d|. */
    void
    triangular_factor(std::vector<double> &W,
                      const int            m,
                      const int            n,
                      std::vector<double> &R,
                      std::vector<int>    &pivots)
    {
      pivots.assign(n, 0);
      std::vector<double> tau(std::min(m, n));
      int                 lwork = -1, info = 0;
      double              size = 0;
      dgeqp3_(
        &m, &n, W.data(), &m, pivots.data(), tau.data(), &size, &lwork, &info);
      lwork = static_cast<int>(size);
      std::vector<double> work(lwork);
      dgeqp3_(&m,
              &n,
              W.data(),
              &m,
              pivots.data(),
              tau.data(),
              work.data(),
              &lwork,
              &info);
      AssertThrow(info == 0, ExcInternalError("dgeqp3 failed"));
      R.assign(std::size_t(n) * n, 0.);
      for (int j = 0; j < n; ++j)
        for (int i = 0; i <= std::min(j, m - 1); ++i)
          R[std::size_t(j) * n + i] = W[std::size_t(j) * m + i];
    }

    /** |R P^T d|^2. */
    double
    factor_norm_squared(const std::vector<double> &R,
                        const std::vector<int>    &pivots,
                        const double              *d)
    {
      const int           n = pivots.size(), one = 1;
      std::vector<double> y(n);
      for (int i = 0; i < n; ++i)
        y[i] = d[pivots[i] - 1];
      dtrmv_("U", "N", "N", &n, R.data(), &n, y.data(), &one);
      double sum = 0;
      for (const double v : y)
        sum += v * v;
      return sum;
    }
    SymmetricTensor<2, 3>
    to_tensor(const std::array<double, 6> &s)
    {
      SymmetricTensor<2, 3> t;
      t[0][0] = s[0];
      t[1][1] = s[1];
      t[2][2] = s[2];
      t[0][1] = s[3];
      t[0][2] = s[4];
      t[1][2] = s[5];
      return t;
    }
  } // namespace

  /** C eps(phi_v e_c) at x on a parallelepiped: the target of the data
   * column j = 3 v + c, on (xx, yy, zz, xy, xz, yz). */
  struct HexahedronShapeMap::UnitStrainStress
  {
    Frame              frame;
    FullMatrix<double> C;
    UnitStrainStress(const std::array<Point<3>, 8> &v,
                     const FullMatrix<double>      &S)
      : frame(v)
      , C(6, 6)
    {
      C.invert(S);
    }
    std::array<double, 6>
    operator()(const unsigned int j, const Point<3> &x) const
    {
      Tensor<1, 3> g;
      HexahedronShapeMap::hat(j / 3, frame.unit(x), g);
      const Tensor<1, 3> grad = transpose(frame.J_inv) * g;
      // eps of u = phi e_c, engineering shears.
      const unsigned int c          = j % 3;
      double             e[6]       = {0, 0, 0, 0, 0, 0};
      const unsigned int pair[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};
      for (unsigned int i = 0; i < 3; ++i)
        e[pair[c][i]] = grad[i];
      std::array<double, 6> s{};
      for (unsigned int a = 0; a < 6; ++a)
        for (unsigned int b = 0; b < 6; ++b)
          s[a] += C(a, b) * e[b];
      return s;
    }
  };

  double
  HexahedronShapeMap::hat(const unsigned int  v,
                          const Tensor<1, 3> &xi,
                          Tensor<1, 3>       &gradient)
  {
    double f[3], df[3];
    for (unsigned int d = 0; d < 3; ++d)
      {
        const bool upper = (v >> d) & 1u;
        f[d]             = upper ? xi[d] : 1 - xi[d];
        df[d]            = upper ? 1 : -1;
      }
    gradient[0] = df[0] * f[1] * f[2];
    gradient[1] = f[0] * df[1] * f[2];
    gradient[2] = f[0] * f[1] * df[2];
    return f[0] * f[1] * f[2];
  }

  std::array<Point<3>, 9>
  HexahedronShapeMap::face_points(const std::array<Point<3>, 8> &v,
                                  const unsigned int             f)
  {
    const Point<3>     p0 = v[GeometryInfo<3>::face_to_cell_vertices(f, 0)];
    const Tensor<1, 3> d1 =
      v[GeometryInfo<3>::face_to_cell_vertices(f, 1)] - p0;
    const Tensor<1, 3> d2 =
      v[GeometryInfo<3>::face_to_cell_vertices(f, 2)] - p0;
    std::array<Point<3>, 9> points;
    for (unsigned int j = 0; j < 3; ++j)
      for (unsigned int i = 0; i < 3; ++i)
        points[3 * j + i] =
          p0 + gauss(3).point(i)[0] * d1 + gauss(3).point(j)[0] * d2;
    return points;
  }

  void
  HexahedronShapeMap::project_traction(
    const std::array<Tensor<1, 3>, 9> &values,
    const unsigned int                 f,
    double                            *d)
  {
    const FullMatrix<double> &P = face_projection();
    for (unsigned int c = 0; c < 3; ++c)
      for (unsigned int b = 0; b < 6; ++b)
        {
          double sum = 0;
          for (unsigned int q = 0; q < 9; ++q)
            sum += P(b, q) * values[q][c];
          d[traction_index(f, c, b)] = sum;
        }
  }

  std::array<Point<3>, 8>
  HexahedronShapeMap::cell_points(const std::array<Point<3>, 8> &v)
  {
    std::array<Point<3>, 8> points;
    for (unsigned int q = 0; q < 8; ++q)
      {
        points[q] = v[0];
        for (unsigned int d = 0; d < 3; ++d)
          points[q] += gauss(2).point((q >> d) & 1u)[0] * (v[1u << d] - v[0]);
      }
    return points;
  }

  void
  HexahedronShapeMap::project_body_force(
    const std::array<Tensor<1, 3>, 8> &values,
    const double                       scale,
    double                            *d)
  {
    // The basis 1, xi_d - 1/2 is orthogonal on the rule (its mass matrix
    // 1, 1/12, 1/12, 1/12 times the volume; the weights 1/8).
    for (unsigned int c = 0; c < 3; ++c)
      {
        double m[4] = {0, 0, 0, 0};
        for (unsigned int q = 0; q < 8; ++q)
          {
            m[0] += values[q][c] / 8;
            for (unsigned int dir = 0; dir < 3; ++dir)
              m[1 + dir] += 12. / 8 *
                            (gauss(2).point((q >> dir) & 1u)[0] - 0.5) *
                            values[q][c];
          }
        for (unsigned int l = 0; l < 4; ++l)
          d[force_index(c, l)] = scale * m[l];
      }
  }

  HexahedronShapeMap::HexahedronShapeMap(HexahedronEquilibration       &eq,
                                         const std::array<Point<3>, 8> &v,
                                         const FullMatrix<double>      &S)
    : h(v[0].distance(v[7]))
  {
    const UnitStrainStress      elastic_stress(v, S);
    std::vector<Vector<double>> X, defects;
    solve_columns(eq, v, elastic_stress, X, defects);
    M.resize(n_unknowns * n_data);
    for (unsigned int j = 0; j < n_data; ++j)
      std::copy(X[j].begin(), X[j].end(), M.begin() + j * n_unknowns);
    factor_residual(eq, S, elastic_stress, X);
    // sigma_h's energy: trilinear times trilinear, exact on the 2 x 2 x 2
    // Gauss rule (the Jacobian is constant).
    G.reinit(48, 48);
    const double volume =
      std::abs(determinant(invert(elastic_stress.frame.J_inv)));
    for (const Point<3> &x : cell_points(v))
      {
        double       N[8];
        Tensor<1, 3> g;
        for (unsigned int a = 0; a < 8; ++a)
          N[a] = hat(a, elastic_stress.frame.unit(x), g);
        for (unsigned int a = 0; a < 8; ++a)
          for (unsigned int b = 0; b < 8; ++b)
            for (unsigned int i = 0; i < 6; ++i)
              for (unsigned int j = 0; j < 6; ++j)
                G(6 * a + i, 6 * b + j) += volume / 8 * N[a] * N[b] * S(i, j);
      }
    const int n = n_data;
    // The constraints' defect A M - c(d) as a linear map of d: data that
    // no balanced cell has (a single column) is not met, so its norm is
    // taken of d as a whole.
    std::vector<double> D(std::size_t(n_rows) * n);
    for (int j = 0; j < n; ++j)
      std::copy(defects[j].begin(),
                defects[j].end(),
                D.begin() + std::size_t(j) * n_rows);
    triangular_factor(D, n_rows, n, R_defect, pivots_defect);
  }

  void
  HexahedronShapeMap::solve_columns(HexahedronEquilibration       &eq,
                                    const std::array<Point<3>, 8> &v,
                                    const UnitStrainStress      &elastic_stress,
                                    std::vector<Vector<double>> &X,
                                    std::vector<Vector<double>> &defects)
  {
    const Frame &frame = elastic_stress.frame;
    // Each data column's problem: the shape's only solves.
    std::vector<HexahedronEquilibration::CellData>         data(n_data);
    std::vector<const HexahedronEquilibration::CellData *> batch;
    for (unsigned int j = 0; j < n_data; ++j)
      {
        HexahedronEquilibration::Traction    traction;
        HexahedronEquilibration::VectorField force;
        HexahedronEquilibration::StressField target;
        if (j < 24)
          {
            traction = [](unsigned int, const Point<3> &) {
              return Tensor<1, 3>();
            };
            target = [&, j](const Point<3> &x) {
              return to_tensor(elastic_stress(j, x));
            };
          }
        else
          {
            target = [](const Point<3> &) { return SymmetricTensor<2, 3>(); };
            if (j < force_index(0, 0))
              {
                const unsigned int f = (j - 24) / 18, c = (j - 24) % 18 / 6,
                                   b = (j - 24) % 6;
                traction             = [&, f, c, b](const unsigned int face,
                                        const Point<3>    &x) {
                  Tensor<1, 3> t;
                  if (face == f)
                    {
                      const auto [a, bb] = face_coordinates(v, f, x);
                      t[c]               = face_basis(a, bb)[b];
                    }
                  return t;
                };
              }
            else
              {
                const unsigned int c = (j - force_index(0, 0)) / 4,
                                   l = (j - force_index(0, 0)) % 4;
                traction             = [](unsigned int, const Point<3> &) {
                  return Tensor<1, 3>();
                };
                force = [&, c, l](const Point<3> &x) {
                  Tensor<1, 3> f;
                  f[c] = l == 0 ? 1. : frame.unit(x)[l - 1] - 0.5;
                  return f;
                };
              }
          }
        eq.data(v, traction, force, target, data[j]);
        AssertThrow(std::abs(data[j].s - 1) < 1e-12,
                    ExcInternalError("the shape map is made on the shape's "
                                     "first cell"));
        batch.push_back(&data[j]);
      }
    rank       = eq.rank;
    n_rows     = data[0].c0.size();
    n_unknowns = eq.n_unknowns;
    std::vector<double> residuals;
    eq.solve(batch, X, residuals, &defects);
  }

  void
  HexahedronShapeMap::factor_residual(HexahedronEquilibration  &eq,
                                      const FullMatrix<double> &S,
                                      const UnitStrainStress   &elastic_stress,
                                      const std::vector<Vector<double>> &X)
  {
    // The residual tau - C eps(u_h) at the rule's points, weighted (S = L
    // L^T, w |L^T r|^2), and its QR factor.
    FullMatrix<double> L(6, 6);
    L.cholesky(S);
    std::vector<Point<3>> points;
    std::vector<double>   weights;
    unsigned int          n_points = 0;
    for (unsigned int k = 0; k < HexahedronEquilibration::n_tetrahedra; ++k)
      {
        eq.tetrahedron_rule(k, points, weights);
        n_points += points.size();
      }
    const int           m = 6 * n_points, n = n_data;
    std::vector<double> W(std::size_t(m) * n, 0.);
    unsigned int        row = 0;
    for (unsigned int k = 0; k < HexahedronEquilibration::n_tetrahedra; ++k)
      {
        eq.tetrahedron_rule(k, points, weights);
        for (unsigned int q = 0; q < points.size(); ++q, row += 6)
          {
            const double sqrt_w = std::sqrt(weights[q]);
            for (unsigned int j = 0; j < n_data; ++j)
              {
                const SymmetricTensor<2, 3> tau = eq.stress(X[j], k, points[q]);
                std::array<double, 6>       r{{tau[0][0],
                                               tau[1][1],
                                               tau[2][2],
                                               tau[0][1],
                                               tau[0][2],
                                               tau[1][2]}};
                if (j < 24)
                  {
                    const auto target = elastic_stress(j, points[q]);
                    for (unsigned int a = 0; a < 6; ++a)
                      r[a] -= target[a];
                  }
                for (unsigned int a = 0; a < 6; ++a)
                  {
                    double y = 0;
                    for (unsigned int b = a; b < 6; ++b)
                      y += L(b, a) * r[b];
                    W[std::size_t(j) * m + row + a] = sqrt_w * y;
                  }
              }
          }
      }
    triangular_factor(W, m, n, R, pivots);
  }

  double
  HexahedronShapeMap::bound_squared(const double *d) const
  {
    return factor_norm_squared(R, pivots, d);
  }

  double
  HexahedronShapeMap::stress_energy(const std::array<double, 48> &s) const
  {
    double sum = 0;
    for (unsigned int a = 0; a < 48; ++a)
      {
        double row = 0;
        for (unsigned int b = 0; b < 48; ++b)
          row += G(a, b) * s[b];
        sum += s[a] * row;
      }
    return sum;
  }

  double
  HexahedronShapeMap::defect(const double *d) const
  {
    return std::sqrt(factor_norm_squared(R_defect, pivots_defect, d));
  }

  void
  HexahedronShapeMap::coefficients(const double *d, Vector<double> &x) const
  {
    x.reinit(n_unknowns);
    const int    m = n_unknowns, n = n_data, one = 1;
    const double plus = 1, zero = 0;
    dgemv_("N", &m, &n, &plus, M.data(), &m, d, &one, &zero, x.begin(), &one);
  }
} // namespace hrcontact
