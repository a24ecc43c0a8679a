// The mortar sums of constraints/mortar.h (Wohlmuth's dual basis, segment
// to segment) on a slave surface and a master surface meshed differently:
//  - 2D: slave segments on y = 0, master segments on a line y = g(x),
//    tilted; 3D: slave parallelograms on z = 0, master quadrilaterals on
//    z = 0.05, both meshes non-matching.
// Biorthogonality (int psi_a N_b = delta_ab int N_a) makes the sums exact
// for linear fields: for each fully covered slave node s and any linear f,
// sum_m M_m f(x_m) = D_s f(x_s), and G_s = D_s g(x_s) for a linear gap;
// sum_s D_s is the covered length (area), and sum_m M_m = D_s (the
// master's partition of unity). A master surface that covers half the
// slave must be reported as covering exactly that.

#include <deal.II/base/mpi.h>

#include <hrcontact/constraints/mortar.h>

#include <cmath>
#include <iostream>

#include "tests.h"

using namespace dealii;
using hrcontact::BoundaryFace;

constexpr unsigned int slave_id = 1, master_id = 2;

/** 2D faces along the x axis between the given abscissae, on y = y(x);
 * nodes numbered from first_node. */
std::vector<BoundaryFace<2>>
line_faces(const std::vector<double>           &xs,
           const std::function<double(double)> &y,
           const unsigned int                   id,
           const unsigned int                   first_node,
           const double                         normal_y,
           std::map<unsigned int, Point<2>>    &node_position)
{
  std::vector<BoundaryFace<2>> faces;
  for (unsigned int i = 0; i + 1 < xs.size(); ++i)
    {
      BoundaryFace<2> f;
      f.boundary_id = id;
      f.nodes       = {first_node + i, first_node + i + 1};
      f.points = {Point<2>(xs[i], y(xs[i])), Point<2>(xs[i + 1], y(xs[i + 1]))};
      const Tensor<1, 2> t = f.points[1] - f.points[0];
      f.normal             = Tensor<1, 2>({-t[1], t[0]}) / t.norm();
      if (f.normal[1] * normal_y < 0)
        f.normal *= -1;
      f.measure = t.norm();
      for (unsigned int a = 0; a < 2; ++a)
        node_position[f.nodes[a]] = f.points[a];
      faces.push_back(f);
    }
  return faces;
}

/** 3D faces of a structured nx x ny grid over [x0, x1] x [y0, y1] at
 * height z, with the given normal's sign; deal.II's vertex order. */
std::vector<BoundaryFace<3>>
plane_faces(const double                      x0,
            const double                      x1,
            const double                      y0,
            const double                      y1,
            const unsigned int                nx,
            const unsigned int                ny,
            const double                      z,
            const unsigned int                id,
            const unsigned int                first_node,
            const double                      normal_z,
            std::map<unsigned int, Point<3>> &node_position)
{
  std::vector<BoundaryFace<3>> faces;
  auto node = [&](const unsigned int i, const unsigned int j) {
    return first_node + j * (nx + 1) + i;
  };
  auto point = [&](const unsigned int i, const unsigned int j) {
    // A slight shear keeps the cells parallelograms but not rectangles.
    const double x = x0 + (x1 - x0) * i / nx, y = y0 + (y1 - y0) * j / ny;
    return Point<3>(x + 0.1 * y, y, z);
  };
  for (unsigned int j = 0; j < ny; ++j)
    for (unsigned int i = 0; i < nx; ++i)
      {
        BoundaryFace<3> f;
        f.boundary_id = id;
        f.nodes       = {node(i, j),
                         node(i + 1, j),
                         node(i, j + 1),
                         node(i + 1, j + 1)};
        f.points      = {point(i, j),
                         point(i + 1, j),
                         point(i, j + 1),
                         point(i + 1, j + 1)};
        f.normal      = Tensor<1, 3>({0, 0, normal_z});
        for (unsigned int a = 0; a < 4; ++a)
          node_position[f.nodes[a]] = f.points[a];
        faces.push_back(f);
      }
  return faces;
}

/** Check the sums of every fully covered slave node against a linear f
 * and the gap function; report the largest errors. */
template <int dim>
void
report(const std::string                                   &name,
       const std::map<unsigned int, hrcontact::MortarSums> &sums,
       const std::map<unsigned int, Point<dim>>            &position,
       const std::function<double(const Point<dim> &)>     &f,
       const std::function<double(const Point<dim> &)>     &f_seen,
       const std::function<double(const Point<dim> &)>     &gap,
       const double                                         expected_covered)
{
  double reproduction = 0, gap_error = 0, unity = 0, total_D = 0, covered = 0;
  unsigned int full = 0;
  for (const auto &[node, S] : sums)
    {
      total_D += S.D;
      covered += S.covered;
      if (S.covered < (1 - 1e-12) * S.length)
        continue;
      ++full;
      double sum_f = 0, sum_M = 0;
      for (const auto &[m, M] : S.M)
        {
          sum_f += M * f(position.at(m));
          sum_M += M;
        }
      const Point<dim> &x = position.at(node);
      reproduction = std::max(reproduction, std::abs(sum_f - S.D * f_seen(x)));
      gap_error    = std::max(gap_error, std::abs(S.G - S.D * gap(x)));
      unity        = std::max(unity, std::abs(sum_M - S.D));
    }
  // Every slave face counts once per node: covered sums each face's cover
  // over its nodes.
  covered /= (dim == 2 ? 2 : 4);
  std::cout
    << name << ": " << full << " of " << sums.size()
    << " slave nodes fully covered"
    << "\n  sum_m M_m f(x_m) = D f(x_s'), f linear, x_s' the slave "
       "node's projection (1e-13): "
    << hrcontact_tests::check(reproduction, 1e-13)
    << "\n  G = D g(x_s) (1e-13): " << hrcontact_tests::check(gap_error, 1e-13)
    << "\n  sum_m M_m = D (1e-13): " << hrcontact_tests::check(unity, 1e-13)
    << "\n  sum_s D_s = covered measure (1e-13): "
    << hrcontact_tests::check(std::abs(total_D - expected_covered), 1e-13)
    << "\n  covered measure as expected (1e-13): "
    << hrcontact_tests::check(std::abs(covered - expected_covered), 1e-13)
    << std::endl;
}

void
test_2d(const double master_end, const std::string &name)
{
  std::map<unsigned int, Point<2>> position;
  // The slave below (normal +y), the master above (normal -y), tilted.
  const auto gap_line = [](const double x) { return 0.02 + 0.01 * x; };
  auto       faces    = line_faces(
    {0, 0.25, 0.5, 0.75, 1.},
    [](double) { return 0.; },
    slave_id,
    0,
    1.,
    position);
  std::vector<double> master_x;
  for (double x = -0.1; x < master_end + 1e-12; x += 0.3)
    master_x.push_back(std::min(x, master_end));
  if (master_x.back() < master_end - 1e-12)
    master_x.push_back(master_end);
  const auto masters_faces =
    line_faces(master_x, gap_line, master_id, 100, -1., position);
  faces.insert(faces.end(), masters_faces.begin(), masters_faces.end());
  std::vector<const BoundaryFace<2> *> masters;
  for (const auto &face : faces)
    if (face.boundary_id == master_id)
      masters.push_back(&face);
  const auto sums = hrcontact::mortar_sums<2>(faces, slave_id, masters, 0.5);
  const auto f = [](const Point<2> &p) { return 1.5 - 2. * p[0] + 0.3 * p[1]; };
  report<2>(
    name,
    sums,
    position,
    f,
    [&](const Point<2> &p) { return f(Point<2>(p[0], gap_line(p[0]))); },
    [&](const Point<2> &p) { return gap_line(p[0]); },
    std::min(1., master_end));
}

void
test_3d()
{
  std::map<unsigned int, Point<3>> position;
  auto faces = plane_faces(0, 1, 0, 1, 4, 3, 0., slave_id, 0, 1., position);
  const auto master_faces = plane_faces(
    -0.2, 1.3, -0.1, 1.1, 3, 5, 0.05, master_id, 1000, -1., position);
  faces.insert(faces.end(), master_faces.begin(), master_faces.end());
  std::vector<const BoundaryFace<3> *> masters;
  for (const auto &face : faces)
    if (face.boundary_id == master_id)
      masters.push_back(&face);
  const auto sums = hrcontact::mortar_sums<3>(faces, slave_id, masters, 0.5);
  const auto f    = [](const Point<3> &p) {
    return 0.7 + 1.3 * p[0] - 0.4 * p[1] + 2. * p[2];
  };
  // The master covers the slave, a sheared unit square (area 1), and lies
  // 0.05 above it.
  report<3>(
    "3D, master covers the slave",
    sums,
    position,
    f,
    [&](const Point<3> &p) { return f(Point<3>(p[0], p[1], 0.05)); },
    [](const Point<3> &) { return 0.05; },
    1.);
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  test_2d(1.3, "2D, master covers the slave");
  test_2d(0.5, "2D, master covers half the slave");
  test_3d();
}
