#include <deal.II/base/mpi.h>

#include <deal.II/distributed/tria_base.h>

#include <hrcontact/material/linear_elasticity.h>

#include <cmath>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  void
  LinearElasticity<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    {
      prm.declare_entry("Young's modulus",
                        "1",
                        Patterns::Anything(),
                        "linear elasticity: Young's modulus E (an expression "
                        "of constants); > 0.");
      prm.declare_entry("Poisson's ratio",
                        "0.3",
                        Patterns::Anything(),
                        "linear elasticity: Poisson's ratio nu (an expression "
                        "of constants); in (-1, 0.5), and below 0.5 in 3D and "
                        "plane strain.");
      prm.declare_entry(
        "Plane condition",
        "plane strain",
        Patterns::Selection("plane strain|plane stress"),
        "2D only: plane strain (eps_zz = 0, reactions per unit thickness) or "
        "plane stress (sigma_zz = 0).");
    }
    prm.leave_subsection();
  }

  template <int dim>
  void
  LinearElasticity<dim>::parse_parameters(ParameterHandler &prm,
                                          const Constants  &constants)
  {
    prm.enter_subsection("Material");
    {
      E            = evaluate_constant_expression(prm.get("Young's modulus"),
                                       constants,
                                       "Material/Young's modulus");
      nu           = evaluate_constant_expression(prm.get("Poisson's ratio"),
                                        constants,
                                        "Material/Poisson's ratio");
      plane_strain = (prm.get("Plane condition") == "plane strain");
    }
    prm.leave_subsection();
    if (!(E > 0))
      throw InputError("Material/Young's modulus must be positive (got " +
                       std::to_string(E) + ").");
    const bool incompressible_limit_matters = (dim == 3 || plane_strain);
    if (!(nu > -1) ||
        (incompressible_limit_matters ? !(nu < 0.5) : !(nu <= 0.5)))
      throw InputError("Material/Poisson's ratio " + std::to_string(nu) +
                       " is outside (-1, 0.5): the compliance would not be "
                       "positive definite.");
  }

  template <int dim>
  SymmetricTensor<2, dim>
  LinearElasticity<dim>::strain_from_stress(
    const SymmetricTensor<2, dim> &sigma) const
  {
    double E_ = E, nu_ = nu;
    if (dim == 2 && plane_strain)
      {
        E_  = E / (1 - nu * nu);
        nu_ = nu / (1 - nu);
      }
    return (1 + nu_) / E_ * sigma -
           nu_ / E_ * trace(sigma) * unit_symmetric_tensor<dim>();
  }

  template <int dim>
  SymmetricTensor<2, dim>
  LinearElasticity<dim>::strain(const SymmetricTensor<2, dim> &sigma,
                                const Point<dim> &) const
  {
    return strain_from_stress(sigma);
  }

  template <int dim>
  SymmetricTensor<2, dim>
  LinearElasticity<dim>::compliance_times(const SymmetricTensor<2, dim> &,
                                          const SymmetricTensor<2, dim> &tau,
                                          const Point<dim> &) const
  {
    return strain_from_stress(tau);
  }

  template <int dim>
  bool
  LinearElasticity<dim>::is_homogeneous() const
  {
    return true;
  }

  template <int dim>
  bool
  LinearElasticity<dim>::is_linear() const
  {
    return true;
  }

  template <int dim>
  double
  LinearElasticity<dim>::nodal_compliance(
    const Triangulation<dim> &triangulation) const
  {
    double c_h = 1 / E;
    if (dim == 2 && plane_strain)
      c_h *= 1 - nu * nu;
    if (dim == 3)
      {
        // Each process its own cells (all of a serial mesh), then the sum.
        double volume = 0;
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned())
            volume += cell->measure();
        if (const auto *parallel_mesh =
              dynamic_cast<const parallel::TriangulationBase<dim> *>(
                &triangulation))
          volume =
            Utilities::MPI::sum(volume, parallel_mesh->get_communicator());
        c_h /= std::cbrt(volume / triangulation.n_global_active_cells());
      }
    return c_h;
  }

  template <int dim>
  double
  LinearElasticity<dim>::out_of_plane_stress(
    const SymmetricTensor<2, dim> &sigma) const
  {
    return (dim == 2 && plane_strain) ? nu * trace(sigma) : 0.;
  }

  template <int dim>
  std::string
  LinearElasticity<dim>::plane_condition_name() const
  {
    if (dim == 3)
      return "3D";
    return plane_strain ? "plane strain" : "plane stress";
  }

  template class LinearElasticity<2>;
  template class LinearElasticity<3>;

  HRCONTACT_REGISTER_MATERIAL_LAW(LinearElasticity, "linear elasticity")
} // namespace hrcontact
