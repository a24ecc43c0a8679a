#ifndef hrcontact_material_loop_h
#define hrcontact_material_loop_h

#include <deal.II/base/parameter_handler.h>

#include <hrcontact/core/input.h>
#include <hrcontact/core/results.h>
#include <hrcontact/discretisation/gauss_point_cone.h>
#include <hrcontact/discretisation/stress_constraint_field.h>
#include <hrcontact/solvers/barrier_path.h>
#include <hrcontact/solvers/material_iteration.h>
#include <hrcontact/solvers/newton_step_path.h>
#include <hrcontact/solvers/stress_constraint_iteration.h>

#include <functional>
#include <memory>
#include <ostream>

namespace hrcontact
{
  /**
   * The material loop of a run: one linear or contact solve at the current
   * linearisation (`solve_once`) run as the scene's material needs. Once
   * for a linear law; under the material Newton iteration for a nonlinear
   * one (MaterialIteration: F_c and d_c refreshed at the last stresses);
   * under the stress constraint's augmented Lagrangian, each inner solve a
   * material iteration, for Material/Admissible stresses
   * (StressConstraintIteration, the multipliers in StressConstraintField).
   */
  template <int dim>
  class MaterialLoop
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /** Whether the scene needs more than one solve (a nonlinear law or a
     * stress constraint). */
    static bool
    iterates(const Scene<dim> &scene);

    /** Whether the scene's stress constraint is imposed in closed form at
     * the Gauss points: its state, the point strains, is then carried from
     * a coarser level (NestedLevelRunner). */
    bool
    projects_constraint(const Scene<dim>  &scene,
                        const std::string &stress_element) const;

    /**
     * How the scene's stress constraint is imposed: Method, automatic
     * resolved to the interior point where it applies (the Stress element
     * is DGQ1, every body's law linear elastic, the cone has a closed form,
     * Constraint points left at its default) and to the augmented
     * Lagrangian elsewhere.
     */
    StressConstraintIteration::Method
    method(const Scene<dim> &scene, const std::string &stress_element) const;

    /** Run solve_once as above; the steps, changes and the constraint's
     * state go to results. */
    void
    run(EquilibriumSystem           &system,
        NewtonStepPath              &path,
        const std::function<void()> &solve_once,
        Results<dim>                &results,
        std::ostream                &log);

    /** The material Newton iteration (its settings and its current step:
     * the displacement-code comparison stops where it stops). */
    MaterialIteration material_iteration;

    /** Set by a caller whose solves carry a state (the contact iteration):
     * the next solve starts as the last one did, which is taken back (a
     * rejected carried start, run_barrier_path). */
    std::function<void()> take_back_last_solve;

  private:
    /** One material Newton iteration; its steps and changes added to
     * results (several per run under a stress constraint). */
    void
    solve_material_iteration(const MaterialIteration::Operations &operations,
                             Results<dim>                        &results,
                             std::ostream                        &log);

    /** Under the stress constraint's augmented Lagrangian. */
    void
    run_constrained(EquilibriumSystem            &system,
                    NewtonStepPath               &path,
                    MaterialIteration::Operations operations,
                    Results<dim>                 &results,
                    std::ostream                 &log);

    /**
     * Under the stress constraint imposed in closed form at the Gauss
     * points (GaussPointCone): the material iteration on the point strains,
     * each step one solve with the consistent tangent and an exact line
     * search; the fracture strains go to a Gauss-point
     * StressConstraintField for output.
     */
    void
    run_projected(EquilibriumSystem            &system,
                  NewtonStepPath               &path,
                  MaterialIteration::Operations operations,
                  Results<dim>                 &results,
                  std::ostream                 &log);

    /**
     * run_projected's iteration for Method = interior point: the elastic
     * step (or one from a coarser level's strains, @p carried) sets the
     * scale @p elastic_stress (its largest stress @p first_stress; the
     * coarser level's if a carried start is rejected), then BarrierPath's
     * stages, each Newton's
     * method from the last one's strains, the last one to
     * @p stress_tolerance. A stage that fails after the strains grew
     * (@p growth, the largest over the elastic step's) beyond 1e5 is
     * reported as a load no admissible field carries.
     */
    void
    run_barrier_path(const MaterialIteration::Operations &operations,
                     FieldVector                         &state,
                     double                              &elastic_stress,
                     const double                        &first_stress,
                     double                              &growth,
                     const double                         stress_tolerance,
                     const bool                           carried,
                     Results<dim>                        &results,
                     std::ostream                        &log);

    /** run_projected's answer: the fracture strains of the point
     * @p strains into a Gauss-point StressConstraintField (the output's),
     * the cracked fraction and the largest opening into @p results. */
    void
    store_fracture_strains(const FieldVector &strains,
                           Results<dim>      &results,
                           std::ostream      &log);

    /** The point strains and stresses of the last solve, the model built
     * at @p state: from the displacements where the path solves for them
     * (GaussPointCone::strains_and_stresses), else from its stresses. */
    void
    step_strains(const NewtonStepPath &path,
                 const FieldVector    &state,
                 const Results<dim>   &results,
                 FieldVector          &stress,
                 FieldVector          &strain) const;

    /** The singular-stiffness error @p singular, with what a cracked
     * region means for it: held only by the residual stiffness. */
    std::string
    cracked_region_hint(const std::string &singular,
                        const Scene<dim>  &scene,
                        const std::string &stress_element) const;

    /** The error that names a load no admissible stress field carries,
     * the strains having grown @p growth times the elastic ones. */
    static NotConvergedError
    no_admissible_field(const Scene<dim>  &scene,
                        const double       growth,
                        const std::string &when);

    StressConstraintIteration                   constraint_iteration;
    BarrierPath                                 barrier_path;
    std::unique_ptr<StressConstraintField<dim>> constraint_field;
    std::unique_ptr<GaussPointCone<dim>>        cone;
  };
} // namespace hrcontact

#endif
