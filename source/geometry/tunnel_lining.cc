#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <hrcontact/geometry/tunnel_lining.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace hrcontact
{
  using namespace dealii;

  namespace
  {
    /**
     * The crossing with x > 0 of the circles |x| = a (centre at the origin)
     * and |x - (0, c)| = b; throws if they do not cross.
     */
    Point<2>
    circle_crossing(const double       a,
                    const double       b,
                    const double       c,
                    const std::string &what)
    {
      const double y  = (a * a - b * b + c * c) / (2 * c);
      const double x2 = a * a - y * y;
      if (!(x2 > 0))
        throw InputError("Geometry: tunnel_lining: the " + what +
                         " arcs do not meet; this is not a lining of two "
                         "arcs (check R_c, R_i and H).");
      return Point<2>(std::sqrt(x2), y);
    }
  } // namespace

  TunnelLining::TunnelLining(const std::string &arguments,
                             const Constants   &constants)
  {
    const auto parts = split_and_trim(arguments, ':');
    if (parts.size() != 5 && parts.size() != 6)
      throw InputError("Geometry: tunnel_lining takes 'R_c : R_i : H : t_c : "
                       "t_i [: cells across]' (crown and invert radii of the "
                       "intrados, clear height, crown and invert thickness).");
    std::vector<double> v;
    for (const auto &p : parts)
      v.push_back(
        evaluate_constant_expression(p, constants, "Geometry/Grid arguments"));
    R_c = v[0];
    R_i = v[1];
    H   = v[2];
    t_c = v[3];
    t_i = v[4];
    if (parts.size() == 6)
      {
        if (!(v[5] >= 1 && v[5] <= 64 && v[5] == std::round(v[5])))
          throw InputError("Geometry: tunnel_lining: cells across the "
                           "thickness must be an integer in [1, 64].");
        cells_across = static_cast<unsigned int>(v[5]);
      }
    if (!(R_c > 0 && R_i > 0 && H > 0 && t_c > 0 && t_i > 0))
      throw InputError("Geometry: tunnel_lining: radii, height and "
                       "thicknesses must be positive.");
    if (!(H > R_c))
      throw InputError("Geometry: tunnel_lining: the clear height H must "
                       "exceed the crown radius R_c (the invert lies below "
                       "the springline).");
    if (!(R_i > R_c))
      throw InputError("Geometry: tunnel_lining: the invert radius R_i must "
                       "exceed the crown radius R_c (a flatter invert).");
    if (!(t_c < 0.5 * R_c && t_i < 0.5 * R_c))
      throw InputError("Geometry: tunnel_lining: thicknesses must stay below "
                       "R_c / 2.");

    // Invert centre on the axis, the intrados bottom at y = R_c - H.
    y_invert  = R_c - H + R_i;
    joint_in  = circle_crossing(R_c, R_i, y_invert, "intrados");
    joint_out = circle_crossing(R_c + t_c, R_i + t_i, y_invert, "extrados");
    if (!(joint_in[1] < 0 && joint_out[1] < 0))
      throw InputError("Geometry: tunnel_lining: the arcs meet above the "
                       "springline, so the clear width would not be 2 R_c; "
                       "increase H or R_i.");
    theta_in  = std::atan2(joint_in[1], joint_in[0]);
    theta_out = std::atan2(joint_out[1], joint_out[0]);
    phi_in    = std::atan2(joint_in[1] - y_invert, joint_in[0]);
    phi_out   = std::atan2(joint_out[1] - y_invert, joint_out[0]);
    if (!(phi_in > -numbers::PI / 2 && phi_out > -numbers::PI / 2 &&
          phi_in < 0 && phi_out < 0))
      throw InputError("Geometry: tunnel_lining: the invert arcs do not lie "
                       "below their centre; check R_i and H.");
  }

  void
  TunnelLining::create_coarse_mesh(Triangulation<2> &tria) const
  {
    const double half_pi = numbers::PI / 2;
    // Near-square coarse cells: along-spacing = thickness / cells across.
    const double crown_length =
      0.5 * (R_c * (half_pi - theta_in) + (R_c + t_c) * (half_pi - theta_out));
    const double invert_length =
      0.5 * (R_i * (phi_in + half_pi) + (R_i + t_i) * (phi_out + half_pi));
    const unsigned int n_c =
      std::max<unsigned int>(1, std::lround(crown_length * cells_across / t_c));
    const unsigned int n_i =
      std::max<unsigned int>(1,
                             std::lround(invert_length * cells_across / t_i));
    const unsigned int n_t = cells_across;

    // Reference rectangle (u, v) = (along, across), then mapped: u in
    // [0, n_c] is the crown from its top, u in [n_c, n_c + n_i] the invert
    // down to its bottom; v from the intrados (0) to the extrados (n_t).
    GridGenerator::subdivided_hyper_rectangle(
      tria, {n_c + n_i, n_t}, Point<2>(0, 0), Point<2>(n_c + n_i, n_t), false);
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            const Point<2> c = cell->face(f)->center();
            cell->face(f)->set_boundary_id(c[1] < 1e-12       ? 0 :
                                           c[1] > n_t - 1e-12 ? 1 :
                                           c[0] < 1e-12       ? 2 :
                                                                3);
          }
    // Manifold ids before the map, while "crown" is still u < n_c.
    tria.set_all_manifold_ids(0);
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() <= 1)
          cell->face(f)->set_manifold_id(cell->center()[0] < n_c ? 1 : 2);

    const Point<2> O_i(0, y_invert);
    GridTools::transform(
      [&](const Point<2> &p) {
        const double t = p[1] / n_t;
        Point<2>     inner, outer;
        if (p[0] <= n_c)
          {
            const double s = p[0] / n_c;
            const double a = half_pi + s * (theta_in - half_pi);
            const double b = half_pi + s * (theta_out - half_pi);
            inner          = Point<2>(R_c * std::cos(a), R_c * std::sin(a));
            outer =
              Point<2>((R_c + t_c) * std::cos(b), (R_c + t_c) * std::sin(b));
          }
        else
          {
            const double s = (p[0] - n_c) / n_i;
            const double a = phi_in + s * (-half_pi - phi_in);
            const double b = phi_out + s * (-half_pi - phi_out);
            inner = O_i + Point<2>(R_i * std::cos(a), R_i * std::sin(a));
            outer = O_i + Point<2>((R_i + t_i) * std::cos(b),
                                   (R_i + t_i) * std::sin(b));
          }
        // The symmetry cuts lie exactly on x = 0.
        Point<2> x = inner + t * (outer - inner);
        if (std::abs(x[0]) < 1e-12 * R_c)
          x[0] = 0;
        return x;
      },
      tria);

    tria.set_manifold(1, SphericalManifold<2>(Point<2>(0, 0)));
    tria.set_manifold(2, SphericalManifold<2>(O_i));
    TransfiniteInterpolationManifold<2> inside;
    inside.initialize(tria);
    tria.set_manifold(0, inside);
  }

  std::vector<SectionStation>
  TunnelLining::sections(const unsigned int n) const
  {
    const double   half_pi = numbers::PI / 2;
    const double   Rm_c = R_c + t_c / 2, Rm_i = R_i + t_i / 2;
    const double   theta_lim = std::max(theta_in, theta_out);
    const double   phi_lim   = std::min(phi_in, phi_out);
    const Point<2> O_i(0, y_invert);
    const double   L_c   = Rm_c * (half_pi - theta_lim);
    const double   L_gap = joint_gap_length();
    const double   L_i   = Rm_i * (phi_lim + half_pi);
    const double   total = L_c + L_gap + L_i;

    std::vector<SectionStation> stations;
    for (unsigned int k = 0; k <= n; ++k)
      {
        const double   s = total * k / n;
        SectionStation station;
        station.s = s;
        if (s <= L_c + 1e-12 * total)
          {
            const double a = half_pi - std::min(s, L_c) / Rm_c;
            station.across = Tensor<1, 2>({std::cos(a), std::sin(a)});
            station.point  = Point<2>(Rm_c * station.across);
            station.part   = "crown";
          }
        else if (s >= L_c + L_gap - 1e-12 * total)
          {
            const double a = phi_lim - std::max(0., s - L_c - L_gap) / Rm_i;
            station.across = Tensor<1, 2>({std::cos(a), std::sin(a)});
            station.point  = O_i + Rm_i * station.across;
            station.part   = "invert";
          }
        else
          continue;
        if (std::abs(station.point[0]) < 1e-12 * R_c)
          station.point[0] = 0;
        stations.push_back(station);
      }
    return stations;
  }

  double
  TunnelLining::extrados_arc_length(const Point<2> &x) const
  {
    const double half_pi = numbers::PI / 2;
    const double theta   = std::atan2(x[1], x[0]);
    if (x[1] >= joint_out[1] - 1e-12 * R_c)
      return (R_c + t_c) * (half_pi - theta);
    const double phi = std::atan2(x[1] - y_invert, x[0]);
    return (R_c + t_c) * (half_pi - theta_out) + (R_i + t_i) * (phi_out - phi);
  }

  double
  TunnelLining::extrados_length() const
  {
    const double half_pi = numbers::PI / 2;
    return (R_c + t_c) * (half_pi - theta_out) +
           (R_i + t_i) * (phi_out + half_pi);
  }

  double
  TunnelLining::joint_gap_length() const
  {
    const double   Rm_c = R_c + t_c / 2, Rm_i = R_i + t_i / 2;
    const double   theta_lim = std::max(theta_in, theta_out);
    const double   phi_lim   = std::min(phi_in, phi_out);
    const Point<2> end_crown(Rm_c * std::cos(theta_lim),
                             Rm_c * std::sin(theta_lim));
    const Point<2> start_invert(Rm_i * std::cos(phi_lim),
                                y_invert + Rm_i * std::sin(phi_lim));
    return end_crown.distance(start_invert);
  }

  std::string
  TunnelLining::describe() const
  {
    std::ostringstream s;
    const double       deg = 180 / numbers::PI;
    s << std::setprecision(5) << "tunnel lining: intrados crown radius " << R_c
      << " (centre 0, 0), invert radius " << R_i << " (centre 0, " << y_invert
      << "), clear width " << 2 * R_c << ", clear height " << H
      << ", thickness " << t_c << " (crown) / " << t_i
      << " (invert); joints at intrados (" << joint_in << ") and extrados ("
      << joint_out << "), i.e. " << theta_in * deg << " / " << theta_out * deg
      << " degrees from the springline";
    return s.str();
  }
} // namespace hrcontact
