#ifndef hrcontact_mortar_h
#define hrcontact_mortar_h

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <hrcontact/constraints/constraint_source.h>

#include <array>
#include <map>
#include <vector>

namespace hrcontact
{
  /**
   * The bilinear (2D: linear) shape functions of a face at the reference
   * point xi, in deal.II's vertex order, and their derivatives.
   */
  template <int dim>
  void
  face_shape(const std::array<double, dim - 1>        &xi,
             std::vector<double>                      &N,
             std::vector<std::array<double, dim - 1>> &dN);

  /**
   * The closest point of a face to x: Gauss-Newton on the face's
   * parametrisation (one step for a straight segment, a few for a bilinear
   * quadrilateral), unclamped. Returns the reference point.
   */
  template <int dim>
  std::array<double, dim - 1>
  closest_point(const std::vector<dealii::Point<dim>> &vertices,
                const dealii::Point<dim>              &x);

  /**
   * The mortar sums of one slave node (dual basis psi_s, the integrals over
   * the parts of its faces that master faces cover): D = int psi_s, M_m =
   * int psi_s N_m, G = int psi_s g, how much of its faces is covered, and
   * their total length (2D) or area (3D).
   */
  struct MortarSums
  {
    double                         D = 0, G = 0, covered = 0, length = 0;
    std::map<unsigned int, double> M;
  };

  /**
   * Segment to segment with dual Lagrange multipliers (Wohlmuth), for the
   * faces of boundary @p slave against the @p masters facing them within
   * @p reach; by slave node. The node's row is then w_n = sum_m (M_m / D)
   * w_m + G / D (ContactPairs).
   *
   * 2D: each slave face is cut where the master faces begin and end,
   * projected along the slave face's normal; on each piece the products of
   * the dual shape functions psi_1 = 2 - 3 xi, psi_2 = 3 xi - 1 with the
   * master's linear ones are integrated exactly (3 Gauss points).
   *
   * 3D: each master face is projected onto the slave face's plane, the two
   * quadrilaterals clipped (clip_convex_polygon), the overlap cut into
   * triangles and integrated with a rule exact to degree 5 (psi_s N_m is of
   * degree 4 on parallel planar faces). The dual basis is the tensor
   * product of the 1D one, biorthogonal on parallelograms; on distorted
   * faces only approximately.
   */
  template <int dim>
  std::map<unsigned int, MortarSums>
  mortar_sums(const std::vector<BoundaryFace<dim>>         &faces,
              const dealii::types::boundary_id              slave,
              const std::vector<const BoundaryFace<dim> *> &masters,
              const double                                  reach);

  /** The point of the master surface closest to a slave node. */
  template <int dim>
  struct MasterPoint
  {
    /** The master face it lies on; null: no face facing the node within
     * reach. */
    const BoundaryFace<dim> *face = nullptr;
    /** The face's shape functions at the point (deal.II's vertex order). */
    std::vector<double> N;
    /** (y - x) . n_m with n_m the face's inward normal -normal: positive
     * when the node is outside the master body. */
    double gap = 0;
    /** Positive: the depth inside the master body of a candidate face
     * (overlapping bodies, an input error); the search stopped there. */
    double overlap = 0;
  };

  /**
   * Node to segment: the closest point to @p x on the @p masters facing the
   * node (whose normal is opposite to @p slave_normal), within @p reach, on
   * a face (its reference point within the face to 1e-8, then clamped). A
   * candidate that would be the closest so far with the node more than
   * 1e-8 of its longest edge inside the master body stops the search
   * (MasterPoint::overlap).
   */
  template <int dim>
  MasterPoint<dim>
  closest_master_point(const std::vector<const BoundaryFace<dim> *> &masters,
                       const dealii::Point<dim>                     &x,
                       const dealii::Tensor<1, dim> &slave_normal,
                       const double                  reach);

  /** A point of a face's plane, in its in-plane coordinates. */
  using PlanePoint = std::array<double, 2>;

  /**
   * The convex polygon @p subject clipped by the convex, counterclockwise
   * polygon @p clip (Sutherland-Hodgman); a point counts as inside an edge
   * down to -@p tolerance of the edge's cross product.
   */
  std::vector<PlanePoint>
  clip_convex_polygon(std::vector<PlanePoint>        subject,
                      const std::vector<PlanePoint> &clip,
                      const double                   tolerance);
} // namespace hrcontact

#endif
