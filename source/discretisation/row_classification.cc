#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/full_matrix.h>

#include <deal.II/distributed/tria_base.h>

#include <hrcontact/core/input.h>
#include <hrcontact/discretisation/hanging_nodes.h>
#include <hrcontact/discretisation/row_classification.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>

namespace hrcontact
{
  using namespace dealii;

  namespace
  {
    /** Node n has the dofs dim n + d (EquilibriumSystem::dof_node). */
    template <int dim>
    types::global_dof_index
    node_dof(const unsigned int node, const unsigned int d)
    {
      return types::global_dof_index(dim) * node + d;
    }

    /**
     * A row d . u at a node; with @p dual, the force row's combination is
     * the dual basis vector and d is kept as the row's direction.
     */
    template <int dim>
    void
    add_row(EquilibriumSystem    &system,
            const unsigned int    node,
            const Tensor<1, dim> &direction,
            const RowClass        row_class,
            const double          value,
            const bool            unilateral = false,
            const Tensor<1, dim> *dual       = nullptr)
    {
      EquilibriumRow row;
      row.row_class  = row_class;
      row.node       = node;
      row.value      = value;
      row.unilateral = unilateral;
      for (unsigned int d = 0; d < dim; ++d)
        row.combination.emplace_back(node_dof<dim>(node, d),
                                     dual ? (*dual)[d] : direction[d]);
      if (dual)
        for (unsigned int d = 0; d < dim; ++d)
          row.direction.push_back(direction[d]);
      system.n_free_rows += (row_class == RowClass::free);
      const unsigned int r = system.rows.size();
      system.rows.push_back(row);
      (row_class == RowClass::free    ? system.free_rows :
       row_class == RowClass::contact ? system.contact_rows :
                                        system.prescribed_rows)
        .push_back(r);
    }
  } // namespace

  template <int dim>
  RowClassification<dim>::RowClassification(const Scene<dim>       &scene,
                                            const MixedSpaces<dim> &spaces)
    : scene(scene)
    , spaces(spaces)
  {}

  template <int dim>
  void
  RowClassification<dim>::read_node_coordinates(EquilibriumSystem &system) const
  {
    const DoFHandler<dim> &dh_u    = spaces.dof_handler_displacement;
    const unsigned int     n_nodes = dh_u.n_dofs() / dim;
    // A distributed mesh: each process keeps the coordinates of the nodes it
    // owns (p4est numbers them as one contiguous range) and, further down,
    // those of the gathered boundary faces; a serial mesh keeps them all.
    const auto *parallel_mesh =
      dynamic_cast<const parallel::TriangulationBase<dim> *>(
        &dh_u.get_triangulation());
    const IndexSet &owned_dofs = dh_u.locally_owned_dofs();
    if (parallel_mesh)
      {
        AssertThrow(owned_dofs.is_contiguous() &&
                      owned_dofs.n_elements() % dim == 0 &&
                      (owned_dofs.n_elements() == 0 ||
                       owned_dofs.nth_index_in_set(0) % dim == 0),
                    ExcMessage("a distributed mesh whose processes do not "
                               "own contiguous ranges of whole nodes"));
        system.node_coordinates.reinit(n_nodes,
                                       owned_dofs.n_elements() ?
                                         owned_dofs.nth_index_in_set(0) / dim :
                                         0,
                                       owned_dofs.n_elements() / dim);
      }
    else
      system.node_coordinates.reinit(n_nodes);
    for (const auto &cell : dh_u.active_cell_iterators())
      if (!cell->is_artificial())
        for (const auto v : cell->vertex_indices())
          {
            const auto node = cell->vertex_dof_index(v, 0) / dim;
            if (parallel_mesh && !owned_dofs.is_element(node_dof<dim>(node, 0)))
              continue;
            NodeCoordinates::Point x = {{0., 0., 0.}};
            for (unsigned int d = 0; d < dim; ++d)
              {
                AssertThrow(cell->vertex_dof_index(v, d) ==
                              node_dof<dim>(node, d),
                            ExcInternalError());
                x[d] = cell->vertex(v)[d];
              }
            system.node_coordinates.set(node, x);
          }
  }

  template <int dim>
  std::vector<BoundaryFace<dim>>
  RowClassification<dim>::constrained_faces() const
  {
    const DoFHandler<dim>         &dh_u = spaces.dof_handler_displacement;
    std::vector<BoundaryFace<dim>> faces;
    const QGauss<dim - 1>          centre(1);
    FEFaceValues<dim>              fv_face(*spaces.fe_displacement,
                              centre,
                              update_normal_vectors | update_JxW_values);
    // Each face from the owner of its cell (every cell on a serial mesh).
    for (const auto &cell : dh_u.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto f : cell->face_indices())
          {
            if (!cell->face(f)->at_boundary())
              continue;
            const types::boundary_id id = cell->face(f)->boundary_id();
            if (std::none_of(scene.constraints.begin(),
                             scene.constraints.end(),
                             [id](const auto &source) {
                               return source->acts_on(id);
                             }))
              continue;
            BoundaryFace<dim> face;
            face.boundary_id = id;
            face.body        = cell->material_id();
            for (const auto v : cell->face(f)->vertex_indices())
              {
                face.nodes.push_back(cell->face(f)->vertex_dof_index(v, 0) /
                                     dim);
                face.points.push_back(cell->face(f)->vertex(v));
              }
            fv_face.reinit(cell, f);
            face.normal  = fv_face.normal_vector(0);
            face.measure = fv_face.JxW(0);
            faces.push_back(face);
          }
    return faces;
  }

  template <int dim>
  std::vector<BoundaryFace<dim>>
  gather_boundary_faces(const std::vector<BoundaryFace<dim>> &local_faces,
                        const MPI_Comm                        communicator)
  {
    std::vector<double> packed;
    for (const auto &face : local_faces)
      {
        packed.push_back(face.boundary_id);
        packed.push_back(face.body);
        packed.push_back(face.nodes.size());
        for (unsigned int v = 0; v < face.nodes.size(); ++v)
          {
            packed.push_back(face.nodes[v]);
            for (unsigned int d = 0; d < dim; ++d)
              packed.push_back(face.points[v][d]);
          }
        for (unsigned int d = 0; d < dim; ++d)
          packed.push_back(face.normal[d]);
        packed.push_back(face.measure);
      }
    std::vector<BoundaryFace<dim>> faces;
    for (const auto &part : Utilities::MPI::all_gather(communicator, packed))
      for (std::size_t k = 0; k < part.size();)
        {
          BoundaryFace<dim> face;
          face.boundary_id     = static_cast<types::boundary_id>(part[k++]);
          face.body            = static_cast<unsigned int>(part[k++]);
          const unsigned int n = static_cast<unsigned int>(part[k++]);
          for (unsigned int v = 0; v < n; ++v)
            {
              face.nodes.push_back(static_cast<unsigned int>(part[k++]));
              Point<dim> x;
              for (unsigned int d = 0; d < dim; ++d)
                x[d] = part[k++];
              face.points.push_back(x);
            }
          for (unsigned int d = 0; d < dim; ++d)
            face.normal[d] = part[k++];
          face.measure = part[k++];
          faces.push_back(face);
        }
    return faces;
  }

  template <int dim>
  void
  RowClassification<dim>::corner_rows(const unsigned int          node,
                                      const NodeConstraints<dim> &c,
                                      EquilibriumSystem          &system) const
  {
    // A corner between obstacles (eq. 11): the normals n_i and free
    // directions t completing them form the node's primal basis,
    // rows w_i = n_i . u; the force rows are its dual basis, so that
    // the nodal reaction is sum_i p_i n_i with every p_i <= 0.
    const std::string where =
      "Contact/Obstacles: " + system.describe_node(node);
    if (c.has_normal || c.own_row_source || c.any_prescribed())
      throw InputError(where + " touches several obstacles and also has a "
                               "prescribed component, a normal constraint or "
                               "a stop; a corner node takes obstacles only.");
    if (c.obstacles.size() > dim)
      throw InputError(
        where + " touches " + std::to_string(c.obstacles.size()) +
        " obstacles; at most " + std::to_string(dim) + " can meet at a node.");
    std::vector<Tensor<1, dim>> basis, orthonormal;
    for (const auto &[id, n, g] : c.obstacles)
      {
        basis.push_back(n);
        Tensor<1, dim> e = n;
        for (const auto &o : orthonormal)
          e -= (e * o) * o;
        if (e.norm() < 1e-6)
          throw InputError(where + " touches obstacles with linearly "
                                   "dependent normals.");
        orthonormal.push_back(e / e.norm());
      }
    for (const auto &t : orthogonal_complement<dim>(orthonormal))
      basis.push_back(t);
    // Dual basis: the rows of (P^T)^{-1}... i.e. c_r . d_s = delta.
    FullMatrix<double> P(dim, dim), Pinv(dim, dim);
    for (unsigned int r = 0; r < dim; ++r)
      for (unsigned int d = 0; d < dim; ++d)
        P(r, d) = basis[r][d];
    Pinv.invert(P);
    for (unsigned int r = 0; r < dim; ++r)
      {
        Tensor<1, dim> dual;
        for (unsigned int d = 0; d < dim; ++d)
          dual[d] = Pinv(d, r);
        const bool is_obstacle = r < c.obstacles.size();
        add_row<dim>(system,
                     node,
                     basis[r],
                     is_obstacle ? RowClass::contact : RowClass::free,
                     is_obstacle ? std::get<2>(c.obstacles[r]) : 0.,
                     is_obstacle,
                     &dual);
        if (is_obstacle)
          system.rows.back().obstacle = std::get<0>(c.obstacles[r]);
      }
  }

  template <int dim>
  void
  RowClassification<dim>::normal_row(const unsigned int           node,
                                     const NodeConstraints<dim>  &c,
                                     EquilibriumSystem           &system,
                                     std::vector<Tensor<1, dim>> &taken) const
  {
    if (c.has_normal && c.obstacle >= 0)
      throw InputError("Supports: " + system.describe_node(node) +
                       " has both a normal constraint (or boundary "
                       "support) and an obstacle.");
    if (!(c.has_normal || c.obstacle >= 0))
      return;
    const bool unilateral  = (c.obstacle >= 0) || c.normal_is_unilateral;
    const Tensor<1, dim> n = (c.obstacle >= 0) ?
                               c.obstacle_normal :
                               c.normal_sum / c.normal_sum.norm();
    for (const auto &nf : c.face_normals)
      if (nf * n < std::cos(numbers::PI / 4))
        throw InputError(
          "Supports/Normal displacements or Contact/Boundary "
          "supports: " +
          system.describe_node(node) +
          " is a corner between faces whose normals differ by more "
          "than 45 degrees; one normal cannot represent it. Prescribe "
          "the displacement components there instead.");
    // With prescribed components at the node, u.n <= g (or = g)
    // only constrains the free part of u: n_free . u_free <= g -
    // n . u-hat, n_free = n minus its prescribed-axis part. The row
    // takes the unit direction of n_free and the scaled gap; if n_free
    // vanishes, the prescribed values fix u.n and there is no row.
    Tensor<1, dim> n_free = n;
    double         g      = c.gap;
    for (unsigned int d = 0; d < dim; ++d)
      if (c.prescribed[d])
        {
          g -= n[d] * c.prescribed_value[d];
          n_free[d] = 0;
        }
    if (n_free.norm() > 1e-8)
      {
        const double length = n_free.norm();
        add_row<dim>(system,
                     node,
                     n_free / length,
                     RowClass::contact,
                     g / length,
                     unilateral);
        if (c.obstacle >= 0)
          system.rows.back().obstacle = c.obstacle;
        taken.push_back(n_free / length);
      }
  }

  template <int dim>
  void
  RowClassification<dim>::classify_node(const unsigned int          node,
                                        const NodeConstraints<dim> &c,
                                        EquilibriumSystem          &system,
                                        const bool lean_rows) const
  {
    if (lean_rows && c.obstacles.empty() && !c.own_row_source &&
        !c.has_normal && c.obstacle < 0 && !c.any_prescribed() && !c.coupled)
      {
        // Implicit: the unit rows of the node's dofs.
        system.n_free_rows += dim;
        return;
      }
    std::vector<Tensor<1, dim>> taken; // directions already used
    for (unsigned int d = 0; d < dim; ++d)
      if (c.prescribed[d])
        {
          Tensor<1, dim> e;
          e[d] = 1.;
          add_row<dim>(
            system, node, e, RowClass::prescribed, c.prescribed_value[d]);
          taken.push_back(e);
        }
    if (c.obstacles.size() > 1)
      {
        corner_rows(node, c, system);
        return;
      }
    if (c.own_row_source)
      {
        // A kind with a row of its own at the node (a two-sided stop).
        Point<dim> x;
        for (unsigned int d = 0; d < dim; ++d)
          x[d] = system.node_coordinates[node][d];
        const OwnRow   own = c.own_row_source->own_row(node, x, c, system);
        Tensor<1, dim> direction;
        for (unsigned int d = 0; d < dim; ++d)
          direction[d] = own.direction[d];
        add_row<dim>(system,
                     node,
                     direction,
                     RowClass::contact,
                     own.value,
                     own.unilateral && !own.law);
        system.rows.back().law = own.law;
        taken.push_back(direction);
      }
    normal_row(node, c, system, taken);
    // The free rows span the orthogonal complement of what is taken.
    for (const auto &t : orthogonal_complement<dim>(taken))
      {
        add_row<dim>(system, node, t, RowClass::free, 0.);
        taken.push_back(t);
      }
    AssertThrow(taken.size() == dim, ExcInternalError());
  }

  template <int dim>
  void
  RowClassification<dim>::classify(EquilibriumSystem &system,
                                   const bool         lean_rows) const
  {
    const DoFHandler<dim> &dh_u = spaces.dof_handler_displacement;
    system.dim                  = dim;
    system.n_displacement_dofs  = dh_u.n_dofs();
    system.n_stress_dofs        = spaces.stress_unknowns().n_dofs();
    const unsigned int n_nodes  = dh_u.n_dofs() / dim;
    read_node_coordinates(system);
    find_hanging_nodes(dh_u,
                       DoFTools::extract_locally_relevant_dofs(dh_u),
                       system);

    // The boundary faces some constraint kind acts on. A distributed mesh:
    // every process classifies the whole boundary (a surface), so that the
    // rows are the same everywhere; the faces are gathered in process order.
    const auto *parallel_mesh =
      dynamic_cast<const parallel::TriangulationBase<dim> *>(
        &dh_u.get_triangulation());
    std::vector<BoundaryFace<dim>> faces = constrained_faces();
    if (parallel_mesh)
      faces = gather_boundary_faces(faces, parallel_mesh->get_communicator());

    // A hanging node has no rows: its displacement follows its parents'.
    // Every process classifies the whole constrained boundary, so the
    // hanging ones among its nodes are gathered from the processes that
    // see them.
    std::set<unsigned int> hanging_nodes;
    for (const auto &face : faces)
      for (const unsigned int node : face.nodes)
        if (is_hanging(system, node_dof<dim>(node, 0)))
          hanging_nodes.insert(node);
    if (parallel_mesh && system.n_hanging_dofs > 0)
      for (const auto &part : Utilities::MPI::all_gather(
             parallel_mesh->get_communicator(),
             std::vector<unsigned int>(hanging_nodes.begin(),
                                       hanging_nodes.end())))
        hanging_nodes.insert(part.begin(), part.end());
    auto hanging = [&](const unsigned int node) {
      return hanging_nodes.count(node) > 0 ||
             is_hanging(system, node_dof<dim>(node, 0));
    };

    // The nodes of the constrained boundary: every process classifies them.
    for (const auto &face : faces)
      for (unsigned int v = 0; v < face.nodes.size(); ++v)
        {
          NodeCoordinates::Point x = {{0., 0., 0.}};
          for (unsigned int d = 0; d < dim; ++d)
            x[d] = face.points[v][d];
          system.node_coordinates.set(face.nodes[v], x);
        }
    system.node_coordinates.compress(
      parallel_mesh ? parallel_mesh->get_communicator() : MPI_COMM_SELF);
    system.n_bodies = scene.n_bodies;
    system.node_body.clear();
    if (scene.n_bodies > 1)
      for (const auto &face : faces)
        for (const unsigned int node : face.nodes)
          system.node_body[node] = face.body;

    // What the constraint kinds ask of each node, face by face.
    for (const auto &source : scene.constraints)
      source->prepare(faces, system);
    NodeConstraintMap<dim> constraints;
    for (const auto &face : faces)
      for (const auto &source : scene.constraints)
        if (source->acts_on(face.boundary_id))
          source->collect(face, system, constraints);

    system.rows.clear();
    system.free_rows.clear();
    system.contact_rows.clear();
    system.prescribed_rows.clear();
    system.lean_rows   = lean_rows;
    system.n_free_rows = 0;
    // Lean rows: only the nodes some face touched can have explicit rows.
    if (lean_rows)
      for (const auto &[node, c] : constraints)
        {
          if (!hanging(node))
            classify_node(node, c, system, lean_rows);
        }
    else
      {
        const NodeConstraints<dim> none;
        for (unsigned int node = 0; node < n_nodes; ++node)
          {
            if (hanging(node))
              continue;
            const auto it = constraints.find(node);
            classify_node(node,
                          it == constraints.end() ? none : it->second,
                          system,
                          lean_rows);
          }
      }
    // Rows that couple nodes (contact between bodies) are extended now that
    // every node has its rows.
    for (const auto &source : scene.constraints)
      source->couple_rows(system);
    add_hanging_shares(system);
    if (lean_rows)
      system.n_free_rows =
        system.n_displacement_dofs - system.contact_rows.size() -
        system.prescribed_rows.size() - system.n_hanging_dofs;
    AssertThrow(system.contact_rows.size() + system.prescribed_rows.size() +
                    system.n_free_rows + system.n_hanging_dofs ==
                  system.n_displacement_dofs,
                ExcInternalError());
    AssertThrow(lean_rows || system.rows.size() + system.n_hanging_dofs ==
                               system.n_displacement_dofs,
                ExcInternalError());
  }

  template <int dim>
  std::vector<Tensor<1, dim>>
  orthogonal_complement(const std::vector<Tensor<1, dim>> &taken)
  {
    std::vector<Tensor<1, dim>> all = taken, complement;
    for (unsigned int d = 0; d < dim && all.size() < dim; ++d)
      {
        Tensor<1, dim> t;
        t[d] = 1.;
        for (const auto &e : all)
          t -= (t * e) * e;
        if (t.norm() < 0.5)
          continue;
        t /= t.norm();
        all.push_back(t);
        complement.push_back(t);
      }
    return complement;
  }

  template class RowClassification<2>;
  template class RowClassification<3>;
  template std::vector<BoundaryFace<2>>
  gather_boundary_faces<2>(const std::vector<BoundaryFace<2>> &,
                           const MPI_Comm);
  template std::vector<BoundaryFace<3>>
  gather_boundary_faces<3>(const std::vector<BoundaryFace<3>> &,
                           const MPI_Comm);
  template std::vector<Tensor<1, 2>>
  orthogonal_complement<2>(const std::vector<Tensor<1, 2>> &);
  template std::vector<Tensor<1, 3>>
  orthogonal_complement<3>(const std::vector<Tensor<1, 3>> &);
} // namespace hrcontact
