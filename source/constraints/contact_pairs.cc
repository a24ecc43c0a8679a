#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>

#include <hrcontact/constraints/contact_pairs.h>
#include <hrcontact/constraints/two_sided_stops.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>

namespace hrcontact
{
  using namespace dealii;

  namespace
  {
    /**
     * The bilinear (2D: linear) shape functions of a face at the reference
     * point xi, in deal.II's vertex order, and their derivatives.
     */
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

    /**
     * The closest point of a face to x: Gauss-Newton on the face's
     * parametrisation (one step for a straight segment, a few for a
     * bilinear quadrilateral), unclamped. Returns the reference point.
     */
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

    /**
     * The mortar sums of one slave node (dual basis psi_s, the
     * integrals over the parts of its faces that master faces cover):
     * D = int psi_s, M_m = int psi_s N_m, G = int psi_s g, and how much of
     * its faces is covered.
     */
    struct MortarSums
    {
      double                         D = 0, G = 0, covered = 0, length = 0;
      std::map<unsigned int, double> M;
    };

    /**
     * Segment to segment with dual Lagrange multipliers (Wohlmuth): each
     * slave face is cut where the master faces facing it (within reach)
     * begin and end, projected along the slave face's normal; on each
     * piece the products of the slave's dual shape functions psi_1 = 2 -
     * 3 xi, psi_2 = 3 xi - 1 with the master's linear ones are integrated
     * exactly (3 Gauss points; both are linear in xi on straight faces).
     */
    template <int dim>
    std::map<unsigned int, MortarSums>
    mortar_sums(const std::vector<BoundaryFace<dim>>         &faces,
                const types::boundary_id                      slave,
                const std::vector<const BoundaryFace<dim> *> &masters,
                const double                                  reach)
    {
      std::map<unsigned int, MortarSums> sums;
      if constexpr (dim == 2)
        {
          const QGauss<1> gauss(3);
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
                      const double w =
                        gauss.weight(q) * (hi - lo) * std::sqrt(L2);
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
        }
      else
        {
          // 3D: each slave face and each master face facing it are
          // projected onto the slave face's plane, the two quadrilaterals
          // clipped (Sutherland-Hodgman: both convex), the overlap cut into
          // triangles and integrated with a rule exact to degree 5 (psi_s
          // N_m is of degree 4 on parallel planar faces). The dual basis is
          // the tensor product of the 1D one, biorthogonal on
          // parallelograms (the slave faces of a box's side); on distorted
          // faces only approximately.
          const QGaussSimplex<2> rule(3);
          using P2 = std::array<double, 2>;
          for (const auto &face : faces)
            {
              if (face.boundary_id != slave)
                continue;
              const Tensor<1, dim> n = face.normal;
              Point<dim>           centre;
              for (const auto &x : face.points)
                centre += x / 4.;
              Tensor<1, dim> t1 = face.points[1] - face.points[0];
              t1 -= (t1 * n) * n;
              t1 /= t1.norm();
              const Tensor<1, dim> t2    = cross_product_3d(n, t1);
              auto                 plane = [&](const Point<dim> &x) -> P2 {
                return {{(x - centre) * t1, (x - centre) * t2}};
              };
              // deal.II's vertex order 0, 1, 3, 2 goes around the face;
              // counterclockwise seen from the normal's side.
              auto polygon = [&](const std::vector<Point<dim>> &v) {
                std::vector<P2> poly = {plane(v[0]),
                                        plane(v[1]),
                                        plane(v[3]),
                                        plane(v[2])};
                double          area = 0;
                for (unsigned int i = 0; i < 4; ++i)
                  area += poly[i][0] * poly[(i + 1) % 4][1] -
                          poly[(i + 1) % 4][0] * poly[i][1];
                if (area < 0)
                  std::reverse(poly.begin(), poly.end());
                return poly;
              };
              const std::vector<P2> slave_poly = polygon(face.points);
              double                slave_area = 0;
              for (unsigned int i = 0; i < 4; ++i)
                slave_area +=
                  0.5 * (slave_poly[i][0] * slave_poly[(i + 1) % 4][1] -
                         slave_poly[(i + 1) % 4][0] * slave_poly[i][1]);
              for (const unsigned int node : face.nodes)
                sums[node].length += slave_area;
              for (const BoundaryFace<dim> *m : masters)
                {
                  if (!(m->normal * n < 0))
                    continue;
                  Point<dim> m_centre;
                  for (const auto &y : m->points)
                    m_centre += y / 4.;
                  if (std::abs((m_centre - centre) * n) > reach)
                    continue;
                  // Clip the master polygon by each edge of the slave's.
                  std::vector<P2> clipped = polygon(m->points);
                  for (unsigned int e = 0; e < 4 && !clipped.empty(); ++e)
                    {
                      const P2 a = slave_poly[e], b = slave_poly[(e + 1) % 4];
                      auto     inside = [&](const P2 &p) {
                        return (b[0] - a[0]) * (p[1] - a[1]) -
                                 (b[1] - a[1]) * (p[0] - a[0]) >=
                               -1e-14 * slave_area;
                      };
                      std::vector<P2> out;
                      for (unsigned int i = 0; i < clipped.size(); ++i)
                        {
                          const P2 &p   = clipped[i],
                                   &q   = clipped[(i + 1) % clipped.size()];
                          const bool ip = inside(p), iq = inside(q);
                          if (ip)
                            out.push_back(p);
                          if (ip != iq)
                            {
                              const double dp = (b[0] - a[0]) * (p[1] - a[1]) -
                                                (b[1] - a[1]) * (p[0] - a[0]);
                              const double dq = (b[0] - a[0]) * (q[1] - a[1]) -
                                                (b[1] - a[1]) * (q[0] - a[0]);
                              const double t = dp / (dp - dq);
                              out.push_back({{p[0] + t * (q[0] - p[0]),
                                              p[1] + t * (q[1] - p[1])}});
                            }
                        }
                      clipped = std::move(out);
                    }
                  if (clipped.size() < 3)
                    continue;
                  double covered = 0;
                  for (unsigned int k = 1; k + 1 < clipped.size(); ++k)
                    {
                      const P2 &A = clipped[0], &B = clipped[k],
                               &C       = clipped[k + 1];
                      const double area = 0.5 * ((B[0] - A[0]) * (C[1] - A[1]) -
                                                 (C[0] - A[0]) * (B[1] - A[1]));
                      if (!(area > 1e-14 * slave_area))
                        continue;
                      covered += area;
                      for (unsigned int q = 0; q < rule.size(); ++q)
                        {
                          const double u     = rule.point(q)[0],
                                       v     = rule.point(q)[1];
                          const double     w = rule.weight(q) * 2 * area;
                          const Point<dim> X =
                            centre +
                            (A[0] + u * (B[0] - A[0]) + v * (C[0] - A[0])) *
                              t1 +
                            (A[1] + u * (B[1] - A[1]) + v * (C[1] - A[1])) * t2;
                          const auto xs = closest_point<dim>(face.points, X);
                          const auto xm = closest_point<dim>(m->points, X);
                          std::vector<double>                      Ns, Nm;
                          std::vector<std::array<double, dim - 1>> dN;
                          face_shape<dim>(xs, Ns, dN);
                          face_shape<dim>(xm, Nm, dN);
                          Point<dim> x, y;
                          for (unsigned int v = 0; v < 4; ++v)
                            {
                              x += Ns[v] * face.points[v];
                              y += Nm[v] * m->points[v];
                            }
                          const double g     = (y - x) * n;
                          const double d0[2] = {2 - 3 * xs[0], 3 * xs[0] - 1},
                                       d1[2] = {2 - 3 * xs[1], 3 * xs[1] - 1};
                          for (unsigned int a = 0; a < 4; ++a)
                            {
                              const double psi = d0[a % 2] * d1[a / 2];
                              MortarSums  &S   = sums[face.nodes[a]];
                              S.D += w * psi;
                              S.G += w * psi * g;
                              for (unsigned int b = 0; b < 4; ++b)
                                S.M[m->nodes[b]] += w * psi * Nm[b];
                            }
                        }
                    }
                  for (const unsigned int node : face.nodes)
                    sums[node].covered += covered;
                }
            }
        }
      return sums;
    }

    /** The bodies overlap at the start: the error, naming the node. */
    InputError
    overlap_error(const std::string &where,
                  const std::string &node,
                  const double       depth,
                  const std::string &measured)
    {
      std::ostringstream s;
      s << where << ": the bodies overlap at the start: " << node << " lies "
        << depth << " inside the master boundary" << measured
        << ". Place the bodies so that the slave surface does not enter the "
           "master body.";
      return InputError(s.str());
    }

    std::string
    pair_name(const unsigned int slave, const unsigned int master)
    {
      return "Contact/Contact pairs, pair " + std::to_string(slave) + " : " +
             std::to_string(master);
    }
  } // namespace

  template <int dim>
  void
  ContactPairs<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    prm.declare_entry(
      "Contact pairs",
      "",
      Patterns::Anything(),
      "Frictionless unilateral contact between deformable bodies, node to "
      "segment: 'slave id : master id [: reach]', entries separated by '|', "
      "e.g. '12 : 3'. Each node of the slave boundary is projected onto the "
      "closest face of the master boundary that faces it; its row "
      "constrains the relative normal displacement (u_slave - sum N_m "
      "u_master).n <= g, n the master face's inward normal, g the gap on "
      "the undeformed surfaces, and its reaction p <= 0 acts on the slave "
      "node and, through the face's shape functions N_m, equal and opposite "
      "on the master nodes. Slave nodes farther than the reach from the "
      "master surface (an expression of the constants; default: a tenth of "
      "the master boundary's bounding box diagonal) get no row: it must "
      "exceed the gap at the edge of the contact zone. Bodies that overlap at the start, or "
      "a slave boundary with no master face in reach, stop with an error. "
      "Matching meshes give node-to-node rows. "
      "Empty: none.");
    prm.declare_entry(
      "Pair method",
      "node to segment",
      Patterns::Selection("node to segment|mortar"),
      "How a pair's rows are built. node to segment: each slave node "
      "against the master face it projects onto (fails the contact patch "
      "test on non-matching meshes by a few per cent). mortar: segment "
      "to segment with dual Lagrange multipliers, the row of a slave node "
      "integrated over its faces (the master weights M_sm / D_s, the gap "
      "the weighted mean); passes the patch test. Slave nodes whose faces "
      "the master does not cover entirely keep a node-to-segment row.");
    prm.declare_entry(
      "Pair laws",
      "",
      Patterns::Anything(),
      "Another law than unilateral contact for a pair, by its slave id, "
      "entries separated by '|': 'id: bilateral' or 'id: stop : g- : g+ : "
      "p0- : p0+ [: k- : k+]'. The law acts on s = w - g, the relative "
      "normal displacement beyond closing the gap (s = 0 where the "
      "surfaces touch, s < 0 apart). bilateral: s = 0, the surfaces slide "
      "on each other but neither separate nor penetrate (an initial gap is "
      "closed), and the reaction has either sign. stop: the two-sided stop "
      "of Contact/Stops on s (free for g- < s < g+; at s = g+ a pushing "
      "reaction down to p0- <= 0, at s = g- a pulling one up to p0+ >= 0; "
      "beyond, the limit reaction or a branch of stiffness k- or k+), e.g. "
      "'12: stop : -1e-4 : 0 : -1e12 : 5e4 : 0 : 1e9' for surfaces that "
      "press freely, open by 0.1 mm, and are then held by a tether of "
      "strength 5e4 and stiffness 1e9 per node. Values are expressions in "
      "x, y (, z) evaluated at the slave node. Empty: every pair unilateral.");
    prm.leave_subsection();
  }

  template <int dim>
  std::string
  ContactPairs<dim>::entry() const
  {
    return "Contact/Contact pairs";
  }

  template <int dim>
  bool
  ContactPairs<dim>::acts_on(const types::boundary_id id) const
  {
    return std::any_of(pairs.begin(), pairs.end(), [id](const Pair &p) {
      return p.slave == id || p.master == id;
    });
  }

  template <int dim>
  bool
  ContactPairs<dim>::parse_parameters(
    ParameterHandler                                          &prm,
    const Constants                                           &constants,
    const std::vector<std::shared_ptr<ConstraintSource<dim>>> &earlier)
  {
    prm.enter_subsection("Contact");
    const std::string text = prm.get("Contact pairs");
    prm.leave_subsection();
    pairs.clear();
    std::set<types::boundary_id> used;
    for (const std::string &item : split_and_trim(text, '|'))
      {
        if (item.empty())
          {
            if (Utilities::trim(text).empty())
              break;
            throw InputError("Contact/Contact pairs: an empty entry in '" +
                             text + "'.");
          }
        const auto parts = split_and_trim(item, ':');
        if (parts.size() != 2 && parts.size() != 3)
          throw InputError("Contact/Contact pairs: expected 'slave id : "
                           "master id [: reach]' in '" +
                           item + "'.");
        unsigned int ids[2];
        for (unsigned int k = 0; k < 2; ++k)
          {
            std::size_t end = 0;
            int         id  = -1;
            try
              {
                id = std::stoi(parts[k], &end);
              }
            catch (const std::exception &)
              {
                end = 0;
              }
            if (end == 0 || end != parts[k].size() || id < 0 ||
                static_cast<types::boundary_id>(id) >=
                  numbers::internal_face_boundary_id)
              throw InputError("Contact/Contact pairs: '" + parts[k] +
                               "' in '" + item + "' is not a boundary id.");
            ids[k] = id;
          }
        Pair pair;
        pair.slave       = ids[0];
        pair.master      = ids[1];
        const auto where = pair_name(pair.slave, pair.master);
        if (pair.slave == pair.master)
          throw InputError(where + ": a boundary cannot touch itself.");
        for (const auto id : {pair.slave, pair.master})
          {
            if (!used.insert(id).second)
              throw InputError(where + ": boundary " + std::to_string(id) +
                               " is in another pair already.");
            require_unconstrained<dim>(
              id,
              where,
              earlier,
              "a normal constraint, an obstacle, a boundary support or a "
              "stop");
          }
        if (parts.size() == 3)
          {
            pair.reach =
              evaluate_constant_expression(parts[2], constants, where);
            if (!(pair.reach > 0))
              throw InputError(where + ": the reach must be positive.");
          }
        pairs.push_back(pair);
      }
    prm.enter_subsection("Contact");
    const std::string laws = prm.get("Pair laws");
    mortar                 = prm.get("Pair method") == "mortar";
    prm.leave_subsection();

    parse_laws(laws, constants);
    return !pairs.empty();
  }

  template <int dim>
  void
  ContactPairs<dim>::parse_laws(const std::string &text,
                                const Constants   &constants)
  {
    for (const BoundaryEntry &e :
         parse_boundary_list(text, dim, false, "Contact/Pair laws"))
      {
        const std::string where =
          "Contact/Pair laws, boundary " + std::to_string(e.boundary_id);
        const auto pair =
          std::find_if(pairs.begin(), pairs.end(), [&e](const Pair &p) {
            return p.slave == e.boundary_id;
          });
        if (pair == pairs.end())
          throw InputError(where + ": not the slave boundary of a contact pair "
                                   "(Contact/Contact pairs).");
        const auto parts = split_and_trim(e.expressions, ':');
        if (parts[0] == "unilateral" && parts.size() == 1)
          pair->law = Pair::Law::unilateral;
        else if (parts[0] == "bilateral" && parts.size() == 1)
          pair->law = Pair::Law::bilateral;
        else if (parts[0] == "stop" && (parts.size() == 5 || parts.size() == 7))
          {
            pair->law            = Pair::Law::stop;
            const char *names[6] = {"g-", "g+", "p0-", "p0+", "k-", "k+"};
            for (unsigned int k = 1; k < parts.size(); ++k)
              pair->stop_values[k - 1] = make_function<dim>(
                parts[k], 1, constants, where + ", " + names[k - 1]);
          }
        else
          throw InputError(where +
                           ": expected 'unilateral', 'bilateral' or "
                           "'stop : g- : g+ : p0- : p0+ [: k- : k+]', "
                           "found '" +
                           e.expressions + "'.");
      }
  }

  template <int dim>
  void
  ContactPairs<dim>::prepare(const std::vector<BoundaryFace<dim>> &faces,
                             const EquilibriumSystem              &system) const
  {
    projections.clear();
    std::set<unsigned int> all_masters;
    for (const Pair &pair : pairs)
      for (const auto &face : faces)
        if (face.boundary_id == pair.master)
          all_masters.insert(face.nodes.begin(), face.nodes.end());

    for (unsigned int k = 0; k < pairs.size(); ++k)
      {
        const Pair       &pair  = pairs[k];
        const std::string where = pair_name(pair.slave, pair.master);
        std::vector<const BoundaryFace<dim> *> masters;
        // The slave nodes, their positions and area-weighted normals.
        std::map<unsigned int, std::pair<Point<dim>, Tensor<1, dim>>> slaves;
        for (const auto &face : faces)
          if (face.boundary_id == pair.master)
            masters.push_back(&face);
          else if (face.boundary_id == pair.slave)
            for (unsigned int v = 0; v < face.nodes.size(); ++v)
              {
                auto &s = slaves[face.nodes[v]];
                s.first = face.points[v];
                s.second += face.measure * face.normal;
              }
        if (masters.empty())
          throw InputError(where +
                           ": the mesh has no face with the master "
                           "boundary id " +
                           std::to_string(pair.master) + ".");
        if (slaves.empty())
          throw InputError(where +
                           ": the mesh has no face with the slave "
                           "boundary id " +
                           std::to_string(pair.slave) + ".");

        // The default reach: a tenth of the master boundary's size, far
        // more than the gap at the edge of any contact zone the small
        // deformation theory describes.
        double reach = pair.reach;
        if (!(reach > 0))
          {
            Point<dim> low = masters.front()->points.front(), high = low;
            for (const BoundaryFace<dim> *face : masters)
              for (const auto &x : face->points)
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    low[d]  = std::min(low[d], x[d]);
                    high[d] = std::max(high[d], x[d]);
                  }
            reach = 0.1 * low.distance(high);
          }
        const auto mortar_rows =
          mortar ? mortar_sums<dim>(faces, pair.slave, masters, reach) :
                   std::map<unsigned int, MortarSums>();
        unsigned int found = 0;
        auto add = [&](const unsigned int node, const Projection &projection) {
          if (!projections.emplace(node, projection).second)
            throw InputError(where + ": " + system.describe_node(node) +
                             " is a slave node of two pairs.");
          ++found;
        };
        for (const auto &[node, slave] : slaves)
          {
            const Point<dim> &x = slave.first;
            if (all_masters.count(node))
              throw InputError(where + ": " + system.describe_node(node) +
                               " is on a slave and a master boundary.");
            // Mortar: a node whose faces the master covers entirely; at the
            // edge of the master surface node to segment below.
            const auto m = mortar_rows.find(node);
            if (m != mortar_rows.end() &&
                m->second.covered >= (1 - 1e-8) * m->second.length &&
                m->second.D > 0)
              {
                const MortarSums &S = m->second;
                Projection        projection;
                projection.pair   = k;
                projection.normal = slave.second / slave.second.norm();
                projection.gap    = S.G / S.D;
                for (const auto &[master, M] : S.M)
                  if (std::abs(M) > 1e-12 * S.D)
                    {
                      projection.master_nodes.push_back(master);
                      projection.shape_values.push_back(M / S.D);
                    }
                // The faces' total length (2D) or area (3D) as a size.
                const double size = dim == 2 ? S.length : std::sqrt(S.length);
                if (projection.gap < -1e-8 * size)
                  throw overlap_error(where,
                                      system.describe_node(node),
                                      -projection.gap,
                                      " (mortar mean)");
                projection.gap = std::max(projection.gap, 0.);
                add(node, projection);
                continue;
              }
            double     best = std::numeric_limits<double>::max();
            Projection projection;
            for (const BoundaryFace<dim> *face : masters)
              {
                // Only faces that face the slave node.
                if (!(face->normal * slave.second < 0))
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
                    length =
                      std::max(length,
                               face->points[v].distance(
                                 face->points[(v + 1) % face->points.size()]));
                  }
                const double distance = x.distance(y);
                if (distance > reach || distance >= best)
                  continue;
                best              = distance;
                projection.pair   = k;
                projection.normal = -face->normal;
                projection.gap    = (y - x) * projection.normal;
                projection.master_nodes.clear();
                projection.shape_values.clear();
                for (unsigned int v = 0; v < face->nodes.size(); ++v)
                  if (std::abs(N[v]) > 1e-12)
                    {
                      projection.master_nodes.push_back(face->nodes[v]);
                      projection.shape_values.push_back(N[v]);
                    }
                if (projection.gap < -1e-8 * length)
                  throw overlap_error(where,
                                      system.describe_node(node),
                                      -projection.gap,
                                      "");
                projection.gap = std::max(projection.gap, 0.);
              }
            if (best == std::numeric_limits<double>::max())
              continue;
            add(node, projection);
          }
        if (found == 0)
          throw InputError(
            where +
            ": no node of the slave boundary has a face of the master "
            "boundary in reach" +
            " (" +
            [reach] {
              std::ostringstream s;
              s << reach;
              return s.str();
            }() +
            ")" +
            ": the bodies are too far apart, the boundaries do not face each "
            "other, or the ids are swapped.");
      }
  }

  template <int dim>
  void
  ContactPairs<dim>::collect(const BoundaryFace<dim> &face,
                             const EquilibriumSystem &system,
                             NodeConstraintMap<dim>  &nodes) const
  {
    for (const Pair &pair : pairs)
      if (face.boundary_id == pair.master)
        for (const unsigned int node : face.nodes)
          nodes[node].coupled = true;
      else if (face.boundary_id == pair.slave)
        for (const unsigned int node : face.nodes)
          if (projections.count(node))
            {
              NodeConstraints<dim> &c = nodes[node];
              if (c.own_row_source && c.own_row_source != this)
                throw InputError(pair_name(pair.slave, pair.master) + ": " +
                                 system.describe_node(node) +
                                 " also has a stop.");
              c.own_row_source   = this;
              c.own_row_boundary = face.boundary_id;
            }
  }

  template <int dim>
  OwnRow
  ContactPairs<dim>::own_row(const unsigned int          node,
                             const Point<dim>           &point,
                             const NodeConstraints<dim> &constraints,
                             const EquilibriumSystem    &system) const
  {
    Projection       &projection = projections.at(node);
    const Pair       &pair       = pairs[projection.pair];
    const std::string where =
      pair_name(pair.slave, pair.master) + ", " + system.describe_node(node);
    if (constraints.has_normal || constraints.obstacle >= 0)
      throw InputError(where + ": the node also has a normal constraint, an "
                               "obstacle or a boundary support.");
    // Prescribed components at the slave node (a symmetry plane at the end
    // of the interface): as for obstacles, the row constrains the free part
    // of the normal, n_free . (u_s - sum N_m u_m) <= g, scaled to a unit
    // direction; the same direction acts at the master nodes.
    Tensor<1, dim> n_free = projection.normal;
    for (unsigned int d = 0; d < dim; ++d)
      if (constraints.prescribed[d])
        {
          projection.gap -= n_free[d] * constraints.prescribed_value[d];
          n_free[d] = 0;
        }
    if (n_free.norm() < 1e-8)
      throw InputError(where + ": every component along the contact normal "
                               "is prescribed.");
    projection.gap /= n_free.norm();
    projection.normal = n_free / n_free.norm();
    OwnRow row;
    for (unsigned int d = 0; d < dim; ++d)
      row.direction.push_back(projection.normal[d]);
    row.value      = projection.gap;
    row.unilateral = pair.law == Pair::Law::unilateral;
    if (pair.law == Pair::Law::stop)
      {
        std::array<const FunctionParser<dim> *, 6> values;
        for (unsigned int k = 0; k < 6; ++k)
          values[k] = pair.stop_values[k].get();
        row.law = two_sided_stop_at<dim>(values, point, where);
      }
    return row;
  }

  template <int dim>
  void
  ContactPairs<dim>::couple_rows(EquilibriumSystem &system) const
  {
    // The rows of the nodes involved.
    std::map<unsigned int, std::vector<unsigned int>> rows_of;
    for (const auto &[slave, projection] : projections)
      {
        rows_of[slave];
        for (const unsigned int m : projection.master_nodes)
          rows_of[m];
      }
    for (unsigned int r = 0; r < system.rows.size(); ++r)
      {
        const auto it = rows_of.find(system.rows[r].node);
        if (it != rows_of.end())
          it->second.push_back(r);
      }
    auto explicit_direction = [](EquilibriumRow &row) {
      if (row.direction.empty())
        for (const auto &[dof, c] : row.combination)
          row.direction.push_back(c);
    };
    auto dof = [&](const unsigned int node, const unsigned int d) {
      return types::global_dof_index(dim) * node + d;
    };
    for (const auto &[slave, projection] : projections)
      {
        const Tensor<1, dim> &n = projection.normal;
        // The slave's contact row: d = (n at the slave, -N_m n at master m).
        EquilibriumRow *q = nullptr;
        for (const unsigned int r : rows_of.at(slave))
          if (system.rows[r].row_class == RowClass::contact)
            q = &system.rows[r];
        AssertThrow(q != nullptr, ExcInternalError());
        explicit_direction(*q);
        for (unsigned int i = 0; i < projection.master_nodes.size(); ++i)
          for (unsigned int d = 0; d < dim; ++d)
            {
              q->combination.emplace_back(dof(projection.master_nodes[i], d),
                                          0.);
              q->direction.push_back(-projection.shape_values[i] * n[d]);
            }
        // Every row r of a master node m: c_r . d_q = 0 needs the slave's
        // normal row alpha n in c_r, alpha = N_m (c_r at m) . n; the
        // directions are unchanged (zero at the slave), so the other
        // products stay as they were.
        for (unsigned int i = 0; i < projection.master_nodes.size(); ++i)
          {
            const unsigned int m = projection.master_nodes[i];
            for (const unsigned int r : rows_of.at(m))
              {
                EquilibriumRow &row   = system.rows[r];
                double          alpha = 0;
                for (const auto &[j, c] : row.combination)
                  if (system.dof_node(j) == m)
                    alpha += c * n[system.dof_component(j)];
                alpha *= projection.shape_values[i];
                if (alpha == 0)
                  continue;
                explicit_direction(row);
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    row.combination.emplace_back(dof(slave, d), alpha * n[d]);
                    row.direction.push_back(0.);
                  }
              }
          }
      }
  }

  template class ContactPairs<2>;
  template class ContactPairs<3>;

  HRCONTACT_REGISTER_CONSTRAINT_SOURCE(ContactPairs, 70)
} // namespace hrcontact
