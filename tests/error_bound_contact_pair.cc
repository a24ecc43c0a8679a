// The guaranteed error bound with a contact pair between two elastic bodies
// (doc/error-bounds.md, ContactTractions):
// - parameters/two-body-signorini-error-bound.prm, whose exact solution is
//   known, at 4 x 4 to 16 x 16 cells per body: effectivity in [1, 2], the
//   reconstruction admissible to 1e-9 (the slave faces carry the nodal
//   reactions compressively and the master faces their opposite), the
//   inequality |u - u_h|^2 + |sigma - tau|^2 <= eta^2 holds;
// - an independent check: each body of that scene solves the one-body
//   Signorini problem of signorini-error-bound.prm (the lower body, half as
//   stiff, with twice the mirror image's displacement and the same
//   stresses), so its bound must be sqrt(3) times that scene's bound on the
//   rigid plane (the lower body's energies are twice the upper's);
// - mortar rows (matched meshes: the same rows) give the same bound;
// - the upper body's displacement pushed into the lower body: lifted back,
//   the bound grows and stays above the pushed field's true error;
// - Supports/Normal displacements along an axis hold like a prescribed
//   component (the same bound as u_x = 0); a normal value Q1 cannot meet
//   is reported as a support mismatch; a normal along no axis is refused;
// - the patch tests stacked-blocks.prm and three-blocks.prm (uniform
//   stress, reproduced by u_h): the bound is round-off;
// - a tied (bilateral) pair, parameters/two-body-tied-error-bound.prm, with
//   tension and compression across it: effectivity in [1, 2], admissible,
//   the inequality, the true error sqrt(3) times the one-body problem's
//   with its base held;
// - meshes that do not match across the pair are refused by name, before
//   the solve (also with Estimator = bound and no Postprocess/Error bound).


#include <hrcontact/adaptivity/adaptive_run.h>
#include <hrcontact/adaptivity/equilibrated_stress.h>
#include <hrcontact/core/input.h>

#include "error_bound_check.h"
#include "tests.h"

using namespace hrcontact_tests;

namespace
{
  std::string
  two_bodies(const unsigned int refinements, const std::string &extra = "")
  {
    return scene_at_refinement("two-body-signorini-error-bound",
                               2,
                               refinements) +
           extra;
  }

  const std::string exact_stress =
    "if(x<x0, -b*lam*(x-x0)^2, -6*k*abs(y)*(lam+2*mu)*(x-x0)); if(x<x0, "
    "-b*(lam+2*mu)*(x-x0)^2, -6*k*lam*abs(y)*(x-x0)); if(x<x0, "
    "-2*b*mu*y*(x-x0), 0)";
} // namespace

int
main()
{
  for (const unsigned int r : {1u, 2u, 3u})
    {
      const auto         problem = solve_from_text<2>(two_bodies(r));
      std::ostringstream quiet;
      problem->output_results(quiet);
      const auto      &s = problem->results().summary;
      const BoundCheck b = bound_against(problem->results(), exact_stress);
      const auto       one =
        solve_from_text<2>(scene_at_refinement("signorini-error-bound", 2, r));
      one->output_results(quiet);
      const double eff = s.get_double("effectivity_index");
      std::cout
        << (2u << r) << " x " << (2u << r)
        << " cells per body: effectivity in [1, 2]: "
        << (eff >= 1 && eff <= 2 ? "yes" : "NO") << " (" << std::setprecision(3)
        << eff << "), tau admissible to 1e-9: "
        << check(std::max(s.get_double("error_bound_traction_residual"),
                          s.get_double("error_bound_equilibrium_residual")),
                 1e-9)
        << "\n  |u - u_h|^2 + |sigma - tau|^2 <= eta^2 (1 + 1e-9): "
        << check(b.slack, 1e-9)
        << ", no lift: " << check(s.get_double("error_bound_lift"), 0)
        << "\n  bound sqrt(3) times the one-body scene's to 1e-6: "
        << check(std::abs(s.get_double("error_bound") /
                            (std::sqrt(3.) *
                             one->results().summary.get_double("error_bound")) -
                          1),
                 1e-6)
        << ", true error likewise: "
        << check(std::abs(s.get_double("energy_error") /
                            (std::sqrt(3.) * one->results().summary.get_double(
                                               "energy_error")) -
                          1),
                 1e-6)
        << std::endl;
    }

  // Mortar rows on matched meshes: the same rows, the same bound.
  {
    const auto node_to_segment = solve_from_text<2>(two_bodies(2));
    const auto mortar          = solve_from_text<2>(
      two_bodies(2, "subsection Contact\n  set Pair method = mortar\nend\n"));
    const double a =
                   bound_against(node_to_segment->results(), exact_stress).eta,
                 m = bound_against(mortar->results(), exact_stress).eta;
    std::cout << "mortar: the same bound to 1e-9: "
              << check(std::abs(m / a - 1), 1e-9) << std::endl;
  }

  // The upper body (material id 0) pushed down by c (1 - y / 2) (1 + x):
  // its base penetrates the lower body; v = u_h + w lifts the slave nodes
  // back.
  {
    const auto  problem = solve_from_text<2>(two_bodies(2));
    auto        pushed(problem->results());
    const auto &dh      = pushed.spaces.dof_handler_displacement;
    const auto  support = displacement_support_points(pushed);
    std::set<dealii::types::global_dof_index>    upper;
    std::vector<dealii::types::global_dof_index> dofs(8);
    for (const auto &cell : dh.active_cell_iterators())
      if (cell->material_id() == 0)
        {
          cell->get_dof_indices(dofs);
          upper.insert(dofs.begin(), dofs.end());
        }
    const double c = 0.05 * pushed.displacement.linfty_norm();
    for (const auto i : upper)
      if (i % 2 == 1)
        pushed.displacement(i) -=
          c * (1 - support[i][1] / 2) * (1 + support[i][0]);
    report_pushed("the lower body",
                  bound_against(problem->results(), exact_stress),
                  bound_against(pushed, exact_stress),
                  c);
  }

  // A tied (bilateral) pair, parameters/two-body-tied-error-bound.prm:
  // tension and compression across it, linear tractions of either sign.
  // Each body solves the one-body problem with its base held in y (the
  // interface stays on y = 0), so the true error must be sqrt(3) times
  // that problem's; the bound is not the same (the held base's moments are
  // the vertex problems' choice, the tied faces' a split by length).
  {
    const std::string tied_stress =
      "-b*lam*(x-0.5)*abs(x-0.5); -b*(lam+2*mu)*(x-0.5)*abs(x-0.5); "
      "-2*b*mu*y*abs(x-0.5)";
    const std::string one_body = R"(set Dimension = 2
set Constants = E = 1e3, nu = 0.3, lam = E*nu/((1+nu)*(1-2*nu)), mu = E/(2*(1+nu)), b = 1e-2
subsection Geometry
  set Grid generator     = subdivided_hyper_rectangle
  set Grid arguments     = 2, 2 : 0, 0 : 1, 1 : true
  set Global refinements = 2
end
subsection Material
  set Young's modulus = E
  set Poisson's ratio = nu
  set Plane condition = plane strain
end
subsection Loads
  set Body force = 2*b*(lam+mu)*abs(x-0.5); 2*b*mu*y*if(x<0.5, -1, 1)
  set Tractions = 0: -b*lam/4; b*mu*y | 1: -b*lam/4; -b*mu*y | 3: -2*b*mu*abs(x-0.5); -b*(lam+2*mu)*(x-0.5)*abs(x-0.5)
end
subsection Supports
  set Prescribed displacements = 0 x: 0 | 2 y: 0
end
subsection Postprocess
  set Error bound      = true
  set Reference stress = -b*lam*(x-0.5)*abs(x-0.5); -b*(lam+2*mu)*(x-0.5)*abs(x-0.5); -2*b*mu*y*abs(x-0.5)
end
subsection Output
  set Write solution = false
  set Output directory = results
end
)";
    for (const unsigned int r : {1u, 2u, 3u})
      {
        const auto problem = solve_from_text<2>(
          scene_at_refinement("two-body-tied-error-bound", 2, r));
        std::ostringstream quiet;
        problem->output_results(quiet);
        const auto       &res  = problem->results();
        const auto       &s    = res.summary;
        const BoundCheck  b    = bound_against(res, tied_stress);
        std::string       one  = one_body;
        const std::string from = "set Global refinements = 2";
        one.replace(one.find(from),
                    from.size(),
                    "set Global refinements = " + std::to_string(r));
        const auto held = solve_from_text<2>(one);
        held->output_results(quiet);
        double most = 0, least = 0;
        for (const double p : res.reactions.contact)
          {
            most  = std::max(most, p);
            least = std::min(least, p);
          }
        const double eff = s.get_double("effectivity_index");
        std::cout << "tied, " << (2u << r) << " x " << (2u << r)
                  << " cells per body: effectivity in [1, 2]: "
                  << (eff >= 1 && eff <= 2 ? "yes" : "NO") << " ("
                  << std::setprecision(3) << eff
                  << "), tau admissible to 1e-9: " << check(b.admissible, 1e-9)
                  << "\n  |u - u_h|^2 + |sigma - tau|^2 <= eta^2 (1 + 1e-9): "
                  << check(b.slack, 1e-9) << ", the pair carries tension and "
                  << "compression: " << (most > 0 && least < 0 ? "yes" : "NO")
                  << ", true error sqrt(3) times the held base's to 1e-6: "
                  << check(std::abs(s.get_double("energy_error") /
                                      (std::sqrt(3.) *
                                       held->results().summary.get_double(
                                         "energy_error")) -
                                    1),
                           1e-6)
                  << std::endl;
      }
  }

  // Normal displacements (u . n = 0) on the lower body's left side instead
  // of u_x = 0 (on the upper body's, its corner would be a slave node with
  // a normal constraint, which the pair refuses): the same problem, the
  // same bound.
  {
    std::string       text = two_bodies(2);
    const std::string held = "set Prescribed displacements = 0 x: 0 | 10 x: 0";
    text.replace(text.find(held),
                 held.size(),
                 "set Prescribed displacements = 0 x: 0\n"
                 "  set Normal displacements = 10: 0");
    const auto         normal = solve_from_text<2>(text);
    const auto         held_x = solve_from_text<2>(two_bodies(2));
    std::ostringstream quiet;
    normal->output_results(quiet);
    const auto &s = normal->results().summary;
    std::cout
      << "Normal displacements along x: the bound of u_x = 0 to 1e-9: "
      << check(std::abs(bound_against(normal->results(), exact_stress).eta /
                          bound_against(held_x->results(), exact_stress).eta -
                        1),
               1e-9)
      << ", admissible to 1e-9: "
      << check(std::max(s.get_double("error_bound_traction_residual"),
                        s.get_double("error_bound_equilibrium_residual")),
               1e-9)
      << ", no support mismatch: "
      << check(s.get_double("error_bound_support_mismatch"), 0) << std::endl;
    // A normal value Q1 cannot meet between the nodes is reported.
    std::string       curved = text;
    const std::string zero   = "set Normal displacements = 10: 0";
    curved.replace(curved.find(zero),
                   zero.size(),
                   "set Normal displacements = 10: 1e-4*y^2");
    const auto bent = solve_from_text<2>(curved);
    bent->output_results(quiet);
    std::cout
      << "  u . n = 1e-4 y^2 reported as a support mismatch (above 1e-5): "
      << (bent->results().summary.get_double("error_bound_support_mismatch") >
              1e-5 ?
            "yes" :
            "NO")
      << std::endl;
    // A normal that is not an axis: Cook's membrane's inclined sides.
    print_input_refusal(
      "a normal constraint along no axis",
      read_file(std::string(SOURCE_DIR) + "/../parameters/cooks-membrane.prm") +
        "subsection Supports\n  set Normal displacements = 2: 0\nend\n"
        "subsection Finite elements\n  set Stress element = DGQ1\nend\n"
        "subsection Postprocess\n  set Error bound = true\nend\n"
        "subsection Output\n  set Write solution = false\n"
        "  set Output directory = results\nend\n");
  }

  // Patch tests between bodies of different stiffness, meshes matched:
  // the exact solution is uniform stress, which u_h reproduces, so the
  // bound must be round-off (a master side that carried the wrong
  // tractions would show here).
  for (const std::string scene : {"stacked-blocks", "three-blocks"})
    {
      const auto problem = solve_from_text<2>(
        read_file(std::string(SOURCE_DIR) + "/../parameters/" + scene +
                  ".prm") +
        "subsection Postprocess\n  set Error bound = true\nend\n"
        "subsection Output\n  set Write solution = false\n"
        "  set Output directory = results\nend\n");
      std::ostringstream quiet;
      problem->output_results(quiet);
      const auto &s = problem->results().summary;
      std::cout << scene << ": uniform stress, bound below 1e-10 (relative): "
                << check(s.get_double("error_bound_relative"), 1e-10)
                << ", admissible to 1e-12: "
                << check(std::max(s.get_double("error_bound_traction_residual"),
                                  s.get_double(
                                    "error_bound_equilibrium_residual")),
                         1e-12)
                << std::endl;
    }

  // The lower body cut into 3 x 2 cells: slave nodes between master nodes.
  std::string       text = two_bodies(1);
  const std::string body_2 =
    "    set Grid arguments = 2, 2 : 0, 0 : 1, 1 : true";
  text.replace(text.find(body_2),
               body_2.size(),
               "    set Grid arguments = 3, 2 : 0, 0 : 1, 1 : true");
  print_input_refusal("non-matching meshes", text);
  // Estimator = bound on them (no Postprocess/Error bound; no cycles after
  // the first, so that its solve would be logged): refused before it too.
  {
    dealii::ParameterHandler prm;
    hrcontact::declare_all_parameters(prm);
    std::string       cycles = text;
    const std::string bound  = "set Error bound      = true";
    cycles.replace(cycles.find(bound), bound.size(), "set Error bound = false");
    prm.parse_input_from_string(cycles + "subsection Mesh refinement\n"
                                         "  set Adaptive cycles = 0\n"
                                         "  set Estimator = bound\nend\n");
    std::ostringstream log;
    try
      {
        hrcontact::run_adaptive_cycles<2>(prm, log, MPI_COMM_WORLD);
        std::cout << "Estimator = bound on non-matching meshes: NOT refused"
                  << std::endl;
      }
    catch (const hrcontact::InputError &e)
      {
        std::cout << "Estimator = bound on non-matching meshes: refused before "
                     "a solve: "
                  << (log.str().find("augmented Lagrangian") ==
                          std::string::npos ?
                        "yes" :
                        "NO")
                  << std::endl;
      }
  }
}
