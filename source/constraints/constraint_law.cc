#include <hrcontact/constraints/constraint_law.h>
#include <hrcontact/core/input.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace hrcontact
{
  namespace
  {
    constexpr double infinity = std::numeric_limits<double>::infinity();

    ContactPiece
    held(const double offset, const unsigned int branch)
    {
      ContactPiece piece;
      piece.offset = offset;
      piece.branch = branch;
      return piece;
    }

    ContactPiece
    spring(const double       offset,
           const double       compliance,
           const unsigned int branch)
    {
      ContactPiece piece;
      piece.spring     = true;
      piece.offset     = offset;
      piece.compliance = compliance;
      piece.branch     = branch;
      return piece;
    }
  } // namespace

  // ------------------------------------------------------------------------
  // ConstraintLaw defaults

  ContactPiece
  ConstraintLaw::trial_piece() const
  {
    return held(0., 0);
  }

  double
  ConstraintLaw::regularised_potential(const double p,
                                       const double mu,
                                       const double alpha) const
  {
    const double pbar = residual(p, mu, alpha);
    return conjugate_potential(p - pbar) + mu * pbar -
           0.5 * alpha * pbar * pbar;
  }

  double
  ConstraintLaw::gradient(const double p,
                          const double mu,
                          const double alpha) const
  {
    return mu - alpha * residual(p, mu, alpha);
  }

  ContactPiece
  ConstraintLaw::next_piece(const ContactPiece &,
                            const double p,
                            const double mu,
                            const double alpha) const
  {
    return piece(p, mu, alpha);
  }

  double
  ConstraintLaw::multiplier_after_step(const ContactPiece &solved,
                                       const double        p,
                                       const double,
                                       const double) const
  {
    return solved.relation(p);
  }

  double
  ConstraintLaw::opening(const ContactPiece &,
                         const double,
                         const double mu) const
  {
    return mu;
  }

  // ------------------------------------------------------------------------
  // Bilateral

  std::string
  BilateralConstraint::name() const
  {
    return "bilateral constraint";
  }

  double
  BilateralConstraint::conjugate_potential(const double) const
  {
    return 0;
  }

  double
  BilateralConstraint::residual(const double,
                                const double mu,
                                const double alpha) const
  {
    return mu / alpha; // mu stays 0
  }

  ContactPiece
  BilateralConstraint::piece(const double, const double, const double) const
  {
    return held(0., 0);
  }

  ContactPiece
  BilateralConstraint::piece_of_branch(const unsigned int,
                                       const double,
                                       const double) const
  {
    return held(0., 0);
  }

  double
  BilateralConstraint::gradient(const double, const double, const double) const
  {
    return 0;
  }

  std::string
  BilateralConstraint::branch_name(const unsigned int) const
  {
    return "held";
  }

  // ------------------------------------------------------------------------
  // Unilateral contact, consistent AL (eq. 26/28)

  std::string
  UnilateralContact::name() const
  {
    return "unilateral contact";
  }

  double
  UnilateralContact::conjugate_potential(const double p) const
  {
    return (p <= 0) ? 0. : -infinity;
  }

  double
  UnilateralContact::residual(const double p,
                              const double mu,
                              const double alpha) const
  {
    return std::max(p, mu / alpha);
  }

  ContactPiece
  UnilateralContact::piece(const double p,
                           const double mu,
                           const double alpha) const
  {
    // Released iff p > mu/alpha (eq. 26): a spring anchored at g + mu.
    return (p > mu / alpha) ? spring(mu, alpha, 1) : held(0., 0);
  }

  ContactPiece
  UnilateralContact::piece_of_branch(const unsigned int branch,
                                     const double       mu,
                                     const double       alpha) const
  {
    return (branch == 1) ? spring(mu, alpha, 1) : held(0., 0);
  }

  double
  UnilateralContact::multiplier_after_step(const ContactPiece &solved,
                                           const double        p,
                                           const double        mu,
                                           const double        alpha) const
  {
    // Eq. 48 as written: a held row takes pbar = mu/alpha, i.e. mu = 0.
    return solved.spring ? mu - alpha * std::max(p, mu / alpha) :
                           mu - alpha * (mu / alpha);
  }

  std::string
  UnilateralContact::branch_name(const unsigned int branch) const
  {
    return branch == 1 ? "open" : "contact";
  }

  // ------------------------------------------------------------------------
  // Unilateral contact, Macaulay AL (eq. 27)

  std::string
  MacaulayUnilateralContact::name() const
  {
    return "unilateral contact (Macaulay)";
  }

  double
  MacaulayUnilateralContact::residual(const double p,
                                      const double,
                                      const double) const
  {
    return std::max(p, 0.);
  }

  ContactPiece
  MacaulayUnilateralContact::piece(const double p,
                                   const double mu,
                                   const double alpha) const
  {
    return (p > 0) ? spring(mu, alpha, 1) : held(0., 0);
  }

  double
  MacaulayUnilateralContact::regularised_potential(const double p,
                                                   const double mu,
                                                   const double alpha) const
  {
    const double pbar = std::max(p, 0.);
    return mu * pbar - 0.5 * alpha * pbar * pbar;
  }

  double
  MacaulayUnilateralContact::gradient(const double p,
                                      const double mu,
                                      const double alpha) const
  {
    return (p > 0) ? mu - alpha * p : 0.;
  }

  double
  MacaulayUnilateralContact::multiplier_after_step(const ContactPiece &solved,
                                                   const double        p,
                                                   const double        mu,
                                                   const double alpha) const
  {
    // A held row keeps its multiplier (pbar = 0 there).
    return solved.spring ? mu - alpha * std::max(p, 0.) : mu;
  }

  double
  MacaulayUnilateralContact::opening(const ContactPiece &current,
                                     const double,
                                     const double mu) const
  {
    return current.spring ? mu : 0.;
  }

  // ------------------------------------------------------------------------
  // Two-sided stop with limit reactions (section 2.4.2)

  TwoSidedStop::TwoSidedStop(const double g_minus,
                             const double g_plus,
                             const double p0_minus,
                             const double p0_plus,
                             const double k_minus,
                             const double k_plus)
    : g_minus(g_minus)
    , g_plus(g_plus)
    , p0_minus(p0_minus)
    , p0_plus(p0_plus)
    , k_minus(k_minus)
    , k_plus(k_plus)
  {
    if (!(g_minus < g_plus))
      throw InputError("two-sided stop: the lower stop g- must lie below the "
                       "upper stop g+.");
    if (!(p0_minus <= 0) || !(p0_plus >= 0))
      throw InputError("two-sided stop: the limit reactions must satisfy "
                       "p0- <= 0 <= p0+ (p0- pushes back from the upper stop, "
                       "p0+ pulls back from the lower one).");
    if (!(k_minus >= 0) || !(k_plus >= 0) || !std::isfinite(k_minus) ||
        !std::isfinite(k_plus))
      throw InputError("two-sided stop: the stiffnesses beyond the limits "
                       "must be finite and >= 0 (0: a constant reaction).");
  }

  std::string
  TwoSidedStop::name() const
  {
    std::ostringstream s;
    s << "two-sided stop [" << g_minus << ", " << g_plus << "], limits "
      << p0_minus << ", " << p0_plus;
    return s.str();
  }

  double
  TwoSidedStop::conjugate_potential(const double q) const
  {
    if (q >= 0)
      {
        if (q <= p0_plus)
          return q * g_minus;
        return (k_plus > 0) ?
                 q * g_minus - (q - p0_plus) * (q - p0_plus) / (2 * k_plus) :
                 -infinity;
      }
    if (q >= p0_minus)
      return q * g_plus;
    return (k_minus > 0) ?
             q * g_plus - (p0_minus - q) * (p0_minus - q) / (2 * k_minus) :
             -infinity;
  }

  ContactPiece
  TwoSidedStop::piece_of_branch(const unsigned int branch,
                                const double       mu,
                                const double       alpha) const
  {
    // A vertex q_v of j^c: w = mu - alpha (p - q_v), a spring of compliance
    // alpha. A quadratic branch j^c = q w0 - c/2 (q - p0)^2 (c = 1/k): the
    // maximiser is q = (w0 + c p0 - mu + alpha p) / (alpha + c), and
    // eliminating q gives the spring w = (mu c + alpha w0 + alpha c p0) /
    // (alpha + c) - alpha c/(alpha + c) p. A linear piece of slope w0: held
    // at w = w0.
    auto quadratic = [&](const double w0, const double p0, const double k) {
      const double c = 1. / k;
      return spring((mu * c + alpha * w0 + alpha * c * p0) / (alpha + c),
                    alpha * c / (alpha + c),
                    branch);
    };
    switch (branch)
      {
        case beyond_upper:
          return (k_minus > 0) ? quadratic(g_plus, p0_minus, k_minus) :
                                 spring(mu + alpha * p0_minus, alpha, branch);
        case at_upper_stop:
          return held(g_plus, branch);
        case at_lower_stop:
          return held(g_minus, branch);
        case beyond_lower:
          return (k_plus > 0) ? quadratic(g_minus, p0_plus, k_plus) :
                                spring(mu + alpha * p0_plus, alpha, branch);
        default:
          return spring(mu, alpha, free);
      }
  }

  ContactPiece
  TwoSidedStop::proximal(const double p,
                         const double mu,
                         const double alpha,
                         double      &q) const
  {
    // Stationarity of the envelope: w(q) := mu - alpha (p - q) lies in the
    // superdifferential of j^c at q. w grows with q, the slope of j^c falls:
    // walk the pieces from the left (most compressive reaction).
    const double q_upper = p - (mu - g_plus) / alpha; // on the piece w = g+
    if (q_upper < p0_minus)
      {
        q = (k_minus > 0) ? (g_plus + p0_minus / k_minus - mu + alpha * p) /
                              (alpha + 1. / k_minus) :
                            p0_minus;
        return piece_of_branch(beyond_upper, mu, alpha);
      }
    if (q_upper <= 0)
      {
        q = q_upper;
        return piece_of_branch(at_upper_stop, mu, alpha);
      }
    const double q_lower = p - (mu - g_minus) / alpha; // on the piece w = g-
    if (q_lower < 0)
      {
        q = 0;
        return piece_of_branch(free, mu, alpha);
      }
    if (q_lower <= p0_plus)
      {
        q = q_lower;
        return piece_of_branch(at_lower_stop, mu, alpha);
      }
    q = (k_plus > 0) ? (g_minus + p0_plus / k_plus - mu + alpha * p) /
                         (alpha + 1. / k_plus) :
                       p0_plus;
    return piece_of_branch(beyond_lower, mu, alpha);
  }

  ContactPiece
  TwoSidedStop::next_piece(const ContactPiece &from,
                           const double        p,
                           const double        mu,
                           const double        alpha) const
  {
    // The branches in the order of the reaction q (most compressive first).
    static const unsigned int order[5] = {
      beyond_upper, at_upper_stop, free, at_lower_stop, beyond_lower};
    auto rank = [](const unsigned int branch) {
      for (int r = 0; r < 5; ++r)
        if (order[r] == branch)
          return r;
      return 2;
    };
    const ContactPiece target = piece(p, mu, alpha);
    const int          r_from = rank(from.branch), r_to = rank(target.branch);
    if (std::abs(r_to - r_from) <= 1)
      return target;
    return piece_of_branch(order[r_from + (r_to > r_from ? 1 : -1)], mu, alpha);
  }

  double
  TwoSidedStop::regularised_potential(const double p,
                                      const double mu,
                                      const double alpha) const
  {
    // With q from the maximiser itself (p - pbar can round out of the domain
    // at a vertex).
    double q = 0;
    proximal(p, mu, alpha, q);
    return conjugate_potential(q) + mu * (p - q) -
           0.5 * alpha * (p - q) * (p - q);
  }

  double
  TwoSidedStop::residual(const double p,
                         const double mu,
                         const double alpha) const
  {
    double q = 0;
    proximal(p, mu, alpha, q);
    return p - q;
  }

  ContactPiece
  TwoSidedStop::piece(const double p, const double mu, const double alpha) const
  {
    double q = 0;
    return proximal(p, mu, alpha, q);
  }

  double
  TwoSidedStop::reaction(const double w) const
  {
    if (w > g_plus)
      return p0_minus - k_minus * (w - g_plus);
    if (w < g_minus)
      return p0_plus - k_plus * (w - g_minus);
    return 0;
  }

  std::string
  TwoSidedStop::branch_name(const unsigned int branch) const
  {
    switch (branch)
      {
        case free:
          return "free";
        case at_upper_stop:
          return "at stop g+";
        case beyond_upper:
          return k_minus > 0 ? "beyond g+ (linear)" : "beyond g+ (limit)";
        case at_lower_stop:
          return "at stop g-";
        case beyond_lower:
          return k_plus > 0 ? "beyond g- (linear)" : "beyond g- (limit)";
        default:
          return "?";
      }
  }
} // namespace hrcontact
