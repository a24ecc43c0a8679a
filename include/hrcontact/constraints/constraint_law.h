#ifndef hrcontact_constraint_law_h
#define hrcontact_constraint_law_h

#include <limits>
#include <string>

namespace hrcontact
{
  /**
   * The quadratic piece of one constraint row in a Newton step, as the
   * Newton-step paths solve it: with w the row's displacement and g its
   * reference value (EquilibriumRow::value),
   *   held row (spring = false):  w - g = offset            (Dirichlet),
   *   spring row:                 w - g = offset - compliance p,
   * i.e. a spring of stiffness 1/compliance anchored at g + offset
   * (compliance = +infinity: no stiffness, p = 0).
   */
  struct ContactPiece
  {
    bool   spring     = false;
    double offset     = 0;
    double compliance = 0;
    /** The law's branch this piece belongs to (for sets and output). */
    unsigned int branch = 0;

    /** w - g that this piece gives for the reaction p. */
    double
    relation(const double p) const
    {
      return spring ? offset - compliance * p : offset;
    }
  };

  /**
   * A reversible constraint law between the reaction p of a row and its
   * displacement w (section 2.4), given through its concave conjugate
   * potential j^c(p) (eq. 14, section 2.4.2), measured from the row's
   * reference value g: w - g is in the superdifferential of j^c at p.
   *
   * The augmented Lagrangian regularises j^c per row with a multiplier mu
   * (the estimate of w - g) and a compliance alpha > 0 (eq. 26-28, written
   * for any law):
   *   L(p; mu, alpha) = max_q [ j^c(q) + mu (p - q) - alpha/2 (p - q)^2 ],
   * the proximal (Moreau) envelope of j^c. With q* the maximiser, pbar = p -
   * q* is the constraint residual of eq. 48, dL/dp = mu - alpha pbar the new
   * multiplier, and L is C^1 and piecewise quadratic: where q* sits on a
   * vertex of j^c (a fixed reaction) the row is a spring of compliance alpha,
   * where it sits on a linear piece of j^c (a fixed displacement) it is held,
   * where j^c is quadratic (a linear branch of the law) it is a stiffer spring.
   * For unilateral contact (j^c = -ind{p <= 0}) this is exactly the paper's
   * pbar = max(p, mu/alpha).
   *
   * The AugmentedLagrangianSolver only calls these functions; a new law is a
   * new class.
   */
  class ConstraintLaw
  {
  public:
    virtual ~ConstraintLaw() = default;

    /** For logs and errors. */
    virtual std::string
    name() const = 0;

    /**
     * j^c(p) - g p: the conjugate potential measured from the reference g;
     * -infinity outside its domain.
     */
    virtual double
    conjugate_potential(const double p) const = 0;

    /** pbar = p - q*(p; mu, alpha), the residual of eq. 48. */
    virtual double
    residual(const double p, const double mu, const double alpha) const = 0;

    /** The quadratic piece of L at p, with its branch. */
    virtual ContactPiece
    piece(const double p, const double mu, const double alpha) const = 0;

    /**
     * The piece of a branch for the multiplier mu and compliance alpha. The
     * first Newton step after a multiplier update reads a spring's branch
     * with the multipliers of the last solve and re-anchors it at the new
     * ones with this (AugmentedLagrangianSolver).
     */
    virtual ContactPiece
    piece_of_branch(const unsigned int branch,
                    const double       mu,
                    const double       alpha) const = 0;

    /**
     * The piece of the trial solution (Step 0): the row held at its
     * reference, w = g.
     */
    virtual ContactPiece
    trial_piece() const;

    /** L(p; mu, alpha) (the regularised conjugate potential). */
    virtual double
    regularised_potential(const double p,
                          const double mu,
                          const double alpha) const;

    /** dL/dp: the displacement estimate w - g at p. */
    virtual double
    gradient(const double p, const double mu, const double alpha) const;

    /**
     * The piece of the next Newton step from the piece `from` it solved
     * last: piece(p) by default. A law with more than two branches crosses
     * at most one kink of L per row and step (a piecewise line search): with
     * alpha large the free vertex between two stops is a very soft spring,
     * and Newton on the held pieces jumps from one stop to the other and back.
     */
    virtual ContactPiece
    next_piece(const ContactPiece &from,
               const double        p,
               const double        mu,
               const double        alpha) const;

    /**
     * The multiplier after an update in the diagonal scheme, whose single
     * Newton step solved this row with the piece `solved`: w - g of that
     * piece at p (a held row sat at its offset, which its reaction says
     * nothing about yet; a spring moved with p).
     */
    virtual double
    multiplier_after_step(const ContactPiece &solved,
                          const double        p,
                          const double        mu,
                          const double        alpha) const;

    /**
     * w - g reported after an update, given the piece at p and the updated
     * multiplier (the multiplier itself for a consistent law).
     */
    virtual double
    opening(const ContactPiece &current, const double p, const double mu) const;

    /** Whether the law has multipliers (a bilateral row has none). */
    virtual bool
    has_multiplier() const
    {
      return true;
    }

    /** Whether the branch transmits no reaction (the row is released). */
    virtual bool
    is_free(const unsigned int branch) const = 0;

    /** Whether the reaction p holds the body (for the floating check). */
    virtual bool
    holds(const double p) const
    {
      return p < 0;
    }

    /** A short name of the branch for tables and summaries. */
    virtual std::string
    branch_name(const unsigned int branch) const = 0;
  };

  /** w = g, any reaction (section 2.4.3): j^c = 0 relative to g. */
  class BilateralConstraint : public ConstraintLaw
  {
  public:
    std::string
    name() const override;
    double
    conjugate_potential(const double p) const override;
    double
    residual(const double p,
             const double mu,
             const double alpha) const override;
    ContactPiece
    piece(const double p, const double mu, const double alpha) const override;
    ContactPiece
    piece_of_branch(const unsigned int branch,
                    const double       mu,
                    const double       alpha) const override;
    double
    gradient(const double p,
             const double mu,
             const double alpha) const override;
    bool
    has_multiplier() const override
    {
      return false;
    }
    bool
    is_free(const unsigned int) const override
    {
      return false;
    }
    std::string
    branch_name(const unsigned int) const override;
  };

  /**
   * Frictionless unilateral contact (eq. 12-14): w - g <= 0, p <= 0,
   * p (w - g) = 0; j^c = -ind{p <= 0}. Regularised by the consistent AL of
   * eq. 26/28: pbar = max(p, mu/alpha). Branch 0: in contact (held at w =
   * g), 1: open (a spring of compliance alpha anchored at g + mu).
   */
  class UnilateralContact : public ConstraintLaw
  {
  public:
    std::string
    name() const override;
    double
    conjugate_potential(const double p) const override;
    double
    residual(const double p,
             const double mu,
             const double alpha) const override;
    ContactPiece
    piece(const double p, const double mu, const double alpha) const override;
    ContactPiece
    piece_of_branch(const unsigned int branch,
                    const double       mu,
                    const double       alpha) const override;
    double
    multiplier_after_step(const ContactPiece &solved,
                          const double        p,
                          const double        mu,
                          const double        alpha) const override;
    bool
    is_free(const unsigned int branch) const override
    {
      return branch == 1;
    }
    std::string
    branch_name(const unsigned int branch) const override;
  };

  /**
   * Unilateral contact regularised by the Macaulay bracket (eq. 27): pbar =
   * max(p, 0). A row is released only once it pulls; a held row keeps its
   * multiplier. Its Hessian jumps at p = 0, where solutions sit.
   */
  class MacaulayUnilateralContact : public UnilateralContact
  {
  public:
    std::string
    name() const override;
    double
    residual(const double p,
             const double mu,
             const double alpha) const override;
    ContactPiece
    piece(const double p, const double mu, const double alpha) const override;
    double
    regularised_potential(const double p,
                          const double mu,
                          const double alpha) const override;
    double
    gradient(const double p,
             const double mu,
             const double alpha) const override;
    double
    multiplier_after_step(const ContactPiece &solved,
                          const double        p,
                          const double        mu,
                          const double        alpha) const override;
    double
    opening(const ContactPiece &current,
            const double        p,
            const double        mu) const override;
  };

  /**
   * The two-sided stop with limit reactions of section 2.4.2 (Fig. 4): free
   * travel for g- < w < g+; at w = g+ a compressive reaction p in [p0-, 0],
   * at w = g- a tensile one p in [0, p0+]; beyond, the row moves on with the
   * limit reaction (hardening 0) or along a linear branch of stiffness k
   * (p = p0- - k- (w - g+) beyond g+, p = p0+ - k+ (w - g-) beyond g-, with
   * k >= 0 here; the paper writes the negative slopes). Measured from
   * reference g = 0 (w is the displacement itself).
   *
   * The conjugate potential (the paper's j^c_n = inf_i j^c_ni):
   *   q g- - (q - p0+)_+^2 / (2 k+)   for q >= 0,
   *   q g+ - (p0- - q)_+^2 / (2 k-)   for q <= 0,
   * with the domain [p0-, p0+] when the branch is a constant reaction.
   * Its vertices (q = 0, and p0+/p0- for constant limits) give springs that
   * the multiplier updates drive to that reaction; its linear pieces give
   * held rows at a stop.
   */
  class TwoSidedStop : public ConstraintLaw
  {
  public:
    /** Branches. */
    enum Branch : unsigned int
    {
      free          = 0,
      at_upper_stop = 1, ///< w = g+, p in [p0-, 0]
      beyond_upper  = 2, ///< w > g+, p = p0- (- k- (w - g+))
      at_lower_stop = 3, ///< w = g-, p in [0, p0+]
      beyond_lower  = 4, ///< w < g-, p = p0+ (- k+ (w - g-))
    };

    /**
     * g- < g+; p0+ >= 0 >= p0- (infinite: a rigid stop); k+, k- >= 0 (0: a
     * constant limit reaction).
     */
    TwoSidedStop(const double g_minus,
                 const double g_plus,
                 const double p0_minus,
                 const double p0_plus,
                 const double k_minus = 0,
                 const double k_plus  = 0);

    std::string
    name() const override;
    double
    conjugate_potential(const double p) const override;
    double
    residual(const double p,
             const double mu,
             const double alpha) const override;
    ContactPiece
    piece(const double p, const double mu, const double alpha) const override;
    ContactPiece
    piece_of_branch(const unsigned int branch,
                    const double       mu,
                    const double       alpha) const override;
    double
    regularised_potential(const double p,
                          const double mu,
                          const double alpha) const override;
    ContactPiece
    next_piece(const ContactPiece &from,
               const double        p,
               const double        mu,
               const double        alpha) const override;
    bool
    is_free(const unsigned int branch) const override
    {
      return branch == free;
    }
    bool
    holds(const double p) const override
    {
      return p != 0;
    }
    std::string
    branch_name(const unsigned int branch) const override;

    /** The reaction the exact law gives for the displacement w (for tests). */
    double
    reaction(const double w) const;

    const double g_minus, g_plus, p0_minus, p0_plus, k_minus, k_plus;

  private:
    /** The maximiser q* of the envelope and its piece. */
    ContactPiece
    proximal(const double p,
             const double mu,
             const double alpha,
             double      &q) const;
  };
} // namespace hrcontact

#endif
