// Identities of the equilibrium reduction (eq. 39-43, 50-51) on a rotated
// block with a clamp, a bilateral normal constraint, body force and
// tractions, for each stress element that gives a full-rank C:
//   C R = 0 (every s0 is self-equilibrated),  C t = f,
//   dim(s0) = tau - rank(C) with rank(C) from an independent SVD,
//   and the displacements of eq. 51 satisfy F s = B^T u (unrotated B, global u)
//   with u.n = g on the normal-constrained nodes.

#include <deal.II/lac/lapack_full_matrix.h>

#include "tests.h"

using namespace dealii;
using namespace hrcontact_tests;

void
run(const std::string &element)
{
  auto               problem = solve_from_text<2>(R"(
set Dimension = 2
subsection Geometry
  set Grid generator = subdivided_hyper_rectangle
  set Grid arguments = 4, 2 : 0, 0 : 2, 1 : true
  set Global refinements = 1
  set Rotation angle = 20
end
subsection Material
  set Young's modulus = 70
  set Poisson's ratio = 0.25
  set Plane condition = plane stress
end
subsection Finite elements
  set Stress element = )" + element +
                                    R"(
end
subsection Loads
  set Body force = 0; -0.3
  set Tractions = 1: 0.2; -1 + y
end
subsection Supports
  set Prescribed displacements = 0 : 0; 0
  set Normal displacements = 2: 0.01*x
end
)");
  const auto        &sys     = problem->results().system;
  const auto        &red     = (*problem->results().solve.reduction);
  const unsigned int tau = sys.n_stress_dofs, n = sys.free_rows.size(),
                     m = red.n_self_equilibrated();

  // Dense C from the rotated rows, for the independent checks.
  LAPACKFullMatrix<double> C(n, tau);
  double                   c_norm = 0;
  for (unsigned int j = 0; j < tau; ++j)
    {
      Vector<double> e(tau);
      e[j] = 1;
      for (unsigned int i = 0; i < n; ++i)
        {
          C(i, j) = sys.row_times(sys.rows[sys.free_rows[i]], e);
          c_norm  = std::max(c_norm, std::abs(C(i, j)));
        }
    }

  // C R = 0, column by column.
  double cr = 0;
  for (unsigned int j = 0; j < m; ++j)
    {
      Vector<double> s0(m), s;
      s0[j] = 1;
      red.apply_R(s0, s);
      for (unsigned int i = 0; i < n; ++i)
        cr = std::max(cr,
                      std::abs(sys.row_times(sys.rows[sys.free_rows[i]], s)) /
                        (c_norm * s.linfty_norm()));
    }
  // C t = f.
  double ct = 0, f_norm = 0;
  for (unsigned int i = 0; i < n; ++i)
    {
      const auto &row = sys.rows[sys.free_rows[i]];
      ct              = std::max(ct,
                    std::abs(sys.row_times(row, red.particular_stress()) -
                             sys.row_load(row)));
      f_norm          = std::max(f_norm, std::abs(sys.row_load(row)));
    }
  // Rank by SVD.
  LAPACKFullMatrix<double> C_copy(C);
  C_copy.compute_svd();
  unsigned int rank = 0;
  for (unsigned int i = 0; i < n; ++i)
    rank += (C_copy.singular_value(i) > 1e-10 * C_copy.singular_value(0));

  // F s = B^T u with the global displacements.
  Vector<double> Fs, Btu(tau);
  const auto    &s_h = problem->results().stress; // complete: a serial run
  sys.multiply_flexibility(Vector<double>(s_h.begin(), s_h.end()), Fs);
  const auto &u_h = problem->results().displacement;
  sys.B.Tvmult(Btu, Vector<double>(u_h.begin(), u_h.end()));
  Vector<double> r = Fs;
  r -= Btu;
  // u.n = g on the Q rows.
  double wn = 0;
  for (const unsigned int q : sys.contact_rows)
    {
      double w = 0;
      for (const auto &[dof, c] : sys.rows[q].combination)
        w += c * problem->results().displacement[dof];
      wn = std::max(wn, std::abs(w - sys.rows[q].value));
    }

  std::cout << element << ": tau = " << tau << ", free rows n = " << n
            << ", rank(C) by SVD = " << rank << ", dim(s0) = " << m << "\n"
            << "  dim(s0) == tau - rank(C): "
            << (m == tau - rank ? "yes" : "NO")
            << "\n  max |C R| / (|C| |R|) < 1e-13: " << check(cr, 1e-13)
            << "\n  max |C t - f| / max |f| < 1e-13: "
            << check(ct / f_norm, 1e-13)
            << "\n  |F s - B^T u| / |F s| < 1e-11: "
            << check(r.linfty_norm() / Fs.linfty_norm(), 1e-11)
            << "\n  max |u.n - g| on Q rows < 1e-14: " << check(wn, 1e-14)
            << std::endl;
}

int
main()
{
  run("DGQ1");
  run("DGP1");
}
