#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>

#include <deal.II/grid/grid_tools.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <deal.II/distributed/tria_base.h>

#include <hrcontact/adaptivity/face_tractions.h>
#include <hrcontact/postprocess/field_values.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
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
    // The cells whose stresses and displacements this process holds (its
    // own and its ghosts): the vertex problems of its own cells' vertices
    // need no more.
    usable.assign(results.triangulation().n_active_cells(), false);
    std::vector<types::global_dof_index> dofs;
    const auto holds = [](const FieldVector &v, const auto &indices) {
      for (const auto i : indices)
        if (!v.in_local_range(i) && !v.get_partitioner()->is_ghost_entry(i))
          return false;
      return true;
    };
    for (const auto &cell :
         results.spaces.dof_handler_stress.active_cell_iterators())
      if (!cell->is_artificial())
        {
          dofs.resize(cell->get_fe().n_dofs_per_cell());
          cell->get_dof_indices(dofs);
          bool ok = holds(results.stress, dofs);
          const DoFHandler<2>::active_cell_iterator u_cell(
            &results.triangulation(),
            cell->level(),
            cell->index(),
            &results.spaces.dof_handler_displacement);
          dofs.resize(u_cell->get_fe().n_dofs_per_cell());
          u_cell->get_dof_indices(dofs);
          usable[cell->active_cell_index()] =
            ok && holds(results.displacement, dofs);
        }
    classify_faces();
    cell_residuals();
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
    // (Prescribed displacements); a point support holds no face.
    std::set<types::global_dof_index> prescribed;
    for (const auto &row : results.system.rows)
      if (row.row_class == RowClass::prescribed)
        prescribed.insert(single_dof(row));
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

  Tensor<1, 2>
  FaceTractions::data_traction(const types::boundary_id id,
                               const Point<2>          &x,
                               const Tensor<1, 2>      &normal) const
  {
    const Scene<2> &scene = results.scene;
    Tensor<1, 2>    t;
    Vector<double>  v(2);
    if (const auto it = scene.tractions.find(id); it != scene.tractions.end())
      {
        it->second->vector_value(x, v);
        for (unsigned int d = 0; d < 2; ++d)
          t[d] += v[d];
      }
    if (const auto it = scene.projected_pressures.find(id);
        it != scene.projected_pressures.end())
      {
        it->second->vector_value(x, v);
        for (unsigned int d = 0; d < 2; ++d)
          t[d] -= v[d] * normal[d];
      }
    return t;
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
      data = data_traction(f.boundary_id, x, normal);
    Tensor<1, 2> t;
    const double legendre = 6 * lambda * lambda - 6 * lambda + 1;
    for (unsigned int i = 0; i < 2; ++i)
      t[i] = f.known[i] ?
               data[i] :
               sign * ((1 - lambda) * f.value[0][i] + lambda * f.value[1][i] +
                       legendre * f.bubble[i]);
    return t;
  }

  void
  FaceTractions::cell_residuals()
  {
    const Scene<2>             &scene = results.scene;
    const FE_Q<2>               hat(1);
    const QGauss<2>             q_cell(4);
    FEValues<2>                 hv(StaticMappingQ1<2>::mapping,
                   hat,
                   q_cell,
                   update_values | update_gradients | update_quadrature_points |
                     update_JxW_values);
    FEValues<2>                 sv(StaticMappingQ1<2>::mapping,
                   *results.spaces.fe_stress,
                   q_cell,
                   update_values);
    const QGauss<1>             q_face(6);
    FEFaceValues<2>             hfv(StaticMappingQ1<2>::mapping,
                        hat,
                        q_face,
                        update_values | update_quadrature_points |
                          update_normal_vectors | update_JxW_values);
    FEFaceValues<2>             sfv(StaticMappingQ1<2>::mapping,
                        *results.spaces.fe_stress,
                        q_face,
                        update_values);
    FESubfaceValues<2>          hsv(StaticMappingQ1<2>::mapping,
                           hat,
                           q_face,
                           update_quadrature_points | update_normal_vectors |
                             update_JxW_values);
    FESubfaceValues<2>          ssv(StaticMappingQ1<2>::mapping,
                           *results.spaces.fe_stress,
                           q_face,
                           update_values);
    std::vector<Vector<double>> s_values(
      q_cell.size(), Vector<double>(MixedSpaces<2>::n_stress_components));
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
          face_moments(cell, hfv, sfv, hsv, ssv);
        }
  }

  void
  FaceTractions::face_moments(const DoFHandler<2>::active_cell_iterator &cell,
                              FEFaceValues<2>                           &hfv,
                              FEFaceValues<2>                           &sfv,
                              FESubfaceValues<2>                        &hsv,
                              FESubfaceValues<2>                        &ssv)
  {
    // Loaded faces: their data moments leave R_K; the others: the averaged
    // sigma_h n moments against the segment's hats, the start of the vertex
    // problems. A face with a hanging node: each half from this side.
    const unsigned int          n_q = hfv.n_quadrature_points;
    std::vector<Vector<double>> s_face(
      n_q, Vector<double>(MixedSpaces<2>::n_stress_components));
    const unsigned int k        = cell->active_cell_index();
    auto              &R        = cell_residual[k];
    const auto        &vertices = results.triangulation().get_vertices();
    const auto         add      = [&](const unsigned int     fn,
                         const unsigned int     id,
                         const FEValuesBase<2> &h,
                         const FEValuesBase<2> &sv) {
      Face &face = faces[id];
      sv.get_function_values(results.stress, s_face);
      const double side =
        (face.boundary ? 1. : 0.5) * (face.owner == k ? 1. : -1.);
      const Point<2> &a = vertices[face.vertices[0]],
                     &b = vertices[face.vertices[1]];
      for (unsigned int q = 0; q < n_q; ++q)
        {
          const Tensor<1, 2> n  = h.normal_vector(q);
          const Tensor<1, 2> sn = stress_tensor<2>(s_face[q]) * n;
          const double       lambda =
            (h.quadrature_point(q) - a) * (b - a) / (b - a).norm_square();
          const std::array<double, 2> hat{{1 - lambda, lambda}};
          const Tensor<1, 2>          t =
            face.boundary ?
                                    data_traction(face.boundary_id, h.quadrature_point(q), n) :
                                    Tensor<1, 2>();
          for (unsigned int fa = 0; fa < 2; ++fa)
            {
              const double phi = hat[fa] * h.JxW(q);
              // A loaded face is a whole face of this cell: its hat is the
              // cell's.
              const unsigned int v =
                GeometryInfo<2>::face_to_cell_vertices(fn, 0);
              const unsigned int cv =
                cell->vertex_index(v) == face.vertices[fa] ?
                               v :
                               GeometryInfo<2>::face_to_cell_vertices(fn, 1);
              for (unsigned int c = 0; c < 2; ++c)
                if (face.known[c])
                  R[cv][c] -= t[c] * phi;
                else
                  average[id][fa][c] += side * sn[c] * phi;
            }
        }
    };
    for (const unsigned int fn : cell->face_indices())
      if (cell->face(fn)->has_children())
        for (unsigned int sf = 0; sf < 2; ++sf)
          {
            hsv.reinit(Triangulation<2>::active_cell_iterator(cell), fn, sf);
            ssv.reinit(cell, fn, sf);
            add(fn, cell->face(fn)->child(sf)->index(), hsv, ssv);
          }
      else
        {
          hfv.reinit(Triangulation<2>::active_cell_iterator(cell), fn);
          sfv.reinit(cell, fn);
          add(fn, cell->face(fn)->index(), hfv, sfv);
        }
  }

  const FullMatrix<double> &
  FaceTractions::pseudo_inverse(const FullMatrix<double> &A,
                                const unsigned int        m)
  {
    // Kept per sign pattern: most vertices share one of a few.
    const unsigned int       n = A.m();
    std::vector<signed char> key{(signed char)n, (signed char)m};
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < m; ++j)
        key.push_back((signed char)A(i, j));
    auto it = pseudo_inverses.find(key);
    if (it == pseudo_inverses.end())
      {
        LAPACKFullMatrix<double> pinv(n, m);
        pinv = A;
        pinv.compute_inverse_svd(1e-12);
        FullMatrix<double> P(m, n);
        Vector<double>     unit(n), column(m);
        for (unsigned int i = 0; i < n; ++i)
          {
            unit    = 0;
            unit(i) = 1;
            pinv.vmult(column, unit);
            for (unsigned int j = 0; j < m; ++j)
              P(j, i) = column(j);
          }
        it = pseudo_inverses.emplace(key, std::move(P)).first;
      }
    return it->second;
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
    const auto &tria         = results.triangulation();
    const auto  vertex_cells = GridTools::vertex_to_cell_map(tria);
    residual                 = 0;
    // The cells with vertex vi (the map also lists the coarse cells on
    // whose faces vi hangs).
    const auto patch = [&](const unsigned int vi) {
      std::vector<Triangulation<2>::active_cell_iterator> cells;
      for (const auto &c : vertex_cells[vi])
        for (const unsigned int v : c->vertex_indices())
          if (c->vertex_index(v) == vi)
            cells.push_back(c);
      return cells;
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
              const auto cells     = patch(h);
              bool       own =
                results.partition.owned_cell[cell->active_cell_index()];
              for (const auto &c : cells)
                own |= results.partition.owned_cell[c->active_cell_index()];
              if (own)
                solve_vertex(h, cells, true);
            }
    exchange_from_coarse_cells(hanging_moment);
    for (unsigned int vi = 0; vi < vertex_cells.size(); ++vi)
      if (!hanging[vi])
        {
          // Only the vertices of this process's own cells (whose patches it
          // holds whole).
          const auto cells = patch(vi);
          bool       own   = false;
          for (const auto &c : cells)
            own |= results.partition.owned_cell[c->active_cell_index()];
          if (own)
            solve_vertex(vi, cells, false);
        }
    const MPI_Comm comm = results.partition.communicator;
    scale               = Utilities::MPI::max(scale, comm);
    residual            = Utilities::MPI::max(residual, comm);
    residual            = scale > 0 ? residual / scale : 0;
  }

  void
  FaceTractions::solve_vertex(
    const unsigned int                                         vi,
    const std::vector<Triangulation<2>::active_cell_iterator> &cells,
    const bool                                                 hanging)
  {
    for (const auto &c : cells)
      AssertThrow(usable[c->active_cell_index()],
                  ExcMessage("Error bound: a vertex patch of an own cell "
                             "is not held whole by this process."));
    // The vertex's index in each cell, the cells' segments through it, and
    // what the hanging nodes' moments already give each row (a coarse
    // cell's face through vi that a hanging node splits: half of that
    // node's moments on both halves, eq. of the conforming hat).
    const unsigned int                     n = cells.size();
    std::vector<unsigned int>              local(n);
    std::vector<std::vector<unsigned int>> cell_faces(n);
    std::vector<std::array<double, 2>>     known(n, {{0., 0.}});
    for (unsigned int i = 0; i < n; ++i)
      {
        for (unsigned int v = 0; v < 4; ++v)
          if (cells[i]->vertex_index(v) == vi)
            local[i] = v;
        for (const unsigned int fn : cells[i]->face_indices())
          {
            const auto face = cells[i]->face(fn);
            if (face->vertex_index(0) != vi && face->vertex_index(1) != vi)
              continue;
            const unsigned int id = segment_through(face, vi);
            cell_faces[i].push_back(id);
            if (!face->has_children())
              continue;
            const double sign =
              faces[id].owner == cells[i]->active_cell_index() ? 1. : -1.;
            for (unsigned int half = 0; half < 2; ++half)
              {
                const auto it = hanging_moment.find(face->child(half)->index());
                AssertThrow(it != hanging_moment.end(),
                            ExcMessage("Error bound: a hanging node's "
                                       "moments are missing."));
                for (unsigned int c = 0; c < 2; ++c)
                  known[i][c] += sign * 0.5 * it->second[c];
              }
          }
      }
    for (unsigned int c = 0; c < 2; ++c)
      {
        std::vector<unsigned int> unknown;
        for (const auto &fs : cell_faces)
          for (const unsigned int id : fs)
            if (!faces[id].known[c] &&
                std::find(unknown.begin(), unknown.end(), id) == unknown.end())
              unknown.push_back(id);
        const unsigned int m = unknown.size();
        Vector<double>     R(n), b0(m), b(m);
        FullMatrix<double> A(n, std::max(m, 1u));
        for (unsigned int i = 0; i < n; ++i)
          {
            R(i) = cell_residual[cells[i]->active_cell_index()][local[i]][c] -
                   known[i][c];
            for (unsigned int j = 0; j < m; ++j)
              if (std::find(cell_faces[i].begin(),
                            cell_faces[i].end(),
                            unknown[j]) != cell_faces[i].end())
                A(i, j) =
                  faces[unknown[j]].owner == cells[i]->active_cell_index() ?
                    1. :
                    -1.;
          }
        for (unsigned int j = 0; j < m; ++j)
          b0(j) =
            average[unknown[j]][faces[unknown[j]].vertices[0] == vi ? 0 : 1][c];
        // b = b0 + A^+ (R - A b0); what is left: R - A b.
        Vector<double> r(R);
        if (m > 0)
          {
            Vector<double> Ab(n);
            A.vmult(Ab, b0);
            r -= Ab;
            pseudo_inverse(A, m).vmult(b, r);
            b += b0;
            A.vmult(Ab, b);
            r = R;
            r -= Ab;
          }
        residual = std::max(residual, r.linfty_norm());
        for (unsigned int j = 0; j < m; ++j)
          {
            Face              &face = faces[unknown[j]];
            const unsigned int end  = face.vertices[0] == vi ? 0 : 1;
            face.moment[end][c]     = b(j);
            if (hanging)
              hanging_moment[unknown[j]][c] = b(j);
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
    exchange_from_coarse_cells(bubble);
    for (const auto &[line, b] : bubble)
      faces[line].bubble = b;
  }

  void
  FaceTractions::exchange_from_coarse_cells(
    std::map<unsigned int, std::array<double, 2>> &values) const
  {
    using Tria       = parallel::TriangulationBase<2>;
    const auto *tria = dynamic_cast<const Tria *>(&results.triangulation());
    if (tria == nullptr || tria->n_global_active_cells() == 0 ||
        Utilities::MPI::n_mpi_processes(results.partition.communicator) == 1)
      return;
    using Cell = Triangulation<2>::active_cell_iterator;
    // Per refined face of an owned cell: its number and its halves'
    // moments.
    GridTools::exchange_cell_data_to_ghosts<std::vector<double>,
                                            Triangulation<2>>(
      results.triangulation(),
      [&](const Cell &cell) -> std::optional<std::vector<double>> {
        std::vector<double> data;
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->has_children())
            {
              data.push_back(f);
              for (unsigned int half = 0; half < 2; ++half)
                for (unsigned int c = 0; c < 2; ++c)
                  data.push_back(
                    values[cell->face(f)->child(half)->index()][c]);
            }
        if (data.empty())
          return {};
        return data;
      },
      [&](const Cell &cell, const std::vector<double> &data) {
        for (unsigned int i = 0; i + 5 <= data.size(); i += 5)
          {
            const auto face = cell->face(static_cast<unsigned int>(data[i]));
            // Where the fine side is artificial here the face is whole: no
            // problem here needs its halves.
            if (!face->has_children())
              continue;
            for (unsigned int half = 0; half < 2; ++half)
              for (unsigned int c = 0; c < 2; ++c)
                values[face->child(half)->index()][c] =
                  data[i + 1 + 2 * half + c];
          }
      });
  }
} // namespace hrcontact
