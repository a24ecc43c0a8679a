#include <hrcontact/core/input.h>
#include <hrcontact/solvers/nested_iteration.h>

#include <cmath>
#include <functional>
#include <limits>

namespace hrcontact
{
  using namespace dealii;

  ContactStart
  transfer_rows_by_position(
    const EquilibriumSystem                                 &coarse,
    const ContactIteration                                  &coarse_state,
    const EquilibriumSystem                                 &fine,
    const std::function<double(unsigned int, unsigned int)> &reaction_scale,
    const std::function<double(unsigned int, unsigned int)> &compliance_scale,
    const double default_compliance_scale)
  {
    const unsigned int nc = coarse.contact_rows.size(),
                       nf = fine.contact_rows.size();
    AssertThrow(coarse_state.p.size() == nc && coarse_state.mu.size() == nc &&
                  coarse_state.alpha.size() == nc,
                ExcMessage("the coarse contact state does not fit its rows"));
    auto same_kind = [](const EquilibriumRow &a, const EquilibriumRow &b) {
      if (a.obstacle != b.obstacle || a.unilateral != b.unilateral ||
          bool(a.law) != bool(b.law))
        return false;
      if (a.law && a.law->name() != b.law->name())
        return false;
      // Rows of one node along different directions (a node in a corner
      // between obstacles) are told apart by their directions.
      double dot = 0, na = 0, nb = 0;
      if (a.combination.size() == b.combination.size())
        for (unsigned int k = 0; k < a.combination.size(); ++k)
          {
            dot += a.direction_component(k) * b.direction_component(k);
            na += a.direction_component(k) * a.direction_component(k);
            nb += b.direction_component(k) * b.direction_component(k);
          }
      return dot > 0.5 * std::sqrt(na * nb);
    };
    auto distance2 = [&](const unsigned int fine_node,
                         const unsigned int coarse_node) {
      double d2 = 0;
      for (unsigned int k = 0; k < 3; ++k)
        {
          const double d = fine.node_coordinates[fine_node][k] -
                           coarse.node_coordinates[coarse_node][k];
          d2 += d * d;
        }
      return d2;
    };

    ContactStart start;
    start.mu.assign(nf, 0.);
    start.alpha.assign(nf, 0.);
    start.p.assign(nf, 0.);
    double alpha_default = 0;
    for (const double a : coarse_state.alpha)
      alpha_default = std::max(alpha_default, a);
    std::vector<unsigned int> nearest;
    for (unsigned int i = 0; i < nf; ++i)
      {
        const EquilibriumRow &row  = fine.rows[fine.contact_rows[i]];
        double                best = std::numeric_limits<double>::max();
        nearest.clear();
        for (unsigned int j = 0; j < nc; ++j)
          {
            const EquilibriumRow &c  = coarse.rows[coarse.contact_rows[j]];
            const double          d2 = distance2(row.node, c.node);
            // The distance first: the kind (a string compare for laws) only
            // for the few rows that could be nearest.
            if (d2 > best * (1 + 1e-6) || !same_kind(row, c))
              continue;
            // Equal distances to round-off: the midpoints of a refinement.
            if (d2 < best * (1 - 1e-6))
              {
                best = d2;
                nearest.assign(1, j);
              }
            else if (d2 <= best * (1 + 1e-6))
              nearest.push_back(j);
          }
        if (nearest.empty())
          {
            // No coarse row of this kind: start it as the trial does.
            start.alpha[i] = alpha_default * default_compliance_scale;
            continue;
          }
        // Each term relative to the first row's scale, which multiplies
        // the sum: uniform scales then add the plain values (the nested
        // iteration's starts stay the same to the last bit).
        const unsigned int j0 = nearest.front();
        const double c0 = compliance_scale(i, j0), r0 = reaction_scale(i, j0);
        for (const unsigned int j : nearest)
          {
            start.mu[i] += coarse_state.mu[j];
            start.alpha[i] +=
              coarse_state.alpha[j] * (compliance_scale(i, j) / c0);
            start.p[i] += coarse_state.p[j] * (reaction_scale(i, j) / r0);
          }
        const double n = nearest.size();
        start.mu[i] /= n;
        start.alpha[i] *= c0 / n;
        start.p[i] *= r0 / n;
      }
    return start;
  }

  ContactStart
  transfer_contact_state(const EquilibriumSystem &coarse,
                         const ContactIteration  &coarse_state,
                         const EquilibriumSystem &fine,
                         const double             reaction_scale,
                         const double             compliance_scale,
                         const bool               may_measure_scale)
  {
    ContactStart start = transfer_rows_by_position(
      coarse,
      coarse_state,
      fine,
      [&](unsigned int, unsigned int) { return reaction_scale; },
      [&](unsigned int, unsigned int) { return compliance_scale; },
      compliance_scale);
    if (coarse_state.scale_per_level > 0)
      {
        start.tolerance_scale =
          coarse_state.tolerance_scale * coarse_state.scale_per_level;
        start.scale_per_level = coarse_state.scale_per_level;
      }
    else if (may_measure_scale)
      {
        // Measured on this level against the coarser level's trial scale.
        start.tolerance_scale     = coarse_state.tolerance_scale;
        start.measure_trial_scale = true;
      }
    else
      start.tolerance_scale = coarse_state.tolerance_scale * reaction_scale;
    start.smallest_scale_per_level = reaction_scale;
    return start;
  }

  void
  NestedIterationSettings::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Nested iteration");
    prm.declare_entry(
      "Coarse levels",
      "automatic",
      Patterns::Anything(),
      "Solve the contact problem first on the mesh with this many fewer "
      "global refinements, then carry its pressed set, multipliers and "
      "penalties up one level at a time (the answer is the fine mesh's own; "
      "only the number of Newton steps on it drops). 0: off. automatic: on "
      "the condensed path with the consistent augmented Lagrangian (the "
      "Macaulay one takes a number), from Minimum dofs up, as many levels as keep the coarsest "
      "at Coarsest level dofs or more; not for a nonlinear law or a stress "
      "constraint under the augmented Lagrangian (a coarse level would run "
      "the whole material iteration to carry the contact state only), but "
      "for a stress constraint in closed-form projection, whose coarser "
      "levels carry their point strains as well (doc/materials.md). A "
      "number needs as many Global refinements.");
    prm.declare_entry("Minimum dofs",
                      "5000",
                      Patterns::Double(0),
                      "automatic: no nested iteration for scenes with fewer "
                      "displacement dofs (their solves cost less than "
                      "building the coarse meshes). Hertz at 6,338 dofs: "
                      "0.35 s and 2 updates with a coarser level of 1,634, "
                      "0.58 s and 7 updates from the trial.");
    prm.declare_entry("Coarsest level dofs",
                      "1000",
                      Patterns::Double(0),
                      "automatic: the coarsest level keeps at least about "
                      "this many displacement dofs. The coarsest level starts "
                      "from the trial solution and takes the most Newton "
                      "steps; one more, smaller level below it costs little "
                      "and saves most of them (doc/benchmarks.md: 2000 left "
                      "Hertz refinement 7 with a 6,338-dof coarsest level of "
                      "38 Newton steps and the 3D block at 807k with a "
                      "14,553-dof one of 18).");
    prm.declare_entry(
      "Coarse level tolerance",
      "1e-5",
      Patterns::Double(0, 1),
      "Relative tolerance of the augmented Lagrangian on the coarser levels "
      "(Augmented Lagrangian/Relative tolerance if that is looser). A coarser "
      "level only carries its pressed set, multipliers and penalties up; the "
      "finest level converges to its own tolerance, so its answer does not "
      "depend on this. The finest level's first update resets the springs' "
      "multipliers to its own gaps, which differ from the coarser level's by "
      "about 1e-6 of the reactions' scale (Hertz), so converging a coarser "
      "level further buys nothing: Hertz refinement 9 on 2 processes spends "
      "12.8 s instead of 18-20 s on its coarser levels at 1e-5 (the level below "
      "stops after its first solve) and takes the same fine steps as at "
      "1e-10 (doc/benchmarks.md).");
    prm.declare_entry(
      "Carry displacements",
      "true",
      Patterns::Bool(),
      "With CG (Linear solver/Solver), the first solve on each finer level "
      "starts from the coarser level's displacements, prolongated, instead "
      "of zero. The answer is the same (each solve stops at Linear "
      "solver/Tolerance of its right-hand side); Hertz refinement 9 on 2 "
      "processes: the first fine solve takes 77 CG iterations instead of 100 "
      "and the 394,754-dof level 58 instead of 73 (doc/benchmarks.md).");
    prm.leave_subsection();
  }

  void
  NestedIterationSettings::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Nested iteration");
    const std::string levels = prm.get("Coarse levels");
    if (levels == "automatic")
      coarse_levels = -1;
    else
      {
        double value = -1;
        if (!parse_number(levels, value) || value < 0 ||
            value != std::floor(value))
          throw InputError("Nested iteration/Coarse levels must be automatic "
                           "or a non-negative integer, not '" +
                           levels + "'.");
        coarse_levels = static_cast<int>(value);
      }
    minimum_dofs           = prm.get_double("Minimum dofs");
    coarsest_level_dofs    = prm.get_double("Coarsest level dofs");
    coarse_level_tolerance = prm.get_double("Coarse level tolerance");
    carry_displacements    = prm.get_bool("Carry displacements");
    prm.leave_subsection();
  }

  unsigned int
  NestedIterationSettings::levels(const unsigned int global_refinements,
                                  const double       displacement_dofs,
                                  const unsigned int dim,
                                  const bool         applies) const
  {
    if (coarse_levels >= 0)
      return coarse_levels;
    if (!applies || displacement_dofs < minimum_dofs)
      return 0;
    unsigned int levels = 0;
    double       dofs   = displacement_dofs;
    while (levels < global_refinements &&
           dofs / std::pow(2., dim) >= coarsest_level_dofs)
      {
        dofs /= std::pow(2., dim);
        ++levels;
      }
    return levels;
  }
} // namespace hrcontact
