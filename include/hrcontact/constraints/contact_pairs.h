#ifndef hrcontact_contact_pairs_h
#define hrcontact_contact_pairs_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <hrcontact/constraints/constraint_source.h>

#include <map>
#include <memory>
#include <vector>

namespace hrcontact
{
  /**
   * Contact/Contact pairs: frictionless unilateral contact between two
   * boundaries of deformable bodies, node to segment. Each slave node x is
   * projected onto the closest master face in reach (closest point, the
   * face's shape functions N_m at the projection); its row has the normal
   * n = -n_master of that face and the gap g = (x_proj - x).n measured on
   * the undeformed master surface, and constrains the relative normal
   * displacement w = (u_s - sum_m N_m u_m).n <= g. The reaction p <= 0 acts
   * as p n on the slave node and -p N_m n on the master nodes (eq. 32 on
   * both sides, equal and opposite). On matching meshes the projection
   * falls on a master node and the row is node to node.
   *
   * The row's direction spans the slave and master dofs, its combination
   * (the equilibrium row it reads the reaction from) the slave's own dofs;
   * the rows of the master nodes take the slave's normal equilibrium row
   * into their combinations so that all rows stay biorthogonal
   * (couple_rows, doc/contact-pairs.md).
   *
   * Contact/Pair method = mortar integrates the row over the slave
   * node's faces with the dual basis instead of taking it at the node
   * (segment to segment): the master weights are M_sm / D_s, and the
   * contact patch test passes on non-matching meshes.
   *
   * Contact/Pair laws gives a pair another law for s = w - g (s = 0 where
   * the surfaces touch): bilateral (s = 0, the surfaces slide but do not
   * separate) or a two-sided stop (section 2.4.2, the law of Contact/Stops
   * on s).
   */
  template <int dim>
  class ContactPairs : public ConstraintSource<dim>
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    bool
    parse_parameters(dealii::ParameterHandler &prm,
                     const Constants          &constants,
                     const std::vector<std::shared_ptr<ConstraintSource<dim>>>
                       &earlier) override;
    std::string
    entry() const override;
    bool
    acts_on(const dealii::types::boundary_id id) const override;
    std::vector<dealii::types::boundary_id>
    boundary_ids() const override;
    void
    prepare(const std::vector<BoundaryFace<dim>> &faces,
            const EquilibriumSystem              &system) const override;
    void
    collect(const BoundaryFace<dim> &face,
            const EquilibriumSystem &system,
            NodeConstraintMap<dim>  &nodes) const override;
    OwnRow
    own_row(const unsigned int          node,
            const dealii::Point<dim>   &point,
            const NodeConstraints<dim> &constraints,
            const EquilibriumSystem    &system) const override;
    void
    couple_rows(EquilibriumSystem &system) const override;
    /** Where each slave node coincides with a master node (matched meshes,
     * straight interface): the error bound's ContactTractions::not_covered
     * checks that row by row and refuses the rest by name. */
    bool
    holds_pointwise_from_nodes() const override
    {
      return true;
    }

    /** One pair as the `.prm` gives it. */
    struct Pair
    {
      dealii::types::boundary_id slave, master;
      /** How far from the master surface a slave node may be and still get
       * a row (0: a tenth of the master boundary's bounding box diagonal). */
      double reach = 0;
      /** The law of s = w - g. */
      enum class Law
      {
        unilateral,
        bilateral,
        stop
      } law = Law::unilateral;
      /** A stop's g-, g+, p0-, p0+ (, k-, k+) at the slave node. */
      std::shared_ptr<dealii::FunctionParser<dim>> stop_values[6];
    };

    /** The pairs as read. */
    const std::vector<Pair> &
    pair_list() const
    {
      return pairs;
    }

    /** Where a slave node meets the master surface. */
    struct Projection
    {
      unsigned int              pair = 0;
      std::vector<unsigned int> master_nodes;
      std::vector<double>       shape_values;
      dealii::Tensor<1, dim>    normal;
      double                    gap = 0;
    };

  private:
    /** Contact/Pair method: mortar rows instead of node to segment. */
    bool mortar = false;

    /** Read Contact/Pair laws into the pairs. */
    void
    parse_laws(const std::string &text, const Constants &constants);

    std::vector<Pair> pairs;
    /** Found by prepare() for the system being classified, by slave node. */
    mutable std::map<unsigned int, Projection> projections;
  };
} // namespace hrcontact

#endif
