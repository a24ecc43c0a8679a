// Frictionless unilateral contact against an independent displacement-based
// discrete Signorini solution on a rectangular grid (where HR with DGQ1
// stresses and Q1 displacements coincide): the standard Q1 stiffness, and a
// primal-dual active-set loop of this test's own with the constraints
// d.u = g imposed by AffineConstraints on the active nodes. Displacements
// and reactions must agree to 1e-8 relative.
// Case A: flat obstacle at a distance (non-zero gap), eccentric load, part of
// the base lifts off. Case B: inclined obstacle with gaps varying along the
// base, partly touching; the corner node with a prescribed u_x keeps only the
// free part of the normal (d = e_y, g' = g / |n_y|).

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>

#include <deal.II/numerics/vector_tools.h>

#include <set>

#include "tests.h"

using namespace dealii;
using namespace hrcontact_tests;

struct Case
{
  std::string                               name;
  std::string                               supports; // prm text
  types::boundary_id                        fixed_x_boundary;
  Point<2>                                  obstacle_point;
  Tensor<1, 2>                              obstacle_normal;
  std::string                               body_force;
  std::map<types::boundary_id, std::string> tractions;
  double                                    E;
};

void
run(const Case &c)
{
  std::ostringstream prm;
  prm << std::setprecision(17) << "set Dimension = 2\n"
      << "subsection Geometry\n"
      << "  set Grid generator = subdivided_hyper_rectangle\n"
      << "  set Grid arguments = 4, 2 : 0, 0 : 2, 1 : true\n"
      << "  set Global refinements = 1\n"
      << "end\n"
      << "subsection Material\n  set Young's modulus = " << c.E
      << "\n  set Poisson's ratio = 0.3\n  set Plane condition = plane strain\n"
      << "end\n"
      << "subsection Loads\n  set Body force = " << c.body_force
      << "\n  set Tractions = ";
  bool first = true;
  for (const auto &[id, t] : c.tractions)
    {
      prm << (first ? "" : " | ") << id << ": " << t;
      first = false;
    }
  prm
    << "\nend\n"
    << c.supports
    << "subsection Contact\n  set Obstacles = 2: " << c.obstacle_point[0]
    << ", " << c.obstacle_point[1] << " : " << c.obstacle_normal[0] << ", "
    << c.obstacle_normal[1] << "\nend\n"
    << "subsection Augmented Lagrangian\n  set Initial penalty = 1\n  set Initial penalty scaling = absolute\n"
    << "  set Relative tolerance = 1e-13\nend\n"
    << "subsection Output\n  set Output directory = results\n"
    << "  set Write solution = false\nend\n";
  auto               problem = solve_from_text<2>(prm.str());
  std::ostringstream quiet;
  problem->output_results(quiet);

  // ---- the independent solution --------------------------------------
  const DoFHandler<2> &dh = problem->results().spaces.dof_handler_displacement;
  const Tensor<1, 2>   n  = c.obstacle_normal / c.obstacle_normal.norm();
  // Contact nodes of boundary 2: x dof, y dof, position; and fixed x dofs.
  std::map<types::global_dof_index,
           std::pair<types::global_dof_index, Point<2>>>
                                    contact; // y dof -> (x dof, point)
  std::set<types::global_dof_index> fixed_x;
  for (const auto &cell : dh.active_cell_iterators())
    for (const auto f : cell->face_indices())
      if (cell->face(f)->at_boundary())
        for (const auto v : cell->face(f)->vertex_indices())
          {
            const auto xd = cell->face(f)->vertex_dof_index(v, 0);
            const auto yd = cell->face(f)->vertex_dof_index(v, 1);
            if (cell->face(f)->boundary_id() == 2)
              contact[yd] = {xd, cell->face(f)->vertex(v)};
            if (cell->face(f)->boundary_id() == c.fixed_x_boundary)
              fixed_x.insert(xd);
          }
  // Direction and gap per contact node (free part of n where u_x is fixed).
  std::map<types::global_dof_index, std::pair<Tensor<1, 2>, double>> dg;
  for (const auto &[yd, xp] : contact)
    {
      double       g = (c.obstacle_point - xp.second) * n;
      Tensor<1, 2> d = n;
      if (fixed_x.count(xp.first))
        {
          d[0] = 0;
          g /= std::abs(n[1]);
          d /= d.norm();
        }
      dg[yd] = {d, g};
    }

  DynamicSparsityPattern dsp(dh.n_dofs());
  DoFTools::make_sparsity_pattern(dh, dsp);
  SparsityPattern sp;
  sp.copy_from(dsp);
  SparseMatrix<double> K_free(sp), K(sp);
  Vector<double>       f_free(dh.n_dofs()), rhs(dh.n_dofs()), u(dh.n_dofs());
  AffineConstraints<double> none;
  none.close();
  assemble_q1_elasticity(
    dh, c.E, 0.3, c.body_force, c.tractions, none, K_free, f_free);

  std::set<types::global_dof_index> active;
  for (const auto &[yd, xp] : contact)
    active.insert(yd);
  std::map<types::global_dof_index, double> p;
  unsigned int                              iterations = 0;
  for (; iterations < 50; ++iterations)
    {
      AffineConstraints<double> constraints;
      for (const auto xd : fixed_x)
        {
          constraints.add_line(xd);
        }
      for (const auto yd : active)
        {
          // d . u = g  ->  u_y = (g - d_x u_x) / d_y.
          const auto &[d, g] = dg[yd];
          const auto xd      = contact[yd].first;
          constraints.add_line(yd);
          if (!fixed_x.count(xd) && d[0] != 0)
            constraints.add_entry(yd, xd, -d[0] / d[1]);
          constraints.set_inhomogeneity(yd, g / d[1]);
        }
      constraints.close();
      SparseMatrix<double> Kc(sp);
      rhs = 0;
      // Condense the unconstrained system.
      Kc.copy_from(K_free);
      Vector<double> f = f_free;
      constraints.condense(Kc, f);
      SparseDirectUMFPACK direct;
      direct.initialize(Kc);
      direct.vmult(u, f);
      constraints.distribute(u);
      // Reaction on the body R = K u - f; p = R . d (<= 0 compressive).
      Vector<double> R(dh.n_dofs());
      K_free.vmult(R, u);
      R -= f_free;
      std::set<types::global_dof_index> new_active;
      for (const auto &[yd, xp] : contact)
        {
          const auto &[d, g] = dg[yd];
          const double pi    = R[xp.first] * d[0] + R[yd] * d[1];
          const double w     = u[xp.first] * d[0] + u[yd] * d[1];
          p[yd]              = active.count(yd) ? pi : 0.;
          if (-p[yd] + c.E * (w - g) > 0)
            new_active.insert(yd);
        }
      if (new_active == active)
        break;
      active = new_active;
    }

  // ---- comparison -------------------------------------------------------
  const auto    &u_h = problem->results().displacement; // a serial run
  Vector<double> diff(u_h.begin(), u_h.end());
  diff -= u;
  double      p_diff = 0, p_max = 0;
  const auto &sys = problem->results().system;
  for (unsigned int k = 0; k < sys.contact_rows.size(); ++k)
    {
      const auto &row = sys.rows[sys.contact_rows[k]];
      const auto  yd  = row.combination[1].first;
      p_diff =
        std::max(p_diff,
                 std::abs(problem->results().reactions.contact[k] - p[yd]));
      p_max = std::max(p_max, std::abs(p[yd]));
    }
  std::cout << c.name << "\n  independent active set: " << active.size()
            << " of " << contact.size() << " base nodes pressed, after "
            << iterations + 1 << " solves\n"
            << "  HR: converged = "
            << problem->results().summary.get("converged") << ", pressed = "
            << problem->results().summary.get("pressed_constraints")
            << "\n  max |u_HR - u_Q1| / max |u_Q1| < 1e-8: "
            << check(diff.linfty_norm() / u.linfty_norm(), 1e-8)
            << "\n  max |p_HR - p_Q1| / max |p_Q1| < 1e-8: "
            << check(p_diff / p_max, 1e-8) << std::endl;
  print_kkt(*problem);
}

int
main()
{
  run({"A: flat obstacle 1e-3 below the base, eccentric load",
       "subsection Supports\n  set Prescribed displacements = 2 x: 0\nend\n",
       2,
       Point<2>(0, -1e-3),
       Tensor<1, 2>({0., -1.}),
       "0; -1",
       {{3, "0; -20*(x > 1.5)"}},
       1000.});
  run({"B: inclined obstacle, gaps 2e-4 to 1e-4 along the base",
       "subsection Supports\n  set Prescribed displacements = 0 x: 0\nend\n",
       0,
       Point<2>(0, -2e-4),
       Tensor<1, 2>({0.00005, -1.}),
       "0; -1",
       {{3, "0; -2"}},
       1e6});
}
