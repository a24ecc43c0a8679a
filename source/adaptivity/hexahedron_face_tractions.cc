#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>

#include <hrcontact/adaptivity/face_tractions.h>
#include <hrcontact/adaptivity/hexahedron_face_tractions.h>
#include <hrcontact/adaptivity/vertex_problems.h>
#include <hrcontact/postprocess/field_values.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace hrcontact
{
  using namespace dealii;

  HexahedronFaceTractions::HexahedronFaceTractions(const Results<3> &results)
    : results(results)
  {
    usable = cells_held_whole(results);
    classify_faces();
    cell_residuals();
    solve_vertex_problems();
    // Moments to the bilinear traction's vertex values: the inverse of the
    // parallelogram's mass matrix |F| / 36 (A x A), A = [2 1; 1 2], is
    // 4 / |F| (B x B), B = [2 -1; -1 2].
    const auto &v = results.triangulation().get_vertices();
    for (Face &f : faces)
      if (f.vertices[0] != f.vertices[1])
        {
          const double area =
            cross_product_3d(v[f.vertices[1]] - v[f.vertices[0]],
                             v[f.vertices[2]] - v[f.vertices[0]])
              .norm();
          const double B[2][2] = {{2, -1}, {-1, 2}};
          for (unsigned int j = 0; j < 4; ++j)
            for (unsigned int c = 0; c < 3; ++c)
              {
                f.value[j][c] = 0;
                for (unsigned int k = 0; k < 4; ++k)
                  f.value[j][c] += 4. / area * B[j % 2][k % 2] *
                                   B[j / 2][k / 2] * f.moment[k][c];
              }
        }
  }

  void
  HexahedronFaceTractions::classify_faces()
  {
    // A boundary face is held in component c when its four nodes are.
    std::set<types::global_dof_index> prescribed;
    for (const auto &row : results.system.rows)
      if (row.row_class == RowClass::prescribed)
        prescribed.insert(single_dof(row));
    const auto &tria = results.triangulation();
    faces.assign(tria.n_raw_faces(), Face());
    std::vector<bool> seen(tria.n_raw_faces(), false);
    for (const auto &cell :
         results.spaces.dof_handler_displacement.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        {
          const unsigned int id = cell->face(f)->index();
          if (seen[id] || !usable[cell->active_cell_index()])
            continue;
          seen[id]         = true;
          Face &face       = faces[id];
          face.owner       = cell->active_cell_index();
          face.boundary    = cell->face(f)->at_boundary();
          face.boundary_id = cell->face(f)->boundary_id();
          for (unsigned int j = 0; j < 4; ++j)
            face.vertices[j] = cell->face(f)->vertex_index(j);
          for (unsigned int c = 0; c < 3; ++c)
            {
              bool held = true;
              for (unsigned int j = 0; j < 4; ++j)
                held = held &&
                       prescribed.count(cell->face(f)->vertex_dof_index(j, c));
              face.known[c] = face.boundary && !held;
            }
        }
  }

  std::array<double, 2>
  HexahedronFaceTractions::face_coordinates(const Face     &face,
                                            const Point<3> &x) const
  {
    const auto        &v  = results.triangulation().get_vertices();
    const Tensor<1, 3> d1 = v[face.vertices[1]] - v[face.vertices[0]],
                       d2 = v[face.vertices[2]] - v[face.vertices[0]],
                       y  = x - v[face.vertices[0]];
    const double a11 = d1 * d1, a12 = d1 * d2, a22 = d2 * d2;
    const double det = a11 * a22 - a12 * a12;
    return {{(a22 * (y * d1) - a12 * (y * d2)) / det,
             (a11 * (y * d2) - a12 * (y * d1)) / det}};
  }

  Tensor<1, 3>
  HexahedronFaceTractions::traction(const unsigned int  face,
                                    const unsigned int  cell,
                                    const Point<3>     &x,
                                    const Tensor<1, 3> &normal) const
  {
    const Face  &f    = faces[face];
    const double sign = (f.owner == cell) ? 1. : -1.;
    Tensor<1, 3> data;
    if (f.known[0] || f.known[1] || f.known[2])
      data = data_traction(results.scene, f.boundary_id, x, normal);
    const auto [a, b]   = face_coordinates(f, x);
    const double hat[4] = {(1 - a) * (1 - b), a * (1 - b), (1 - a) * b, a * b};
    Tensor<1, 3> t;
    for (unsigned int i = 0; i < 3; ++i)
      if (f.known[i])
        t[i] = data[i];
      else
        for (unsigned int j = 0; j < 4; ++j)
          t[i] += sign * hat[j] * f.value[j][i];
    return t;
  }

  void
  HexahedronFaceTractions::cell_residuals()
  {
    // R_K on the HR assembly's 2 x 2 x 2 rule; the faces' data moments and
    // averaged sigma_h n on a 3 x 3 rule.
    const Scene<3>             &scene = results.scene;
    const FE_Q<3>               hat(1);
    const QGauss<3>             q_cell(2);
    const QGauss<2>             q_face(3);
    FEValues<3>                 hv(StaticMappingQ1<3>::mapping,
                   hat,
                   q_cell,
                   update_values | update_gradients | update_quadrature_points |
                     update_JxW_values);
    FEValues<3>                 sv(StaticMappingQ1<3>::mapping,
                   *results.spaces.fe_stress,
                   q_cell,
                   update_values);
    FEFaceValues<3>             hf(StaticMappingQ1<3>::mapping,
                       hat,
                       q_face,
                       update_values | update_quadrature_points |
                         update_normal_vectors | update_JxW_values);
    FEFaceValues<3>             sf(StaticMappingQ1<3>::mapping,
                       *results.spaces.fe_stress,
                       q_face,
                       update_values);
    std::vector<Vector<double>> s_cell(q_cell.size(), Vector<double>(6)),
      s_face(q_face.size(), Vector<double>(6));
    cell_residual.assign(results.triangulation().n_active_cells(), {});
    average.assign(faces.size(), {});
    Vector<double> f(3);
    for (const auto &cell :
         results.spaces.dof_handler_stress.active_cell_iterators())
      if (usable[cell->active_cell_index()])
        {
          const Triangulation<3>::active_cell_iterator tc(cell);
          hv.reinit(tc);
          sv.reinit(cell);
          sv.get_function_values(results.stress, s_cell);
          auto &R = cell_residual[cell->active_cell_index()];
          for (unsigned int q = 0; q < q_cell.size(); ++q)
            {
              const auto sigma = stress_tensor<3>(s_cell[q]);
              f                = 0;
              if (scene.body_force)
                scene.body_force->vector_value(hv.quadrature_point(q), f);
              for (unsigned int v = 0; v < 8; ++v)
                {
                  const Tensor<1, 3> sg = sigma * hv.shape_grad(v, q);
                  for (unsigned int c = 0; c < 3; ++c)
                    R[v][c] +=
                      (sg[c] - f[c] * hv.shape_value(v, q)) * hv.JxW(q);
                }
            }
          for (unsigned int v = 0; v < 8; ++v)
            for (unsigned int c = 0; c < 3; ++c)
              scale = std::max(scale, std::abs(R[v][c]));
          for (const unsigned int fn : cell->face_indices())
            {
              hf.reinit(tc, fn);
              sf.reinit(cell, fn);
              sf.get_function_values(results.stress, s_face);
              const unsigned int id   = cell->face(fn)->index();
              Face              &face = faces[id];
              const double       side =
                (face.boundary ? 1. : 0.5) *
                (face.owner == cell->active_cell_index() ? 1. : -1.);
              for (unsigned int q = 0; q < q_face.size(); ++q)
                {
                  const Tensor<1, 3> n  = hf.normal_vector(q);
                  const Tensor<1, 3> sn = stress_tensor<3>(s_face[q]) * n;
                  const Tensor<1, 3> data =
                    face.boundary ? data_traction(results.scene,
                                                  face.boundary_id,
                                                  hf.quadrature_point(q),
                                                  n) :
                                    Tensor<1, 3>();
                  for (unsigned int j = 0; j < 4; ++j)
                    {
                      // The cell's vertex at the face's slot j, by global
                      // index: a face seen from its other side may be
                      // oriented otherwise.
                      unsigned int v = 0;
                      while (cell->vertex_index(v) != face.vertices[j])
                        ++v;
                      const double phi = hf.shape_value(v, q) * hf.JxW(q);
                      for (unsigned int c = 0; c < 3; ++c)
                        if (face.known[c])
                          R[v][c] -= data[c] * phi;
                        else
                          average[id][j][c] += side * sn[c] * phi;
                    }
                }
            }
        }
  }

  void
  HexahedronFaceTractions::solve_vertex_problems()
  {
    const auto &tria = results.triangulation();
    std::vector<std::vector<Triangulation<3>::active_cell_iterator>> patch(
      tria.n_vertices());
    for (const auto &cell : tria.active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int v : cell->vertex_indices())
          patch[cell->vertex_index(v)].push_back(cell);
    for (unsigned int v = 0; v < tria.n_vertices(); ++v)
      {
        bool own = false;
        for (const auto &c : patch[v])
          own = own || results.partition.owned_cell[c->active_cell_index()];
        if (own)
          solve_vertex(v, patch[v]);
      }
    const MPI_Comm comm = results.partition.communicator;
    scale               = Utilities::MPI::max(scale, comm);
    residual            = Utilities::MPI::max(residual, comm);
    residual            = scale > 0 ? residual / scale : 0;
  }

  void
  HexahedronFaceTractions::solve_vertex(
    const unsigned int                                         vi,
    const std::vector<Triangulation<3>::active_cell_iterator> &cells)
  {
    const unsigned int n = cells.size();
    // The faces through vi, each cell's local index of vi and its faces'
    // signs.
    std::vector<unsigned int>             face_ids;
    std::vector<unsigned int>             local(n), cell_index(n);
    constexpr unsigned int                max_faces = 32;
    std::vector<std::vector<signed char>> sign(
      n, std::vector<signed char>(max_faces, 0));
    for (unsigned int i = 0; i < n; ++i)
      {
        AssertThrow(usable[cells[i]->active_cell_index()],
                    ExcMessage("Error bound: a vertex patch of an own cell "
                               "is not held whole by this process."));
        cell_index[i] = cells[i]->active_cell_index();
        for (unsigned int v = 0; v < 8; ++v)
          if (cells[i]->vertex_index(v) == vi)
            local[i] = v;
        for (const unsigned int fn : cells[i]->face_indices())
          {
            const auto face    = cells[i]->face(fn);
            bool       through = false;
            for (unsigned int j = 0; j < 4; ++j)
              through = through || face->vertex_index(j) == vi;
            if (!through)
              continue;
            const unsigned int id = face->index();
            unsigned int       k  = 0;
            while (k < face_ids.size() && face_ids[k] != id)
              ++k;
            if (k == face_ids.size())
              face_ids.push_back(id);
            AssertThrow(face_ids.size() <= max_faces,
                        ExcMessage("Error bound: too many faces at a vertex."));
            sign[i][k] = faces[id].owner == cell_index[i] ? 1 : -1;
          }
      }
    const auto slot = [&](const Face &face) {
      unsigned int j = 0;
      while (face.vertices[j] != vi)
        ++j;
      return j;
    };
    std::vector<signed char> key;
    for (unsigned int c = 0; c < 3; ++c)
      {
        std::vector<unsigned int> unknown;
        for (unsigned int k = 0; k < face_ids.size(); ++k)
          if (!faces[face_ids[k]].known[c])
            unknown.push_back(k);
        const unsigned int m = unknown.size();
        key.assign({(signed char)n, (signed char)m});
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int k = 0; k < m; ++k)
            key.push_back(sign[i][unknown[k]]);
        const auto A = [&](const unsigned int i, const unsigned int k) {
          return double(key[2 + i * m + k]);
        };
        // b = b0 + A^+ (R - A b0); what is left: R - A b.
        std::vector<double> b(m), r(n), R(n);
        for (unsigned int k = 0; k < m; ++k)
          {
            const Face &face = faces[face_ids[unknown[k]]];
            b[k]             = average[face_ids[unknown[k]]][slot(face)][c];
          }
        for (unsigned int i = 0; i < n; ++i)
          {
            R[i] = cell_residual[cell_index[i]][local[i]][c];
            r[i] = R[i];
            for (unsigned int k = 0; k < m; ++k)
              r[i] -= A(i, k) * b[k];
          }
        if (m > 0)
          {
            const FullMatrix<double> &P = pseudo_inverse(key);
            for (unsigned int k = 0; k < m; ++k)
              for (unsigned int i = 0; i < n; ++i)
                b[k] += P(k, i) * r[i];
          }
        for (unsigned int i = 0; i < n; ++i)
          {
            double Ab = 0;
            for (unsigned int k = 0; k < m; ++k)
              Ab += A(i, k) * b[k];
            residual = std::max(residual, std::abs(R[i] - Ab));
          }
        for (unsigned int k = 0; k < m; ++k)
          {
            Face &face                 = faces[face_ids[unknown[k]]];
            face.moment[slot(face)][c] = b[k];
          }
      }
  }
} // namespace hrcontact
