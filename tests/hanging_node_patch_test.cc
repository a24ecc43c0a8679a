// Hanging nodes (Mesh refinement/Refinement region) on the condensed path.
// (1) Patch tests, 2D and 3D, DGQ1 and the assumed stresses: a uniform stress
//     state on a locally refined mesh, driven by its linear displacement on
//     the whole boundary or by tractions, reproduced to 1e-10.
// (2) Contact on a refined contact surface: a block pressed by a uniform
//     traction q onto a flat frictionless obstacle, refined at part of its
//     base (in 3D hanging nodes lie on the contact face and have no row).
//     Exact: sigma_yy = -q everywhere, and each contact node carries q times
//     its tributary length of the conforming trace (2D: the hat functions
//     of the base's nodes; the hanging nodes' values are interpolated).
// (3) Hertz on a mesh refined around the contact zone: the global balance
//     holds to round-off (it needs the hanging nodes' equations shared among
//     their parents' rows), and the peak pressure is that of the uniformly
//     refined mesh with the same cells there, within 0.2 %, at a third of
//     its dofs.

#include <hrcontact/discretisation/hanging_nodes.h>
#include <hrcontact/postprocess/field_values.h>

#include <algorithm>

#include "tests.h"

using namespace hrcontact_tests;

template <int dim>
std::string
block_text(const std::string &element,
           const std::string &region,
           const std::string &supports_and_loads,
           const std::string &reference)
{
  return "set Dimension = " + std::to_string(dim) +
         "\n"
         "subsection Geometry\n"
         "  set Grid generator = subdivided_hyper_cube\n"
         "  set Grid arguments = 4 : 0 : 1 : true\n"
         "end\n"
         "subsection Mesh refinement\n"
         "  set Refinement region = " +
         region +
         "\n"
         "  set Region refinements = 2\n"
         "end\n"
         "subsection Material\n"
         "  set Young's modulus = 1000\n"
         "  set Poisson's ratio = 0.3\n"
         "  set Plane condition = plane strain\n"
         "end\n"
         "subsection Finite elements\n"
         "  set Stress element = " +
         element + "\nend\n" + supports_and_loads +
         "subsection Postprocess\n"
         "  set Reference stress = " +
         reference + "\nend\n";
}

template <int dim>
std::string
region()
{
  return dim == 2 ? "0.1, -0.1 : 0.6, 0.45" : "0.1, -0.1, 0.1 : 0.6, 0.45, 0.6";
}

template <int dim>
void
report(const std::string               &name,
       const hrcontact::HRProblem<dim> &problem,
       const std::string               &reference)
{
  const auto &r                = problem.results();
  const auto [max_err, l2_err] = stress_errors<dim>(r, reference);
  std::cout << "  " << name << ": " << r.triangulation().n_active_cells()
            << " cells, " << r.system.n_hanging_dofs / dim
            << " hanging nodes, max relative stress error < 1e-10: "
            << check(max_err, 1e-10) << ", L2 < 1e-10: " << check(l2_err, 1e-10)
            << std::endl;
}

template <int dim>
void
patch(const std::string &element)
{
  std::cout << "dim = " << dim << ", stress element " << element << std::endl;
  double s[3][3], eps[3][3];
  patch_state<dim>(1000, 0.3, s, eps);
  const std::string reference = stress_reference<dim>(s),
                    normal    = stress_reference<dim>(s, true);
  report<dim>("displacement patch",
              *solve_from_text<dim>(
                block_text<dim>(element,
                                region<dim>(),
                                linear_displacement_supports<dim>(eps),
                                reference)),
              reference);
  report<dim>(
    "traction patch",
    *solve_from_text<dim>(block_text<dim>(
      element, region<dim>(), normal_traction_supports<dim>(s), normal)),
    normal);
}

template <int dim>
void
pressed_block()
{
  const double q = 2.5;
  std::cout << "dim = " << dim << ", block pressed onto an obstacle"
            << std::endl;
  std::ostringstream t, reference;
  t << "subsection Supports\n  set Prescribed displacements = 0 x: 0"
    << (dim == 3 ? " | 4 z: 0" : "") << "\nend\n"
    << "subsection Contact\n  set Obstacles = 2: 0, 0"
    << (dim == 3 ? ", 0" : "") << " : 0, -1" << (dim == 3 ? ", 0" : "")
    << "\nend\n"
    << "subsection Loads\n  set Tractions = 3: 0; " << -q
    << (dim == 3 ? "; 0" : "") << "\nend\n";
  for (unsigned int c = 0; c < hrcontact::MixedSpaces<dim>::n_stress_components;
       ++c)
    reference << (c ? "; " : "") << (c == 1 ? -q : 0.);
  const auto problem = solve_from_text<dim>(
    block_text<dim>("DGQ1", region<dim>(), t.str(), reference.str()));
  report<dim>("pressed block", *problem, reference.str());
  const auto &r      = problem->results();
  const auto &system = r.system;

  // The base's nodes: those with a contact row, and the hanging ones.
  std::vector<std::pair<double, double>> rows; // (x, reaction), 2D
  double                                 total = 0, largest_p = -1e300;
  for (unsigned int k = 0; k < system.contact_rows.size(); ++k)
    {
      const auto &row = system.rows[system.contact_rows[k]];
      total += r.reactions.contact[k];
      largest_p = std::max(largest_p, r.reactions.contact[k]);
      rows.emplace_back(system.node_coordinates[row.node][0],
                        r.reactions.contact[k]);
    }
  unsigned int hanging_on_base = 0;
  for (const auto &cell :
       r.spaces.dof_handler_displacement.active_cell_iterators())
    for (const auto &face : cell->face_iterators())
      if (face->at_boundary() && face->boundary_id() == 2)
        for (unsigned int v = 0; v < face->n_vertices(); ++v)
          if (hrcontact::is_hanging(r.system, face->vertex_dof_index(v, 0)))
            ++hanging_on_base;
  std::cout << "  " << rows.size() << " contact rows, every one pressed: "
            << (largest_p < 0 ? "yes" : "no")
            << "; hanging base nodes (counted per face) " << hanging_on_base
            << (dim == 3 ? " (3D: some)" : " (2D: none)") << ": "
            << ((dim == 3) == (hanging_on_base > 0) ? "yes" : "no") << std::endl
            << "  total contact force = " << total
            << ", -q x base area within 1e-10: "
            << check(std::abs(total + q) / q, 1e-10) << std::endl;
  if (dim == 2)
    {
      // Each node's share of the conforming trace: half the distance
      // between its neighbours along the base.
      std::sort(rows.begin(), rows.end());
      double worst = 0;
      for (unsigned int k = 0; k < rows.size(); ++k)
        {
          const double left = k > 0 ? rows[k - 1].first : rows[k].first;
          const double right =
            k + 1 < rows.size() ? rows[k + 1].first : rows[k].first;
          worst =
            std::max(worst, std::abs(rows[k].second + q * (right - left) / 2));
        }
      std::cout << "  each node's reaction = -q x its tributary length, to "
                   "1e-10 q: "
                << check(worst / q, 1e-10) << std::endl;
    }
}

void
hertz()
{
  auto run = [](const unsigned int global, const unsigned int local) {
    auto problem = solve_from_text<2>(
      read_file(std::string(SOURCE_DIR) + "/../parameters/hertz.prm") +
      "subsection Geometry\n  set Global refinements = " +
      std::to_string(global) +
      "\nend\n"
      "subsection Mesh refinement\n"
      "  set Refinement region = " +
      (local > 0 ? "-0.001, -0.051 : 0.015, -0.043" : "") +
      "\n  set Region refinements = " + std::to_string(local) +
      "\nend\n"
      "subsection Output\n  set Write solution = false\n  set Print timing = "
      "false\n  set Output directory = results\nend\n");
    std::ostringstream quiet;
    problem->output_results(quiet);
    return problem;
  };
  std::cout << "Hertz, refined around the contact zone" << std::endl;
  const auto  local   = run(3, 2);
  const auto  uniform = run(5, 0);
  const auto  coarse  = run(3, 0);
  const auto &s = local->results().summary, &u = uniform->results().summary,
             &c          = coarse->results().summary;
  const double p_local   = s.get_double("peak_pressure"),
               p_uniform = u.get_double("peak_pressure");
  std::cout << std::setprecision(4) << "  " << s.get("displacement_dofs")
            << " dofs (" << s.get("cells") << " cells, "
            << local->results().system.n_hanging_dofs / 2
            << " hanging nodes) against " << u.get("displacement_dofs")
            << " uniform, converged = " << s.get("converged") << std::endl
            << "  equilibrium imbalance < 1e-10 of the load: "
            << check(s.get_double("equilibrium_imbalance") /
                       std::abs(s.get_double("total_load_y")),
                     1e-10)
            << std::endl
            << "  peak pressure error "
            << s.get_double("relative_error_peak_pressure") << ", uniform "
            << u.get_double("relative_error_peak_pressure") << ", coarse "
            << c.get_double("relative_error_peak_pressure")
            << "; local within 0.2 % of uniform: "
            << check(std::abs(p_local - p_uniform) / p_uniform, 2e-3)
            << ", local error below half the coarse one: "
            << check(std::abs(s.get_double("relative_error_peak_pressure")),
                     0.5 *
                       std::abs(c.get_double("relative_error_peak_pressure")))
            << std::endl
            << "  half width error "
            << s.get_double("relative_error_half_width") << ", uniform "
            << u.get_double("relative_error_half_width") << ", equal to 1e-6: "
            << check(std::abs(s.get_double("contact_half_width") -
                              u.get_double("contact_half_width")) /
                       u.get_double("contact_half_width"),
                     1e-6)
            << std::endl;
  print_kkt(*local);
}

int
main()
{
  std::cout << std::setprecision(6);
  for (const std::string element : {"DGQ1", "Pian-Sumihara"})
    {
      patch<2>(element);
      patch<3>(element);
    }
  pressed_block<2>();
  pressed_block<3>();
  hertz();
}
