#include <deal.II/base/quadrature_lib.h>

#include <hrcontact/constraints/mortar.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  void
  face_shape(const std::array<double, dim - 1>        &xi,
             std::vector<double>                      &N,
             std::vector<std::array<double, dim - 1>> &dN)
  {
    if constexpr (dim == 2)
      {
        N  = {1 - xi[0], xi[0]};
        dN = {{{-1.}}, {{1.}}};
      }
    else
      {
        const double a = xi[0], b = xi[1];
        N  = {(1 - a) * (1 - b), a * (1 - b), (1 - a) * b, a * b};
        dN = {{{-(1 - b), -(1 - a)}},
              {{(1 - b), -a}},
              {{-b, (1 - a)}},
              {{b, a}}};
      }
  }

  template <int dim>
  std::array<double, dim - 1>
  closest_point(const std::vector<Point<dim>> &vertices, const Point<dim> &x)
  {
    std::array<double, dim - 1>              xi;
    std::vector<double>                      N;
    std::vector<std::array<double, dim - 1>> dN;
    xi.fill(0.5);
    for (unsigned int it = 0; it < 20; ++it)
      {
        face_shape<dim>(xi, N, dN);
        Point<dim>                          y;
        std::array<Tensor<1, dim>, dim - 1> t;
        for (unsigned int v = 0; v < vertices.size(); ++v)
          {
            y += N[v] * vertices[v];
            for (unsigned int a = 0; a < dim - 1; ++a)
              t[a] += dN[v][a] * vertices[v];
          }
        const Tensor<1, dim> r = x - y;
        // The normal equations (t_a . t_b) dxi_b = t_a . r.
        double step[2] = {0, 0};
        if constexpr (dim == 2)
          step[0] = (t[0] * r) / (t[0] * t[0]);
        else
          {
            const double g11 = t[0] * t[0], g12 = t[0] * t[1],
                         g22 = t[1] * t[1];
            const double b1 = t[0] * r, b2 = t[1] * r;
            const double det = g11 * g22 - g12 * g12;
            step[0]          = (g22 * b1 - g12 * b2) / det;
            step[1]          = (g11 * b2 - g12 * b1) / det;
          }
        double change = 0;
        for (unsigned int a = 0; a < dim - 1; ++a)
          {
            xi[a] += step[a];
            change = std::max(change, std::abs(step[a]));
          }
        if (change < 1e-14)
          break;
      }
    return xi;
  }

  template <int dim>
  MasterPoint<dim>
  closest_master_point(const std::vector<const BoundaryFace<dim> *> &masters,
                       const Point<dim>                             &x,
                       const Tensor<1, dim> &slave_normal,
                       const double          reach)
  {
    MasterPoint<dim> found;
    double           best = std::numeric_limits<double>::max();
    for (const BoundaryFace<dim> *face : masters)
      {
        // Only faces that face the slave node.
        if (!(face->normal * slave_normal < 0))
          continue;
        const auto   xi     = closest_point<dim>(face->points, x);
        const double tol    = 1e-8;
        bool         inside = true;
        for (const double a : xi)
          inside &= (a >= -tol && a <= 1 + tol);
        if (!inside)
          continue;
        std::array<double, dim - 1> clamped;
        for (unsigned int a = 0; a < dim - 1; ++a)
          clamped[a] = std::clamp(xi[a], 0., 1.);
        std::vector<double>                      N;
        std::vector<std::array<double, dim - 1>> dN;
        face_shape<dim>(clamped, N, dN);
        Point<dim> y;
        double     length = 0;
        for (unsigned int v = 0; v < face->points.size(); ++v)
          {
            y += N[v] * face->points[v];
            length = std::max(length,
                              face->points[v].distance(
                                face->points[(v + 1) % face->points.size()]));
          }
        const double distance = x.distance(y);
        if (distance > reach || distance >= best)
          continue;
        best       = distance;
        found.face = face;
        found.N    = N;
        found.gap  = (y - x) * (-face->normal);
        if (found.gap < -1e-8 * length)
          {
            found.overlap = -found.gap;
            return found;
          }
      }
    return found;
  }

  std::vector<PlanePoint>
  clip_convex_polygon(std::vector<PlanePoint>        clipped,
                      const std::vector<PlanePoint> &clip,
                      const double                   tolerance)
  {
    const unsigned int n = clip.size();
    for (unsigned int e = 0; e < n && !clipped.empty(); ++e)
      {
        const PlanePoint a = clip[e], b = clip[(e + 1) % n];
        auto             inside = [&](const PlanePoint &p) {
          return (b[0] - a[0]) * (p[1] - a[1]) -
                   (b[1] - a[1]) * (p[0] - a[0]) >=
                 -tolerance;
        };
        std::vector<PlanePoint> out;
        for (unsigned int i = 0; i < clipped.size(); ++i)
          {
            const PlanePoint &p = clipped[i],
                             &q = clipped[(i + 1) % clipped.size()];
            const bool ip = inside(p), iq = inside(q);
            if (ip)
              out.push_back(p);
            if (ip != iq)
              {
                const double dp =
                  (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
                const double dq =
                  (b[0] - a[0]) * (q[1] - a[1]) - (b[1] - a[1]) * (q[0] - a[0]);
                const double t = dp / (dp - dq);
                out.push_back(
                  {{p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])}});
              }
          }
        clipped = std::move(out);
      }
    return clipped;
  }

  namespace
  {
    std::map<unsigned int, MortarSums>
    mortar_sums_2d(const std::vector<BoundaryFace<2>>         &faces,
                   const types::boundary_id                    slave,
                   const std::vector<const BoundaryFace<2> *> &masters,
                   const double                                reach)
    {
      constexpr int                      dim = 2;
      std::map<unsigned int, MortarSums> sums;
      const QGauss<1>                    gauss(3);
      for (const auto &face : faces)
        {
          if (face.boundary_id != slave)
            continue;
          const Point<2>    &x0 = face.points[0];
          const Tensor<1, 2> t  = face.points[1] - x0;
          const double       L2 = t * t;
          for (unsigned int a = 0; a < 2; ++a)
            sums[face.nodes[a]].length += std::sqrt(L2);
          for (const BoundaryFace<dim> *m : masters)
            {
              if (!(m->normal * face.normal < 0))
                continue;
              const Point<2>    &y0 = m->points[0];
              const Tensor<1, 2> s  = m->points[1] - y0;
              if (std::abs(s * t) < 1e-12 * std::sqrt(L2 * (s * s)))
                continue;
              const double xa = (y0 - x0) * t / L2,
                           xb = (m->points[1] - x0) * t / L2;
              const double lo = std::max(0., std::min(xa, xb)),
                           hi = std::min(1., std::max(xa, xb));
              if (hi - lo <= 1e-12)
                continue;
              // Within reach at the middle of the piece.
              {
                const Point<2> x   = x0 + 0.5 * (lo + hi) * t;
                const double   eta = ((x - y0) * t) / (s * t);
                if (x.distance(y0 + eta * s) > reach)
                  continue;
              }
              for (unsigned int q = 0; q < gauss.size(); ++q)
                {
                  const double xi = lo + (hi - lo) * gauss.point(q)[0];
                  const double w  = gauss.weight(q) * (hi - lo) * std::sqrt(L2);
                  const Point<2> x      = x0 + xi * t;
                  const double   eta    = ((x - y0) * t) / (s * t);
                  const Point<2> y      = y0 + eta * s;
                  const double   g      = (y - x) * face.normal;
                  const double   psi[2] = {2 - 3 * xi, 3 * xi - 1};
                  const double   N[2]   = {1 - eta, eta};
                  for (unsigned int a = 0; a < 2; ++a)
                    {
                      MortarSums &S = sums[face.nodes[a]];
                      S.D += w * psi[a];
                      S.G += w * psi[a] * g;
                      for (unsigned int b = 0; b < 2; ++b)
                        S.M[m->nodes[b]] += w * psi[a] * N[b];
                    }
                }
              for (unsigned int a = 0; a < 2; ++a)
                sums[face.nodes[a]].covered += (hi - lo) * std::sqrt(L2);
            }
        }
      return sums;
    }

    /**
     * A slave face's plane: its centre, in-plane axes t1, t2 (t1 along
     * its first edge) and normal n; faces as counterclockwise polygons in
     * it.
     */
    struct SlavePlane
    {
      explicit SlavePlane(const BoundaryFace<3> &face)
        : n(face.normal)
      {
        for (const auto &x : face.points)
          centre += x / 4.;
        t1 = face.points[1] - face.points[0];
        t1 -= (t1 * n) * n;
        t1 /= t1.norm();
        t2 = cross_product_3d(n, t1);
      }

      PlanePoint
      project(const Point<3> &x) const
      {
        return {{(x - centre) * t1, (x - centre) * t2}};
      }

      /** The face's vertices projected, counterclockwise seen from the
       * normal's side (deal.II's vertex order 0, 1, 3, 2 goes around). */
      std::vector<PlanePoint>
      polygon(const std::vector<Point<3>> &v) const
      {
        std::vector<PlanePoint> poly = {project(v[0]),
                                        project(v[1]),
                                        project(v[3]),
                                        project(v[2])};
        double                  area = 0;
        for (unsigned int i = 0; i < 4; ++i)
          area += poly[i][0] * poly[(i + 1) % 4][1] -
                  poly[(i + 1) % 4][0] * poly[i][1];
        if (area < 0)
          std::reverse(poly.begin(), poly.end());
        return poly;
      }

      Point<3>     centre;
      Tensor<1, 3> n, t1, t2;
    };

    /**
     * The overlap of a slave and a master face (a convex polygon in the
     * slave's plane) cut into triangles from its first vertex, each
     * integrated with @p rule; returns the area covered.
     */
    double
    integrate_overlap(const BoundaryFace<3>              &face,
                      const BoundaryFace<3>              &master,
                      const SlavePlane                   &plane,
                      const std::vector<PlanePoint>      &clipped,
                      const double                        slave_area,
                      const Quadrature<2>                &rule,
                      std::map<unsigned int, MortarSums> &sums)
    {
      constexpr int dim     = 3;
      double        covered = 0;
      for (unsigned int k = 1; k + 1 < clipped.size(); ++k)
        {
          const PlanePoint &A = clipped[0], &B = clipped[k],
                           &C = clipped[k + 1];
          const double area   = 0.5 * ((B[0] - A[0]) * (C[1] - A[1]) -
                                     (C[0] - A[0]) * (B[1] - A[1]));
          if (!(area > 1e-14 * slave_area))
            continue;
          covered += area;
          for (unsigned int q = 0; q < rule.size(); ++q)
            {
              const double     u = rule.point(q)[0], v = rule.point(q)[1];
              const double     w = rule.weight(q) * 2 * area;
              const Point<dim> X =
                plane.centre +
                (A[0] + u * (B[0] - A[0]) + v * (C[0] - A[0])) * plane.t1 +
                (A[1] + u * (B[1] - A[1]) + v * (C[1] - A[1])) * plane.t2;
              const auto          xs = closest_point<dim>(face.points, X);
              const auto          xm = closest_point<dim>(master.points, X);
              std::vector<double> Ns, Nm;
              std::vector<std::array<double, dim - 1>> dN;
              face_shape<dim>(xs, Ns, dN);
              face_shape<dim>(xm, Nm, dN);
              Point<dim> x, y;
              for (unsigned int c = 0; c < 4; ++c)
                {
                  x += Ns[c] * face.points[c];
                  y += Nm[c] * master.points[c];
                }
              const double g     = (y - x) * plane.n;
              const double d0[2] = {2 - 3 * xs[0], 3 * xs[0] - 1},
                           d1[2] = {2 - 3 * xs[1], 3 * xs[1] - 1};
              for (unsigned int a = 0; a < 4; ++a)
                {
                  const double psi = d0[a % 2] * d1[a / 2];
                  MortarSums  &S   = sums[face.nodes[a]];
                  S.D += w * psi;
                  S.G += w * psi * g;
                  for (unsigned int b = 0; b < 4; ++b)
                    S.M[master.nodes[b]] += w * psi * Nm[b];
                }
            }
        }
      return covered;
    }

    std::map<unsigned int, MortarSums>
    mortar_sums_3d(const std::vector<BoundaryFace<3>>         &faces,
                   const types::boundary_id                    slave,
                   const std::vector<const BoundaryFace<3> *> &masters,
                   const double                                reach)
    {
      std::map<unsigned int, MortarSums> sums;
      const QGaussSimplex<2>             rule(3);
      for (const auto &face : faces)
        {
          if (face.boundary_id != slave)
            continue;
          const SlavePlane              plane(face);
          const std::vector<PlanePoint> slave_poly = plane.polygon(face.points);
          double                        slave_area = 0;
          for (unsigned int i = 0; i < 4; ++i)
            slave_area += 0.5 * (slave_poly[i][0] * slave_poly[(i + 1) % 4][1] -
                                 slave_poly[(i + 1) % 4][0] * slave_poly[i][1]);
          for (const unsigned int node : face.nodes)
            sums[node].length += slave_area;
          for (const BoundaryFace<3> *m : masters)
            {
              if (!(m->normal * plane.n < 0))
                continue;
              Point<3> m_centre;
              for (const auto &y : m->points)
                m_centre += y / 4.;
              if (std::abs((m_centre - plane.centre) * plane.n) > reach)
                continue;
              const std::vector<PlanePoint> clipped =
                clip_convex_polygon(plane.polygon(m->points),
                                    slave_poly,
                                    1e-14 * slave_area);
              if (clipped.size() < 3)
                continue;
              const double covered = integrate_overlap(
                face, *m, plane, clipped, slave_area, rule, sums);
              for (const unsigned int node : face.nodes)
                sums[node].covered += covered;
            }
        }
      return sums;
    }
  } // namespace

  template <int dim>
  std::map<unsigned int, MortarSums>
  mortar_sums(const std::vector<BoundaryFace<dim>>         &faces,
              const types::boundary_id                      slave,
              const std::vector<const BoundaryFace<dim> *> &masters,
              const double                                  reach)
  {
    if constexpr (dim == 2)
      return mortar_sums_2d(faces, slave, masters, reach);
    else
      return mortar_sums_3d(faces, slave, masters, reach);
  }

  template void
  face_shape<2>(const std::array<double, 1> &,
                std::vector<double> &,
                std::vector<std::array<double, 1>> &);
  template void
  face_shape<3>(const std::array<double, 2> &,
                std::vector<double> &,
                std::vector<std::array<double, 2>> &);
  template std::array<double, 1>
  closest_point<2>(const std::vector<Point<2>> &, const Point<2> &);
  template std::array<double, 2>
  closest_point<3>(const std::vector<Point<3>> &, const Point<3> &);
  template MasterPoint<2>
  closest_master_point<2>(const std::vector<const BoundaryFace<2> *> &,
                          const Point<2> &,
                          const Tensor<1, 2> &,
                          const double);
  template MasterPoint<3>
  closest_master_point<3>(const std::vector<const BoundaryFace<3> *> &,
                          const Point<3> &,
                          const Tensor<1, 3> &,
                          const double);
  template std::map<unsigned int, MortarSums>
  mortar_sums<2>(const std::vector<BoundaryFace<2>> &,
                 const types::boundary_id,
                 const std::vector<const BoundaryFace<2> *> &,
                 const double);
  template std::map<unsigned int, MortarSums>
  mortar_sums<3>(const std::vector<BoundaryFace<3>> &,
                 const types::boundary_id,
                 const std::vector<const BoundaryFace<3> *> &,
                 const double);
} // namespace hrcontact
