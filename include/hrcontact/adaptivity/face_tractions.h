#ifndef hrcontact_face_tractions_h
#define hrcontact_face_tractions_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/point.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/tensor.h>

#include <deal.II/lac/full_matrix.h>

#include <hrcontact/adaptivity/contact_tractions.h>
#include <hrcontact/adaptivity/vertex_problems.h>
#include <hrcontact/core/results.h>

#include <array>
#include <map>
#include <memory>
#include <vector>

namespace hrcontact
{
  /** The one displacement dof of an unrotated row (a single coefficient
   * +-1), or -1. */
  long long
  single_dof(const EquilibriumRow &row);


  /**
   * Linear face tractions that balance every cell of a 2D conforming mesh
   * (Ladevèze's element equilibration, step 1 of EquilibratedStress). The
   * HR stresses satisfy equilibrium against every Q1 test function that is
   * not held (eq. 38's free rows), so around each vertex v the cells'
   * residuals R_K = int_K sigma_h : eps(phi_v e_c) - f_c phi_v (less their
   * loaded faces' data moments) sum to zero; per vertex and component the
   * unknown moments b_F = int_F t phi_v solve A b = R (A: +1 on the face's
   * owner, -1 on its other side), the one closest to the averaged sigma_h n
   * (b = b0 + A^+ (R - A b0)). The hat functions sum to one and reproduce
   * linear fields, so each cell's tractions balance its body force in force
   * and moment.
   *
   * Hanging nodes: the faces are the mesh's active lines, so a coarse cell
   * beside refined ones sees two linear tractions on such a face. The
   * conforming hat of a parent vertex a is, on that face, a's hat plus half
   * the hanging node's, so the vertex problems of a hanging node h (its two
   * fine cells, three faces: solvable for any residuals) are solved first,
   * and their moments on the two halves of the coarse face enter the coarse
   * cell's rows of a and b as data. The rows of every parent problem still
   * sum to the HR equation of its conforming test function, so each stays
   * solvable and the coarse cell balances too. On several processes the
   * owner of the coarse cell solves its hanging nodes and sends the moments
   * to its ghosts (a parent's patch holds the coarse cell, not always both
   * fine cells).
   *
   * The two halves' linear tractions need not meet at the hanging node, and
   * a kink there that is not along the coarse cell's inner edge to it is
   * one no piecewise-polynomial symmetric stress of the coarse cell's split
   * can take. So each half gets the Legendre quadratic 6 s^2 - 6 s + 1
   * times the amount that makes the halves meet at their mean: it is
   * orthogonal to the linear functions, so no moment, force or moment of a
   * cell changes.
   */
  class FaceTractions
  {
  public:
    /** One face (a line of the mesh, by index): the traction of its owner
     * side at its two vertices, by component; `known`: a loaded boundary
     * face whose traction is the data. */
    struct Face
    {
      unsigned int                         owner = 0;
      std::array<unsigned int, 2>          vertices{};
      std::array<std::array<double, 2>, 2> moment{}, value{};
      /** The Legendre quadratic's coefficient per component (halves of a
       * face with a hanging node). */
      std::array<double, 2>      bubble{};
      std::array<bool, 2>        known{};
      bool                       boundary    = false;
      dealii::types::boundary_id boundary_id = 0;
    };

    /** Computes the tractions of @p results (2D, serial, conforming). */
    explicit FaceTractions(const Results<2> &results);

    /** The traction the cell @p cell sees at @p x of its face @p face
     * (outward normal @p normal): the data on a loaded face, else the
     * linear traction (sign flipped on the side that does not own it). */
    dealii::Tensor<1, 2>
    traction(const unsigned int          face,
             const unsigned int          cell,
             const dealii::Point<2>     &x,
             const dealii::Tensor<1, 2> &normal) const;

    /** The largest residual of the vertex problems, relative to the
     * largest cell residual R_K: round-off when the HR equations hold. */
    double residual = 0;

    /** The contact faces' tractions (null without contact rows). */
    const ContactTractions *
    contact() const
    {
      return contact_tractions.get();
    }

  private:
    const Results<2> &results;
    /** Per active cell: whether this process holds its fields. */
    std::vector<bool> usable;
    std::vector<Face> faces;
    /** R_K per cell, vertex and component; the averaged moments per face,
     * face vertex and component. */
    std::vector<std::array<std::array<double, 2>, 4>> cell_residual;
    std::vector<std::array<std::array<double, 2>, 2>> average;
    double                                            scale = 0;

    std::unique_ptr<ContactTractions> contact_tractions;

    void
    classify_faces();
    /** The contact faces' moments leave R_K as loaded faces' do. */
    void
    subtract_contact_moments();
    void
    cell_residuals();
    /** One cell's face moments from sigma_h at the unit points of
     * cell_residuals() (after the cell's four: per face six, the whole
     * face's two and each half's two). */
    void
    face_moments(const dealii::DoFHandler<2>::active_cell_iterator &cell,
                 const dealii::QGauss<1>                           &q_face,
                 const std::vector<dealii::Vector<double>>         &s_values);
    void
    solve_vertex_problems();
    /** The vertex problems of vertex @p vertex on @p cells (those with it as
     * a vertex), both components; a @p hanging node's moments are kept for
     * its parents' problems. */
    void
    solve_vertex(const unsigned int vertex,
                 const dealii::ArrayView<
                   const dealii::Triangulation<2>::active_cell_iterator> &cells,
                 const bool hanging);
    /** The segment (an active line) of @p face through @p vertex. */
    static unsigned int
    segment_through(
      const dealii::TriaIterator<dealii::TriaAccessor<1, 2, 2>> &face,
      const unsigned int                                         vertex);
    /** The halves' Legendre quadratics (after the vertex values). */
    void
    join_halves();
    /** Per half of a refined face (by line index): the moment against the
     * hanging node's hat, by component. */
    std::map<unsigned int, std::array<double, 2>> hanging_moment;
    /** A^+ of a vertex problem's +-1 matrix, given as its key. */
    VertexProblemInverses pseudo_inverse;
    /** Scratch of solve_vertex(). */
    std::vector<signed char> key;
  };
} // namespace hrcontact

#endif
