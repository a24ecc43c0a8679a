#include <deal.II/base/array_view.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>

#include <hrcontact/adaptivity/contact_row_kinds.h>
#include <hrcontact/adaptivity/face_tractions.h>
#include <hrcontact/adaptivity/refined_face_exchange.h>
#include <hrcontact/postprocess/field_values.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>

namespace hrcontact
{
  using namespace dealii;

  long long
  single_dof(const EquilibriumRow &row)
  {
    long long dof = -1;
    for (const auto &[d, c] : row.combination)
      if (c != 0)
        {
          if (dof >= 0 || std::abs(std::abs(c) - 1) > 1e-14)
            return -1;
          dof = d;
        }
    return dof;
  }

  FaceTractions::FaceTractions(const Results<2> &results)
    : results(results)
  {
    usable = cells_held_whole(results);
    if (!results.system.contact_rows.empty())
      contact_tractions = std::make_unique<ContactTractions>(results);
    classify_faces();
    cell_residuals();
    subtract_contact_moments();
    solve_vertex_problems();
    // Moments to the linear traction's vertex values (the face's mass
    // matrix |F| / 6 [2 1; 1 2]).
    const auto &vertices = results.triangulation().get_vertices();
    for (Face &f : faces)
      if (f.vertices[0] != f.vertices[1])
        {
          const double L =
            (vertices[f.vertices[1]] - vertices[f.vertices[0]]).norm();
          for (unsigned int c = 0; c < 2; ++c)
            {
              f.value[0][c] = 2. / L * (2 * f.moment[0][c] - f.moment[1][c]);
              f.value[1][c] = 2. / L * (2 * f.moment[1][c] - f.moment[0][c]);
            }
        }
    join_halves();
  }

  void
  FaceTractions::classify_faces()
  {
    // A boundary face is held in component c when both its nodes are
    // (Prescribed displacements, Normal displacements along an axis); a
    // point support holds no face.
    std::set<types::global_dof_index> prescribed;
    for (const auto &row : results.system.rows)
      if (row.row_class == RowClass::prescribed)
        prescribed.insert(single_dof(row));
    // Bilateral normal rows along an axis hold their component likewise.
    for (const unsigned int r : results.system.contact_rows)
      if (const long long dof =
            ContactRowKinds::held_dof(results.system, results.system.rows[r]);
          dof >= 0)
        prescribed.insert(dof);
    const auto &tria = results.triangulation();
    faces.assign(tria.n_raw_lines(), Face());
    std::vector<bool> seen(tria.n_raw_lines(), false);
    for (const auto &cell :
         results.spaces.dof_handler_displacement.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        {
          // A face with a hanging node: its halves are the fine cells'.
          const unsigned int id = cell->face(f)->index();
          if (seen[id] || !usable[cell->active_cell_index()] ||
              cell->face(f)->has_children())
            continue;
          seen[id]      = true;
          Face &face    = faces[id];
          face.owner    = cell->active_cell_index();
          face.vertices = {
            {cell->face(f)->vertex_index(0), cell->face(f)->vertex_index(1)}};
          face.boundary    = cell->face(f)->at_boundary();
          face.boundary_id = cell->face(f)->boundary_id();
          for (unsigned int c = 0; c < 2; ++c)
            face.known[c] =
              face.boundary &&
              !(prescribed.count(cell->face(f)->vertex_dof_index(0, c)) &&
                prescribed.count(cell->face(f)->vertex_dof_index(1, c)));
        }
  }

  void
  FaceTractions::subtract_contact_moments()
  {
    if (!contact_tractions)
      return;
    for (const auto &cell : results.triangulation().active_cell_iterators())
      if (usable[cell->active_cell_index()])
        for (const unsigned int f : cell->face_indices())
          if (const auto *c = contact_tractions->find(cell->face(f)->index()))
            {
              const auto m =
                ContactTractions::moments(*c, cell->face(f)->measure());
              for (unsigned int fa = 0; fa < 2; ++fa)
                for (const unsigned int v : cell->vertex_indices())
                  if (cell->vertex_index(v) == cell->face(f)->vertex_index(fa))
                    for (unsigned int i = 0; i < 2; ++i)
                      cell_residual[cell->active_cell_index()][v][i] -=
                        m[fa] * c->direction[i];
            }
  }

  Tensor<1, 2>
  FaceTractions::traction(const unsigned int  face,
                          const unsigned int  cell,
                          const Point<2>     &x,
                          const Tensor<1, 2> &normal) const
  {
    const Face  &f      = faces[face];
    const auto  &v      = results.triangulation().get_vertices();
    const double sign   = (f.owner == cell) ? 1. : -1.;
    const double lambda = (x - v[f.vertices[0]]) *
                          (v[f.vertices[1]] - v[f.vertices[0]]) /
                          (v[f.vertices[1]] - v[f.vertices[0]]).norm_square();
    Tensor<1, 2> data;
    if (f.known[0] || f.known[1])
      data = data_traction(results.scene, f.boundary_id, x, normal);
    Tensor<1, 2> t;
    const double legendre = 6 * lambda * lambda - 6 * lambda + 1;
    for (unsigned int i = 0; i < 2; ++i)
      t[i] = f.known[i] ?
               data[i] :
               sign * ((1 - lambda) * f.value[0][i] + lambda * f.value[1][i] +
                       legendre * f.bubble[i]);
    if (contact_tractions)
      if (const auto *c = contact_tractions->find(face))
        t += ContactTractions::traction(*c, lambda);
    return t;
  }

  void
  FaceTractions::cell_residuals()
  {
    // sigma_h at the cell's 2 x 2 Gauss points (the HR assembly's rule) and
    // at two Gauss points of each face and of each of its halves, all from
    // one FEValues on unit points (values only: no mapping per face).
    const Scene<2> &scene = results.scene;
    const FE_Q<2>   hat(1);
    const QGauss<2> q_cell(2);
    const QGauss<1> q_face(2);
    // Per face: the whole face, then its halves from vertex 0 and 1.
    std::vector<Point<2>> unit(q_cell.get_points());
    for (const unsigned int f : GeometryInfo<2>::face_indices())
      {
        const Point<2> a = GeometryInfo<2>::unit_cell_vertex(
                         GeometryInfo<2>::face_to_cell_vertices(f, 0)),
                       b = GeometryInfo<2>::unit_cell_vertex(
                         GeometryInfo<2>::face_to_cell_vertices(f, 1));
        for (const auto &[from, length] :
             {std::pair(0., 1.), std::pair(0., 0.5), std::pair(0.5, 0.5)})
          for (unsigned int g = 0; g < 2; ++g)
            unit.push_back(a + (from + length * q_face.point(g)[0]) * (b - a));
      }
    FEValues<2>                 hv(StaticMappingQ1<2>::mapping,
                   hat,
                   q_cell,
                   update_values | update_gradients | update_quadrature_points |
                     update_JxW_values);
    FEValues<2>                 sv(StaticMappingQ1<2>::mapping,
                   *results.spaces.fe_stress,
                   Quadrature<2>(unit),
                   update_values);
    std::vector<Vector<double>> s_values(
      unit.size(), Vector<double>(MixedSpaces<2>::n_stress_components));
    cell_residual.assign(results.triangulation().n_active_cells(), {});
    average.assign(faces.size(), {});
    Vector<double> f(2);
    for (const auto &cell :
         results.spaces.dof_handler_stress.active_cell_iterators())
      if (usable[cell->active_cell_index()])
        {
          hv.reinit(Triangulation<2>::active_cell_iterator(cell));
          sv.reinit(cell);
          sv.get_function_values(results.stress, s_values);
          auto &R = cell_residual[cell->active_cell_index()];
          for (unsigned int q = 0; q < q_cell.size(); ++q)
            {
              const auto sigma = stress_tensor<2>(s_values[q]);
              f                = 0;
              if (scene.body_force)
                scene.body_force->vector_value(hv.quadrature_point(q), f);
              for (unsigned int v = 0; v < 4; ++v)
                {
                  const Tensor<1, 2> sg = sigma * hv.shape_grad(v, q);
                  for (unsigned int c = 0; c < 2; ++c)
                    R[v][c] +=
                      (sg[c] - f[c] * hv.shape_value(v, q)) * hv.JxW(q);
                }
            }
          for (unsigned int v = 0; v < 4; ++v)
            for (unsigned int c = 0; c < 2; ++c)
              scale = std::max(scale, std::abs(R[v][c]));
          face_moments(cell, q_face, s_values);
        }
  }

  void
  FaceTractions::face_moments(const DoFHandler<2>::active_cell_iterator &cell,
                              const QGauss<1>                           &q_face,
                              const std::vector<Vector<double>> &s_values)
  {
    // Loaded faces: their data moments leave R_K; the others: the averaged
    // sigma_h n moments against the segment's hats, the start of the vertex
    // problems. A face with a hanging node: each half from this side. The
    // faces are straight (Q1 mapping): points, lengths and normals from the
    // vertices.
    const unsigned int k        = cell->active_cell_index();
    auto              &R        = cell_residual[k];
    const auto        &vertices = results.triangulation().get_vertices();
    for (const unsigned int fn : cell->face_indices())
      {
        const unsigned int v0 = GeometryInfo<2>::face_to_cell_vertices(fn, 0),
                           v1 = GeometryInfo<2>::face_to_cell_vertices(fn, 1);
        const Point<2> p0 = cell->vertex(v0), p1 = cell->vertex(v1);
        // Outward: faces 0 and 3 turn the tangent p0 -> p1
        // counter-clockwise, faces 1 and 2 clockwise.
        const Tensor<1, 2> t    = (p1 - p0) / (p1 - p0).norm();
        const Tensor<1, 2> n    = (fn == 0 || fn == 3) ?
                                    Tensor<1, 2>({-t[1], t[0]}) :
                                    Tensor<1, 2>({t[1], -t[0]});
        const auto         face = cell->face(fn);
        for (unsigned int part = 0; part < (face->has_children() ? 2 : 1);
             ++part)
          {
            // The segment, and which half of p0 -> p1 it covers.
            unsigned int id = face->index(), first = 4 + 6 * fn;
            double       from = 0, length = 1;
            if (face->has_children())
              {
                id = face->child(part)->index();
                const bool at_p0 =
                  face->child(part)->vertex_index(0) ==
                    cell->vertex_index(v0) ||
                  face->child(part)->vertex_index(1) == cell->vertex_index(v0);
                from   = at_p0 ? 0. : 0.5;
                length = 0.5;
                first += at_p0 ? 2 : 4;
              }
            Face        &face_data = faces[id];
            const double side      = (face_data.boundary ? 1. : 0.5) *
                                (face_data.owner == k ? 1. : -1.);
            const Point<2> &a = vertices[face_data.vertices[0]],
                           &b = vertices[face_data.vertices[1]];
            const double L    = length * (p1 - p0).norm();
            for (unsigned int g = 0; g < q_face.size(); ++g)
              {
                const Point<2> x =
                  p0 + (from + length * q_face.point(g)[0]) * (p1 - p0);
                const double       JxW = q_face.weight(g) * L;
                const Tensor<1, 2> sn =
                  stress_tensor<2>(s_values[first + g]) * n;
                const double lambda = (x - a) * (b - a) / (b - a).norm_square();
                const std::array<double, 2> hat{{1 - lambda, lambda}};
                const Tensor<1, 2>          data =
                  face_data.boundary ?
                             data_traction(results.scene, face_data.boundary_id, x, n) :
                             Tensor<1, 2>();
                for (unsigned int fa = 0; fa < 2; ++fa)
                  {
                    // A loaded face is a whole face of this cell: its hat
                    // is the cell's.
                    const unsigned int cv =
                      cell->vertex_index(v0) == face_data.vertices[fa] ? v0 :
                                                                         v1;
                    for (unsigned int c = 0; c < 2; ++c)
                      if (face_data.known[c])
                        R[cv][c] -= data[c] * hat[fa] * JxW;
                      else
                        average[id][fa][c] += side * sn[c] * hat[fa] * JxW;
                  }
              }
          }
      }
  }

  unsigned int
  FaceTractions::segment_through(
    const TriaIterator<TriaAccessor<1, 2, 2>> &face,
    const unsigned int                         vertex)
  {
    if (!face->has_children())
      return face->index();
    return face->child(0)->vertex_index(0) == vertex ||
               face->child(0)->vertex_index(1) == vertex ?
             face->child(0)->index() :
             face->child(1)->index();
  }

  void
  FaceTractions::solve_vertex_problems()
  {
    const auto &tria = results.triangulation();
    residual         = 0;
    // The cells with each vertex (not those on whose faces it hangs), in
    // one array by vertex: cells[start[v]] .. cells[start[v + 1] - 1].
    using Cell = Triangulation<2>::active_cell_iterator;
    std::vector<unsigned int> start(tria.n_vertices() + 1, 0);
    for (const auto &cell : tria.active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int v : cell->vertex_indices())
          ++start[cell->vertex_index(v) + 1];
    for (unsigned int v = 0; v < tria.n_vertices(); ++v)
      start[v + 1] += start[v];
    std::vector<Cell>         cells(start.back());
    std::vector<unsigned int> filled(start.begin(), start.end() - 1);
    for (const auto &cell : tria.active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int v : cell->vertex_indices())
          cells[filled[cell->vertex_index(v)]++] = cell;
    const auto patch = [&](const unsigned int v) {
      return ArrayView<const Cell>(cells.data() + start[v],
                                   start[v + 1] - start[v]);
    };
    const auto own = [&](const ArrayView<const Cell> &patch) {
      for (const auto &c : patch)
        if (results.partition.owned_cell[c->active_cell_index()])
          return true;
      return false;
    };
    // First the hanging nodes: those on this process's own coarse cells'
    // faces or of its own fine cells (it holds their three cells).
    std::vector<bool> hanging(tria.n_vertices(), false);
    for (const auto &cell : tria.active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->has_children())
            {
              const unsigned int h = cell->face(f)->child(0)->vertex_index(1);
              hanging[h]           = true;
              if (results.partition.owned_cell[cell->active_cell_index()] ||
                  own(patch(h)))
                solve_vertex(h, patch(h), true);
            }
    exchange_from_coarse_cells(results.triangulation(),
                               results.partition.communicator,
                               hanging_moment);
    // Then the others of this process's own cells (whose patches it holds
    // whole).
    for (unsigned int v = 0; v < tria.n_vertices(); ++v)
      if (!hanging[v] && own(patch(v)))
        solve_vertex(v, patch(v), false);
    const MPI_Comm comm = results.partition.communicator;
    scale               = Utilities::MPI::max(scale, comm);
    residual            = Utilities::MPI::max(residual, comm);
    residual            = scale > 0 ? residual / scale : 0;
  }

  void
  FaceTractions::solve_vertex(
    const unsigned int                                             vi,
    const ArrayView<const Triangulation<2>::active_cell_iterator> &cells,
    const bool                                                     hanging)
  {
    // Fixed-size scratch: a 2D vertex has a handful of cells.
    constexpr unsigned int max_cells = 16;
    const unsigned int     n         = cells.size();
    AssertThrow(n <= max_cells,
                ExcMessage("Error bound: more than 16 cells at a vertex."));
    // The vertex's index in each cell, the segments through it (bit j of
    // member[i]: segment j is a face of cell i, with sign[i][j]), and what
    // the hanging nodes' moments already give each row (a coarse cell's
    // face through vi that a hanging node splits: half of that node's
    // moments on both halves, from the conforming hat).
    std::array<unsigned int, max_cells>          local{}, cell{};
    std::array<unsigned int, 2 * max_cells>      segment{};
    std::array<std::uint32_t, max_cells>         member{};
    std::array<std::array<double, 2>, max_cells> known{};
    std::array<std::array<signed char, 2 * max_cells>, max_cells> sign{};
    unsigned int n_segments = 0;
    for (unsigned int i = 0; i < n; ++i)
      {
        AssertThrow(usable[cells[i]->active_cell_index()],
                    ExcMessage("Error bound: a vertex patch of an own cell "
                               "is not held whole by this process."));
        cell[i] = cells[i]->active_cell_index();
        for (unsigned int v = 0; v < 4; ++v)
          if (cells[i]->vertex_index(v) == vi)
            local[i] = v;
        for (const unsigned int fn : cells[i]->face_indices())
          {
            const auto face = cells[i]->face(fn);
            if (face->vertex_index(0) != vi && face->vertex_index(1) != vi)
              continue;
            const unsigned int id = segment_through(face, vi);
            unsigned int       j  = 0;
            while (j < n_segments && segment[j] != id)
              ++j;
            if (j == n_segments)
              segment[n_segments++] = id;
            member[i] |= 1u << j;
            sign[i][j] = faces[id].owner == cell[i] ? 1 : -1;
            if (!face->has_children())
              continue;
            for (unsigned int half = 0; half < 2; ++half)
              {
                const auto it = hanging_moment.find(face->child(half)->index());
                AssertThrow(it != hanging_moment.end(),
                            ExcMessage("Error bound: a hanging node's "
                                       "moments are missing."));
                for (unsigned int c = 0; c < 2; ++c)
                  known[i][c] += sign[i][j] * 0.5 * it->second[c];
              }
          }
      }
    std::array<unsigned int, 2 * max_cells> unknown{};
    std::array<double, 2 * max_cells>       b{}, start{};
    std::array<double, max_cells>           R{}, r{};
    for (unsigned int c = 0; c < 2; ++c)
      {
        // The unknowns (faces not loaded in c) and A's sign pattern.
        unsigned int m = 0;
        for (unsigned int j = 0; j < n_segments; ++j)
          if (!faces[segment[j]].known[c])
            unknown[m++] = j;
        key.assign({(signed char)n, (signed char)m});
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int k = 0; k < m; ++k)
            key.push_back((member[i] >> unknown[k]) & 1u ? sign[i][unknown[k]] :
                                                           (signed char)0);
        const auto A = [&](const unsigned int i, const unsigned int k) {
          return double(key[2 + i * m + k]);
        };
        for (unsigned int k = 0; k < m; ++k)
          {
            const Face &face = faces[segment[unknown[k]]];
            start[k] =
              average[segment[unknown[k]]][face.vertices[0] == vi ? 0 : 1][c];
          }
        // b = b0 + A^+ (R - A b0); what is left: R - A b.
        for (unsigned int i = 0; i < n; ++i)
          {
            R[i] = cell_residual[cell[i]][local[i]][c] - known[i][c];
            r[i] = R[i];
            for (unsigned int k = 0; k < m; ++k)
              r[i] -= A(i, k) * start[k];
          }
        if (m > 0)
          {
            const FullMatrix<double> &P = pseudo_inverse(key);
            for (unsigned int k = 0; k < m; ++k)
              {
                b[k] = start[k];
                for (unsigned int i = 0; i < n; ++i)
                  b[k] += P(k, i) * r[i];
              }
          }
        double left = 0;
        for (unsigned int i = 0; i < n; ++i)
          {
            double Ab = 0;
            for (unsigned int k = 0; k < m; ++k)
              Ab += A(i, k) * b[k];
            left = std::max(left, std::abs(R[i] - Ab));
          }
        residual = std::max(residual, left);
        for (unsigned int k = 0; k < m; ++k)
          {
            Face &face = faces[segment[unknown[k]]];
            face.moment[face.vertices[0] == vi ? 0 : 1][c] = b[k];
            if (hanging)
              hanging_moment[segment[unknown[k]]][c] = b[k];
          }
      }
  }

  void
  FaceTractions::join_halves()
  {
    // On own coarse cells: the mean of the halves' linear tractions at the
    // hanging node (the halves' owners, the fine cells, share the normal).
    std::map<unsigned int, std::array<double, 2>> bubble;
    for (const auto &cell : results.triangulation().active_cell_iterators())
      if (results.partition.owned_cell[cell->active_cell_index()])
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->has_children())
            {
              const unsigned int h = cell->face(f)->child(0)->vertex_index(1);
              std::array<std::array<double, 2>, 2> at_h;
              for (unsigned int half = 0; half < 2; ++half)
                {
                  const Face &face = faces[cell->face(f)->child(half)->index()];
                  at_h[half]       = face.value[face.vertices[0] == h ? 0 : 1];
                }
              for (unsigned int half = 0; half < 2; ++half)
                for (unsigned int c = 0; c < 2; ++c)
                  bubble[cell->face(f)->child(half)->index()][c] =
                    0.5 * (at_h[1 - half][c] - at_h[half][c]);
            }
    exchange_from_coarse_cells(results.triangulation(),
                               results.partition.communicator,
                               bubble);
    for (const auto &[line, b] : bubble)
      faces[line].bubble = b;
  }

} // namespace hrcontact
