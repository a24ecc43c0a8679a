// Under mpirun -np 2 the condensed path runs on the p4est partition: the
// stiffness, its constraints, the AMG hierarchy and CG (or MUMPS for Solver =
// direct) are distributed. Each scene is solved on MPI_COMM_WORLD and, on
// every process, serially on MPI_COMM_SELF; the two must give the same
// augmented Lagrangian history (alpha sequence, released sets, p to 1e-9 of
// max |p|) and the same displacements and stresses. The partition itself must
// give every dof and cell exactly one owner and each process a share.

#include <deal.II/base/mpi.h>

#include "tests.h"

template <int dim>
std::unique_ptr<hrcontact::HRProblem<dim>>
run(const std::string &scene, const std::string &extra, const MPI_Comm comm)
{
  return hrcontact_tests::solve_from_text<dim>(
    hrcontact_tests::read_file(std::string(SOURCE_DIR) + "/../parameters/" +
                               scene) +
      extra +
      "subsection Equilibrium reduction\n  set Path = condensed\nend\n"
      "subsection Output\n  set Write solution = false\n"
      "  set Output directory = results\nend\n",
    comm);
}

template <int dim>
void
compare(const std::string &scene, const std::string &extra)
{
  using dealii::Utilities::MPI::sum;
  const auto parallel = run<dim>(scene, extra, MPI_COMM_WORLD);
  const auto serial   = run<dim>(scene, extra, MPI_COMM_SELF);

  const auto  &partition = parallel->results().partition;
  const auto   n_owned   = partition.owned.n_elements();
  const double n_cells =
    std::count(partition.owned_cell.begin(), partition.owned_cell.end(), true);
  const bool complete = sum(n_owned, MPI_COMM_WORLD) ==
                          parallel->results().system.n_displacement_dofs &&
                        sum(n_cells, MPI_COMM_WORLD) ==
                          parallel->results().triangulation().n_active_cells();
  const bool shared = dealii::Utilities::MPI::min(n_owned, MPI_COMM_WORLD) > 0;

  const auto c =
    hrcontact_tests::compare_histories((*parallel->results().contact),
                                       (*serial->results().contact));
  dealii::Vector<double> du = parallel->results().displacement,
                         ds = parallel->results().stress;
  du -= serial->results().displacement;
  ds -= serial->results().stress;
  const double u_difference =
    du.linfty_norm() / serial->results().displacement.linfty_norm();
  const double s_difference =
    ds.linfty_norm() / serial->results().stress.linfty_norm();

  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::cout
      << scene << " (" << dim << "D, "
      << parallel->results().system.n_displacement_dofs << " dofs, "
      << parallel->results().linear_statistics.solver << "):\n  "
      << partition.n_processes
      << " processes, p4est partition complete: " << (complete ? "yes" : "NO")
      << ", every process owns dofs: " << (shared ? "yes" : "NO") << "\n  "
      << (*serial->results().contact).history.size() << " multiplier updates, "
      << (*serial->results().contact).total_newton_steps
      << " Newton steps (serial); same alpha sequence: "
      << (c.same_alpha ? "yes" : "NO")
      << ", same released sets: " << (c.same_sets ? "yes" : "NO")
      << "\n  max |p_mpi - p_serial| / max |p| over all updates < 1e-9: "
      << hrcontact_tests::check(c.p_difference, 1e-9)
      << "\n  displacements agree to 1e-9: "
      << hrcontact_tests::check(u_difference, 1e-9)
      << "\n  stresses agree to 1e-9: "
      << hrcontact_tests::check(s_difference, 1e-9) << std::endl;
}

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  compare<2>("hertz.prm",
             "subsection Geometry\n  set Global refinements = 3\nend\n"
             "subsection Linear solver\n  set Solver = cg-amg\nend\n");
  compare<2>("lift-off.prm",
             "subsection Linear solver\n  set Solver = direct\nend\n");
  compare<3>("block-3d-contact.prm",
             "subsection Geometry\n  set Global refinements = 1\nend\n"
             "subsection Linear solver\n  set Solver = cg-amg\nend\n");
}
