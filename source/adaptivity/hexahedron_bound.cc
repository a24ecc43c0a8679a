#include <deal.II/base/mpi.h>

#include <deal.II/fe/fe.h>

#include <hrcontact/adaptivity/hexahedron_bound.h>
#include <hrcontact/adaptivity/hexahedron_equilibration.h>
#include <hrcontact/adaptivity/hexahedron_face_tractions.h>
#include <hrcontact/adaptivity/hexahedron_shape_map.h>
#include <hrcontact/adaptivity/triangle_split.h>
#include <hrcontact/postprocess/field_values.h>

#include <cmath>
#include <map>
#include <memory>

namespace hrcontact
{
  using namespace dealii;

  namespace
  {
    double
    hat(const unsigned int v, const Tensor<1, 3> &xi, Tensor<1, 3> &gradient)
    {
      return HexahedronShapeMap::hat(v, xi, gradient);
    }

    /** The components (xx, yy, zz, xy, xz, yz) of a stress. */
    std::array<double, 6>
    components(const SymmetricTensor<2, 3> &s)
    {
      return {{s[0][0], s[1][1], s[2][2], s[0][1], s[0][2], s[1][2]}};
    }

    double
    energy(const FullMatrix<double> &S, const SymmetricTensor<2, 3> &s)
    {
      const auto v   = components(s);
      double     sum = 0;
      for (unsigned int a = 0; a < 6; ++a)
        for (unsigned int b = 0; b < 6; ++b)
          sum += v[a] * S(a, b) * v[b];
      return sum;
    }

    std::array<Point<3>, 8>
    vertices_of(const Triangulation<3>::cell_iterator &cell)
    {
      std::array<Point<3>, 8> v;
      for (unsigned int i = 0; i < 8; ++i)
        v[i] = cell->vertex(i);
      return v;
    }

    /** Whether every shape function of @p fe is trilinear on the unit cell
     * (it equals the interpolation of its vertex values). */
    bool
    in_q1(const FiniteElement<3> &fe)
    {
      for (const Point<3> p :
           {Point<3>(0.3, 0.7, 0.2), Point<3>(0.81, 0.13, 0.6)})
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          {
            double       sum = 0;
            Tensor<1, 3> g;
            for (unsigned int v = 0; v < 8; ++v)
              sum += fe.shape_value(i, GeometryInfo<3>::unit_cell_vertex(v)) *
                     hat(v, p, g);
            if (std::abs(sum - fe.shape_value(i, p)) > 1e-12)
              return false;
          }
      return true;
    }
  } // namespace

  struct HexahedronBound::Body
  {
    FullMatrix<double>                                                    S;
    HexahedronEquilibration                                               eq;
    std::map<std::vector<long long>, std::unique_ptr<HexahedronShapeMap>> maps;
    explicit Body(const FullMatrix<double> &S)
      : S(S)
      , eq(S)
    {}
  };

  HexahedronBound::HexahedronBound(const Results<3> &results)
    : results(results)
  {
    const auto table = [](const FiniteElement<3>             &fe,
                          std::vector<std::array<double, 8>> &values) {
      values.resize(fe.n_dofs_per_cell());
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        for (unsigned int v = 0; v < 8; ++v)
          values[i][v] =
            fe.shape_value(i, GeometryInfo<3>::unit_cell_vertex(v));
    };
    table(*results.spaces.fe_displacement, u_at_vertices);
    table(*results.spaces.fe_stress, s_at_vertices);
  }

  HexahedronBound::~HexahedronBound() = default;

  std::string
  HexahedronBound::not_covered(const Results<3> &r)
  {
    if (r.triangulation().has_hanging_nodes())
      return "conforming meshes only in 3D (no hanging nodes)";
    if (!r.system.contact_rows.empty())
      return "no contact in 3D yet";
    for (unsigned int body = 0; body < std::max(1u, r.scene.n_bodies); ++body)
      if (!r.scene.material_of(body).is_linear())
        return "linear elastic bodies only in 3D";
    if (!in_q1(*r.spaces.fe_displacement) || !in_q1(*r.spaces.fe_stress))
      return "elements whose shape functions are trilinear only in 3D";
    double distortion = 0;
    for (const auto &cell : r.triangulation().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const Point<3>     v0   = cell->vertex(0);
          const Tensor<1, 3> e[3] = {cell->vertex(1) - v0,
                                     cell->vertex(2) - v0,
                                     cell->vertex(4) - v0};
          for (unsigned int i = 0; i < 8; ++i)
            {
              Point<3> p = v0;
              for (unsigned int d = 0; d < 3; ++d)
                if ((i >> d) & 1u)
                  p += e[d];
              distortion =
                std::max(distortion,
                         p.distance(cell->vertex(i)) / cell->diameter());
            }
        }
    if (Utilities::MPI::max(distortion, r.partition.communicator) > 1e-10)
      return "meshes of parallelepipeds only in 3D (the cell problem's "
             "factors are kept per shape)";
    return "";
  }

  SymmetricTensor<2, 3>
  HexahedronBound::CellFields::strain(const Point<3> &x) const
  {
    const Tensor<1, 3> xi = J_inv * (x - v0);
    Tensor<2, 3>       grad;
    for (unsigned int v = 0; v < 8; ++v)
      {
        Tensor<1, 3> g;
        hat(v, xi, g);
        grad += outer_product(u[v], transpose(J_inv) * g);
      }
    return symmetrize(grad);
  }

  SymmetricTensor<2, 3>
  HexahedronBound::CellFields::stress(const Point<3> &x) const
  {
    const Tensor<1, 3>    xi = J_inv * (x - v0);
    SymmetricTensor<2, 3> sigma;
    for (unsigned int v = 0; v < 8; ++v)
      {
        Tensor<1, 3> g;
        sigma += hat(v, xi, g) * s[v];
      }
    return sigma;
  }

  void
  HexahedronBound::sample(const DoFHandler<3>::active_cell_iterator &cell,
                          CellFields &fields) const
  {
    // The fields' vertex values: sum_i U_i phi_i(vertex).
    const auto                               &fe_u = cell->get_fe();
    const DoFHandler<3>::active_cell_iterator s_cell(
      &results.triangulation(),
      cell->level(),
      cell->index(),
      &results.spaces.dof_handler_stress);
    const auto                          &fe_s = s_cell->get_fe();
    std::vector<types::global_dof_index> u_dofs(fe_u.n_dofs_per_cell()),
      s_dofs(fe_s.n_dofs_per_cell());
    cell->get_dof_indices(u_dofs);
    s_cell->get_dof_indices(s_dofs);
    fields.v0 = cell->vertex(0);
    Tensor<2, 3> J;
    for (unsigned int d = 0; d < 3; ++d)
      for (unsigned int i = 0; i < 3; ++i)
        J[i][d] = cell->vertex(1u << d)[i] - fields.v0[i];
    fields.J_inv = invert(J);
    std::array<std::array<double, 6>, 8> s{};
    for (unsigned int v = 0; v < 8; ++v)
      fields.u[v] = Tensor<1, 3>();
    for (unsigned int i = 0; i < u_dofs.size(); ++i)
      {
        const unsigned int c = fe_u.system_to_component_index(i).first;
        const double       U = results.displacement(u_dofs[i]);
        for (unsigned int v = 0; v < 8; ++v)
          fields.u[v][c] += U * u_at_vertices[i][v];
      }
    for (unsigned int j = 0; j < s_dofs.size(); ++j)
      {
        const unsigned int c = fe_s.system_to_component_index(j).first;
        const double       S = results.stress(s_dofs[j]);
        for (unsigned int v = 0; v < 8; ++v)
          s[v][c] += S * s_at_vertices[j][v];
      }
    for (unsigned int v = 0; v < 8; ++v)
      {
        Vector<double> components(s[v].begin(), s[v].end());
        fields.s[v] = stress_tensor<3>(components);
      }
  }

  void
  HexahedronBound::compute(std::vector<double> &bound_squared,
                           double              &solution_energy,
                           double              &traction_residual,
                           double              &cell_residual)
  {
    const HexahedronFaceTractions faces(results);
    // The largest stress dof over every process.
    const double sigma_max = results.stress.linfty_norm();
    traction_residual      = faces.residual;
    cell_residual = solution_energy = 0;
    cell_maps.assign(results.triangulation().n_active_cells(), CellMap());
    CellFields     fields;
    Vector<double> f(3);
    for (const auto &cell :
         results.spaces.dof_handler_displacement.active_cell_iterators())
      if (results.partition.owned_cell[cell->active_cell_index()])
        {
          const unsigned int index = cell->active_cell_index();
          auto              &body  = bodies[cell->material_id()];
          if (!body)
            body = std::make_unique<Body>(component_compliance(
              results.scene.material_of(cell->material_id())));
          // The shape's map, made on its first cell.
          const auto vertices = vertices_of(cell);
          auto &map = body->maps[HexahedronEquilibration::shape_key(vertices)];
          if (!map)
            map =
              std::make_unique<HexahedronShapeMap>(body->eq, vertices, body->S);
          const double s = vertices[0].distance(vertices[7]) / map->h;
          sample(cell, fields);
          CellMap &c = cell_maps[index];
          c.map      = map.get();
          c.s        = s;
          c.d.assign(HexahedronShapeMap::n_data, 0.);
          for (unsigned int v = 0; v < 8; ++v)
            for (unsigned int i = 0; i < 3; ++i)
              c.d[HexahedronShapeMap::u_index(v, i)] = fields.u[v][i] / s;
          for (unsigned int k = 0; k < 6; ++k)
            {
              const auto   face = cell->face(k);
              Tensor<1, 3> n =
                cross_product_3d(face->vertex(1) - face->vertex(0),
                                 face->vertex(2) - face->vertex(0));
              if (n * (face->center() - cell->center()) < 0)
                n = -n;
              n /= n.norm();
              const auto points = HexahedronShapeMap::face_points(vertices, k);
              std::array<Tensor<1, 3>, 9> t;
              for (unsigned int q = 0; q < 9; ++q)
                t[q] = faces.traction(face->index(), index, points[q], n);
              HexahedronShapeMap::project_traction(t, k, c.d.data());
            }
          if (results.scene.body_force)
            {
              const auto points = HexahedronShapeMap::cell_points(vertices);
              std::array<Tensor<1, 3>, 8> values;
              for (unsigned int q = 0; q < 8; ++q)
                {
                  results.scene.body_force->vector_value(points[q], f);
                  values[q] = Tensor<1, 3>({f[0], f[1], f[2]});
                }
              HexahedronShapeMap::project_body_force(values, s, c.d.data());
            }
          bound_squared[index] = s * s * s * map->bound_squared(c.d.data());
          std::array<double, 48> stresses;
          for (unsigned int v = 0; v < 8; ++v)
            {
              const auto a = components(fields.s[v]);
              std::copy(a.begin(), a.end(), stresses.begin() + 6 * v);
            }
          solution_energy += s * s * s * map->stress_energy(stresses);
          // Relative to the largest stress times the cell's face area, as in
          // 2D (the largest stress times its edge length).
          const double h = cell->diameter();
          cell_residual  = std::max(cell_residual,
                                   s * s * map->defect(c.d.data()) /
                                     std::max(sigma_max * h * h, 1e-300));
        }
    const MPI_Comm comm = results.partition.communicator;
    cell_residual       = Utilities::MPI::max(cell_residual, comm);
    solution_energy     = Utilities::MPI::sum(solution_energy, comm);
  }

  std::array<double, 4>
  HexahedronBound::compare(const Function<3> &reference) const
  {
    std::array<double, 4> sums{};
    CellFields            fields;
    std::vector<Point<3>> points;
    std::vector<double>   weights;
    Vector<double>        ref(6);
    for (const auto &cell :
         results.spaces.dof_handler_displacement.active_cell_iterators())
      if (results.partition.owned_cell[cell->active_cell_index()])
        {
          Body                     &body = *bodies.at(cell->material_id());
          const FullMatrix<double> &S    = body.S;
          FullMatrix<double>        C(6, 6);
          C.invert(S);
          HexahedronEquilibration &eq = body.eq;
          eq.set_cell(vertices_of(cell));
          const CellMap &c = cell_maps[cell->active_cell_index()];
          Vector<double> x;
          c.map->coefficients(c.d.data(), x);
          sample(cell, fields);
          for (unsigned int k = 0; k < HexahedronEquilibration::n_tetrahedra;
               ++k)
            {
              eq.tetrahedron_rule(k, points, weights);
              for (unsigned int q = 0; q < points.size(); ++q)
                {
                  reference.vector_value(points[q], ref);
                  const auto     sigma = stress_tensor<3>(ref);
                  const auto     e     = fields.strain(points[q]);
                  const double   ev[6] = {e[0][0],
                                          e[1][1],
                                          e[2][2],
                                          2 * e[0][1],
                                          2 * e[0][2],
                                          2 * e[1][2]};
                  Vector<double> c(6);
                  for (unsigned int a = 0; a < 6; ++a)
                    for (unsigned int b = 0; b < 6; ++b)
                      c(a) += C(a, b) * ev[b];
                  const double w = weights[q];
                  sums[0] += w * energy(S, sigma - stress_tensor<3>(c));
                  sums[1] += w * energy(S, sigma - eq.stress(x, k, points[q]));
                  sums[2] += w * energy(S, sigma - fields.stress(points[q]));
                  sums[3] += w * energy(S, sigma);
                }
            }
        }
    return sums;
  }
} // namespace hrcontact
