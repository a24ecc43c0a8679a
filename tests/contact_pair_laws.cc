// Laws on contact pairs (issue 19: "the same constraint laws (unilateral,
// two-sided stops) apply to the relative normal displacement"):
// - Tension across a pair (parameters/stacked-blocks.prm with the top
//   pulled up by delta): a unilateral pair lets the blocks separate (no
//   stress), a bilateral pair transmits the uniform tension
//   sigma_yy = delta / (H/E1' + H/E2') exactly, and a stop that lets the
//   interface open by delta/4 before it holds transmits 3/4 of it; 1e-10 at
//   every cell centre, both Newton-step paths.
// - A stop law on a pair whose master surface is held fixed is the stop of
//   Contact/Stops on the slave body alone: under an eccentric load that
//   presses one end and pulls the other beyond the stop onto its stiffness
//   branch, displacements, stresses and reactions agree to 1e-10 (both
//   paths).
// - Bad input stops with a named error.

#include <hrcontact/constraints/constraint_law.h>
#include <hrcontact/postprocess/field_values.h>

#include <map>

#include "tests.h"

using namespace dealii;

const std::string blocks = hrcontact_tests::read_file(
  std::string(SOURCE_DIR) + "/../parameters/stacked-blocks.prm");
const std::string quiet = "subsection Output\n  set Write solution = false\n"
                          "  set Output directory = results\nend\n";

std::string
path(const std::string &name)
{
  return "subsection Equilibrium reduction\n  set Path = " + name + "\nend\n";
}

std::string
contact(const std::string &pairs, const std::string &laws)
{
  return "subsection Contact\n  set Contact pairs = " + pairs +
         "\n  set Pair laws = " + laws + "\nend\n";
}

/** max over cell centres of |sigma - (0, sigma_yy, 0)| / |reference|. */
double
uniform_error(const hrcontact::Results<2> &r,
              const double                 sigma_yy,
              const double                 reference)
{
  double error = 0;
  for (const auto &cell : r.triangulation().active_cell_iterators())
    for (const std::string q : {"sxx", "syy", "sxy"})
      error = std::max(error,
                       std::abs(hrcontact::point_value(r, cell->center(), q) -
                                (q == "syy" ? sigma_yy : 0.)));
  return error / std::abs(reference);
}

/** Pair rows and stops on each branch of their law. */
std::string
branches(const hrcontact::Results<2> &r)
{
  std::map<std::string, unsigned int> count;
  for (unsigned int k = 0; k < r.system.contact_rows.size(); ++k)
    {
      const auto &row = r.system.rows[r.system.contact_rows[k]];
      // Pair rows span two nodes; other rows without a law are the
      // scene's normal constraints.
      if (!row.law && row.combination.size() <= 2)
        continue;
      if (const auto *stop =
            dynamic_cast<const hrcontact::TwoSidedStop *>(row.law.get()))
        ++count[stop->branch_name(r.contact->pieces[k].branch)];
      else
        ++count[row.law ? row.law->name() :
                row.unilateral ?
                          (r.contact->released[k] ? "released" : "pressed") :
                          "bilateral"];
    }
  std::string s;
  for (const auto &[name, n] : count)
    s += (s.empty() ? "" : ", ") + std::to_string(n) + " " + name;
  return s;
}

void
tension()
{
  const double E1 = 30e9, E2 = 10e9, nu = 0.2, H = 1, delta = 1e-3;
  const double full = delta / (H * (1 - nu * nu) / E1 + H * (1 - nu * nu) / E2);
  const std::string pulled = "subsection Supports\n  set Prescribed "
                             "displacements = 0 x: 0 | 10 x: 0 | 13 y: "
                             "delta\nend\n";
  std::cout << "tension across the pair (top pulled up by delta):\n";
  for (const std::string p : {"null-space", "condensed"})
    {
      std::cout << "  " << p << ":\n";
      const auto lifted =
        hrcontact_tests::solve_from_text<2>(blocks + pulled + path(p) + quiet);
      std::cout << "    unilateral (" << branches(lifted->results())
                << "): no stress to 1e-10: "
                << hrcontact_tests::check(
                     uniform_error(lifted->results(), 0, full), 1e-10)
                << '\n';
      const auto glued = hrcontact_tests::solve_from_text<2>(
        blocks + pulled + contact("12 : 3", "12: bilateral") + path(p) + quiet);
      std::cout << "    bilateral (" << branches(glued->results())
                << "): uniform sigma_yy = delta / (H/E1' + H/E2') to 1e-10: "
                << hrcontact_tests::check(
                     uniform_error(glued->results(), full, full), 1e-10)
                << '\n';
      const auto tether = hrcontact_tests::solve_from_text<2>(
        blocks + pulled +
        contact("12 : 3", "12: stop : -delta/4 : 0 : -1e20 : 1e20") + path(p) +
        quiet);
      std::cout << "    stop opening by delta/4 ("
                << branches(tether->results())
                << "): uniform 3/4 of it to 1e-10: "
                << hrcontact_tests::check(
                     uniform_error(tether->results(), 0.75 * full, full), 1e-10)
                << std::endl;
    }
}

void
stop_on_fixed_master()
{
  // The upper block (body 2, 4 x 2 cells refined once on (0, 1)-(2, 2)) on
  // the lower one whose top is held; its top loaded from -q (pressing) at
  // x = 0 to +2 q (pulling) at x = 2.
  const std::string law  = "stop : -1e-5 : 0 : -1e20 : 4e4 : 0 : 2e9*(1 + x)";
  const std::string load = "subsection Loads\n  set Tractions = 13: 0; "
                           "1e6*(1.5*x - 1)\nend\n";
  const std::string two =
    blocks + load + contact("12 : 3", "12: " + law) +
    "subsection Supports\n  set Prescribed displacements = 10 x: 0 | 3 xy: "
    "0; 0\n  set Normal displacements = 2: 0\nend\n";
  const std::string one =
    "set Dimension = 2\nset Constants = E2 = 10e9, nu = 0.2\n"
    "subsection Geometry\n  set Grid generator = "
    "subdivided_hyper_rectangle\n  set Grid arguments = 4, 2 : 0, 1 : 2, 2 "
    ": true\n  set Global refinements = 1\nend\n"
    "subsection Material\n  set Young's modulus = E2\n  set Poisson's ratio "
    "= nu\n  set Plane condition = plane strain\nend\n"
    "subsection Loads\n  set Tractions = 3: 0; 1e6*(1.5*x - 1)\nend\n"
    "subsection Supports\n  set Prescribed displacements = 0 x: 0\nend\n"
    "subsection Contact\n  set Stops = 2: 0, -1 : " +
    law.substr(7) + "\nend\n";
  std::cout << "a stop on a pair with a fixed master surface = Contact/Stops "
               "on the slave body alone:\n";
  for (const std::string p : {"null-space", "condensed"})
    {
      const auto a = hrcontact_tests::solve_from_text<2>(two + path(p) + quiet);
      const auto b = hrcontact_tests::solve_from_text<2>(one + path(p) + quiet);
      const auto &ra = a->results(), &rb = b->results();
      double      du = 0, ds = 0, u_max = 0, s_max = 0;
      for (const auto &cell : rb.triangulation().active_cell_iterators())
        for (const std::string q : {"ux", "uy", "sxx", "syy", "sxy"})
          {
            const double va = hrcontact::point_value(ra, cell->center(), q);
            const double vb = hrcontact::point_value(rb, cell->center(), q);
            (q[0] == 'u' ? du : ds) =
              std::max(q[0] == 'u' ? du : ds, std::abs(va - vb));
            (q[0] == 'u' ? u_max : s_max) =
              std::max(q[0] == 'u' ? u_max : s_max, std::abs(vb));
          }
      // Reactions by the slave node's position.
      auto reactions = [](const hrcontact::Results<2> &r) {
        std::map<std::pair<long, long>, double> by_point;
        for (unsigned int k = 0; k < r.system.contact_rows.size(); ++k)
          {
            const auto &row = r.system.rows[r.system.contact_rows[k]];
            const auto &x   = r.system.node_coordinates[row.node];
            by_point[{std::lround(1e6 * x[0]), std::lround(1e6 * x[1])}] =
              r.reactions.contact[k];
          }
        return by_point;
      };
      const auto   pa = reactions(ra), pb = reactions(rb);
      double       dp = 0, p_max = 0;
      unsigned int matched = 0;
      for (const auto &[x, p] : pb)
        {
          p_max = std::max(p_max, std::abs(p));
          if (pa.count(x))
            {
              ++matched;
              dp = std::max(dp, std::abs(pa.at(x) - p));
            }
        }
      std::cout << "  " << p << ": pair (" << branches(ra) << "), stops ("
                << branches(rb) << ")\n    " << matched << " of " << pb.size()
                << " rows at the same nodes; u, sigma and p agree to 1e-10: "
                << hrcontact_tests::check(
                     std::max({du / u_max, ds / s_max, dp / p_max}), 1e-10)
                << std::endl;
    }
}

void
expect_error(const std::string &name, const std::string &extra)
{
  try
    {
      hrcontact_tests::solve_from_text<2>(blocks + extra + quiet);
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
  tension();
  stop_on_fixed_master();
  std::cout << "bad input:\n";
  expect_error("a law for a boundary that is no slave",
               contact("12 : 3", "3: bilateral"));
  expect_error("an unknown law", contact("12 : 3", "12: glued"));
  expect_error("a stop with g- >= g+",
               contact("12 : 3", "12: stop : 0 : -1e-4 : -1 : 1"));
  expect_error("a stop with too few values",
               contact("12 : 3", "12: stop : -1e-4 : 0 : -1"));
}
