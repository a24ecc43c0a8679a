// AMG aggregates by node coordinates on stretched cells (Linear solver/AMG
// aggregation). The graded Hertz mesh (aspect ratios far above 4) takes the
// coordinates under `automatic`, the tunnel lining and the 3D block (near
// square cells) the matrix graph. On Hertz the plain Q1 floor's CG must need
// at most 60 % of the iterations it needs with the matrix graph (measured:
// about 30 % at refinements 7-9), and the contact solve must give the
// reactions of UMFPACK to 1e-8 relative with either aggregation.

#include <deal.II/base/mpi.h>

#include "tests.h"

template <int dim>
std::unique_ptr<hrcontact::HRProblem<dim>>
run(const std::string &scene, const std::string &extra)
{
  return hrcontact_tests::solve_from_text<dim>(hrcontact_tests::condensed_scene(
    scene, extra + "subsection Output\n  set Time the Q1 floor = true\nend\n"));
}

template <int dim>
void
automatic_choice(const std::string &scene, const std::string &extra)
{
  const auto problem =
    run<dim>(scene,
             extra + "subsection Linear solver\n  set Solver = "
                     "cg-amg\nend\n");
  const auto &r = problem->results();
  std::cout << scene << ": largest cell aspect ratio above 4: "
            << (r.solve.largest_aspect_ratio > 4 ? "yes" : "no")
            << ", automatic aggregation by "
            << r.solve.linear_statistics.aggregation << std::endl;
}

double
max_abs(const std::vector<double> &p)
{
  double m = 0;
  for (const double v : p)
    m = std::max(m, std::abs(v));
  return m;
}

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                        hertz_r5 =
    "subsection Geometry\n  set Global refinements = 5\nend\n";
  automatic_choice<2>("hertz.prm", hertz_r5);
  automatic_choice<2>("tunnel.prm",
                      "subsection Geometry\n  set Global refinements = 2\n"
                      "end\n");
  automatic_choice<3>("block-3d-contact.prm",
                      "subsection Geometry\n  set Global refinements = 1\n"
                      "end\n");

  const auto direct =
    run<2>("hertz.prm",
           hertz_r5 + "subsection Linear solver\n  set Solver = direct\nend\n");
  const auto  &p_ref = direct->results().contact->p;
  unsigned int floor_iterations[2];
  unsigned int k = 0;
  for (const std::string aggregation : {"matrix", "coordinates"})
    {
      const auto          cg = run<2>("hertz.prm",
                             hertz_r5 +
                               "subsection Linear solver\n  set Solver = "
                                        "cg-amg\n  set AMG aggregation = " +
                               aggregation + "\nend\n");
      const auto         &r  = cg->results();
      std::vector<double> difference(p_ref.size());
      for (unsigned int i = 0; i < p_ref.size(); ++i)
        difference[i] = r.contact->p[i] - p_ref[i];
      floor_iterations[k++] = r.diagnostics.floor_iterations;
      std::cout << "Hertz refinement 5, aggregation by " << aggregation
                << ": converged: " << (r.converged() ? "yes" : "NO")
                << ", p as UMFPACK to 1e-8: "
                << hrcontact_tests::check(max_abs(difference) / max_abs(p_ref),
                                          1e-8)
                << std::endl;
    }
  std::cout << "Q1 floor CG iterations, coordinates / matrix <= 0.6: "
            << hrcontact_tests::check(double(floor_iterations[1]) /
                                        floor_iterations[0],
                                      0.6)
            << std::endl;
}
