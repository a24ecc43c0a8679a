#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>

#include <hrcontact/adaptivity/contact_row_kinds.h>
#include <hrcontact/adaptivity/contact_tractions.h>
#include <hrcontact/adaptivity/triangle_split.h>
#include <hrcontact/postprocess/field_values.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hrcontact
{
  using namespace dealii;

  namespace
  {
    /** A node's reaction is shared between its faces so that each face's
     * end moments are within this ratio (nonpositive quadratics). */
    constexpr double ratio = 3;

    /** A contact state the construction cannot carry: the run ends with
     * this message (exit code 2), no bound. */
    [[noreturn]] void
    refuse(const std::string &why)
    {
      throw std::runtime_error("Error bound: " + why + ".");
    }

    Tensor<1, 2>
    row_direction(const EquilibriumRow &row)
    {
      return Tensor<1, 2>(
        {row.direction_component(0), row.direction_component(1)});
    }

    /** @p visit(face, row at its vertex 0, row at its vertex 1) for every
     * boundary face of this process's own and ghost cells whose two nodes
     * have rows in @p row_of_node. */
    template <typename Visit>
    void
    for_each_face_with_rows(
      const Results<2>                           &results,
      const std::map<unsigned int, unsigned int> &row_of_node,
      const Visit                                &visit)
    {
      for (const auto &cell :
           results.spaces.dof_handler_displacement.active_cell_iterators())
        if (!cell->is_artificial())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              {
                const auto face = cell->face(f);
                const auto a =
                  row_of_node.find(face->vertex_dof_index(0, 0) / 2);
                const auto b =
                  row_of_node.find(face->vertex_dof_index(1, 0) / 2);
                if (a != row_of_node.end() && b != row_of_node.end())
                  visit(cell, f, a->second, b->second);
              }
    }

  } // namespace

  ContactTractions::ContactTractions(const Results<2> &results)
  {
    // The gaps of v = u_h from the displacement itself (its own and ghost
    // entries hold every node of these cells), so that the bound is of the
    // field it is given.
    const EquilibriumSystem             &sys = results.system;
    const unsigned int                   nq  = sys.contact_rows.size();
    std::map<unsigned int, unsigned int> row_of_node;
    std::vector<unsigned int> master_node(nq, numbers::invalid_unsigned_int);
    bool                      pairs = false;
    for (unsigned int k = 0; k < nq; ++k)
      {
        const EquilibriumRow &row = sys.rows[sys.contact_rows[k]];
        if (ContactRowKinds::held_dof(sys, row) >=
            0) // a held component: no contact face
          continue;
        row_of_node[row.node] = k;
        if (row.obstacle < 0)
          {
            master_node[k] = ContactRowKinds::matched_master(sys, row);
            pairs          = true;
          }
      }
    // A pair row's master node may be on no cell of this process.
    const std::vector<double> pair_w =
      pairs ? row_displacements(results) : std::vector<double>();
    std::vector<double> penetration(nq, 0.);
    const auto          gap =
      [&](const auto &face, const unsigned int v, const unsigned int k) {
        const EquilibriumRow &row = sys.rows[sys.contact_rows[k]];
        double                w   = 0;
        if (row.obstacle < 0)
          w = pair_w[k];
        else
          for (unsigned int c = 0; c < 2; ++c)
            w += row.direction_component(c) *
                 results.displacement(face->vertex_dof_index(v, c));
        // A bilateral (tied) row: v meets it as an equation, lifted either
        // way; its contact term is zero.
        penetration[k] =
          row.unilateral ? std::max(0., w - row.value) : w - row.value;
        largest_penetration =
          std::max(largest_penetration, std::abs(penetration[k]));
        return row.unilateral ? std::max(0., row.value - w) : 0.;
      };
    // Both rows of a face: the same obstacle, or pair rows of the same
    // normal (a straight interface).
    const auto same_kind = [&](const unsigned int a, const unsigned int b) {
      const EquilibriumRow &r = sys.rows[sys.contact_rows[a]],
                           &s = sys.rows[sys.contact_rows[b]];
      return r.obstacle == s.obstacle && r.unilateral == s.unilateral &&
             (r.obstacle >= 0 ||
              (row_direction(r) - row_direction(s)).norm() < 1e-12);
    };
    // sigma_h on the contact faces (their natural shares), one FEFaceValues
    // for all.
    FEFaceValues<2> fv(StaticMappingQ1<2>::mapping,
                       *results.spaces.fe_stress,
                       QGauss<1>(3),
                       update_values | update_normal_vectors |
                         update_JxW_values | update_quadrature_points);
    for_each_face_with_rows(results,
                            row_of_node,
                            [&](const auto        &cell,
                                const unsigned int f,
                                const unsigned int a,
                                const unsigned int b) {
                              if (!same_kind(a, b))
                                return;
                              const auto face = cell->face(f);
                              Face      &c    = faces[face->index()];
                              c.row           = {{a, b}};
                              c.direction =
                                row_direction(sys.rows[sys.contact_rows[a]]);
                              c.gap = {{gap(face, 0, a), gap(face, 1, b)}};
                              c.natural =
                                natural_moments(results, cell, f, c, fv);
                            });
    if (pairs)
      find_master_faces(results, master_node);
    share_reactions(results);
    lift(results, penetration);
  }

  void
  ContactTractions::gather_faces(const Results<2> &results)
  {
    // The contact faces of all processes (each from its owner's cell):
    // rows, length and end points, so that every process solves the same
    // sharing problem.
    std::vector<double> own;
    for (const auto &cell :
         results.spaces.dof_handler_displacement.active_cell_iterators())
      if (results.partition.owned_cell[cell->active_cell_index()])
        for (const unsigned int f : cell->face_indices())
          if (const Face *c = find(cell->face(f)->index());
              c != nullptr && !c->master)
            own.insert(own.end(),
                       {double(c->row[0]),
                        double(c->row[1]),
                        cell->face(f)->measure(),
                        cell->face(f)->vertex(0)[0],
                        cell->face(f)->vertex(0)[1],
                        cell->face(f)->vertex(1)[0],
                        cell->face(f)->vertex(1)[1],
                        c->natural[0],
                        c->natural[1]});
    all.clear();
    for (const auto &part :
         Utilities::MPI::all_gather(results.partition.communicator, own))
      for (unsigned int i = 0; i + 8 < part.size(); i += 9)
        all.push_back({std::array<unsigned int, 2>{
                         {(unsigned int)part[i], (unsigned int)part[i + 1]}},
                       part[i + 2],
                       {{Point<2>(part[i + 3], part[i + 4]),
                         Point<2>(part[i + 5], part[i + 6])}},
                       {{0., 0.}},
                       {{part[i + 7], part[i + 8]}}});
    std::sort(all.begin(), all.end(), [](const auto &x, const auto &y) {
      return x.row < y.row;
    });
    at.assign(results.reactions.contact.size(), {});
    for (unsigned int i = 0; i < all.size(); ++i)
      for (const unsigned int e : {0, 1})
        {
          if (at[all[i].row[e]].size() == 2)
            refuse("a contact node with more than two contact faces" +
                   where(all[i].row[e]));
          at[all[i].row[e]].push_back(i);
        }
  }

  std::string
  ContactTractions::where(const unsigned int k) const
  {
    for (const unsigned int i : at[k])
      {
        const Point<2> &x = all[i].point[all[i].row[0] == k ? 0 : 1];
        return " (the contact node at " + std::to_string(x[0]) + ", " +
               std::to_string(x[1]) + ")";
      }
    return "";
  }

  void
  ContactTractions::share_chain(const std::vector<unsigned int> &node,
                                const std::vector<unsigned int> &face,
                                const std::vector<double>       &P,
                                const double                     tol)
  {
    const unsigned int m        = face.size();
    const auto         too_fast = [&](const unsigned int k) {
      return ExcMessage("Error bound: the contact reactions change too fast "
                                "along the contact surface to be carried by "
                                "compressive tractions" +
                        where(k) + "; refine there.");
    };
    // Forward: the interval of a_j (node j-1's share on face j) for which
    // the chain up to node j-1 can be shared within the ratio.
    std::vector<double> lo(m + 1), hi(m + 1);
    lo[1] = hi[1] = P[node[0]];
    for (unsigned int j = 1; j < m; ++j)
      {
        const double b_lo = lo[j] / ratio,
                     b_hi = std::min(ratio * hi[j], P[node[j]]);
        if (b_lo > b_hi + tol)
          too_fast(node[j]);
        lo[j + 1] = std::max(0., P[node[j]] - b_hi);
        hi[j + 1] = std::max(0., P[node[j]] - b_lo);
      }
    // Backward: b_m is the last node's reaction; each a_j within the ratio
    // of b_j and its interval, nearest sigma_h's own split (below).
    double b = P[node[m]];
    for (unsigned int j = m; j >= 1; --j)
      {
        const double a_lo = std::max(lo[j], b / ratio),
                     a_hi = std::min(hi[j], ratio * b);
        if (a_lo > a_hi + tol)
          too_fast(node[j]);
        // Nearest the split of sigma_h's own moments (their natural
        // shares), the difference halved between the two faces.
        const auto natural = [&](const unsigned int i, const unsigned int k) {
          return all[i].natural[all[i].row[0] == k ? 0 : 1];
        };
        const double n_j = natural(face[j - 1], node[j - 1]),
                     n_i = j >= 2 ? natural(face[j - 2], node[j - 1]) : 0;
        const double target =
          j >= 2 ? n_j + 0.5 * (P[node[j - 1]] - n_j - n_i) : P[node[j - 1]];
        const double a         = std::clamp(target, a_lo, a_hi);
        all[face[j - 1]].share = all[face[j - 1]].row[0] == node[j - 1] ?
                                   std::array<double, 2>{{a, b}} :
                                   std::array<double, 2>{{b, a}};
        b                      = std::max(0., P[node[j - 1]] - a);
      }
  }

  void
  ContactTractions::share_reactions(const Results<2> &results)
  {
    gather_faces(results);
    const std::vector<double> &p       = results.reactions.contact;
    const unsigned int         nq      = p.size();
    double                     largest = 0;
    for (unsigned int k = 0; k < nq; ++k)
      if (results.system.rows[results.system.contact_rows[k]].unilateral)
        largest = std::max(largest, -p[k]);
    const double tol = 1e-12 * largest;
    // A released row's reaction is the contact iteration's round-off (a
    // spring's force, of either sign): not carried, it shows in the vertex
    // problems' residual (FaceTractions::residual) instead.
    // A bilateral normal row's reaction is a held component's (the vertex
    // problems take it); a tied pair's, of either sign, is split freely.
    std::vector<double> P(nq);
    std::vector<bool>   done(nq, false);
    for (unsigned int k = 0; k < nq; ++k)
      if (const EquilibriumRow &row =
            results.system.rows[results.system.contact_rows[k]];
          !row.unilateral)
        {
          done[k] = true;
          if (ContactRowKinds::held_dof(results.system, row) < 0)
            share_tied(k, -p[k]);
        }
      else if (!results.contact || !results.contact->released[k])
        {
          if (p[k] > 1e-8 * largest)
            refuse("a pressed contact row pulls" + where(k));
          P[k] = std::max(0., -p[k]);
        }
    // Each chain n_0 .. n_m of contact faces f_1 .. f_m from an end.
    for (unsigned int start = 0; start < nq; ++start)
      {
        if (done[start] || at[start].size() == 2)
          continue;
        done[start] = true;
        if (at[start].empty() && P[start] > tol)
          refuse("the contact reaction of a node with no contact face beside "
                 "it cannot be carried by a compressive traction" +
                 where(start) + "; refine the contact surface");
        std::vector<unsigned int> node{start}, face;
        while (true)
          {
            unsigned int next = numbers::invalid_unsigned_int;
            for (const unsigned int i : at[node.back()])
              if (face.empty() || i != face.back())
                next = i;
            if (next == numbers::invalid_unsigned_int)
              break;
            face.push_back(next);
            node.push_back(all[next].row[all[next].row[0] == node.back()]);
            done[node.back()] = true;
          }
        if (!face.empty())
          share_chain(node, face, P, tol);
      }
    for (unsigned int k = 0; k < nq; ++k)
      if (!done[k] && P[k] > tol)
        refuse("a closed chain of contact faces is not covered" + where(k));

    // Each local face's quadratic: linear where the end moments allow it,
    // else the Bernstein pair (1-s)^2, s^2 (ratio up to 3).
    // (A master face takes its slave face's, whose vertices may be in the
    // other order.)
    const auto slave_face = [&](const std::array<unsigned int, 2> &row) {
      const auto it = std::lower_bound(all.begin(),
                                       all.end(),
                                       row,
                                       [](const auto &g, const auto &r) {
                                         return g.row < r;
                                       });
      return it != all.end() && it->row == row ? &*it : nullptr;
    };
    for (auto &[line, c] : faces)
      {
        const bool tied =
          !results.system.rows[results.system.contact_rows[c.row[0]]]
             .unilateral;
        const GlobalFace *it = slave_face(c.row);
        const GlobalFace *reverse =
          c.master && it == nullptr ?
            slave_face(std::array<unsigned int, 2>{{c.row[1], c.row[0]}}) :
            nullptr;
        AssertThrow(it != nullptr || reverse != nullptr,
                    ExcMessage("Error bound: a contact face is missing."));
        const double a = it ? it->share[0] : reverse->share[1],
                     b = it ? it->share[1] : reverse->share[0],
                     L = it ? it->length : reverse->length;
        if (tied || (2 * a >= b && 2 * b >= a))
          {
            const double q0 = -2 * (2 * a - b) / L, q1 = -2 * (2 * b - a) / L;
            c.bernstein = {{q0, 0.5 * (q0 + q1), q1}};
          }
        else
          c.bernstein = {
            {-(4.5 * a - 1.5 * b) / L, 0., -(4.5 * b - 1.5 * a) / L}};
      }
  }

  void
  ContactTractions::lift(const Results<2>          &results,
                         const std::vector<double> &penetration)
  {
    if (largest_penetration == 0)
      return;
    // w at the vertices: -delta d at a penetrating node, and at a hanging
    // node the mean of its parents' (w is then conforming).
    const EquilibriumSystem             &sys = results.system;
    std::map<unsigned int, unsigned int> row_of_node;
    for (unsigned int k = 0; k < sys.contact_rows.size(); ++k)
      if (penetration[k] != 0)
        row_of_node[sys.rows[sys.contact_rows[k]].node] = k;
    std::map<unsigned int, Tensor<1, 2>> w_at;
    for (const auto &cell :
         results.spaces.dof_handler_displacement.active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int v : cell->vertex_indices())
          if (const auto it =
                row_of_node.find(cell->vertex_dof_index(v, 0) / 2);
              it != row_of_node.end())
            w_at[cell->vertex_index(v)] =
              -penetration[it->second] *
              row_direction(sys.rows[sys.contact_rows[it->second]]);
    for (const auto &cell : results.triangulation().active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->has_children())
            {
              Tensor<1, 2> mean;
              for (const unsigned int e : {0u, 1u})
                if (const auto it = w_at.find(cell->face(f)->vertex_index(e));
                    it != w_at.end())
                  mean += 0.5 * it->second;
              if (mean.norm() > 0)
                w_at[cell->face(f)->child(0)->vertex_index(1)] = mean;
            }
    const FE_Q<2>   hat(1);
    const QGauss<2> rule(3);
    FEValues<2>     fv(StaticMappingQ1<2>::mapping,
                   hat,
                   rule,
                   update_gradients | update_JxW_values);
    for (const auto &cell : results.triangulation().active_cell_iterators())
      {
        if (!results.partition.owned_cell[cell->active_cell_index()])
          continue;
        std::array<Tensor<1, 2>, 4> w;
        bool                        any = false;
        for (const unsigned int v : cell->vertex_indices())
          if (const auto it = w_at.find(cell->vertex_index(v));
              it != w_at.end())
            {
              w[v] = it->second;
              any  = true;
            }
        if (!any)
          continue;
        fv.reinit(cell);
        FullMatrix<double> C(3, 3);
        C.invert(
          component_compliance(results.scene.material_of(cell->material_id())));
        for (unsigned int q = 0; q < rule.size(); ++q)
          {
            Tensor<2, 2> grad;
            for (unsigned int v = 0; v < 4; ++v)
              grad += outer_product(w[v], fv.shape_grad(v, q));
            const double e[3] = {grad[0][0],
                                 grad[1][1],
                                 grad[0][1] + grad[1][0]};
            for (unsigned int i = 0; i < 3; ++i)
              for (unsigned int j = 0; j < 3; ++j)
                lift_energy_squared += e[i] * C(i, j) * e[j] * fv.JxW(q);
          }
      }
  }

  std::array<double, 2>
  ContactTractions::natural_moments(
    const Results<2>                          &results,
    const DoFHandler<2>::active_cell_iterator &cell,
    const unsigned int                         f,
    const Face                                &face,
    FEFaceValues<2>                           &fv)
  {
    // The magnitude -(sigma_h n) . d of this side's traction, against the
    // face's hats (vertex 0, 1 of the line).
    const unsigned int                        n_points = fv.n_quadrature_points;
    const DoFHandler<2>::active_cell_iterator stress_cell(
      &results.triangulation(),
      cell->level(),
      cell->index(),
      &results.spaces.dof_handler_stress);
    fv.reinit(stress_cell, f);
    std::vector<Vector<double>> values(
      n_points, Vector<double>(MixedSpaces<2>::n_stress_components));
    fv.get_function_values(results.stress, values);
    const Point<2> a = cell->face(f)->vertex(0), b = cell->face(f)->vertex(1);
    std::array<double, 2> m{{0., 0.}};
    for (unsigned int q = 0; q < n_points; ++q)
      {
        const double lambda =
          (fv.quadrature_point(q) - a) * (b - a) / (b - a).norm_square();
        const double t =
          -(stress_tensor<2>(values[q]) * fv.normal_vector(q)) * face.direction;
        m[0] += t * (1 - lambda) * fv.JxW(q);
        m[1] += t * lambda * fv.JxW(q);
      }
    return m;
  }

  void
  ContactTractions::share_tied(const unsigned int k, const double P)
  {
    // Either sign, so any split balances.
    if (at[k].empty())
      {
        if (P != 0)
          refuse("the reaction of a tied node with no pair face beside it "
                 "cannot be carried" +
                 where(k));
        return;
      }
    // Nearest sigma_h's own moments, the difference shared equally.
    double natural = 0;
    for (const unsigned int i : at[k])
      natural += all[i].natural[all[i].row[0] == k ? 0 : 1];
    for (const unsigned int i : at[k])
      all[i].share[all[i].row[0] == k ? 0 : 1] =
        all[i].natural[all[i].row[0] == k ? 0 : 1] +
        (P - natural) / at[k].size();
  }

  void
  ContactTractions::find_master_faces(
    const Results<2>                &results,
    const std::vector<unsigned int> &master_node)
  {
    const EquilibriumSystem             &sys = results.system;
    std::map<unsigned int, unsigned int> row_of_master;
    for (unsigned int k = 0; k < master_node.size(); ++k)
      if (master_node[k] != numbers::invalid_unsigned_int)
        row_of_master[master_node[k]] = k;
    for_each_face_with_rows(
      results,
      row_of_master,
      [&](const auto        &cell,
          const unsigned int f,
          const unsigned int a,
          const unsigned int b) {
        const auto         face = cell->face(f);
        const Tensor<1, 2> n    = row_direction(sys.rows[sys.contact_rows[a]]);
        if ((n - row_direction(sys.rows[sys.contact_rows[b]])).norm() > 1e-12)
          return;
        Face &c     = faces[face->index()];
        c.row       = {{a, b}};
        c.direction = -n;
        c.master    = true;
      });
  }

  std::vector<double>
  ContactTractions::row_displacements(const Results<2> &results)
  {
    const EquilibriumSystem &sys = results.system;
    std::vector<double>      w(sys.contact_rows.size(), 0.);
    for (unsigned int k = 0; k < w.size(); ++k)
      {
        const EquilibriumRow &row = sys.rows[sys.contact_rows[k]];
        for (unsigned int i = 0; i < row.combination.size(); ++i)
          if (results.partition.owned.is_element(row.combination[i].first))
            w[k] += row.direction_component(i) *
                    results.displacement(row.combination[i].first);
      }
    const ArrayView<const double> values(w.data(), w.size());
    const ArrayView<double>       sums(w.data(), w.size());
    Utilities::MPI::sum(values, results.partition.communicator, sums);
    return w;
  }

  const ContactTractions::Face *
  ContactTractions::find(const unsigned int line) const
  {
    const auto it = faces.find(line);
    return it == faces.end() ? nullptr : &it->second;
  }

  Tensor<1, 2>
  ContactTractions::traction(const Face &face, const double s)
  {
    const auto &c = face.bernstein;
    return (c[0] * (1 - s) * (1 - s) + c[1] * 2 * s * (1 - s) + c[2] * s * s) *
           face.direction;
  }

  std::array<double, 2>
  ContactTractions::moments(const Face &face, const double L)
  {
    const auto &c = face.bernstein;
    return {{L * (c[0] / 4 + c[1] / 6 + c[2] / 12),
             L * (c[0] / 12 + c[1] / 6 + c[2] / 4)}};
  }

  double
  ContactTractions::gap_term(const Face &face, const double L)
  {
    // The gap is linear: its integral against q is the moments'.
    const auto m = moments(face, L);
    return -2 * (face.gap[0] * m[0] + face.gap[1] * m[1]);
  }
} // namespace hrcontact
