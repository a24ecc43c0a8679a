#ifndef hrcontact_contact_tractions_h
#define hrcontact_contact_tractions_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <deal.II/fe/fe_values.h>

#include <hrcontact/core/results.h>

#include <array>
#include <map>
#include <string>
#include <vector>

namespace hrcontact
{
  /**
   * The equilibrated stress's tractions on the contact faces, and the
   * contact term of the Prager-Synge bound (doc/error-bounds.md): with a
   * unilateral constraint v.d <= g on Gamma_c,
   *
   *   |u - v|_E^2 + |sigma - tau|^2 <= |tau - C eps(v)|^2
   *                                   + 2 int_Gamma_c (-q) (g - v.d)
   *
   * for every v that meets it and every tau with tau n = q d, q <= 0 on
   * Gamma_c (frictionless, compressive): tau's sign is what makes the
   * inequality one-sided, so q must be nonpositive pointwise.
   *
   * A contact face is a boundary face whose two nodes have unilateral rows
   * of the same straight obstacle (2D; Contact/Obstacles): the gap to a
   * straight obstacle and the Q1 normal displacement are linear along it,
   * so v = u_h meets the constraint on the face when it does at the nodes.
   * A contact pair (Contact/Contact pairs) is covered where each slave node
   * coincides with a master node (matched meshes: the row is n . (u_s -
   * u_m) <= g) and both rows of a slave face have the same normal: the
   * slave face carries tau n = q n, the master face between the two master
   * nodes the opposite traction -q n (action and reaction, pointwise), and
   * the relative normal displacement is linear along the pair of faces. The
   * contact term is the slave face's. A bilateral (tied) pair carries a
   * linear traction of either sign, and v meets its rows as equations
   * (lifted either way), so that it has no contact term.
   * Where a node penetrates (the contact iteration's tolerance), v lifts
   * it by its penetration along d with its hat function; the bound then
   * adds that lift's energy (lift_energy, triangle inequality).
   *
   * The nodal reactions p_k (<= 0) are what the tractions must carry: the
   * moments of q against the hats of a node's contact faces sum to p_k.
   * Each face's q is a quadratic with nonpositive Bernstein coefficients,
   * which can carry end moments in the ratio [1/3, 3]; how a node's
   * reaction is shared between its two faces is a small interval problem
   * along each chain of contact faces (every process solves the whole
   * boundary's, gathered, so that all agree), the shares as close as it
   * allows to sigma_h's own compressive moments on the two faces (the
   * vertex problems' choice for the other faces). A node whose reaction no such
   * share can carry (a contact zone of one node) is refused by name.
   */
  class ContactTractions
  {
  public:
    /** One contact face, by the line index of the mesh. */
    struct Face
    {
      /** The Q rows at the line's vertex 0 and 1. */
      std::array<unsigned int, 2> row{};
      /** q = c0 (1-s)^2 + c1 2 s (1-s) + c2 s^2, s from vertex 0; all <= 0. */
      std::array<double, 3> bernstein{};
      /** The obstacle's direction d (tau n = q d). */
      dealii::Tensor<1, 2> direction;
      /** v's gap g - v.d at the two vertices (>= 0; 0 on a master face,
       * whose pair's slave face carries the contact term). */
      std::array<double, 2> gap{};
      /** The master side of a contact pair: tau n = -q n, with n (the
       * direction) already turned. */
      bool master = false;
      /** The moments of sigma_h's own compressive traction -(sigma_h n) . d
       * at the two vertices: the shares the reactions are split nearest. */
      std::array<double, 2> natural{};
    };

    /** Every contact face of this process's own and ghost cells. */
    explicit ContactTractions(const Results<2> &results);

    /** The face on line @p line, or null. */
    const Face *
    find(const unsigned int line) const;

    /** tau n on @p face at s in [0, 1] from its vertex 0. */
    static dealii::Tensor<1, 2>
    traction(const Face &face, const double s);

    /** int q phi at the two vertices of a face of length @p L. */
    static std::array<double, 2>
    moments(const Face &face, const double L);

    /** 2 int (-q) (g - v.d) over a face of length @p L: its share of the
     * bound (>= 0). */
    static double
    gap_term(const Face &face, const double L);

    /** |v - u_h|_E^2 over this process's own cells (0 when no node
     * penetrates). */
    double lift_energy_squared = 0;

    /** The largest penetration lifted (0: u_h meets the constraint). */
    double largest_penetration = 0;

  private:
    std::map<unsigned int, Face> faces;

    /** A contact face of any process, as every process sees it. */
    struct GlobalFace
    {
      std::array<unsigned int, 2>     row;
      double                          length;
      std::array<dealii::Point<2>, 2> point;
      /** The magnitudes of its moments at its two rows. */
      std::array<double, 2> share{};
      /** Face::natural. */
      std::array<double, 2> natural{};
    };
    /** All contact faces, by rows; the faces at each row. */
    std::vector<GlobalFace>                all;
    std::vector<std::vector<unsigned int>> at;

    void
    gather_faces(const Results<2> &results);
    /** Where row @p k's node is, for messages. */
    std::string
    where(const unsigned int k) const;
    /** The shares along one chain of nodes and the faces between them. */
    void
    share_chain(const std::vector<unsigned int> &node,
                const std::vector<unsigned int> &face,
                const std::vector<double>       &P,
                const double                     tol);
    void
    share_reactions(const Results<2> &results);
    /** Face::natural of @p face, the @p f-th face of @p cell. */
    static std::array<double, 2>
    natural_moments(const Results<2>                                  &results,
                    const dealii::DoFHandler<2>::active_cell_iterator &cell,
                    const unsigned int                                 f,
                    const Face                                        &face,
                    dealii::FEFaceValues<2>                           &fv);
    /** A tied (bilateral pair) row's reaction @p P, of either sign, between
     * its faces nearest their natural moments. */
    void
    share_tied(const unsigned int k, const double P);
    void
    lift(const Results<2> &results, const std::vector<double> &penetration);
    /** The master faces of contact pairs: the faces between the master
     * nodes of two rows of the same normal. */
    void
    find_master_faces(const Results<2>                &results,
                      const std::vector<unsigned int> &master_node);
    /** d . u_h of every contact row (complete on every process: each sums
     * the entries of its own dofs). */
    static std::vector<double>
    row_displacements(const Results<2> &results);
  };
} // namespace hrcontact

#endif
