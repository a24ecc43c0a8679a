#ifndef hrcontact_body_placement_h
#define hrcontact_body_placement_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <deal.II/grid/manifold.h>

#include <memory>

namespace hrcontact
{
  /**
   * Where a body of a multi-body scene goes: x -> Q x + b, Q a mirror in
   * one coordinate (or none) followed by a rotation about the origin (about
   * z in 3D), b a shift. An isometry, so that a body's manifold placed with
   * it (MovedManifold) describes the same curved surface.
   */
  template <int dim>
  struct BodyPlacement
  {
    /** The coordinate mirrored (x -> -x, ...), or -1: none. */
    int                    mirror           = -1;
    double                 rotation_degrees = 0;
    dealii::Tensor<1, dim> shift;

    /** Q x + b. */
    dealii::Point<dim>
    operator()(const dealii::Point<dim> &x) const;

    /** Q^T (y - b). */
    dealii::Point<dim>
    inverse(const dealii::Point<dim> &y) const;

    /** Q v: a vector of the body's frame in the scene's. */
    dealii::Tensor<1, dim>
    rotate(const dealii::Tensor<1, dim> &v) const;

    /** Q^T w. */
    dealii::Tensor<1, dim>
    rotate_back(const dealii::Tensor<1, dim> &w) const;

    /** Whether Q turns cells inside out. */
    bool
    mirrors() const
    {
      return mirror >= 0;
    }
  };

  /**
   * A body's manifold carried along by its placement: the points it is
   * asked about are taken back to the body's own frame, the body's manifold
   * places the new point there, and the result is moved again. With it a
   * body keeps its curved boundary when the coarse meshes of several bodies
   * are joined and refined together (MultiBodyGrid on a distributed mesh).
   * deal.II has no such wrapper; the placement being an isometry, the
   * result is exactly the moved manifold.
   */
  template <int dim>
  class MovedManifold : public dealii::Manifold<dim>
  {
  public:
    MovedManifold(const dealii::Manifold<dim> &manifold,
                  const BodyPlacement<dim>    &placement);

    std::unique_ptr<dealii::Manifold<dim>>
    clone() const override;

    dealii::Point<dim>
    get_intermediate_point(const dealii::Point<dim> &p1,
                           const dealii::Point<dim> &p2,
                           const double              w) const override;

    dealii::Point<dim>
    get_new_point(
      const dealii::ArrayView<const dealii::Point<dim>> &surrounding_points,
      const dealii::ArrayView<const double> &weights) const override;

    dealii::Point<dim>
    project_to_manifold(
      const dealii::ArrayView<const dealii::Point<dim>> &surrounding_points,
      const dealii::Point<dim> &candidate) const override;

    dealii::Tensor<1, dim>
    get_tangent_vector(const dealii::Point<dim> &x1,
                       const dealii::Point<dim> &x2) const override;

  private:
    std::unique_ptr<dealii::Manifold<dim>> manifold;
    BodyPlacement<dim>                     placement;
  };
} // namespace hrcontact

#endif
