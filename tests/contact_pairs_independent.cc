// Contact between two deformable bodies against a solution of the test's
// own (issue 19): parameters/stacked-blocks-lift-off.prm, a block on a
// block under an eccentric load with partial lift-off, on rectangular
// matching grids, where HR with DGQ1 stresses is the Q1 displacement
// problem (tests/hr_equals_q1). Here: both blocks' Q1 stiffness assembled
// from their Lame constants (tests.h's assemble_q1_elasticity, a modulus
// per body), the traction integrated on the top face, the
// node-to-node gap rows u_s,y >= u_m,y, and a primal-dual active set
// iteration of the test's own (each step a sparse direct solve with the
// active rows as constraints u_s,y = u_m,y). Displacements and contact
// reactions agree with hrcontact's to 1e-8 on both Newton-step paths.

#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>

#include <deal.II/numerics/vector_tools.h>

#include <map>
#include <set>

#include "tests.h"

using namespace dealii;

int
main()
{
  const std::string scene = hrcontact_tests::read_file(
    std::string(SOURCE_DIR) + "/../parameters/stacked-blocks-lift-off.prm");
  const double E[2] = {30e9, 10e9}, nu = 0.2, q = 1e7, W = 2;

  for (const std::string path : {"null-space", "condensed"})
    {
      const auto problem = hrcontact_tests::solve_from_text<2>(
        scene + "subsection Equilibrium reduction\n  set Path = " + path +
        "\nend\nsubsection Output\n  set Write solution = false\n"
        "  set Output directory = results\nend\n");
      const auto &r    = problem->results();
      const auto &tria = r.triangulation();

      // The independent problem on the same mesh.
      const FESystem<2> fe(FE_Q<2>(1), 2);
      DoFHandler<2>     dh(tria);
      dh.distribute_dofs(fe);
      const unsigned int n = dh.n_dofs();

      // The pairs: each node of the upper block's bottom (id 12) and the
      // lower block's node at the same place (top, id 3), by vertex.
      std::map<std::pair<long, long>, unsigned int>      top_of_lower;
      std::vector<std::pair<unsigned int, unsigned int>> pairs; // y dofs s, m
      auto key = [](const Point<2> &x) {
        return std::make_pair(std::lround(x[0] * 1e6), std::lround(x[1] * 1e6));
      };
      for (const auto &cell : dh.active_cell_iterators())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == 3)
            for (const auto v : cell->face(f)->vertex_indices())
              top_of_lower[key(cell->face(f)->vertex(v))] =
                cell->face(f)->vertex_dof_index(v, 1);
      std::set<unsigned int> seen;
      for (const auto &cell : dh.active_cell_iterators())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == 12)
            for (const auto v : cell->face(f)->vertex_indices())
              {
                const unsigned int s = cell->face(f)->vertex_dof_index(v, 1);
                if (seen.insert(s).second)
                  pairs.emplace_back(
                    s, top_of_lower.at(key(cell->face(f)->vertex(v))));
              }

      // K and f.
      DynamicSparsityPattern dsp(n, n);
      DoFTools::make_sparsity_pattern(dh, dsp);
      for (const auto &[s, m] : pairs)
        {
          // the couplings a constraint s = m fills in
          std::vector<unsigned int> around;
          for (auto it = dsp.begin(s); it != dsp.end(s); ++it)
            around.push_back(it->column());
          for (const auto i : around)
            {
              dsp.add(i, m);
              dsp.add(m, i);
            }
        }
      SparsityPattern sp;
      sp.copy_from(dsp);
      SparseMatrix<double> K(sp);
      Vector<double>       f(n);
      // K and f unconstrained (the reactions are K u - f): both blocks'
      // moduli by material id, q on the top's right quarter.
      AffineConstraints<double> none;
      none.close();
      hrcontact_tests::assemble_q1_elasticity(
        dh,
        E[0],
        nu,
        "0; 0",
        {{13,
          "0; (x > " + std::to_string(0.75 * W) + ") ? " + std::to_string(-q) +
            " : 0"}},
        none,
        K,
        f,
        {E[0], E[1]});

      // Primal-dual active set: start with every pair pressed.
      std::vector<bool> active(pairs.size(), true);
      Vector<double>    u(n), reaction(n);
      unsigned int      steps = 0;
      for (bool changed = true; changed && steps < 50; ++steps)
        {
          AffineConstraints<double> constraints;
          VectorTools::interpolate_boundary_values(
            dh, 2, Functions::ZeroFunction<2>(2), constraints);
          VectorTools::interpolate_boundary_values(
            dh,
            10,
            Functions::ZeroFunction<2>(2),
            constraints,
            ComponentMask(std::vector<bool>{true, false}));
          for (unsigned int k = 0; k < pairs.size(); ++k)
            if (active[k])
              {
                constraints.add_line(pairs[k].first);
                constraints.add_entry(pairs[k].first, pairs[k].second, 1.);
              }
          constraints.close();
          SparseMatrix<double> A(sp);
          A.copy_from(K);
          Vector<double> b = f;
          constraints.condense(A, b);
          SparseDirectUMFPACK solver;
          solver.initialize(A);
          solver.vmult(u, b);
          constraints.distribute(u);
          // The force each pair row carries: r = K u - f at the slave's y.
          K.vmult(reaction, u);
          reaction -= f;
          changed = false;
          for (unsigned int k = 0; k < pairs.size(); ++k)
            {
              const double lambda_k = active[k] ? reaction[pairs[k].first] : 0.;
              const double penetration = u[pairs[k].second] - u[pairs[k].first];
              const bool   now = lambda_k + 1e-6 * E[1] * penetration > 0;
              changed |= (now != active[k]);
              active[k] = now;
            }
        }

      // Compare: displacements, and p = n . (K u - f) at each slave node
      // (n = (0, -1)) against hrcontact's reactions of its pair rows.
      double du = 0, u_scale = 0;
      for (unsigned int i = 0; i < n; ++i)
        {
          du      = std::max(du, std::abs(u[i] - r.displacement[i]));
          u_scale = std::max(u_scale, std::abs(u[i]));
        }
      std::map<unsigned int, double> p_own;
      for (const auto &[s, m] : pairs)
        p_own[s / 2] = -reaction[s];
      double       dp = 0, p_scale = 0;
      unsigned int compared = 0, pressed = 0;
      for (unsigned int k = 0; k < r.system.contact_rows.size(); ++k)
        {
          const auto &row = r.system.rows[r.system.contact_rows[k]];
          if (!row.unilateral)
            continue;
          const double own = p_own.at(row.node);
          dp      = std::max(dp, std::abs(own - r.reactions.contact[k]));
          p_scale = std::max(p_scale, std::abs(own));
          ++compared;
        }
      for (const bool a : active)
        pressed += a;
      std::cout << path << ": " << compared << " pair rows, " << pressed
                << " pressed in the independent solution after " << steps
                << " active-set steps, "
                << r.contact->released.size() -
                     std::count(r.contact->released.begin(),
                                r.contact->released.end(),
                                true)
                << " pressed in hrcontact's\n  displacements agree to 1e-8: "
                << hrcontact_tests::check(du / u_scale, 1e-8)
                << "\n  contact reactions agree to 1e-8: "
                << hrcontact_tests::check(dp / p_scale, 1e-8) << std::endl;
    }
}
