#ifndef hrcontact_constraint_source_h
#define hrcontact_constraint_source_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <hrcontact/constraints/constraint_law.h>
#include <hrcontact/core/input.h>
#include <hrcontact/discretisation/equilibrium_system.h>
#include <hrcontact/solvers/row_relinearisation.h>

#include <array>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

namespace hrcontact
{
  template <int dim>
  class ConstraintSource;

  /**
   * What the boundary constraint kinds ask of one node, gathered over the
   * boundary faces around it. HRAssembler::classify_rows turns it into the
   * node's rows: prescribed components (H), then the obstacles of a corner
   * (eq. 11), or a source's own row (a stop) and one normal row (Q), then
   * the free rows (C) that complete the basis.
   */
  template <int dim>
  struct NodeConstraints
  {
    /** Prescribed displacement components and their values. */
    std::array<bool, dim>   prescribed{};
    std::array<double, dim> prescribed_value{};
    /**
     * A normal constraint along the body's own normal (bilateral or a
     * unilateral boundary support): the area-weighted face normals, each
     * unit face normal (to detect corners) and the value g.
     */
    bool                                has_normal           = false;
    bool                                normal_is_unilateral = false;
    dealii::Tensor<1, dim>              normal_sum;
    std::vector<dealii::Tensor<1, dim>> face_normals;
    double                              gap = 0;
    /** Obstacles touching the node: boundary id, normal into the obstacle,
     * gap (several at a corner, eq. 11); the last one is `obstacle`. */
    std::vector<
      std::tuple<dealii::types::boundary_id, dealii::Tensor<1, dim>, double>>
                           obstacles;
    int                    obstacle = -1;
    dealii::Tensor<1, dim> obstacle_normal;
    /** A source that adds a row of its own here (a two-sided stop), with
     * the boundary id it acts for. */
    const ConstraintSource<dim> *own_row_source   = nullptr;
    int                          own_row_boundary = -1;
    /** A source will couple the node's rows to those of other nodes
     * (ConstraintSource::couple_rows): its rows are stored even when lean. */
    bool coupled = false;

    /** Whether some component is prescribed. */
    bool
    any_prescribed() const;

    /** Prescribe component @p d to @p value; false (and nothing changed)
     * when another kind already prescribed it to a different value. */
    bool
    prescribe(const unsigned int d, const double value);
    /** Record an obstacle (once per boundary id). */
    void
    touch(const dealii::types::boundary_id id,
          const dealii::Tensor<1, dim>    &normal,
          const double                     gap);
  };

  /**
   * The constraints of the nodes some boundary face touches, by node
   * (EquilibriumSystem numbering); nodes no source touched are absent. A map
   * rather than one entry per node: the boundary is a surface, and with a
   * distributed mesh no process knows every node.
   */
  template <int dim>
  using NodeConstraintMap = std::map<unsigned int, NodeConstraints<dim>>;

  /** One boundary face as the constraint sources see it. */
  template <int dim>
  struct BoundaryFace
  {
    dealii::types::boundary_id boundary_id;
    /** The body of the face's cell (its material id). */
    unsigned int body = 0;
    /** The face's nodes (EquilibriumSystem numbering) and positions. */
    std::vector<unsigned int>       nodes;
    std::vector<dealii::Point<dim>> points;
    /** Outward unit normal and measure at the face centre. */
    dealii::Tensor<1, dim> normal;
    double                 measure = 0;
  };

  /** A row a source adds at a node itself: direction, value and law. */
  struct OwnRow
  {
    std::vector<double>                  direction;
    double                               value = 0;
    std::shared_ptr<const ConstraintLaw> law;
    /** Without a law: unilateral contact (w - g <= 0, p <= 0) rather than
     * a bilateral constraint w = g. */
    bool unilateral = false;
  };

  /**
   * One kind of boundary constraint (prescribed displacements, normal
   * displacements, straight or curved obstacles, boundary supports, stops):
   * it owns its `.prm` entry, records on the nodes of its boundaries what it
   * asks (collect), adds a row of its own where the kind needs one (a stop),
   * and, when its rows follow the configuration, re-linearises them between
   * multiplier updates through the RowRelinearisation it hands out. Kinds
   * register with HRCONTACT_REGISTER_CONSTRAINT_SOURCE; a scene creates only
   * those its `.prm` uses (doc/design.md, "Adding a constraint kind").
   *
   * A row may combine the dofs of several nodes (EquilibriumRow::combination
   * is a list of dof-coefficient pairs); EquilibriumRow::node is then the
   * node the row is reported at.
   */
  template <int dim>
  class ConstraintSource
  {
  public:
    virtual ~ConstraintSource() = default;

    /** Read the entry; false when it is empty (the scene does not use this
     * kind). `earlier` are the kinds read before it. */
    virtual bool
    parse_parameters(
      dealii::ParameterHandler                                  &prm,
      const Constants                                           &constants,
      const std::vector<std::shared_ptr<ConstraintSource<dim>>> &earlier) = 0;

    /** The entry it reads, e.g. "Contact/Obstacles", for messages. */
    virtual std::string
    entry() const = 0;

    /** Whether it constrains the nodes of this boundary. */
    virtual bool
    acts_on(const dealii::types::boundary_id id) const = 0;

    /** The boundary ids its entry names, each of which must be on the mesh
     * (check_named_boundary_ids). */
    virtual std::vector<dealii::types::boundary_id>
    boundary_ids() const = 0;

    /** Whether it puts a normal-type constraint on its boundaries (one
     * such kind per boundary). */
    virtual bool
    is_normal_kind() const;

    /**
     * Whether Q1 displacements that meet its rows at the nodes meet them
     * at every point of its faces (the error bound needs a kinematically
     * admissible u_h): true for the kinds that are not normal, false
     * unless a normal kind says so (a straight obstacle: the gap is linear
     * along a straight face).
     */
    virtual bool
    holds_pointwise_from_nodes() const
    {
      return !is_normal_kind();
    }

    /**
     * The value this kind prescribes for displacement component @p d at
     * @p x of its boundary @p id, or NaN where it prescribes none: what
     * u_h must meet between the nodes too for the error bound to be
     * guaranteed (SupportMismatch).
     */
    virtual double
    prescribed_value(const dealii::types::boundary_id id,
                     const unsigned int               d,
                     const dealii::Point<dim>        &x) const
    {
      (void)id;
      (void)d;
      (void)x;
      return std::numeric_limits<double>::quiet_NaN();
    }

    /**
     * The value g of u . n = g this kind prescribes at @p x of its boundary
     * @p id along the face's outward normal n, or NaN where it prescribes
     * none (a bilateral normal constraint: SupportMismatch checks u_h
     * against it between the nodes).
     */
    virtual double
    normal_value(const dealii::types::boundary_id id,
                 const dealii::Point<dim>        &x) const
    {
      (void)id;
      (void)x;
      return std::numeric_limits<double>::quiet_NaN();
    }

    /**
     * Called once with every face of every kind's boundaries before any
     * collect(): a kind whose rows couple nodes of several faces (contact
     * pairs) finds its partners here. Does nothing by default.
     */
    virtual void
    prepare(const std::vector<BoundaryFace<dim>> &faces,
            const EquilibriumSystem              &system) const;

    /** Record what it asks of the nodes of one of its faces. */
    virtual void
    collect(const BoundaryFace<dim> &face,
            const EquilibriumSystem &system,
            NodeConstraintMap<dim>  &nodes) const = 0;

    /** The row of its own at a node that collect() marked (a stop). */
    virtual OwnRow
    own_row(const unsigned int          node,
            const dealii::Point<dim>   &point,
            const NodeConstraints<dim> &constraints,
            const EquilibriumSystem    &system) const;

    /**
     * After every node's rows are built: extend the rows this kind made to
     * the dofs of other nodes, keeping the directions and combinations of
     * all rows biorthogonal (EquilibriumRow). Does nothing by default.
     */
    virtual void
    couple_rows(EquilibriumSystem &system) const;

    /** Whether its rows change during the solve (then the null-space path
     * cannot be used). */
    virtual bool
    changes_rows() const;

    /** The re-linearisation of its rows in `system` (after the rows were
     * classified), or null when its rows stay as classified. */
    virtual std::unique_ptr<RowRelinearisation>
    relinearisation(EquilibriumSystem &system) const;
  };

  /** The boundary ids of a kind's entries, the keys of its map by id. */
  template <typename MapById>
  std::vector<dealii::types::boundary_id>
  boundary_ids_of(const MapById &entries)
  {
    std::vector<dealii::types::boundary_id> ids;
    for (const auto &entry : entries)
      ids.push_back(entry.first);
    return ids;
  }

  /**
   * One normal-type constraint kind per boundary: InputError "WHERE:
   * boundary ID already has WHAT." if an earlier normal kind acts on it.
   */
  template <int dim>
  void
  require_unconstrained(
    const dealii::types::boundary_id                           id,
    const std::string                                         &where,
    const std::vector<std::shared_ptr<ConstraintSource<dim>>> &earlier,
    const std::string                                         &what);

  /**
   * The registry of constraint kinds and the kinds a scene uses, in the
   * order of their registered positions (which orders parsing and each
   * node's rows).
   */
  template <int dim>
  class ConstraintSources
  {
  public:
    using Factory = std::function<std::unique_ptr<ConstraintSource<dim>>()>;

    static bool
    register_source(
      const unsigned int                                     position,
      const std::function<void(dealii::ParameterHandler &)> &declare,
      const Factory                                         &factory);

    /** Every registered kind's entries. */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** The kinds the parameters use, read in order. */
    static std::vector<std::shared_ptr<ConstraintSource<dim>>>
    create(dealii::ParameterHandler &prm, const Constants &constants);

  private:
    struct Entry
    {
      unsigned int                                    position;
      std::function<void(dealii::ParameterHandler &)> declare;
      Factory                                         factory;
    };
    static std::vector<Entry> &
    registry();
  };
} // namespace hrcontact

/** Register CLASSNAME<2> and CLASSNAME<3> at POSITION of the kinds. */
#define HRCONTACT_REGISTER_CONSTRAINT_SOURCE(classname, position) \
  namespace                                                       \
  {                                                               \
    const bool classname##_registered_2d =                        \
      ::hrcontact::ConstraintSources<2>::register_source(         \
        position,                                                 \
        &classname<2>::declare_parameters,                        \
        [] { return std::make_unique<classname<2>>(); });         \
    const bool classname##_registered_3d =                        \
      ::hrcontact::ConstraintSources<3>::register_source(         \
        position,                                                 \
        &classname<3>::declare_parameters,                        \
        [] { return std::make_unique<classname<3>>(); });         \
  }

#endif
