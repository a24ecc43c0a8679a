#ifndef hrcontact_field_values_h
#define hrcontact_field_values_h

#include <deal.II/base/function.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/lac/vector.h>

#include <hrcontact/core/input.h>
#include <hrcontact/core/results.h>

#include <memory>
#include <string>
#include <utility>

namespace hrcontact
{
  /** The stress tensor from its independent components (MixedSpaces
   * order). */
  template <int dim>
  dealii::SymmetricTensor<2, dim>
  stress_tensor(const dealii::Vector<double> &components);

  /**
   * The entry Postprocess/Reference stress (the subsection entered) as a
   * function of dim (dim + 1) / 2 components, or null when it is empty;
   * read by the probes and the error bound.
   */
  template <int dim>
  std::unique_ptr<dealii::FunctionParser<dim>>
  parse_reference_stress(dealii::ParameterHandler &prm,
                         const Constants          &constants);

  /** von Mises stress including the out-of-plane component szz in 2D. */
  template <int dim>
  double
  von_mises(const dealii::SymmetricTensor<2, dim> &sigma, const double szz);

  /**
   * Whether a cell of the mesh (under the Q1 mapping) contains the point;
   * collective on a distributed mesh, which asks every process's own cells.
   */
  template <int dim>
  bool
  mesh_contains_point(const dealii::Triangulation<dim> &triangulation,
                      const dealii::Point<dim>         &point);

  /**
   * A displacement or stress quantity of the results at a point: ux, uy,
   * uz, sxx, syy, szz, sxy, sxz, syz or von_mises (szz in 2D from the
   * material's out-of-plane stress). A stress at a point shared by cells is
   * taken from the first cell found. InputError outside the mesh.
   */
  template <int dim>
  double
  point_value(const Results<dim>       &results,
              const dealii::Point<dim> &point,
              const std::string        &quantity);

  /**
   * Max and L2 norms of sigma_h - sigma_ref over the mesh, each relative to
   * the same norm of sigma_ref (Frobenius norm pointwise); the reference has
   * one component per independent stress component.
   */
  template <int dim>
  std::pair<double, double>
  stress_error(const MixedSpaces<dim>      &spaces,
               const FieldVector           &stress,
               const dealii::Function<dim> &reference);
} // namespace hrcontact

#endif
