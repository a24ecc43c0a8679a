#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <hrcontact/adaptivity/adaptive_run.h>
#include <hrcontact/core/hr_problem.h>
#include <hrcontact/core/input.h>
#include <hrcontact/core/run.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace hrcontact
{
  using namespace dealii;

  void
  declare_all_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Dimension",
                      "2",
                      Patterns::Integer(2, 3),
                      "Space dimension of the scene: 2 or 3.");
    // The parameter tree is the same in 2D and 3D; expressions are checked
    // against the dimension when they are parsed.
    HRProblem<2>::declare_parameters(prm);
  }

  void
  read_parameter_file(ParameterHandler &prm, const std::string &file)
  {
    std::ifstream in(file);
    if (!in)
      throw InputError("cannot open the parameter file '" + file + "'.");
    try
      {
        prm.parse_input(file, "", false, true);
      }
    catch (const ExceptionBase &e)
      {
        std::ostringstream s;
        e.print_info(s);
        throw InputError("in parameter file '" + file +
                         "': " + Utilities::trim(s.str()));
      }
  }

  namespace
  {
    template <int dim>
    void
    run_dimension(ParameterHandler &prm, std::ostream &log)
    {
      prm.enter_subsection("Mesh refinement");
      const bool adaptive = prm.get_integer("Adaptive cycles") > 0;
      prm.leave_subsection();
      if (adaptive)
        {
          run_adaptive_cycles<dim>(prm, log);
          return;
        }
      HRProblem<dim> problem(prm);
      problem.run(log);
    }
  } // namespace

  int
  run_parameter_file(const std::string &file,
                     std::ostream      &log_on_root,
                     std::ostream      &err_on_root)
  {
    // Every process runs the same replicated iteration; process 0 speaks.
    std::ostream  silent(nullptr); // discards what it is given
    const bool    root = is_root_process(MPI_COMM_WORLD);
    std::ostream &log  = root ? log_on_root : silent;
    std::ostream &err  = root ? err_on_root : silent;
    try
      {
        ParameterHandler prm;
        declare_all_parameters(prm);
        read_parameter_file(prm, file);
        log << "hrcontact: " << std::filesystem::path(file).filename().string()
            << std::endl;
        if (prm.get_integer("Dimension") == 2)
          run_dimension<2>(prm, log);
        else
          run_dimension<3>(prm, log);
        return 0;
      }
    catch (const NotConvergedError &e)
      {
        log << std::flush;
        err << "hrcontact: error: " << e.what() << std::endl;
        return 3;
      }
    catch (const InputError &e)
      {
        log << std::flush;
        err << "hrcontact: error: " << e.what() << std::endl;
        return 1;
      }
    catch (const ExceptionBase &e)
      {
        log << std::flush;
        std::ostringstream s;
        e.print_info(s);
        err << "hrcontact: error (" << e.get_exc_name()
            << "): " << Utilities::trim(s.str()) << std::endl;
        return 2;
      }
    catch (const std::exception &e)
      {
        log << std::flush;
        err << "hrcontact: error: " << e.what() << std::endl;
        return 2;
      }
  }
} // namespace hrcontact
