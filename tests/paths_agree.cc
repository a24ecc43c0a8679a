// The two exact Newton-step paths (doc/method.md): the paper's
// null-space reduction and the condensed sparse system must give the same
// augmented Lagrangian history: the same alpha sequence, the same released
// set at every multiplier update, and p equal to 1e-9 relative (lift-off and
// Hertz at a small size); and without contact the same stresses and
// displacements (cantilever).

#include "tests.h"

template <int dim>
std::unique_ptr<hrcontact::HRProblem<dim>>
run(const std::string &scene, const std::string &extra, const std::string &path)
{
  return hrcontact_tests::solve_from_text<dim>(
    hrcontact_tests::read_file(std::string(SOURCE_DIR) + "/../parameters/" +
                               scene) +
    extra + "subsection Equilibrium reduction\n  set Path = " + path +
    "\nend\nsubsection Output\n  set Write solution = false\n"
    "  set Output directory = results\nend\n");
}

void
compare_contact(const std::string &scene, const std::string &extra)
{
  const auto  a  = run<2>(scene, extra, "null-space");
  const auto  b  = run<2>(scene, extra, "condensed");
  const auto &ha = (*a->results().contact), &hb = (*b->results().contact);
  const auto  c = hrcontact_tests::compare_histories(ha, hb);
  std::cout
    << scene << ": " << ha.history.size() << " and " << hb.history.size()
    << " multiplier updates, " << ha.total_newton_steps << " and "
    << hb.total_newton_steps
    << " Newton steps\n  same alpha sequence: " << (c.same_alpha ? "yes" : "NO")
    << "\n  same released set at every update: " << (c.same_sets ? "yes" : "NO")
    << "\n  max |p_null - p_condensed| / max |p| over all updates < 1e-9: "
    << hrcontact_tests::check(c.p_difference, 1e-9) << std::endl;
  // The condensed path keeps the blocks of the contact and support cells
  // only (a lean system); the null-space path keeps them all.
  auto stored = [](const hrcontact::EquilibriumSystem &sys) {
    unsigned int n = 0;
    for (unsigned int cell = 0; cell < sys.n_cells(); ++cell)
      n += sys.is_stored(cell);
    return n;
  };
  std::cout << "  cells with stored blocks: " << stored(a->results().system)
            << " and " << stored(b->results().system) << " of "
            << a->results().system.n_cells() << std::endl;
}

int
main()
{
  compare_contact("lift-off.prm", "");
  compare_contact("hertz.prm",
                  "subsection Geometry\n  set Global refinements = 3\nend\n");
  const auto             a  = run<2>("cantilever.prm", "", "null-space");
  const auto             b  = run<2>("cantilever.prm", "", "condensed");
  const auto            &sa = a->results().stress; // complete: a serial run
  const auto            &ua = a->results().displacement;
  dealii::Vector<double> ds(sa.begin(), sa.end()), du(ua.begin(), ua.end());
  const auto            &sb = b->results().stress;
  ds -= dealii::Vector<double>(sb.begin(), sb.end());
  const auto &ub = b->results().displacement;
  du -= dealii::Vector<double>(ub.begin(), ub.end());
  std::cout << "cantilever.prm (no contact):\n  stresses agree to 1e-10: "
            << hrcontact_tests::check(ds.linfty_norm() /
                                        a->results().stress.linfty_norm(),
                                      1e-10)
            << "\n  displacements agree to 1e-10: "
            << hrcontact_tests::check(du.linfty_norm() /
                                        a->results().displacement.linfty_norm(),
                                      1e-10)
            << std::endl;
}
