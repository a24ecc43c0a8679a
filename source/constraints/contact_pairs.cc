#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>

#include <hrcontact/constraints/contact_pairs.h>
#include <hrcontact/constraints/mortar.h>
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

    /** A tenth of the size of the master boundary's bounding box. */
    template <int dim>
    double
    default_reach(const std::vector<const BoundaryFace<dim> *> &masters)
    {
      Point<dim> low = masters.front()->points.front(), high = low;
      for (const BoundaryFace<dim> *face : masters)
        for (const auto &x : face->points)
          for (unsigned int d = 0; d < dim; ++d)
            {
              low[d]  = std::min(low[d], x[d]);
              high[d] = std::max(high[d], x[d]);
            }
      return 0.1 * low.distance(high);
    }

    /** A fully covered slave node's row from its mortar sums: w_n = sum_m
     * (M_m / D) w_m + G / D along the node's mean normal. */
    template <typename Projection, int dim>
    Projection
    mortar_projection(const MortarSums &S, const Tensor<1, dim> &normal)
    {
      Projection projection;
      projection.normal = normal / normal.norm();
      projection.gap    = S.G / S.D;
      for (const auto &[master, M] : S.M)
        if (std::abs(M) > 1e-12 * S.D)
          {
            projection.master_nodes.push_back(master);
            projection.shape_values.push_back(M / S.D);
          }
      return projection;
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
  std::vector<types::boundary_id>
  ContactPairs<dim>::boundary_ids() const
  {
    std::vector<types::boundary_id> ids;
    for (const Pair &p : pairs)
      {
        ids.push_back(p.slave);
        ids.push_back(p.master);
      }
    return ids;
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
        const double reach =
          (pair.reach > 0) ? pair.reach : default_reach(masters);
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
                Projection        projection =
                  mortar_projection<Projection>(S, slave.second);
                projection.pair = k;
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
            // Node to segment.
            const auto closest =
              closest_master_point<dim>(masters, x, slave.second, reach);
            if (closest.overlap > 0)
              throw overlap_error(where,
                                  system.describe_node(node),
                                  closest.overlap,
                                  "");
            if (!closest.face)
              continue;
            Projection projection;
            projection.pair   = k;
            projection.normal = -closest.face->normal;
            projection.gap    = std::max(closest.gap, 0.);
            for (unsigned int v = 0; v < closest.face->nodes.size(); ++v)
              if (std::abs(closest.N[v]) > 1e-12)
                {
                  projection.master_nodes.push_back(closest.face->nodes[v]);
                  projection.shape_values.push_back(closest.N[v]);
                }
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
