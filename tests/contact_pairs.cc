// Contact between deformable bodies (issue 19): two blocks of different
// moduli stacked and pressed together through a contact pair
// (parameters/stacked-blocks.prm).
// - Matching meshes: the node-to-node rows transmit the uniform stress
//   sigma_yy = -delta / (H/E1' + H/E2') exactly (1e-10 at every cell
//   centre, both Newton-step paths).
// - Non-matching meshes: node to segment does not pass the patch test; the
//   error is printed (both paths agree on it to 1e-9).
// - Action and reaction: every pair row's nodal reactions (slave and
//   master) sum to zero, and loads and reactions balance.
// - Bad input stops with a named error: overlapping bodies, a slave
//   boundary with no master in reach, a pair naming one boundary twice,
//   two bodies with the same boundary id, a body held by nothing but
//   contact and pulled away.

#include <hrcontact/postprocess/field_values.h>

#include "tests.h"

using namespace dealii;

const std::string scene = hrcontact_tests::read_file(
  std::string(SOURCE_DIR) + "/../parameters/stacked-blocks.prm");
const std::string quiet = "subsection Output\n  set Write solution = false\n"
                          "  set Output directory = results\nend\n";

std::unique_ptr<hrcontact::HRProblem<2>>
run(const std::string &extra, const std::string &path)
{
  return hrcontact_tests::solve_from_text<2>(
    scene + extra + "subsection Equilibrium reduction\n  set Path = " + path +
    "\nend\n" + quiet);
}

/** max over cell centres of |sigma - exact| / |exact sigma_yy|. */
double
patch_error(const hrcontact::Results<2> &r)
{
  const double E1 = 30e9, E2 = 10e9, nu = 0.2, H = 1, delta = 1e-3;
  const double exact =
    -delta / (H * (1 - nu * nu) / E1 + H * (1 - nu * nu) / E2);
  double error = 0;
  for (const auto &cell : r.triangulation().active_cell_iterators())
    for (const std::string q : {"sxx", "syy", "sxy"})
      {
        const double v = hrcontact::point_value(r, cell->center(), q);
        error = std::max(error, std::abs(v - (q == "syy" ? exact : 0.)));
      }
  return error / std::abs(exact);
}

/**
 * The largest |sum of a pair row's nodal reactions| / |p| (by component)
 * and the global imbalance |f + reactions| / max |reaction|.
 */
std::pair<double, double>
balance(const hrcontact::Results<2> &r)
{
  const auto &sys      = r.system;
  double      pair_sum = 0, largest = 0;
  double      total[2] = {0, 0};
  for (unsigned int i = 0; i < sys.n_displacement_dofs; ++i)
    total[i % 2] += sys.load[i];
  auto add = [&](const hrcontact::EquilibriumRow &row, const double p) {
    const auto sum = hrcontact_tests::row_force(sys, row, p);
    for (unsigned int d = 0; d < 2; ++d)
      total[d] += sum[d];
    largest = std::max(largest, std::abs(p));
    return std::max(std::abs(sum[0]), std::abs(sum[1]));
  };
  for (unsigned int k = 0; k < sys.contact_rows.size(); ++k)
    {
      const auto  &row = sys.rows[sys.contact_rows[k]];
      const double s   = add(row, r.reactions.contact[k]);
      if (row.unilateral && r.reactions.contact[k] != 0)
        pair_sum = std::max(pair_sum, s / std::abs(r.reactions.contact[k]));
    }
  for (unsigned int k = 0; k < sys.prescribed_rows.size(); ++k)
    add(sys.rows[sys.prescribed_rows[k]], r.reactions.support[k]);
  return {pair_sum, std::max(std::abs(total[0]), std::abs(total[1])) / largest};
}

void
report(const std::string &name, const hrcontact::Results<2> &r)
{
  unsigned int pair_rows = 0, spanning = 0;
  for (const unsigned int k : r.system.contact_rows)
    if (r.system.rows[k].unilateral)
      {
        ++pair_rows;
        spanning += r.system.rows[k].combination.size() > 4;
      }
  const auto [pair_sum, imbalance] = balance(r);
  std::cout << "  " << name << ": " << pair_rows << " pair rows (" << spanning
            << " on a master segment, the others node to node), "
            << r.contact->history.size() << " multiplier updates\n"
            << "    each pair row's reactions sum to zero (1e-12 |p|): "
            << hrcontact_tests::check(pair_sum, 1e-12)
            << "\n    loads and reactions balance (1e-10): "
            << hrcontact_tests::check(imbalance, 1e-10) << std::endl;
}

void
expect_error(const std::string &name, const std::string &extra)
{
  try
    {
      hrcontact_tests::solve_from_text<2>(scene + extra + quiet);
      std::cout << "  " << name << ": NO ERROR" << std::endl;
    }
  catch (const std::exception &e)
    {
      std::cout << "  " << name << ": " << e.what() << std::endl;
    }
}

int
main()
{
  std::cout << "matching meshes (4 x 2 cells on 4 x 2, refined once):\n";
  for (const std::string path : {"null-space", "condensed"})
    {
      const auto p = run("", path);
      report(path, p->results());
      std::cout << "    uniform stress to 1e-10: "
                << hrcontact_tests::check(patch_error(p->results()), 1e-10)
                << std::endl;
    }

  std::cout << "non-matching meshes (upper block 3 x 2 on 4 x 2):\n";
  const std::string coarser = "subsection Bodies\n  subsection Body 2\n"
                              "    set Grid arguments = 3, 2 : 0, 0 : 2, 1 : "
                              "true\n  end\nend\n";
  double            errors[2];
  for (unsigned int k = 0; k < 2; ++k)
    {
      const auto p = run(coarser, k == 0 ? "null-space" : "condensed");
      report(k == 0 ? "null-space" : "condensed", p->results());
      errors[k] = patch_error(p->results());
    }
  std::cout << std::setprecision(3)
            << "    node to segment fails the patch test: largest stress "
               "error / |sigma_yy| = "
            << errors[0] << "\n    the paths agree on it to 1e-9: "
            << hrcontact_tests::check(std::abs(errors[0] - errors[1]), 1e-9)
            << std::endl;

  // Mortar (segment to segment, dual basis): the same non-matching meshes
  // pass the patch test.
  for (const std::string path : {"null-space", "condensed"})
    {
      const auto p =
        run(coarser + "subsection Contact\n  set Pair method = mortar\nend\n",
            path);
      report("mortar, " + path, p->results());
      std::cout << "    uniform stress to 1e-10: "
                << hrcontact_tests::check(patch_error(p->results()), 1e-10)
                << std::endl;
    }

  // 3D: two boxes of different moduli pressed together, matching meshes
  // (bilinear master faces, node to node) and non-matching (4 x 4 on 3 x 3
  // faces in plan: node to face).
  for (const auto &[upper, method] :
       std::vector<std::pair<unsigned int, std::string>>{{4, "node to segment"},
                                                         {3, "node to segment"},
                                                         {3, "mortar"}})
    {
      const std::string text =
        "set Dimension = 3\n"
        "set Constants = delta = 1e-3, E1 = 30e9, E2 = 10e9, nu = 0.2\n"
        "subsection Geometry\n  set Grid generator = "
        "subdivided_hyper_rectangle\n"
        "  set Grid arguments = 4, 4, 2 : 0, 0, 0 : 1, 1, 0.5 : true\nend\n"
        "subsection Material\n  set Young's modulus = E1\n  set Poisson's "
        "ratio = nu\nend\n"
        "subsection Bodies\n  set Number of bodies = 2\n  subsection Body 2\n"
        "    set Grid generator = subdivided_hyper_rectangle\n"
        "    set Grid arguments = " +
        std::to_string(upper) + ", " + std::to_string(upper) +
        ", 2 : 0, 0, 0 : 1, 1, 0.5 : true\n"
        "    set Shift = 0, 0, 0.5\n    set Own material = true\n"
        "    subsection Material\n      set Young's modulus = E2\n"
        "      set Poisson's ratio = nu\n    end\n  end\nend\n"
        "subsection Supports\n  set Prescribed displacements = 0 x: 0 | 2 y: "
        "0 | 10 x: 0 | 12 y: 0 | 15 z: -delta\n"
        "  set Normal displacements = 4: 0\nend\n"
        "subsection Contact\n  set Contact pairs = 14 : 5\n"
        "  set Pair method = " +
        method +
        "\nend\n"
        "subsection Equilibrium reduction\n  set Path = condensed\nend\n" +
        quiet;
      const auto   p     = hrcontact_tests::solve_from_text<3>(text);
      const auto  &r3    = p->results();
      const double exact = -1e-3 / (0.5 / 30e9 + 0.5 / 10e9);
      double       error = 0;
      for (const auto &cell : r3.triangulation().active_cell_iterators())
        for (const std::string q : {"sxx", "syy", "szz", "sxy", "sxz", "syz"})
          error =
            std::max(error,
                     std::abs(hrcontact::point_value(r3, cell->center(), q) -
                              (q == "szz" ? exact : 0.)));
      unsigned int rows = 0, on_face = 0;
      for (const unsigned int k : r3.system.contact_rows)
        if (r3.system.rows[k].unilateral)
          {
            ++rows;
            on_face += r3.system.rows[k].combination.size() > 6;
          }
      std::cout << "3D, " << method << ", upper box " << upper << " x " << upper
                << " on 4 x 4 cells: " << rows << " pair rows (" << on_face
                << " on master faces)\n";
      if (upper == 4 || method == "mortar")
        std::cout << "  uniform stress to 1e-10 (uniaxial, lateral "
                     "expansion free): "
                  << hrcontact_tests::check(error / std::abs(exact), 1e-10)
                  << std::endl;
      else
        std::cout << std::setprecision(3)
                  << "  node to face fails the patch test: largest stress "
                     "error / |sigma_zz| = "
                  << error / std::abs(exact) << std::endl;
    }

  std::cout << "bad input:\n";
  expect_error("overlap",
               "subsection Bodies\n  subsection Body 2\n    set Shift = 0, "
               "0.9\n  end\nend\n");
  expect_error("out of reach",
               "subsection Bodies\n  subsection Body 2\n    set Shift = 0, "
               "3\n  end\nend\n");
  expect_error("one boundary twice",
               "subsection Contact\n  set Contact pairs = 12 : 12\nend\n");
  expect_error("swapped ids",
               "subsection Contact\n  set Contact pairs = 3 : 2\nend\n");
  // The upper block held only by contact and pulled off: the run stops
  // with the floating outcome (hrcontact exits with code 3 and its message).
  {
    const auto p = hrcontact_tests::solve_from_text<2>(
      scene +
      "subsection Supports\n  set Prescribed displacements = 0 x: 0 | 10 x: "
      "0\nend\nsubsection Loads\n  set Tractions = 13: 0; 1e6\nend\n" +
      quiet);
    const auto &r = p->results();
    std::cout << "  pulled away: " << r.free_rigid_motions
              << " rigid motion(s) held only by contact, converged "
              << (r.converged() ? "true" : "false") << ", outcome floating: "
              << (r.contact->outcome == hrcontact::SolveOutcome::floating ?
                    "yes" :
                    "NO")
              << std::endl;
  }
  // Three blocks (parameters/three-blocks.prm): the middle one pressed
  // onto the bottom one by a shear on its side, the top one pulled off. One
  // pair stays pressed while the top body floats: the run stops with the
  // floating outcome for body 3 (before, every contact row had to be
  // released, and the solve went on with a singular system).
  {
    const auto p = hrcontact_tests::solve_from_text<2>(
      hrcontact_tests::read_file(std::string(SOURCE_DIR) +
                                 "/../parameters/three-blocks.prm") +
      "subsection Supports\n  set Prescribed displacements = 0 x: 0 | 10 x: "
      "0 | 20 x: 0\nend\nsubsection Loads\n  set Tractions = 10: 0; -1e6 | "
      "23: 0; 1e6\nend\n" +
      quiet);
    const auto  &r       = p->results();
    unsigned int pressed = 0;
    for (unsigned int k = 0; k < r.system.contact_rows.size(); ++k)
      pressed += !r.contact->released[k];
    std::cout << "  top body of three pulled away: outcome floating: "
              << (r.contact->outcome == hrcontact::SolveOutcome::floating ?
                    "yes" :
                    "NO")
              << " (" << r.contact->floating_body << "), " << pressed
              << " pair rows still pressed" << std::endl;
  }
  expect_error("same boundary ids",
               "subsection Bodies\n  subsection Body 2\n    set Boundary id "
               "offset = 2\n  end\nend\n");
}
