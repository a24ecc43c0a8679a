#include <hrcontact/core/input.h>
#include <hrcontact/solvers/contact_solve.h>
#include <hrcontact/solvers/row_relinearisation.h>

#include <numeric>
#include <optional>
#include <set>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  ContactSolve<dim>::ContactSolve(AugmentedLagrangianSolver &contact_solver,
                                  MaterialLoop<dim>         &material_loop)
    : contact_solver(contact_solver)
    , material_loop(material_loop)
  {}

  template <int dim>
  void
  ContactSolve<dim>::run_without_contact(EquilibriumSystem &system,
                                         NewtonStepPath    &path,
                                         Results<dim>      &r,
                                         std::ostream      &log)
  {
    // Without contact every rigid motion must be held by a support: a
    // sparse direct solver may return a vector for the singular system
    // without a word (the null-space reduction stops earlier on its
    // rank deficiency).
    const unsigned int free = rigid_motions_held_only_by_contact(system);
    if (free > 0)
      throw InputError(
        "Supports: " + std::to_string(free) +
        " rigid-body motion(s) of the body are held by no support (the "
        "body floats). Prescribe displacements or normal constraints that "
        "stop every translation and rotation.");
    const unsigned int  nq = system.contact_rows.size();
    std::vector<double> p;
    auto                linear_solve = [&]() {
      path.solve(std::vector<bool>(nq, false),
                 std::vector<double>(nq, 0.),
                 std::vector<double>(nq, 1.),
                 p);
    };
    material_loop.run(system, path, linear_solve, r, log);
    r.reactions.contact_w = system.contact_row_values();
  }

  template <int dim>
  unsigned int
  ContactSolve<dim>::find_bodies_held_only_by_contact(
    const EquilibriumSystem &system)
  {
    const auto free = rigid_motions_held_only_by_contact_by_body(system);
    auto      &held = contact_solver.held_only_by_contact;
    held.clear();
    std::vector<int> index(free.size(), -1);
    for (unsigned int b = 0; b < free.size(); ++b)
      if (free[b] > 0)
        {
          index[b] = held.size();
          held.push_back(
            {free.size() > 1 ? "body " + std::to_string(b + 1) : "",
             free[b],
             {}});
        }
    auto body_of = [&system](const unsigned int node) {
      const auto it = system.node_body.find(node);
      return it == system.node_body.end() ? 0u : it->second;
    };
    for (unsigned int i = 0; i < system.contact_rows.size(); ++i)
      {
        std::set<unsigned int> bodies;
        for (const auto &[dof, c] :
             system.rows[system.contact_rows[i]].combination)
          bodies.insert(body_of(system.dof_node(dof)));
        for (const unsigned int b : bodies)
          if (b < index.size() && index[b] >= 0)
            held[index[b]].rows.push_back(i);
      }
    return std::accumulate(free.begin(), free.end(), 0u);
  }

  template <int dim>
  void
  ContactSolve<dim>::run(EquilibriumSystem &system,
                         NewtonStepPath    &path,
                         Results<dim>      &r,
                         TimerOutput       &timer,
                         std::ostream      &log)
  {
    r.contact = nullptr;
    r.reactions.contact_w.assign(system.contact_rows.size(), 0.);
    if (!r.has_contact)
      {
        TimerOutput::Scope t(timer, "solve");
        run_without_contact(system, path, r, log);
        return;
      }
    TimerOutput::Scope t(timer, "augmented Lagrangian");
    // The largest nodal load (distributed: the largest on any process).
    const double load_scale = system.load.linfty_norm();
    contact_solver.set_nodal_compliance(
      r.scene.nodal_compliance(r.triangulation()));
    const auto floating = rigid_motions_no_row_holds(system);
    for (unsigned int b = 0; b < floating.size(); ++b)
      if (!floating[b].empty())
        {
          const auto &motions = floating[b];
          std::string names   = floating.size() > 1 ?
                                  "body " + std::to_string(b + 1) + "'s " :
                                  "the body's ";
          for (unsigned int k = 0; k < motions.size(); ++k)
            names += (k == 0                  ? "" :
                      k + 1 == motions.size() ? " and " :
                                                ", ") +
                     motions[k];
          throw InputError(
            "Supports: nothing holds " + names +
            " (no support, and no contact whatever touches: a frictionless "
            "contact holds only its normal), so the body floats. Prescribe "
            "displacements or point supports that stop " +
            (motions.size() == 1 ? "it." : "them."));
        }
    r.free_rigid_motions = find_bodies_held_only_by_contact(system);
    // Kinds whose rows follow the configuration (curved obstacles).
    std::vector<std::unique_ptr<RowRelinearisation>> relinearisations;
    for (const auto &source : r.scene.constraints)
      if (auto relinearisation = source->relinearisation(system))
        relinearisations.push_back(std::move(relinearisation));
    AssertThrow(relinearisations.size() <= 1,
                ExcMessage("one kind of constraint rows that follow the "
                           "configuration per scene"));
    // A nonlinear law or a stress constraint: each material Newton step is
    // a whole augmented Lagrangian solve at the compliances and strain terms
    // of the last stresses, started (consistent and Macaulay AL) from the
    // previous step's multipliers, compliances and reactions, so that the
    // later steps take one or two updates. When the stresses stop changing,
    // the law and the contact conditions hold together.
    bool first = true, repeat = false;
    // The start of the last solve, for a material step taken back.
    std::optional<ContactStart> last_start;
    auto                        contact_solve = [&]() {
      if (repeat && last_start)
        contact_solver.start_from(*last_start);
      else if (!first && contact_solver.carries_state())
        contact_solver.start_from_result("the last material step's state");
      last_start = contact_solver.pending_start();
      first = repeat = false;
      if (relinearisations.empty())
        contact_solver.solve(system, path, load_scale, log);
      else
        contact_solver.solve(
          system, path, load_scale, *relinearisations.front(), log);
      if (!contact_solver.result().converged() &&
          MaterialLoop<dim>::iterates(r.scene))
        throw NotConvergedError(
          "Material iteration, step " +
          std::to_string(material_loop.material_iteration.n_steps() + 1) +
          ": the contact iteration did not converge: " +
          contact_solver.outcome_message(r.free_rigid_motions));
    };
    material_loop.take_back_last_solve = [&]() { repeat = true; };
    material_loop.run(system, path, contact_solve, r, log);
    material_loop.take_back_last_solve = nullptr;
    r.contact                          = &contact_solver.result();
    // After the last multiplier update mu = w_n - g (pressed: mu = 0).
    r.reactions.contact_w = system.contact_row_values();
    for (unsigned int k = 0; k < r.reactions.contact_w.size(); ++k)
      r.reactions.contact_w[k] += r.contact->opening[k];
  }

  template class ContactSolve<2>;
  template class ContactSolve<3>;
} // namespace hrcontact
