#include <deal.II/base/numbers.h>

#include <hrcontact/geometry/body_placement.h>

#include <cmath>
#include <vector>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  Tensor<1, dim>
  BodyPlacement<dim>::rotate(const Tensor<1, dim> &v) const
  {
    Tensor<1, dim> m = v;
    if (mirror >= 0)
      m[mirror] = -m[mirror];
    const double   angle = rotation_degrees * numbers::PI / 180.;
    const double   c = std::cos(angle), s = std::sin(angle);
    Tensor<1, dim> r = m;
    r[0]             = c * m[0] - s * m[1];
    r[1]             = s * m[0] + c * m[1];
    return r;
  }

  template <int dim>
  Tensor<1, dim>
  BodyPlacement<dim>::rotate_back(const Tensor<1, dim> &w) const
  {
    const double   angle = rotation_degrees * numbers::PI / 180.;
    const double   c = std::cos(angle), s = std::sin(angle);
    Tensor<1, dim> r = w;
    r[0]             = c * w[0] + s * w[1];
    r[1]             = -s * w[0] + c * w[1];
    if (mirror >= 0)
      r[mirror] = -r[mirror];
    return r;
  }

  template <int dim>
  Point<dim>
  BodyPlacement<dim>::operator()(const Point<dim> &x) const
  {
    return Point<dim>(rotate(x) + shift);
  }

  template <int dim>
  Point<dim>
  BodyPlacement<dim>::inverse(const Point<dim> &y) const
  {
    return Point<dim>(rotate_back(y - Point<dim>(shift)));
  }

  template <int dim>
  MovedManifold<dim>::MovedManifold(const Manifold<dim>      &manifold,
                                    const BodyPlacement<dim> &placement)
    : manifold(manifold.clone())
    , placement(placement)
  {}

  template <int dim>
  std::unique_ptr<Manifold<dim>>
  MovedManifold<dim>::clone() const
  {
    return std::make_unique<MovedManifold<dim>>(*manifold, placement);
  }

  template <int dim>
  Point<dim>
  MovedManifold<dim>::get_intermediate_point(const Point<dim> &p1,
                                             const Point<dim> &p2,
                                             const double      w) const
  {
    return placement(manifold->get_intermediate_point(placement.inverse(p1),
                                                      placement.inverse(p2),
                                                      w));
  }

  template <int dim>
  Point<dim>
  MovedManifold<dim>::get_new_point(
    const ArrayView<const Point<dim>> &surrounding_points,
    const ArrayView<const double>     &weights) const
  {
    std::vector<Point<dim>> local(surrounding_points.size());
    for (unsigned int i = 0; i < local.size(); ++i)
      local[i] = placement.inverse(surrounding_points[i]);
    return placement(manifold->get_new_point(make_array_view(local), weights));
  }

  template <int dim>
  Point<dim>
  MovedManifold<dim>::project_to_manifold(
    const ArrayView<const Point<dim>> &surrounding_points,
    const Point<dim>                  &candidate) const
  {
    std::vector<Point<dim>> local(surrounding_points.size());
    for (unsigned int i = 0; i < local.size(); ++i)
      local[i] = placement.inverse(surrounding_points[i]);
    return placement(
      manifold->project_to_manifold(make_array_view(local),
                                    placement.inverse(candidate)));
  }

  template <int dim>
  Tensor<1, dim>
  MovedManifold<dim>::get_tangent_vector(const Point<dim> &x1,
                                         const Point<dim> &x2) const
  {
    return placement.rotate(
      manifold->get_tangent_vector(placement.inverse(x1),
                                   placement.inverse(x2)));
  }

  template struct BodyPlacement<2>;
  template struct BodyPlacement<3>;
  template class MovedManifold<2>;
  template class MovedManifold<3>;
} // namespace hrcontact
