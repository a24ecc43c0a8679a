// HexahedronEquilibration, the error bound's 3D cell problem (24
// tetrahedra, symmetric quadratic stresses): on a cube and on a sheared,
// stretched parallelepiped,
// - random bilinear tractions on the six faces with a linear body force
//   that balances them in force and moment must be met exactly (the split
//   is what makes an admissible field exist): A x - c <= 1e-11 (data of
//   order one);
// - the tractions and body force of a random quadratic stress field must
//   give that field back (the bound against it 0 to round-off);
// - a translated and scaled copy reuses the factors and gives the scaled
//   answer;
// - the shape's map (HexahedronShapeMap, made on the first cell) must give
//   on the translated and scaled copies, from the data (u_h at the
//   vertices, the tractions at the face points, the body force at the cell
//   points), the bound and tau of the direct solve with the target C
//   eps(u_h) of a random trilinear u_h to 1e-10 (tau's coefficients to
//   1e-6: both are the triangular solve of R_11, whose conditioning
//   amplifies round-off to 5e-8 on the sheared cell), a defect of the
//   constraints below 1e-11, and the energy of a random trilinear stress
//   as a 3 x 3 x 3 Gauss rule integrates it to 1e-12.

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <hrcontact/adaptivity/hexahedron_equilibration.h>
#include <hrcontact/adaptivity/hexahedron_shape_map.h>

#include <iostream>
#include <random>

#include "tests.h"

using namespace dealii;

/** A parallelepiped v0 + J xi, xi in [0, 1]^3, with deal.II's vertex order. */
std::array<Point<3>, 8>
parallelepiped(const Point<3> &v0, const Tensor<2, 3> &J)
{
  std::array<Point<3>, 8> v;
  for (unsigned int i = 0; i < 8; ++i)
    {
      const Tensor<1, 3> xi(
        {double(i % 2), double((i / 2) % 2), double(i / 4)});
      v[i] = v0 + J * xi;
    }
  return v;
}

FullMatrix<double>
isotropic_compliance(const double E, const double nu)
{
  FullMatrix<double> S(6, 6);
  for (unsigned int a = 0; a < 3; ++a)
    {
      for (unsigned int b = 0; b < 3; ++b)
        S(a, b) = (a == b ? 1. : -nu) / E;
      S(a + 3, a + 3) = 2 * (1 + nu) / E;
    }
  return S;
}

void
balanced_data(const std::array<Point<3>, 8> &v,
              const Tensor<2, 3>            &J,
              std::mt19937                  &random)
{
  std::uniform_real_distribution<double> uniform(-1., 1.);
  const Tensor<2, 3>                     J_inv = invert(J);
  const Point<3>                         v0    = v[0];
  // t_f = T_f0 + T_f1 a + T_f2 b + T_f3 a b, (a, b) the face's reference
  // coordinates; f = f0 + F1 (x - v0), then corrected by a rigid-body
  // field a + b x (x - x_c) so that everything balances.
  std::array<std::array<Tensor<1, 3>, 4>, 6> T;
  for (auto &face : T)
    for (auto &t : face)
      for (unsigned int i = 0; i < 3; ++i)
        t[i] = uniform(random);
  Tensor<1, 3> f0;
  Tensor<2, 3> F1;
  for (unsigned int i = 0; i < 3; ++i)
    {
      f0[i] = uniform(random);
      for (unsigned int j = 0; j < 3; ++j)
        F1[i][j] = uniform(random);
    }
  const auto traction = [&](const unsigned int f, const Point<3> &x) {
    const Tensor<1, 3> xi = J_inv * (x - v0);
    const unsigned int d = f / 2, p = (d + 1) % 3, q = (d + 2) % 3;
    const double       a = xi[std::min(p, q)], b = xi[std::max(p, q)];
    return Tensor<1, 3>(T[f][0] + a * T[f][1] + b * T[f][2] + a * b * T[f][3]);
  };
  // Net force and moment about the centre, by Gauss rules on the
  // parallelepiped and its faces.
  Point<3> x_c;
  for (const auto &p : v)
    x_c += p / 8.;
  const double    volume = std::abs(determinant(J));
  const QGauss<3> cell_rule(3);
  const QGauss<2> face_rule(3);
  Tensor<1, 3>    force, moment;
  Tensor<2, 3>    inertia;
  for (unsigned int q = 0; q < cell_rule.size(); ++q)
    {
      const Point<3>     x = v0 + J * Tensor<1, 3>(cell_rule.point(q));
      const double       w = cell_rule.weight(q) * volume;
      const Tensor<1, 3> r = x - x_c, f = f0 + F1 * (x - v0);
      force += w * f;
      moment += w * cross_product_3d(r, f);
      // int r x (b x r) = (|r|^2 I - r r) b.
      inertia +=
        w * ((r * r) * unit_symmetric_tensor<3>() - outer_product(r, r));
    }
  for (unsigned int f = 0; f < 6; ++f)
    {
      const unsigned int d = f / 2, p = std::min((d + 1) % 3, (d + 2) % 3),
                         q2 = std::max((d + 1) % 3, (d + 2) % 3);
      const Tensor<1, 3> ep = J * Tensor<1, 3>(Point<3>::unit_vector(p)),
                         eq = J * Tensor<1, 3>(Point<3>::unit_vector(q2));
      const double area     = cross_product_3d(ep, eq).norm();
      for (unsigned int k = 0; k < face_rule.size(); ++k)
        {
          Tensor<1, 3> xi;
          xi[d]                = f % 2;
          xi[p]                = face_rule.point(k)[0];
          xi[q2]               = face_rule.point(k)[1];
          const Point<3>     x = v0 + J * xi;
          const Tensor<1, 3> t = traction(f, x);
          force += face_rule.weight(k) * area * t;
          moment += face_rule.weight(k) * area * cross_product_3d(x - x_c, t);
        }
    }
  const Tensor<1, 3> a          = -force / volume;
  const Tensor<1, 3> b          = -(invert(inertia) * moment);
  const auto         body_force = [&](const Point<3> &x) {
    return Tensor<1, 3>(f0 + F1 * (x - v0) + a + cross_product_3d(b, x - x_c));
  };
  const auto target = [](const Point<3> &) { return SymmetricTensor<2, 3>(); };
  hrcontact::HexahedronEquilibration cell(isotropic_compliance(1., 0.3));
  Vector<double>                     x;
  cell.solve(v, traction, body_force, target, x);
  std::cout << "  balanced bilinear tractions, linear body force: "
            << cell.n_rows << " rows, " << cell.n_unknowns << " unknowns, rank "
            << cell.rank
            << "; met (1e-11): " << hrcontact_tests::check(cell.residual, 1e-11)
            << std::endl;
}

/** The map of the shape on the cell @p w of size @p s times the map's,
 * against the direct solve, for the data @p traction and @p body_force
 * and a random trilinear u_h. */
void
compare_with_map(const hrcontact::HexahedronShapeMap                &map,
                 const std::array<Point<3>, 8>                      &w,
                 const double                                        s,
                 const hrcontact::HexahedronEquilibration::Traction &traction,
                 const hrcontact::HexahedronEquilibration::VectorField &force,
                 std::mt19937                                          &random)
{
  using Map = hrcontact::HexahedronShapeMap;
  std::uniform_real_distribution<double> uniform(-1., 1.);
  const FullMatrix<double>               S = isotropic_compliance(1., 0.3);
  FullMatrix<double>                     C(6, 6);
  C.invert(S);
  Tensor<2, 3> J;
  for (unsigned int d = 0; d < 3; ++d)
    for (unsigned int i = 0; i < 3; ++i)
      J[i][d] = w[1u << d][i] - w[0][i];
  const Tensor<2, 3>          J_inv = invert(J);
  std::array<Tensor<1, 3>, 8> u;
  for (auto &uv : u)
    for (unsigned int i = 0; i < 3; ++i)
      uv[i] = 1e-3 * uniform(random);
  const auto target = [&](const Point<3> &x) {
    Tensor<2, 3> grad;
    for (unsigned int a = 0; a < 8; ++a)
      {
        Tensor<1, 3> g;
        Map::hat(a, J_inv * (x - w[0]), g);
        grad += outer_product(u[a], transpose(J_inv) * g);
      }
    const SymmetricTensor<2, 3> e     = symmetrize(grad);
    const double                ev[6] = {
                     e[0][0], e[1][1], e[2][2], 2 * e[0][1], 2 * e[0][2], 2 * e[1][2]};
    double c[6] = {0, 0, 0, 0, 0, 0};
    for (unsigned int a = 0; a < 6; ++a)
      for (unsigned int b = 0; b < 6; ++b)
        c[a] += C(a, b) * ev[b];
    SymmetricTensor<2, 3> sigma;
    sigma[0][0] = c[0];
    sigma[1][1] = c[1];
    sigma[2][2] = c[2];
    sigma[0][1] = c[3];
    sigma[0][2] = c[4];
    sigma[1][2] = c[5];
    return sigma;
  };
  hrcontact::HexahedronEquilibration direct(S);
  Vector<double>                     x_direct, x_map;
  const double eta_direct = direct.solve(w, traction, force, target, x_direct);
  std::vector<double> d(Map::n_data, 0.);
  for (unsigned int a = 0; a < 8; ++a)
    for (unsigned int i = 0; i < 3; ++i)
      d[Map::u_index(a, i)] = u[a][i] / s;
  for (unsigned int f = 0; f < 6; ++f)
    {
      const auto                  points = Map::face_points(w, f);
      std::array<Tensor<1, 3>, 9> t;
      for (unsigned int q = 0; q < 9; ++q)
        t[q] = traction(f, points[q]);
      Map::project_traction(t, f, d.data());
    }
  const auto                  points = Map::cell_points(w);
  std::array<Tensor<1, 3>, 8> f;
  for (unsigned int q = 0; q < 8; ++q)
    f[q] = force(points[q]);
  Map::project_body_force(f, s, d.data());
  const double eta_map = s * s * s * map.bound_squared(d.data());
  map.coefficients(d.data(), x_map);
  x_map -= x_direct;
  // A random trilinear stress: its energy by the map and by a Gauss rule.
  std::array<double, 48> sv;
  for (double &a : sv)
    a = uniform(random);
  const QGauss<3> rule(3);
  double          energy = 0;
  for (unsigned int q = 0; q < rule.size(); ++q)
    {
      const Tensor<1, 3> xi(rule.point(q));
      double             sigma[6] = {0, 0, 0, 0, 0, 0};
      for (unsigned int a = 0; a < 8; ++a)
        {
          Tensor<1, 3> g;
          const double N = Map::hat(a, xi, g);
          for (unsigned int i = 0; i < 6; ++i)
            sigma[i] += N * sv[6 * a + i];
        }
      for (unsigned int i = 0; i < 6; ++i)
        for (unsigned int j = 0; j < 6; ++j)
          energy += rule.weight(q) * std::abs(determinant(J)) * sigma[i] *
                    S(i, j) * sigma[j];
    }
  const double energy_map = s * s * s * map.stress_energy(sv);
  const double h          = w[0].distance(w[7]);
  std::cout
    << "    the shape's map: the direct bound (1e-10): "
    << hrcontact_tests::check(std::abs(eta_map - eta_direct) / eta_direct,
                              1e-10)
    << ", tau (1e-6): "
    << hrcontact_tests::check(x_map.linfty_norm() / x_direct.linfty_norm(),
                              1e-6)
    << ", defect (1e-11): "
    << hrcontact_tests::check(s * s * map.defect(d.data()) / (h * h), 1e-11)
    << ", trilinear energy (1e-12): "
    << hrcontact_tests::check(std::abs(energy_map - energy) / energy, 1e-12)
    << std::endl;
}

void
exact_field(const std::array<Point<3>, 8>       &v,
            const double                         scale,
            const Tensor<1, 3>                  &shift,
            std::mt19937                        &random,
            const hrcontact::HexahedronShapeMap &map)
{
  std::uniform_real_distribution<double> uniform(-1., 1.);
  // sigma_ij = sum over the ten quadratic monomials of (x, y, z).
  std::array<std::array<double, 10>, 6> coefficient;
  for (auto &c : coefficient)
    for (auto &a : c)
      a = uniform(random);
  const auto basis = [](const Point<3>               &x,
                        std::array<double, 10>       &m,
                        std::array<Tensor<1, 3>, 10> &g) {
    m = {{1,
          x[0],
          x[1],
          x[2],
          x[0] * x[0],
          x[0] * x[1],
          x[0] * x[2],
          x[1] * x[1],
          x[1] * x[2],
          x[2] * x[2]}};
    g = {{Tensor<1, 3>(),
          Tensor<1, 3>({1, 0, 0}),
          Tensor<1, 3>({0, 1, 0}),
          Tensor<1, 3>({0, 0, 1}),
          Tensor<1, 3>({2 * x[0], 0, 0}),
          Tensor<1, 3>({x[1], x[0], 0}),
          Tensor<1, 3>({x[2], 0, x[0]}),
          Tensor<1, 3>({0, 2 * x[1], 0}),
          Tensor<1, 3>({0, x[2], x[1]}),
          Tensor<1, 3>({0, 0, 2 * x[2]})}};
  };
  const unsigned int comp[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};
  const auto         sigma      = [&](const Point<3> &x) {
    std::array<double, 10>       m;
    std::array<Tensor<1, 3>, 10> g;
    basis(x, m, g);
    SymmetricTensor<2, 3> s;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = i; j < 3; ++j)
        for (unsigned int k = 0; k < 10; ++k)
          s[i][j] += coefficient[comp[i][j]][k] * m[k];
    return s;
  };
  const auto body_force = [&](const Point<3> &x) {
    std::array<double, 10>       m;
    std::array<Tensor<1, 3>, 10> g;
    basis(x, m, g);
    Tensor<1, 3> f;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        for (unsigned int k = 0; k < 10; ++k)
          f[i] -= coefficient[comp[i][j]][k] * g[k][j];
    return f;
  };
  std::array<Point<3>, 8> w;
  Point<3>                centre;
  for (unsigned int i = 0; i < 8; ++i)
    {
      w[i] = Point<3>(scale * v[i] + shift);
      centre += w[i] / 8.;
    }
  const auto traction = [&](const unsigned int f, const Point<3> &x) {
    // The outward normal of face f: the face's plane through x, away from
    // the centre.
    const auto  &fv = GeometryInfo<3>::face_to_cell_vertices;
    Tensor<1, 3> n  = cross_product_3d(w[fv(f, 1, true, false, false)] -
                                        w[fv(f, 0, true, false, false)],
                                      w[fv(f, 2, true, false, false)] -
                                        w[fv(f, 0, true, false, false)]);
    if (n * (x - centre) < 0)
      n = -n;
    return Tensor<1, 3>(sigma(x) * (n / n.norm()));
  };
  static hrcontact::HexahedronEquilibration cell(isotropic_compliance(1., 0.3));
  Vector<double>                            x;
  const double bound = cell.solve(w, traction, body_force, sigma, x);
  // The field's own energy on the cell, for scale.
  const auto zero = [](const Point<3> &) { return SymmetricTensor<2, 3>(); };
  Vector<double>                     y;
  hrcontact::HexahedronEquilibration other(isotropic_compliance(1., 0.3));
  const double energy = other.solve(w, traction, body_force, zero, y);
  std::cout << "  a quadratic stress field (scale " << scale
            << "): given back, |tau - sigma|^2 / |sigma|^2 (1e-20): "
            << hrcontact_tests::check(bound / energy, 1e-20)
            << "; constraints met (1e-11): "
            << hrcontact_tests::check(cell.residual, 1e-11) << std::endl;
  compare_with_map(map, w, scale, traction, body_force, random);
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::mt19937                     random(3);
  Tensor<2, 3>                     cube = unit_symmetric_tensor<3>();
  Tensor<2, 3>                     sheared;
  sheared[0][0] = 2.;
  sheared[1][1] = 0.7;
  sheared[2][2] = 1.3;
  sheared[0][1] = 0.4;
  sheared[1][2] = -0.3;
  sheared[0][2] = 0.2;
  for (const auto &[name, J] : {std::make_pair("cube", cube),
                                std::make_pair("parallelepiped", sheared)})
    {
      std::cout << name << ":" << std::endl;
      const auto v = parallelepiped(Point<3>(0.1, -0.2, 0.3), J);
      balanced_data(v, J, random);
      hrcontact::HexahedronEquilibration  eq(isotropic_compliance(1., 0.3));
      const hrcontact::HexahedronShapeMap map(eq,
                                              v,
                                              isotropic_compliance(1., 0.3));
      exact_field(v, 1., Tensor<1, 3>(), random, map);
      exact_field(v, 0.25, Tensor<1, 3>({3., 1., -2.}), random, map);
      exact_field(v, 2.5, Tensor<1, 3>({-1., 0.5, 4.}), random, map);
    }
}
