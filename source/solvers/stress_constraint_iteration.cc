#include <hrcontact/core/input.h>
#include <hrcontact/solvers/stress_constraint_iteration.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace hrcontact
{
  using namespace dealii;

  void
  StressConstraintIteration::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Stress constraint iteration");
    prm.declare_entry(
      "Method",
      "automatic",
      Patterns::Selection("automatic|augmented Lagrangian|closed-form "
                          "projection|interior point"),
      "How Material/Admissible stresses is imposed. automatic: the interior "
      "point where it applies (DGQ1 stresses, the default element, a linear "
      "elastic law and a cone with a closed form: no tension, no "
      "compression), else the augmented Lagrangian (also where Constraint "
      "points is set to cell centres or Gauss points). augmented Lagrangian: "
      "the paper's Steps 1-6 with multipliers at the Constraint points "
      "below (any law, e.g. Ramberg-Osgood). closed-form projection: at "
      "every Gauss point of the compliance, each point's stress the "
      "projection of C eps onto the cone in closed form, solved by Newton's "
      "method on the point strains with the consistent tangent and an "
      "exact line search (GaussPointCone; DGQ1 stresses, a linear elastic "
      "law). Sound everywhere the energy is evaluated and exact on "
      "homogeneous states, but where the strains that minimise the energy "
      "are not finite (crack fronts under a point load, an arch near its "
      "hinges) it creeps instead of converging: doc/materials.md measures "
      "both. interior point: the same points and unknowns, the cone's log "
      "barrier driven to zero (BarrierPath): every stress strictly inside "
      "the cone, each barrier value a smooth strictly convex problem.");
    prm.declare_entry(
      "Stress tolerance",
      "automatic",
      Patterns::Anything(),
      "automatic: 1e-6 for the closed-form projection, 1e-4 for the "
      "interior point; or a positive number. closed-form projection: stop "
      "when the stresses of the last Newton model (equilibrated) and the projected stresses of its strains (in "
      "the cone) differ nowhere by more than this times the largest stress. "
      "Near crack fronts and in cracked regions the strains that minimise "
      "the energy need not be finite, so the iteration converges there in "
      "stresses only, linearly (doc/materials.md measures the steps per "
      "tolerance). interior point: the same measure for the last barrier "
      "stage (1e-4 gives the stresses of 1e-6 to six digits there, "
      "doc/materials.md).");
    prm.declare_entry(
      "Residual stiffness",
      "1e-4",
      Patterns::Double(0),
      "closed-form projection: this times the elastic stiffness is added to "
      "the Newton tangent (not to the stresses), so that each step's system "
      "stays solvable where cracks open in every direction. The converged "
      "stresses do not depend on it; larger damps the steps in cracked "
      "regions, smaller conditions the solves worse.");
    prm.declare_entry(
      "Initial penalty",
      "100",
      Patterns::Double(0),
      "The augmented Lagrangian's penalty alpha of Material/Admissible "
      "stresses, in units of the elastic compliance 1/E: where a point is "
      "cracked its compliance grows by alpha. Larger takes fewer multiplier "
      "updates and worse conditioned solves (doc/materials.md measures "
      "it). Grown tenfold when an update does not cut the residual by 4 "
      "(eq. 49).");
    prm.declare_entry("Relative tolerance",
                      "1e-10",
                      Patterns::Double(0),
                      "Stop when the largest change of a multiplier over "
                      "alpha (a stress) is at most this times the largest "
                      "stress.");
    prm.declare_entry("Maximum updates",
                      "50",
                      Patterns::Integer(1),
                      "Multiplier updates before the run stops as not "
                      "converged.");
    prm.declare_entry(
      "Maximum penalty",
      "1e8",
      Patterns::Double(1),
      "The penalty may grow to this times its initial value; beyond, the "
      "load is taken as one no admissible stress field carries (e.g. "
      "tension on a no-tension body) and the run stops.");
    prm.declare_entry(
      "Constraint points",
      "vertices",
      Patterns::Selection("vertices|Gauss points|cell centres"),
      "augmented Lagrangian: where the cone is imposed. vertices: the DGQ1 stress dofs, so the "
      "whole bilinear stress field of each cell is admissible (exact on "
      "homogeneous states; near free edges and crack fronts no finite "
      "fracture strains may exist and the iteration then stalls). Gauss "
      "points: the 2^dim Gauss points, alike. cell centres: one point per "
      "cell, which converges where the others stall but leaves the "
      "bilinear stress modes free: tension can hide in them (a pulled "
      "no-tension bar is carried). doc/materials.md measures all three.");
    prm.leave_subsection();
  }

  void
  StressConstraintIteration::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Stress constraint iteration");
    initial_penalty    = prm.get_double("Initial penalty");
    relative_tolerance = prm.get_double("Relative tolerance");
    maximum_updates    = prm.get_integer("Maximum updates");
    maximum_penalty    = prm.get_double("Maximum penalty");
    constraint_points  = prm.get("Constraint points");
    method             = get_selection<Method>(
      prm,
      "Method",
      {{"automatic", Method::automatic},
                   {"augmented Lagrangian", Method::augmented_lagrangian},
                   {"closed-form projection", Method::closed_form_projection},
                   {"interior point", Method::interior_point}});
    residual_stiffness          = prm.get_double("Residual stiffness");
    const std::string tolerance = prm.get("Stress tolerance");
    if (tolerance == "automatic")
      stress_tolerance = 0;
    else if (!parse_number(tolerance, stress_tolerance) ||
             !(stress_tolerance > 0))
      throw InputError("Stress constraint iteration/Stress tolerance = '" +
                       tolerance + "': give automatic or a positive number.");
    prm.leave_subsection();
    if (!(initial_penalty > 0))
      throw InputError("Stress constraint iteration/Initial penalty must be "
                       "positive.");
    if (!(relative_tolerance > 0))
      throw InputError("Stress constraint iteration/Relative tolerance must "
                       "be positive (0 would never stop).");
  }

  void
  StressConstraintIteration::solve(const Operations &operations,
                                   const double      compliance,
                                   std::ostream     &log)
  {
    residuals.clear();
    penalties.clear();
    inner_steps.clear();
    double alpha = initial_penalty * compliance;
    operations.set_penalty(alpha);
    // Step 1-2: the first inner solve, from the elastic one.
    double eps   = std::max(relative_tolerance, 1e-2);
    auto   inner = operations.solve_material(eps);
    inner_steps.push_back(inner.first);
    FieldVector stress;
    while (true)
      {
        operations.stresses(stress);
        const double scale = std::max(stress.linfty_norm(), 1e-300);
        // Step 4 (the violation before the multipliers move).
        const double violation = operations.violation(stress);
        const double residual  = operations.update_multipliers(stress) / scale;
        residuals.push_back(residual);
        penalties.push_back(alpha);
        log << "    constraint update " << std::setw(3) << residuals.size()
            << ": material steps " << std::setw(2) << inner_steps.back()
            << ", residual " << std::scientific << std::setprecision(3)
            << residual << ", largest violation " << violation / scale
            << ", alpha E " << alpha / compliance << std::defaultfloat
            << std::setprecision(6) << std::endl;
        if (!std::isfinite(residual))
          throw NotConvergedError(
            "Stress constraint iteration: non-finite stresses at update " +
            std::to_string(residuals.size()) + ".");
        // Step 6.
        if (residual <= relative_tolerance &&
            inner.second <= relative_tolerance)
          return;
        if (residuals.size() >= maximum_updates)
          {
            std::ostringstream s;
            s << "Stress constraint iteration: no convergence in "
              << maximum_updates << " multiplier updates (residual "
              << std::setprecision(3) << residual << " of the largest stress, "
              << "largest violation " << violation / scale
              << "). If the violation does not fall, the load needs stresses "
                 "the material cannot carry; else raise Stress constraint "
                 "iteration/Maximum updates.";
            throw NotConvergedError(s.str());
          }
        // Step 5 (eq. 49).
        const unsigned int n = residuals.size();
        if (n >= 2 && residual > 0.25 * residuals[n - 2])
          {
            alpha *= 10;
            if (alpha > maximum_penalty * initial_penalty * compliance)
              {
                std::ostringstream s;
                s << "Material/Admissible stresses: no admissible stress "
                     "field carries this load: after "
                  << n << " multiplier updates the penalty passed "
                  << "Stress constraint iteration/Maximum penalty and the "
                  << "stresses still leave the cone by " << std::setprecision(3)
                  << violation / scale
                  << " of the largest stress (e.g. tension that only the "
                     "material's tensile strength could carry).";
                throw NotConvergedError(s.str());
              }
            operations.set_penalty(alpha);
          }
        // Step 2: the inner tolerance follows the residual.
        eps = std::max(relative_tolerance, std::min(eps, residual * residual));
        operations.linearise_at(stress);
        inner = operations.solve_material(eps);
        inner_steps.push_back(inner.first);
      }
  }
} // namespace hrcontact
