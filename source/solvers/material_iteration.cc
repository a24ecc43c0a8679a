#include <hrcontact/core/input.h>
#include <hrcontact/solvers/material_iteration.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace hrcontact
{
  using namespace dealii;

  void
  MaterialIteration::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material iteration");
    prm.declare_entry(
      "Relative tolerance",
      "1e-10",
      Patterns::Double(0),
      "A nonlinear material law (Material/Model) is solved by Newton's "
      "method on its complementary energy, the cell compliances refreshed at "
      "the last stresses each step. It stops when the largest change of a "
      "stress dof is at most this times the largest stress (near the answer "
      "the change falls quadratically: 1e-10 costs one step more than "
      "1e-5). Not used by a linear law.");
    prm.declare_entry("Maximum steps",
                      "100",
                      Patterns::Integer(1),
                      "Newton steps of the material iteration before the run "
                      "stops as not converged (each step is one linear "
                      "solve and one refresh of the cell compliances).");
    prm.leave_subsection();
  }

  void
  MaterialIteration::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material iteration");
    relative_tolerance = prm.get_double("Relative tolerance");
    maximum_steps      = prm.get_integer("Maximum steps");
    prm.leave_subsection();
    if (!(relative_tolerance > 0))
      throw InputError("Material iteration/Relative tolerance must be "
                       "positive (0 would never stop).");
  }

  bool
  MaterialIteration::at_roundoff(const std::vector<double> &changes,
                                 const double               ceiling)
  {
    const unsigned int n = changes.size();
    return n >= 3 && changes[n - 1] <= ceiling && changes[n - 2] <= ceiling &&
           changes[n - 3] <= ceiling && changes[n - 1] > 0.5 * changes[n - 2] &&
           changes[n - 2] > 0.5 * changes[n - 3];
  }

  double
  MaterialIteration::relative_change(const FieldVector &previous,
                                     const FieldVector &current)
  {
    FieldVector difference;
    difference.reinit(current, true);
    difference.copy_locally_owned_data_from(current);
    difference.add(-1., previous);
    const double scale = current.linfty_norm();
    return (scale > 0) ? difference.linfty_norm() / scale :
                         difference.linfty_norm();
  }

  void
  MaterialIteration::line_search(const Operations  &operations,
                                 const FieldVector &previous,
                                 FieldVector       &current,
                                 std::ostream      &log)
  {
    // The exact line search along delta = current - previous.
    FieldVector delta;
    delta.reinit(current, true);
    delta.copy_locally_owned_data_from(current);
    delta.add(-1., previous);
    double       curvature = 0;
    const double slope_0 =
      operations.energy_slope(previous, delta, 0., &curvature);
    const auto derivative = [&](const double theta) {
      return operations.energy_slope(previous, delta, theta, nullptr) -
             slope_0 - curvature;
    };
    double       a = 0, fa = -curvature, b = 1, fb = derivative(1.);
    double       theta = 1;
    const double stop  = 1e-3 * std::abs(curvature);
    if (fb > stop)
      {
        // Regula falsi (Illinois) on the increasing derivative.
        int side = 0;
        for (unsigned int k = 0; k < 30; ++k)
          {
            theta           = (a * fb - b * fa) / (fb - fa);
            const double ft = derivative(theta);
            if (std::abs(ft) <= stop)
              break;
            if (ft > 0)
              {
                b = theta, fb = ft;
                if (side == -1)
                  fa /= 2;
                side = -1;
              }
            else
              {
                a = theta, fa = ft;
                if (side == 1)
                  fb /= 2;
                side = 1;
              }
          }
        log << "    line search: step " << std::setprecision(3) << theta
            << std::setprecision(6) << std::endl;
        current.sadd(theta, 1 - theta, previous);
        current.update_ghost_values();
      }
  }

  void
  MaterialIteration::solve(const Operations &operations, std::ostream &log)
  {
    changes.clear();
    steps            = 0;
    roundoff_limited = false;
    FieldVector previous, current;
    bool        has_previous = operations.start != nullptr;
    if (has_previous)
      {
        previous.reinit(*operations.start, true);
        previous.copy_locally_owned_data_from(*operations.start);
      }
    operations.solve();
    ++steps;
    operations.stresses(current);
    while (true)
      {
        // A sum over every process: a NaN anywhere stops them all.
        if (!std::isfinite(current.l2_norm()))
          throw NotConvergedError(
            "Material iteration: step " + std::to_string(steps) +
            " left non-finite stresses (the law's compliance is singular "
            "or the load exceeds what the material can carry).");
        if (has_previous)
          {
            const double change = operations.change ?
                                    operations.change(previous, current) :
                                    relative_change(previous, current);
            changes.push_back(change);
            log << "  material step " << steps << ": " << state_name
                << " change " << std::scientific << std::setprecision(2)
                << change << std::defaultfloat << std::setprecision(6)
                << std::endl;
            if (change <= relative_tolerance)
              return;
            // Round-off of the path (the dense null-space reduction with stiff
            // contact rows: about 5e-10 on lift-off) can sit above a tight
            // tolerance. Three changes in a row that are tiny and no longer
            // fall are that floor, not a slow iteration: accept them, and say
            // so.
            if (at_roundoff(changes, roundoff_ceiling))
              {
                roundoff_limited = true;
                log << "  material iteration: the " << state_name
                    << " change stagnates at " << std::scientific
                    << std::setprecision(2) << change << std::defaultfloat
                    << std::setprecision(6) << ", above the tolerance "
                    << relative_tolerance
                    << ": the round-off of the linear solves; accepted"
                    << std::endl;
                return;
              }
          }
        if (steps >= maximum_steps)
          {
            std::ostringstream s;
            s << "Material iteration: no convergence in " << maximum_steps
              << " Newton steps (the last " << state_name << " change "
              << std::setprecision(3) << (changes.empty() ? 0. : changes.back())
              << " of the largest " << state_name << ", tolerance "
              << relative_tolerance
              << "). Raise Material iteration/Maximum steps, or check that "
                 "the load is one the material can carry.";
            throw NotConvergedError(s.str());
          }
        if (has_previous && operations.energy_slope)
          line_search(operations, previous, current, log);
        operations.linearise_at(current);
        has_previous = true;
        previous.reinit(current, true);
        previous.copy_locally_owned_data_from(current);
        operations.solve();
        ++steps;
        operations.stresses(current);
      }
  }
} // namespace hrcontact
