// Bad input under mpirun -np 2 on a distributed mesh: a boundary id that
// the mesh does not have and a probe outside the body are found
// collectively (each process knows only its own cells), and every process
// stops with the same named error instead of one process hanging in the
// solve. Runs the inputs of tests/input/ on the condensed path, refined so
// that p4est splits the mesh.

#include <deal.II/base/mpi.h>

#include "tests.h"

using namespace hrcontact_tests;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                           comm = MPI_COMM_WORLD;
  const std::string                        extra =
    "subsection Equilibrium reduction\n  set Path = condensed\nend\n"
    "subsection Geometry\n  set Global refinements = 3\nend\n";
  for (const std::string name : {"floating-on-foundation",
                                 "traction-missing-id",
                                 "obstacle-missing-id",
                                 "support-missing-id",
                                 "probe-outside"})
    {
      std::string message = "no error";
      try
        {
          solve_from_text<2>(read_file(std::string(SOURCE_DIR) + "/input/" +
                                       name + ".prm") +
                               extra,
                             comm);
        }
      catch (const hrcontact::InputError &e)
        {
          message = e.what();
        }
      const std::vector<std::string> all =
        dealii::Utilities::MPI::all_gather(comm, message);
      bool same = true;
      for (const std::string &m : all)
        same &= (m == message);
      if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
        std::cout << name << " on " << all.size() << " processes: "
                  << (same ? "the same error on every process" :
                             "DIFFERENT errors")
                  << "\n  " << message << std::endl;
    }
}
