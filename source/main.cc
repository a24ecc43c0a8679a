// hrcontact: run a scene described by a parameter file.
//   hrcontact parameters/NAME.prm
//   hrcontact --print-parameters
#include <deal.II/base/mpi.h>

#include <hrcontact/core/run.h>

#include <cstring>
#include <iostream>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (argc == 2 && std::strcmp(argv[1], "--print-parameters") == 0)
    {
      dealii::ParameterHandler prm;
      hrcontact::declare_all_parameters(prm);
      prm.print_parameters(std::cout, dealii::ParameterHandler::PRM);
      return 0;
    }
  if (argc != 2 || argv[1][0] == '-')
    {
      std::cerr << "usage: hrcontact PARAMETER_FILE.prm\n"
                   "       hrcontact --print-parameters   (every parameter "
                   "with its documentation and default)\n";
      return 2;
    }
  return hrcontact::run_parameter_file(argv[1], std::cout, std::cerr);
}
