#include <deal.II/lac/lapack_full_matrix.h>

#include <hrcontact/discretisation/equilibrium_system.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <numeric>
#include <sstream>

namespace hrcontact
{
  using namespace dealii;

  void
  EquilibriumSystem::add_row_transpose(const EquilibriumRow &row,
                                       const double          coefficient,
                                       Vector<double>       &v) const
  {
    for (const auto &[dof, c] : row.combination)
      for (auto it = B.begin(b_row(dof)); it != B.end(b_row(dof)); ++it)
        v[it->column()] += coefficient * c * it->value();
  }

  namespace
  {
    /** Whether every cell the filter accepts is stored (else recompute). */
    bool
    every_cell_stored(const EquilibriumSystem                 &system,
                      const std::function<bool(unsigned int)> &filter)
    {
      for (unsigned int c = 0; c < system.n_cells(); ++c)
        if (filter(c) && !system.is_stored(c))
          return false;
      return true;
    }
  } // namespace

  void
  EquilibriumSystem::for_each_cell_blocks(
    const std::function<bool(unsigned int)>       &filter,
    const std::function<void(const CellBlocks &)> &worker) const
  {
    if (!every_cell_stored(*this, filter))
      {
        Assert(recompute_cell_blocks, ExcInternalError());
        recompute_cell_blocks(filter, worker);
        return;
      }
    // From storage. The cell load is not kept per cell: left empty.
    CellBlocks blocks;
    for (unsigned int c = 0; c < n_cells(); ++c)
      if (filter(c))
        {
          blocks.cell              = c;
          blocks.displacement_dofs = cell_displacement_dofs[c];
          blocks.stress_dofs       = cell_stress_dofs[c];
          const auto &du           = blocks.displacement_dofs;
          const auto &ds           = blocks.stress_dofs;
          blocks.B.reinit(du.size(), ds.size());
          for (unsigned int i = 0; i < du.size(); ++i)
            for (unsigned int j = 0; j < ds.size(); ++j)
              blocks.B(i, j) = B.el(b_row(du[i]), ds[j]);
          blocks.F = cell_flexibility[c];
          if (c < cell_strain_term.size())
            blocks.strain_term = cell_strain_term[c];
          else
            blocks.strain_term.reinit(0);
          worker(blocks);
        }
  }

  void
  EquilibriumSystem::for_each_cell_dofs(
    const std::function<bool(unsigned int)> &filter,
    const std::function<void(unsigned int,
                             const std::vector<types::global_dof_index> &)>
      &worker) const
  {
    if (!every_cell_stored(*this, filter))
      {
        Assert(recompute_cell_dofs, ExcInternalError());
        recompute_cell_dofs(filter, worker);
        return;
      }
    for (unsigned int c = 0; c < n_cells(); ++c)
      if (filter(c))
        worker(c, cell_displacement_dofs[c]);
  }

  void
  EquilibriumSystem::equilibrium_residual(const Vector<double> &s,
                                          Vector<double>       &residual) const
  {
    AssertThrow(is_complete(load),
                ExcMessage("the equilibrium residual needs the whole load "
                           "vector (a serial mesh)"));
    residual.reinit(load.size());
    for (unsigned int i = 0; i < load.size(); ++i)
      residual[i] = -load[i];
    for_each_cell_blocks([](const unsigned int) { return true; },
                         [&](const CellBlocks &b) {
                           const auto &du = b.displacement_dofs;
                           const auto &ds = b.stress_dofs;
                           for (unsigned int i = 0; i < du.size(); ++i)
                             for (unsigned int j = 0; j < ds.size(); ++j)
                               residual[du[i]] += b.B(i, j) * s[ds[j]];
                         });
    // The conforming test space: each hanging dof's equation goes to its
    // parents (T^T (B s - f)).
    for (const auto &line : hanging_nodes.get_lines())
      {
        for (const auto &[parent, a] : line.entries)
          residual[parent] += a * residual[line.index];
        residual[line.index] = 0;
      }
  }

  double
  EquilibriumSystem::row_load(const EquilibriumRow &row) const
  {
    double sum = 0;
    for (const auto *terms : {&row.combination, &row.shares})
      for (const auto &[dof, c] : *terms)
        sum += c * load[dof];
    return sum;
  }

  bool
  EquilibriumSystem::has_contact() const
  {
    bool contact = false;
    for (const unsigned int row : contact_rows)
      contact |= rows[row].unilateral || bool(rows[row].law);
    return contact;
  }

  std::vector<double>
  EquilibriumSystem::contact_row_values() const
  {
    std::vector<double> values(contact_rows.size());
    for (unsigned int k = 0; k < contact_rows.size(); ++k)
      values[k] = rows[contact_rows[k]].value;
    return values;
  }

  void
  EquilibriumSystem::multiply_flexibility(const Vector<double> &s,
                                          Vector<double>       &Fs) const
  {
    Fs.reinit(n_stress_dofs);
    for (unsigned int c = 0; c < cell_stress_dofs.size(); ++c)
      {
        const auto &dofs = cell_stress_dofs[c];
        const auto &Fc   = cell_flexibility[c];
        for (unsigned int i = 0; i < dofs.size(); ++i)
          {
            double sum = 0;
            for (unsigned int j = 0; j < dofs.size(); ++j)
              sum += Fc(i, j) * s[dofs[j]];
            Fs[dofs[i]] += sum;
          }
      }
  }

  void
  EquilibriumSystem::add_strain_terms(Vector<double> &v) const
  {
    for (unsigned int c = 0; c < cell_strain_term.size(); ++c)
      {
        const auto &d = cell_strain_term[c];
        if (d.size() == 0)
          continue;
        const auto &dofs = cell_stress_dofs[c];
        AssertDimension(d.size(), dofs.size());
        for (unsigned int i = 0; i < dofs.size(); ++i)
          v[dofs[i]] += d[i];
      }
  }

  void
  EquilibriumSystem::displacements_from_row_values(
    const std::vector<double> &row_values,
    Vector<double>            &u) const
  {
    AssertThrow(!lean_rows, ExcMessage("lean rows have no value per row"));
    u.reinit(n_displacement_dofs);
    for (unsigned int r = 0; r < rows.size(); ++r)
      for (const auto &[dof, c] : rows[r].combination)
        u[dof] += row_values[r] * c;
  }

  std::string
  EquilibriumSystem::describe_node(const unsigned int node) const
  {
    std::ostringstream s;
    s << std::setprecision(6) << "node (";
    for (unsigned int d = 0; d < dim; ++d)
      s << (d ? ", " : "") << node_coordinates[node][d];
    s << ")";
    return s.str();
  }

  std::string
  EquilibriumSystem::describe_row(const unsigned int r) const
  {
    const EquilibriumRow &row = rows[r];
    std::ostringstream    s;
    s << describe_node(row.node) << " direction (";
    std::vector<double> dir(dim, 0.);
    // The combination holds the node's dofs in component order.
    for (unsigned int k = 0; k < row.combination.size(); ++k)
      dir[k] = row.direction_component(k);
    for (unsigned int d = 0; d < dim; ++d)
      s << (d ? ", " : "") << std::setprecision(3) << dir[d];
    s << ")";
    return s.str();
  }
  unsigned int
  rigid_motions_held_only_by_contact(const EquilibriumSystem &system)
  {
    const auto by_body = rigid_motions_held_only_by_contact_by_body(system);
    return std::accumulate(by_body.begin(), by_body.end(), 0u);
  }

  namespace
  {
    /**
     * The rigid-body motions of @p body that the prescribed rows and the
     * contact rows @p holds accepts leave free, one null vector of those
     * rows restricted to the motions per free motion (in the basis of
     * translations e_k and rotations about the centroid, scaled by the
     * bodies' size so that the Gram matrix is balanced).
     */
    std::vector<std::vector<double>>
    free_rigid_motions(const EquilibriumSystem &system,
                       const unsigned int       body,
                       const std::function<bool(const EquilibriumRow &)> &holds)
    {
      const unsigned int          dim     = system.dim;
      const unsigned int          n_modes = (dim == 2) ? 3 : 6;
      const std::array<double, 3> centre  = system.node_coordinates.centre();
      const double size = std::max(system.node_coordinates.extent(), 1e-300);
      dealii::LAPACKFullMatrix<double> gram(n_modes, n_modes);
      auto add_row = [&](const EquilibriumRow &row) {
        if (!system.node_body.empty())
          {
            const auto it = system.node_body.find(row.node);
            if (it == system.node_body.end() || it->second != body)
              return;
          }
        const auto           &x = row.node < system.node_coordinates.size() ?
                                    system.node_coordinates[row.node] :
                                    centre;
        std::array<double, 3> r = {{(x[0] - centre[0]) / size,
                                    (x[1] - centre[1]) / size,
                                    (x[2] - centre[2]) / size}};
        // d . m for the modes: translations e_k, rotations (-y, x, 0),
        // (0, -z, y), (z, 0, -x).
        std::array<double, 3> d = {{0, 0, 0}};
        for (unsigned int k = 0; k < row.combination.size() && k < dim; ++k)
          d[k] = row.direction_component(k);
        std::vector<double> v(n_modes, 0.);
        for (unsigned int k = 0; k < dim; ++k)
          v[k] = d[k];
        v[dim] = -r[1] * d[0] + r[0] * d[1];
        if (dim == 3)
          {
            v[4] = -r[2] * d[1] + r[1] * d[2];
            v[5] = r[2] * d[0] - r[0] * d[2];
          }
        for (unsigned int a = 0; a < n_modes; ++a)
          for (unsigned int b = 0; b < n_modes; ++b)
            gram(a, b) += v[a] * v[b];
      };
      for (const unsigned int r : system.prescribed_rows)
        add_row(system.rows[r]);
      for (const unsigned int r : system.contact_rows)
        if (holds(system.rows[r]))
          add_row(system.rows[r]);

      dealii::Vector<double>     eigenvalues;
      dealii::FullMatrix<double> vectors;
      gram.compute_eigenvalues_symmetric(-1., 1e300, 0., eigenvalues, vectors);
      double largest = 0;
      for (unsigned int k = 0; k < eigenvalues.size(); ++k)
        largest = std::max(largest, eigenvalues[k]);
      // No row at all: every motion is free.
      std::vector<std::vector<double>> free;
      if (largest == 0)
        {
          for (unsigned int m = 0; m < n_modes; ++m)
            {
              free.emplace_back(n_modes, 0.);
              free.back()[m] = 1;
            }
          return free;
        }
      for (unsigned int k = 0; k < eigenvalues.size(); ++k)
        if (eigenvalues[k] <= 1e-10 * std::max(largest, 1.))
          {
            free.emplace_back(n_modes);
            for (unsigned int m = 0; m < n_modes; ++m)
              free.back()[m] = vectors(m, k);
          }
      return free;
    }

    /** "translation along x", "rotation about z", ...: the mode a null
     * vector of free_rigid_motions is mostly. */
    std::string
    describe_rigid_motion(const std::vector<double> &v)
    {
      static const char *names[] = {"translation along x",
                                    "translation along y",
                                    "translation along z",
                                    "rotation about z",
                                    "rotation about x",
                                    "rotation about y"};
      unsigned int       largest = 0;
      for (unsigned int m = 1; m < v.size(); ++m)
        if (std::abs(v[m]) > std::abs(v[largest]))
          largest = m;
      // 2D: the third mode is the rotation (about z).
      const unsigned int name = (v.size() == 3 && largest == 2) ? 3 : largest;
      return names[name];
    }
  } // namespace

  std::vector<unsigned int>
  rigid_motions_held_only_by_contact_by_body(const EquilibriumSystem &system)
  {
    // Each body on its own (a scene of several bodies): the rows of its
    // nodes must hold its rigid motions. Bilateral rows hold; unilateral
    // contacts and rows with a law of their own (a stop in free travel) may
    // not.
    std::vector<unsigned int> free_modes(system.n_bodies, 0);
    for (unsigned int body = 0; body < system.n_bodies; ++body)
      free_modes[body] =
        free_rigid_motions(system, body, [](const EquilibriumRow &row) {
          return !row.unilateral && !row.law;
        }).size();
    return free_modes;
  }

  std::vector<std::vector<std::string>>
  rigid_motions_no_row_holds(const EquilibriumSystem &system)
  {
    // A row that couples several nodes (a contact pair) may hold a body
    // through another one: such scenes are left to the contact iteration.
    for (const unsigned int r : system.contact_rows)
      {
        const auto &combination = system.rows[r].combination;
        for (const auto &[dof, c] : combination)
          if (system.dof_node(dof) != system.dof_node(combination[0].first))
            return {};
      }
    std::vector<std::vector<std::string>> names(system.n_bodies);
    for (unsigned int body = 0; body < system.n_bodies; ++body)
      for (const auto &motion :
           free_rigid_motions(system, body, [](const EquilibriumRow &) {
             return true;
           }))
        names[body].push_back(describe_rigid_motion(motion));
    return names;
  }
} // namespace hrcontact
