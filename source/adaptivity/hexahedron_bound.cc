#include <deal.II/base/mpi.h>

#include <deal.II/fe/fe.h>

#include <hrcontact/adaptivity/hexahedron_bound.h>
#include <hrcontact/adaptivity/hexahedron_equilibration.h>
#include <hrcontact/adaptivity/hexahedron_face_tractions.h>
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
    /** The trilinear hat of unit vertex v at xi, and its gradient. */
    double
    hat(const unsigned int v, const Tensor<1, 3> &xi, Tensor<1, 3> &gradient)
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

  HexahedronBound::HexahedronBound(const Results<3> &results)
    : results(results)
  {}

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
    for (unsigned int v = 0; v < 8; ++v)
      {
        const Point<3> p = GeometryInfo<3>::unit_cell_vertex(v);
        fields.u[v]      = Tensor<1, 3>();
        for (unsigned int i = 0; i < u_dofs.size(); ++i)
          fields.u[v][fe_u.system_to_component_index(i).first] +=
            results.displacement(u_dofs[i]) * fe_u.shape_value(i, p);
        Vector<double> components(6);
        for (unsigned int j = 0; j < s_dofs.size(); ++j)
          components(fe_s.system_to_component_index(j).first) +=
            results.stress(s_dofs[j]) * fe_s.shape_value(j, p);
        fields.s[v] = stress_tensor<3>(components);
      }
  }

  void
  HexahedronBound::compute(std::vector<Vector<double>> &coefficients,
                           std::vector<double>         &bound_squared,
                           double                      &solution_energy,
                           double                      &traction_residual,
                           double                      &cell_residual) const
  {
    const HexahedronFaceTractions faces(results);
    // The largest stress dof over every process.
    const double sigma_max = results.stress.linfty_norm();
    traction_residual      = faces.residual;
    cell_residual = solution_energy = 0;
    // Per body: its cell problem and compliance; the own cells in batches
    // of 64 a body (each shape's factors streamed once a batch).
    std::map<types::material_id, std::unique_ptr<HexahedronEquilibration>>
                                                    problems;
    std::map<types::material_id, std::vector<Cell>> pending;
    const auto flush = [&](const types::material_id body) {
      std::vector<Cell> &cells = pending[body];
      if (cells.empty())
        return;
      auto &eq = problems[body];
      if (!eq)
        eq = std::make_unique<HexahedronEquilibration>(
          component_compliance(results.scene.material_of(body)));
      solve_batch(faces,
                  sigma_max,
                  *eq,
                  cells,
                  coefficients,
                  bound_squared,
                  solution_energy,
                  cell_residual);
      cells.clear();
    };
    for (const auto &cell :
         results.spaces.dof_handler_displacement.active_cell_iterators())
      if (results.partition.owned_cell[cell->active_cell_index()])
        {
          pending[cell->material_id()].push_back(cell);
          if (pending[cell->material_id()].size() == 64)
            flush(cell->material_id());
        }
    for (const auto &[body, cells] : pending)
      flush(body);
    const MPI_Comm comm = results.partition.communicator;
    cell_residual       = Utilities::MPI::max(cell_residual, comm);
    solution_energy     = Utilities::MPI::sum(solution_energy, comm);
  }

  void
  HexahedronBound::solve_batch(const HexahedronFaceTractions &faces,
                               const double                   sigma_max,
                               HexahedronEquilibration       &eq,
                               const std::vector<Cell>       &cells,
                               std::vector<Vector<double>>   &coefficients,
                               std::vector<double>           &bound_squared,
                               double                        &solution_energy,
                               double &cell_residual) const
  {
    const auto        &law = results.scene.material_of(cells[0]->material_id());
    FullMatrix<double> S   = component_compliance(law), C(6, 6);
    C.invert(S);
    // Each cell's fields, sampled once; the callbacks read the current one.
    std::vector<CellFields> sampled(cells.size());
    const CellFields       *fields = nullptr;
    Cell                    cell;
    const auto traction = [&](const unsigned int f, const Point<3> &x) {
      const auto   face = cell->face(f);
      Tensor<1, 3> n    = cross_product_3d(face->vertex(1) - face->vertex(0),
                                        face->vertex(2) - face->vertex(0));
      if (n * (face->center() - cell->center()) < 0)
        n = -n;
      return faces.traction(face->index(),
                            cell->active_cell_index(),
                            x,
                            n / n.norm());
    };
    const auto body_force = [&](const Point<3> &x) {
      Vector<double> f(3);
      results.scene.body_force->vector_value(x, f);
      return Tensor<1, 3>({f[0], f[1], f[2]});
    };
    // C eps(u_h): C on the components, engineering shear strains.
    const auto target = [&](const Point<3> &x) {
      const auto   e     = fields->strain(x);
      const double ev[6] = {
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
    const HexahedronEquilibration::VectorField force =
      results.scene.body_force ?
        HexahedronEquilibration::VectorField(body_force) :
        HexahedronEquilibration::VectorField();
    std::vector<HexahedronEquilibration::CellData>         data(cells.size());
    std::vector<const HexahedronEquilibration::CellData *> batch;
    for (unsigned int i = 0; i < cells.size(); ++i)
      {
        cell = cells[i];
        sample(cell, sampled[i]);
        fields = &sampled[i];
        eq.data(vertices_of(cell), traction, force, target, data[i]);
        batch.push_back(&data[i]);
      }
    std::vector<Vector<double>> x;
    std::vector<double>         residuals;
    eq.solve(batch, x, residuals);
    std::vector<Point<3>> points;
    std::vector<double>   weights;
    for (unsigned int i = 0; i < cells.size(); ++i)
      {
        cell                     = cells[i];
        const unsigned int index = cell->active_cell_index();
        eq.set_cell(vertices_of(cell));
        coefficients[index]  = x[i];
        bound_squared[index] = eq.distance(x[i], data[i].targets);
        // Relative to the largest stress times the cell's face area, as in
        // 2D (the largest stress times its edge length).
        const double h = cell->diameter();
        cell_residual =
          std::max(cell_residual,
                   residuals[i] / std::max(sigma_max * h * h, 1e-300));
        for (unsigned int k = 0; k < HexahedronEquilibration::n_tetrahedra; ++k)
          {
            eq.tetrahedron_rule(k, points, weights);
            for (unsigned int q = 0; q < points.size(); ++q)
              solution_energy +=
                weights[q] * energy(S, sampled[i].stress(points[q]));
          }
      }
  }

  std::array<double, 4>
  HexahedronBound::compare(const std::vector<Vector<double>> &coefficients,
                           const Function<3>                 &reference) const
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
          const auto &law      = results.scene.material_of(cell->material_id());
          FullMatrix<double> S = component_compliance(law), C(6, 6);
          C.invert(S);
          HexahedronEquilibration eq(S);
          eq.set_cell(vertices_of(cell));
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
                  sums[1] +=
                    w *
                    energy(S,
                           sigma -
                             eq.stress(coefficients[cell->active_cell_index()],
                                       k,
                                       points[q]));
                  sums[2] += w * energy(S, sigma - fields.stress(points[q]));
                  sums[3] += w * energy(S, sigma);
                }
            }
        }
    return sums;
  }
} // namespace hrcontact
