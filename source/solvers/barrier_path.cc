#include <hrcontact/core/input.h>
#include <hrcontact/solvers/barrier_path.h>

#include <algorithm>
#include <iomanip>

namespace hrcontact
{
  using namespace dealii;

  void
  BarrierPath::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Stress constraint iteration");
    prm.declare_entry(
      "Initial barrier",
      "1e-2",
      Patterns::Double(0),
      "interior point: the first stage's barrier tau, in units of s^2 / E "
      "(s the largest stress of the elastic step). Larger starts further "
      "inside the cone.");
    prm.declare_entry(
      "Carried initial barrier",
      "1e-4",
      Patterns::Double(0),
      "interior point, Nested iteration: a finer level's first step is one "
      "closed-form projection step from the coarser level's answer, then "
      "the last stage. Where that step misses the law by more than 100 "
      "times the largest stress (cracks that moved between the meshes), "
      "the level starts over from the coarser level's strains at this "
      "barrier (units as Initial barrier) and follows the path from there "
      "(doc/materials.md).");
    prm.declare_entry(
      "Barrier reduction",
      "0.1",
      Patterns::Double(0, 1),
      "interior point: tau is multiplied by this after each stage. Smaller "
      "takes fewer stages and more Newton steps per stage.");
    prm.declare_entry(
      "Final barrier",
      "1e-8",
      Patterns::Double(0),
      "interior point: the last stage's tau (units as Initial barrier), "
      "solved to Stress tolerance. The energy of the answer is within "
      "dim tau per unit volume of the constrained one (the duality gap): "
      "doc/materials.md measures the stress errors per value.");
    prm.declare_entry(
      "Tension allowance",
      "1e-6",
      Patterns::Double(0),
      "interior point: the principal stress of the wrong sign the barrier "
      "allows, in units of s. The Gauss-point discretisation of a cracked "
      "region often has no stress strictly inside the cone (then no finite "
      "strains minimise the barrier energy); allowing this much tension "
      "gives it one. The stresses move by about the square root of it "
      "(doc/materials.md).");
    prm.declare_entry(
      "Barrier residual stiffness",
      "1e-8",
      Patterns::Double(0),
      "interior point: this times the elastic stiffness is added to the "
      "Newton tangent (not to the stresses), so that the systems stay "
      "solvable where cracks have opened far (the barrier's own stiffness "
      "there, tau / mu^2, falls below round-off). Larger converges "
      "linearly, so a Stress tolerance stops it further from the answer.");
    prm.declare_entry(
      "Stage tolerance",
      "1e-1",
      Patterns::Double(0),
      "interior point: the model stress error (relative to the largest "
      "stress) at which a stage before the last one stops.");
    prm.leave_subsection();
  }

  void
  BarrierPath::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Stress constraint iteration");
    initial_barrier    = prm.get_double("Initial barrier");
    carried_barrier    = prm.get_double("Carried initial barrier");
    reduction          = prm.get_double("Barrier reduction");
    final_barrier      = prm.get_double("Final barrier");
    stage_tolerance    = prm.get_double("Stage tolerance");
    allowance          = prm.get_double("Tension allowance");
    residual_stiffness = prm.get_double("Barrier residual stiffness");
    prm.leave_subsection();
    if (!(final_barrier > 0) || !(initial_barrier >= final_barrier))
      throw InputError("Stress constraint iteration: Final barrier must be "
                       "positive and at most Initial barrier.");
    if (!(reduction > 0 && reduction < 1))
      throw InputError("Stress constraint iteration/Barrier reduction must "
                       "lie strictly between 0 and 1.");
  }

  void
  BarrierPath::run(const std::function<void(double)>               &set_barrier,
                   const std::function<unsigned int(const double)> &solve_stage,
                   const double  stress_tolerance,
                   const double  first,
                   std::ostream &log)
  {
    double t = std::max(final_barrier, first);
    while (true)
      {
        const bool last = t <= final_barrier * (1 + 1e-12);
        set_barrier(t);
        const double tolerance =
          last ? stress_tolerance : std::max(stress_tolerance, stage_tolerance);
        const unsigned int steps = solve_stage(tolerance);
        log << "  barrier " << std::scientific << std::setprecision(1) << t
            << std::defaultfloat << std::setprecision(6) << ": " << steps
            << " Newton steps" << std::endl;
        if (last)
          return;
        t = std::max(final_barrier, t * reduction);
      }
  }
} // namespace hrcontact
