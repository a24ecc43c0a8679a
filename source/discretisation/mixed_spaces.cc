#include <deal.II/fe/fe_dgp.h>
#include <deal.II/fe/fe_dgq.h>
#include <deal.II/fe/fe_q.h>

#include <hrcontact/core/input.h>
#include <hrcontact/discretisation/mixed_spaces.h>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  MixedSpaces<dim>::MixedSpaces() = default;

  template <int dim>
  void
  MixedSpaces<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Finite elements");
    prm.declare_entry(
      "Stress element",
      "DGQ1",
      Patterns::Selection("DGQ1|DGP1|DGP0"),
      "Discontinuous element for each stress component: DGQ1 (bilinear per "
      "cell; on parallelograms the HR solution equals the Q1 displacement "
      "solution), DGP1 (linear) or DGP0 (constant; too poor for most meshes: "
      "the equilibrium reduction reports the resulting mechanisms).");
    prm.leave_subsection();
  }

  template <int dim>
  void
  MixedSpaces<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Finite elements");
    stress_element_name = prm.get("Stress element");
    prm.leave_subsection();
  }

  template <int dim>
  void
  MixedSpaces<dim>::setup(const Triangulation<dim> &triangulation)
  {
    fe_displacement = std::make_unique<FESystem<dim>>(FE_Q<dim>(1), dim);
    if (stress_element_name == "DGQ1")
      fe_stress =
        std::make_unique<FESystem<dim>>(FE_DGQ<dim>(1), n_stress_components);
    else if (stress_element_name == "DGP1")
      fe_stress =
        std::make_unique<FESystem<dim>>(FE_DGP<dim>(1), n_stress_components);
    else if (stress_element_name == "DGP0")
      fe_stress =
        std::make_unique<FESystem<dim>>(FE_DGP<dim>(0), n_stress_components);
    else
      throw InputError("Finite elements/Stress element: unknown element '" +
                       stress_element_name + "'.");

    dof_handler_displacement.reinit(triangulation);
    dof_handler_displacement.distribute_dofs(*fe_displacement);
    dof_handler_stress.reinit(triangulation);
    dof_handler_stress.distribute_dofs(*fe_stress);
  }

  template <int dim>
  std::pair<unsigned int, unsigned int>
  MixedSpaces<dim>::stress_component_indices(const unsigned int c)
  {
    if (c < dim)
      return {c, c};
    if (dim == 2)
      return {0, 1};
    static const std::pair<unsigned int, unsigned int> off[3] = {{0, 1},
                                                                 {0, 2},
                                                                 {1, 2}};
    return off[c - dim];
  }

  template <int dim>
  SymmetricTensor<2, dim>
  MixedSpaces<dim>::stress_basis_tensor(const unsigned int c)
  {
    const auto              ab = stress_component_indices(c);
    SymmetricTensor<2, dim> t;
    t[ab.first][ab.second] = 1.; // symmetric storage sets (b,a) as well
    return t;
  }

  template <int dim>
  std::string
  MixedSpaces<dim>::stress_component_name(const unsigned int c)
  {
    const char *xyz = "xyz";
    const auto  ab  = stress_component_indices(c);
    return std::string("s") + xyz[ab.first] + xyz[ab.second];
  }

  template class MixedSpaces<2>;
  template class MixedSpaces<3>;
} // namespace hrcontact
