// The manufactured no-tension pier posed so that the closed form is exact
// on the whole pier (parameters/no-tension-manufactured-pier-held.prm, issue
// 54): the base held at one point, and the edge of the compressed width, x
// = 1/3, inside a column of cells at every mesh (at a third or two thirds of
// a cell). DGQ1 stresses hold the triangle exactly on every other cell, so
// the error is the kink's on that column: O(h) at its worst and O(h^1.5) in
// L2 (one column of width h with an O(h) error). At 4, 8 and 16 cells
// across, with the default interior-point method: both rates, measured by a
// rule that resolves the kink; the resultant N on every cell row's mid-line
// to round-off and the moment N e; the compressed width at mid-height within
// one cell; no Gauss point in tension beyond the allowance and the stress
// tolerance; at most 40 Newton steps per mesh.

#include <deal.II/base/quadrature_lib.h>

#include <hrcontact/postprocess/section_forces.h>

#include "tests.h"

using namespace hrcontact_tests;

namespace
{
  const double b = 1, H = 6, N = 1e5, c = 2. / 3, e = b / 2 - c / 3,
               q = 2 * N / c;

  double
  exact_syy(const double x)
  {
    return (x > b - c) ? -q * (x - (b - c)) / c : 0.;
  }

  /** Max and L2 norms of sigma_h - sigma over the pier, relative to those
   * of sigma, on 8 x 8 copies of the 3-point Gauss rule per cell (the
   * kink's cell resolved to h / 8). */
  std::pair<double, double>
  stress_errors(const hrcontact::Results<2> &res)
  {
    const auto                &fe = *res.spaces.fe_stress;
    const dealii::QIterated<2> rule(dealii::QGauss<1>(3), 8);
    dealii::FEValues<2>        fv(fe,
                           rule,
                           dealii::update_values |
                             dealii::update_quadrature_points |
                             dealii::update_JxW_values);
    dealii::Vector<double>     values(fe.n_dofs_per_cell());
    double                     max_e = 0, max_s = 0, l2_e = 0, l2_s = 0;
    for (const auto &cell :
         res.spaces.dof_handler_stress.active_cell_iterators())
      {
        fv.reinit(cell);
        res.spaces.cell_values(cell, res.stress, values);
        for (unsigned int t = 0; t < rule.size(); ++t)
          {
            dealii::SymmetricTensor<2, 2> sigma, exact;
            for (unsigned int j = 0; j < values.size(); ++j)
              sigma += values[j] * fv.shape_value(j, t) *
                       hrcontact::MixedSpaces<2>::stress_basis_tensor(
                         fe.system_to_component_index(j).first);
            exact[1][1]    = exact_syy(fv.quadrature_point(t)[0]);
            const double d = (sigma - exact).norm(), s = exact.norm();
            max_e = std::max(max_e, d);
            max_s = std::max(max_s, s);
            l2_e += d * d * fv.JxW(t);
            l2_s += s * s * fv.JxW(t);
          }
      }
    return {max_e / max_s, std::sqrt(l2_e / l2_s)};
  }
} // namespace

int
main()
{
  std::cout << std::setprecision(3);
  double previous_max = 0, previous_l2 = 0;
  for (const unsigned int r : {2u, 3u, 4u})
    {
      const auto problem = solve_from_text<2>(
        scene_at_refinement("no-tension-manufactured-pier-held", 2, r));
      const auto        &res   = problem->results();
      const unsigned int cells = 1u << r;
      const double       h     = b / cells;
      std::cout << cells << " x " << 6 * cells
                << " cells: converged to the stress tolerance: "
                << check(res.material.changes.back(), 1e-6)
                << ", in at most 40 Newton steps: "
                << (res.material.newton_steps <= 40 ? "yes" : "NO") << '\n';

      // Every cell row's mid-line carries the same resultant to round-off:
      // the load the top's face rule applies, which misses N by O(h^2)
      // because the traction's kink lies inside a face. The moment about
      // the centre line within h^2 / 10 of N e.
      const double applied =
        -horizontal_section(res, dealii::Point<2>(b / 2, 0.5 * h)).N;
      double worst_n = 0, worst_m = 0;
      for (unsigned int row = 0; row < 6 * cells; ++row)
        {
          const auto f =
            horizontal_section(res, dealii::Point<2>(b / 2, (row + 0.5) * h));
          worst_n = std::max(worst_n, std::abs(f.N + applied) / N);
          worst_m = std::max(worst_m, std::abs(f.M / (N * e) - 1));
        }
      std::cout << "  on every row's mid-line: the same resultant to 1e-9: "
                << check(worst_n, 1e-9) << ", N within h^2 / 10: "
                << check(std::abs(applied / N - 1), 0.1 * h * h)
                << ", moment N e within h^2 / 10: "
                << check(worst_m, 0.1 * h * h) << '\n';

      // The compressed width at mid-height, and the cone at the points.
      unsigned int compressed = 0;
      const double y0         = H / 2 + 0.5 * h;
      for (unsigned int i = 0; i < 4000; ++i)
        if (hrcontact::point_value(res,
                                   dealii::Point<2>((i + 0.5) * b / 4000, y0),
                                   "syy") < -1e-3 * q)
          ++compressed;
      std::cout << "  compressed width within one cell of c: "
                << check(std::abs(compressed * b / 4000 - c), h)
                << ", tension at any Gauss point below the allowance and "
                   "the tolerance (1e-8 + 1e-6 of the largest stress): "
                << check(largest_gauss_point_stress(res), 1.01e-6) << '\n';

      const auto [max_error, l2_error] = stress_errors(res);
      std::cout << "  stress error: max " << max_error << ", L2 " << l2_error;
      if (previous_max > 0)
        {
          const double max_rate = std::log2(previous_max / max_error),
                       l2_rate  = std::log2(previous_l2 / l2_error);
          std::cout << "; rates: max " << max_rate << " (1 expected, within "
                    << "0.85-1.15: "
                    << (std::abs(max_rate - 1) <= 0.15 ? "yes" : "NO")
                    << "), L2 " << l2_rate << " (1.5 expected, within "
                    << "1.3-1.7: "
                    << (std::abs(l2_rate - 1.5) <= 0.2 ? "yes" : "NO") << ")";
        }
      std::cout << std::endl;
      previous_max = max_error;
      previous_l2  = l2_error;
    }
}
