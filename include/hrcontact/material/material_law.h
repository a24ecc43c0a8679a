#ifndef hrcontact_material_law_h
#define hrcontact_material_law_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/grid/tria.h>

#include <hrcontact/core/input.h>

#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace hrcontact
{
  template <int dim>
  class LinearElasticity;

  /**
   * A material in stresses: its convex complementary potential phi^c(sigma)
   * (section 2.3), through the strain eps = d phi^c / d sigma and the
   * compliance d^2 phi^c / d sigma^2 at a stress point, which gives the cell
   * flexibility F_c of section 4.2 quadrature point by quadrature point.
   * Each law registers itself by name with HRCONTACT_REGISTER_MATERIAL_LAW
   * and declares its own parameters in subsection Material; Material/Model
   * chooses one (doc/design.md, "Adding a material law").
   */
  template <int dim>
  class MaterialLaw
  {
  public:
    virtual ~MaterialLaw() = default;

    /** Read the parameters this law declared; InputError if unusable. */
    virtual void
    parse_parameters(dealii::ParameterHandler &prm,
                     const Constants          &constants) = 0;

    /** The strain d phi^c / d sigma at the stress sigma. */
    virtual dealii::SymmetricTensor<2, dim>
    strain(const dealii::SymmetricTensor<2, dim> &sigma,
           const dealii::Point<dim>              &x) const = 0;

    /**
     * The compliance d^2 phi^c / d sigma^2 at the stress sigma applied to
     * tau: the strain increment of a stress increment tau. The assembler
     * builds F_c from it (eq. 30); a linear law returns E^{-1} tau whatever
     * sigma is.
     */
    virtual dealii::SymmetricTensor<2, dim>
    compliance_times(const dealii::SymmetricTensor<2, dim> &sigma,
                     const dealii::SymmetricTensor<2, dim> &tau,
                     const dealii::Point<dim>              &x) const = 0;

    /**
     * The complementary potential phi^c(sigma) itself, whose gradient is
     * strain(): the error bound's Fenchel-Young gap (doc/error-bounds.md).
     * NaN for a law that does not give it.
     */
    virtual double
    complementary_energy(const dealii::SymmetricTensor<2, dim> &sigma,
                         const dealii::Point<dim>              &x) const
    {
      (void)sigma;
      (void)x;
      return std::numeric_limits<double>::quiet_NaN();
    }

    /** Whether the compliance is the same at every stress (F fixed). */
    virtual bool
    is_linear() const = 0;

    /**
     * Whether the compliance is the same at every point: the assembler then
     * takes F_c and B_c of a cell that is a translation of the previous one
     * from that cell (HRAssembler::for_each_cell). False unless a law says
     * so.
     */
    virtual bool
    is_homogeneous() const
    {
      return false;
    }

    /**
     * The nodal compliance c_h of the mesh and material that scales the
     * augmented Lagrangian's initial penalty: the displacement of a
     * boundary node per unit nodal force, up to a factor of order one.
     */
    virtual double
    nodal_compliance(const dealii::Triangulation<dim> &triangulation) const = 0;

    /** The out-of-plane stress sigma_zz in 2D (0 in plane stress and 3D). */
    virtual double
    out_of_plane_stress(const dealii::SymmetricTensor<2, dim> &sigma) const = 0;

    /** "plane strain" or "plane stress" in 2D, "3D" in 3D. */
    virtual std::string
    plane_condition_name() const = 0;

    /**
     * The linear isotropic law the compliance starts from at zero stress,
     * if the law has one: the Q1 floor (Output/Time the Q1 floor) solves
     * the plain displacement problem of this part. Null if none.
     */
    virtual const LinearElasticity<dim> *
    elastic_part() const
    {
      return nullptr;
    }
  };

  /** The law's compliance at sigma as a fourth-order tensor C, C : tau =
   * MaterialLaw::compliance_times(sigma, tau). */
  template <int dim>
  dealii::SymmetricTensor<4, dim>
  compliance_tensor(const MaterialLaw<dim>                &law,
                    const dealii::SymmetricTensor<2, dim> &sigma,
                    const dealii::Point<dim>              &x);

  /**
   * The stress whose strain is @p eps: the law inverted by Newton's method
   * on strain(sigma) = eps (the compliance its Jacobian, steps halved while
   * they do not reduce the misfit), from @p start (a stress near the answer)
   * or else the elastic stress. It maximises
   * sigma : eps - phi^c(sigma), so phi^c's conjugate is W(eps) = sigma :
   * eps - phi^c(sigma) there. Throws NotConvergedError after 50 steps.
   */
  template <int dim>
  dealii::SymmetricTensor<2, dim>
  stress_at_strain(const MaterialLaw<dim>                &law,
                   const dealii::SymmetricTensor<2, dim> &eps,
                   const dealii::Point<dim>              &x,
                   const dealii::SymmetricTensor<2, dim> *start = nullptr);

  /**
   * The name -> factory registry of material laws and the Material/Model
   * entry.
   */
  template <int dim>
  class MaterialLawFactory
  {
  public:
    using Factory = std::function<std::unique_ptr<MaterialLaw<dim>>()>;

    static bool
    register_law(const std::string                                     &name,
                 const std::function<void(dealii::ParameterHandler &)> &declare,
                 const Factory &factory);

    /** Material/Model and every registered law's parameters. */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** The law Material/Model names, its parameters read. */
    static std::unique_ptr<MaterialLaw<dim>>
    create(dealii::ParameterHandler &prm, const Constants &constants);

  private:
    struct Entry
    {
      std::string                                     name;
      std::function<void(dealii::ParameterHandler &)> declare;
      Factory                                         factory;
    };
    static std::vector<Entry> &
    registry();
  };
} // namespace hrcontact

/** Register CLASSNAME<2> and CLASSNAME<3> as material law NAME. */
#define HRCONTACT_REGISTER_MATERIAL_LAW(classname, name)  \
  namespace                                               \
  {                                                       \
    const bool classname##_registered_2d =                \
      ::hrcontact::MaterialLawFactory<2>::register_law(   \
        name,                                             \
        &classname<2>::declare_parameters,                \
        [] { return std::make_unique<classname<2>>(); }); \
    const bool classname##_registered_3d =                \
      ::hrcontact::MaterialLawFactory<3>::register_law(   \
        name,                                             \
        &classname<3>::declare_parameters,                \
        [] { return std::make_unique<classname<3>>(); }); \
  }

#endif
