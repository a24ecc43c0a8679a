// On parallelogram cells, E eps(u_h) of a Q1 field lies in the DGQ1 stress
// space, so the Hellinger-Reissner solution equals the standard Q1
// displacement solution. The standard solution is computed here on its own:
// stiffness assembled from Lame constants, constraints by deal.II
// (interpolate_boundary_values, compute_nonzero_normal_flux_constraints),
// sparse direct solve. Case A: a rectangle with a clamp, a body force and
// tractions. Case B: the same rectangle rotated by 30 degrees, with a
// bilateral normal constraint u.n = g (the Q rows) on its bottom side.

#include <deal.II/base/function_parser.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>

#include <deal.II/numerics/vector_tools.h>

#include "tests.h"

using namespace dealii;
using namespace hrcontact_tests;

const std::string common = R"(
set Dimension = 2
set Constants = E = 1000, nu = 0.3
subsection Geometry
  set Grid generator = subdivided_hyper_rectangle
  set Grid arguments = 5, 3 : 0, 0 : 2, 1 : true
  set Global refinements = 1
end
subsection Material
  set Young's modulus = E
  set Poisson's ratio = nu
  set Plane condition = plane strain
end
subsection Loads
  set Body force = 0.5*y; -1 + x
  set Tractions = 1: 1 + y; 0.5 | 3: -0.2*x; 0
end
)";

void
compare(const std::string &name, const std::string &text, const double angle)
{
  auto        problem = solve_from_text<2>(common + text);
  const auto &dh      = problem->results().spaces.dof_handler_displacement;
  const auto &fe      = *problem->results().spaces.fe_displacement;

  // Independent standard displacement solution.
  const double E = 1000, nu = 0.3;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)); // plane strain
  const double mu     = E / (2 * (1 + nu));


  AffineConstraints<double> constraints;
  VectorTools::interpolate_boundary_values(dh,
                                           0,
                                           Functions::ZeroFunction<2>(2),
                                           constraints);
  std::unique_ptr<Function<2>> g_times_n;
  if (angle != 0)
    {
      // u.n = g on the bottom side, n = (sin a, -cos a) after rotation.
      const double nx = std::sin(angle), ny = -std::cos(angle);
      g_times_n            = std::make_unique<FunctionParser<2>>(2);
      const std::string  g = "(1e-3*(1 + x*x))";
      std::ostringstream expr;
      expr << std::setprecision(17) << g << "*(" << nx << "); " << g << "*("
           << ny << ")";
      static_cast<FunctionParser<2> *>(g_times_n.get())
        ->initialize("x,y", expr.str(), {});
      std::map<types::boundary_id, const Function<2> *> fmap = {
        {2, g_times_n.get()}};
      VectorTools::compute_nonzero_normal_flux_constraints(
        dh, 0, {2}, fmap, constraints);
    }
  constraints.close();

  DynamicSparsityPattern dsp(dh.n_dofs());
  DoFTools::make_sparsity_pattern(dh, dsp, constraints, false);
  SparsityPattern sp;
  sp.copy_from(dsp);
  SparseMatrix<double> K(sp);
  Vector<double>       rhs(dh.n_dofs()), u(dh.n_dofs());

  assemble_q1_elasticity(dh,
                         E,
                         nu,
                         "0.5*y; -1 + x",
                         {{1, "1 + y; 0.5"}, {3, "-0.2*x; 0"}},
                         constraints,
                         K,
                         rhs);
  const QGauss<2> quadrature(3);
  FEValues<2>     fv(fe, quadrature, update_gradients);

  SparseDirectUMFPACK direct;
  direct.initialize(K);
  direct.vmult(u, rhs);
  constraints.distribute(u);

  const auto    &u_h = problem->results().displacement; // a serial run
  Vector<double> diff(u_h.begin(), u_h.end());
  diff -= u;
  const double u_err = diff.linfty_norm() / u.linfty_norm();

  // Stresses: sigma_h against C eps(u) at quadrature points.
  FEValues<2>                 fs(*problem->results().spaces.fe_stress,
                 quadrature,
                 update_values);
  std::vector<Vector<double>> sh(quadrature.size(), Vector<double>(3));
  std::vector<std::vector<Tensor<1, 2>>> grads(quadrature.size(),
                                               std::vector<Tensor<1, 2>>(2));
  double                                 s_err = 0, s_max = 0;
  auto cs = problem->results().spaces.dof_handler_stress.begin_active();
  for (const auto &cell : dh.active_cell_iterators())
    {
      fv.reinit(cell);
      fs.reinit(cs);
      fv.get_function_gradients(u, grads);
      fs.get_function_values(problem->results().stress, sh);
      for (unsigned int q = 0; q < quadrature.size(); ++q)
        {
          const double exx = grads[q][0][0], eyy = grads[q][1][1],
                       exy = 0.5 * (grads[q][0][1] + grads[q][1][0]);
          const double sxx = lambda * (exx + eyy) + 2 * mu * exx;
          const double syy = lambda * (exx + eyy) + 2 * mu * eyy;
          const double sxy = 2 * mu * exy;
          s_err            = std::max({s_err,
                                       std::abs(sh[q][0] - sxx),
                                       std::abs(sh[q][1] - syy),
                                       std::abs(sh[q][2] - sxy)});
          s_max =
            std::max({s_max, std::abs(sxx), std::abs(syy), std::abs(sxy)});
        }
      ++cs;
    }

  std::cout << name << ": "
            << problem->results().triangulation().n_active_cells()
            << " cells, rows C/Q/H = "
            << problem->results().system.free_rows.size() << "/"
            << problem->results().system.contact_rows.size() << "/"
            << problem->results().system.prescribed_rows.size() << "\n"
            << "  max |u_HR - u_Q1| / max |u_Q1| < 1e-10: "
            << check(u_err, 1e-10)
            << "\n  max |s_HR - C eps(u_Q1)| / max |C eps(u_Q1)| < 1e-10: "
            << check(s_err / s_max, 1e-10)
            << "\n  max |u_Q1| = " << u.linfty_norm() << std::endl;
}

int
main()
{
  std::cout << std::setprecision(6);
  compare(
    "A: rectangle, clamp, body force, tractions",
    "subsection Supports\n  set Prescribed displacements = 0: 0; 0\nend\n",
    0.);
  compare("B: rotated rectangle, bilateral normal constraint on the bottom",
          "subsection Geometry\n  set Rotation angle = 30\nend\n"
          "subsection Supports\n  set Prescribed displacements = 0: 0; 0\n"
          "  set Normal displacements = 2: 1e-3*(1 + x*x)\nend\n",
          numbers::PI / 6);
}
