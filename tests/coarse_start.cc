// Nested iteration with CG starts each finer level's first solve from the
// coarser level's displacements (Nested iteration/Carry displacements).
// First the prolongation itself: a linear field interpolated on a mesh is
// carried exactly to the mesh one global refinement finer (2D and 3D; under
// mpirun -np 2 on p4est meshes, whose cells without a parent on this process
// would stay zero: none may). Then Hertz at 6 refinements with CG + AMG, two
// coarser levels, with and without the carried displacements: the same
// reactions and displacements to 1e-8 (every solve stops at Linear
// solver/Tolerance of its right-hand side either way), and the first fine
// solve takes at most 0.9 of the CG iterations it takes from zero.

#include <deal.II/base/function_lib.h>
#include <deal.II/base/mpi.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>

#include <deal.II/grid/grid_generator.h>

#include <deal.II/numerics/vector_tools.h>

#include <deal.II/distributed/tria.h>

#include <hrcontact/discretisation/prolongation.h>

#include "tests.h"

using namespace dealii;

/** u_c(x) = c + 1 + sum_k (k + c + 1) x_k: a linear field per component. */
template <int dim>
class LinearField : public Function<dim>
{
public:
  LinearField()
    : Function<dim>(dim)
  {}
  double
  value(const Point<dim> &x, const unsigned int c) const override
  {
    double v = c + 1;
    for (unsigned int k = 0; k < dim; ++k)
      v += (k + c + 1.) * x[k];
    return v;
  }
};

template <int dim>
std::unique_ptr<Triangulation<dim>>
make_mesh(const unsigned int refinements)
{
  std::unique_ptr<Triangulation<dim>> mesh;
  if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
    mesh = std::make_unique<parallel::distributed::Triangulation<dim>>(
      MPI_COMM_WORLD);
  else
    mesh = std::make_unique<Triangulation<dim>>();
  GridGenerator::subdivided_hyper_rectangle(*mesh,
                                            std::vector<unsigned int>(dim, 3),
                                            Point<dim>(),
                                            dim == 2 ? Point<dim>(3., 2.) :
                                                       Point<dim>(3., 2., 1.));
  mesh->refine_global(refinements);
  return mesh;
}

template <int dim>
void
prolongate_linear_field()
{
  const FESystem<dim> fe(FE_Q<dim>(1), dim);
  const unsigned int  coarse_refinements = (dim == 2) ? 2 : 1;
  const auto          coarse_mesh        = make_mesh<dim>(coarse_refinements),
             fine_mesh = make_mesh<dim>(coarse_refinements + 1);
  DoFHandler<dim> coarse_dofs(*coarse_mesh), fine_dofs(*fine_mesh);
  coarse_dofs.distribute_dofs(fe);
  fine_dofs.distribute_dofs(fe);
  hrcontact::FieldVector coarse, fine, exact;
  hrcontact::reinit_field(coarse, coarse_dofs);
  hrcontact::reinit_field(fine, fine_dofs);
  hrcontact::reinit_field(exact, fine_dofs);
  VectorTools::interpolate(coarse_dofs, LinearField<dim>(), coarse);
  VectorTools::interpolate(fine_dofs, LinearField<dim>(), exact);
  coarse.update_ghost_values();
  hrcontact::prolongate_to_finer_mesh(coarse_dofs, coarse, fine_dofs, fine);
  double       error = 0, scale = 0;
  unsigned int zeros = 0;
  for (const auto i : fine_dofs.locally_owned_dofs())
    {
      error = std::max(error, std::abs(fine(i) - exact(i)));
      scale = std::max(scale, std::abs(exact(i)));
      zeros += (fine(i) == 0);
    }
  error = Utilities::MPI::max(error, MPI_COMM_WORLD);
  scale = Utilities::MPI::max(scale, MPI_COMM_WORLD);
  zeros = Utilities::MPI::sum(zeros, MPI_COMM_WORLD);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::cout << dim << "D, " << coarse_dofs.n_dofs() << " -> "
              << fine_dofs.n_dofs()
              << " dofs: the prolongated linear field equals the fine "
                 "interpolant to 1e-13: "
              << hrcontact_tests::check(error / scale, 1e-13)
              << ", owned entries left at zero: " << zeros << std::endl;
}

std::unique_ptr<hrcontact::HRProblem<2>>
run_hertz(const bool carry)
{
  return hrcontact_tests::solve_from_text<2>(hrcontact_tests::condensed_scene(
    "hertz.prm",
    std::string("subsection Geometry\n  set Global refinements = 6\nend\n"
                "subsection Linear solver\n  set Solver = cg-amg\nend\n"
                "subsection Nested iteration\n  set Carry displacements = ") +
      (carry ? "true" : "false") + "\nend\n"));
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  prolongate_linear_field<2>();
  prolongate_linear_field<3>();

  const auto  carried = run_hertz(true), zero = run_hertz(false);
  const auto &a = carried->results(), &b = zero->results();
  const auto  differences = hrcontact_tests::answer_differences(a, b);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::cout << "Hertz, 6 refinements, CG + AMG, " << a.coarse_levels.size()
              << " coarser levels: converged: "
              << (a.converged() ? "yes" : "NO") << " and "
              << (b.converged() ? "yes" : "NO")
              << "\n  Q-row reactions agree to 1e-8: "
              << hrcontact_tests::check(differences[0], 1e-8)
              << "\n  displacements agree to 1e-8: "
              << hrcontact_tests::check(differences[1], 1e-8)
              << "\n  first fine solve, CG iterations carried / from zero <= "
                 "0.9: "
              << hrcontact_tests::check(
                   double(a.solve.linear_statistics.first_solve_iterations) /
                     b.solve.linear_statistics.first_solve_iterations,
                   0.9)
              << std::endl;
}
