// A short Hertz adaptive sequence against uniform refinement at equal dofs
// (issue 51). From 4 global refinements, 5 cycles of the contact residual
// estimator with Doerfler marking (fraction 0.5) end with fewer dofs than
// the uniform 6 refinements, an end of the contact zone closer to the
// converged one, and both the zone end and the peak pressure within the
// issue's targets (0.2 % and 0.05 %): the uniform mesh needs 7 refinements
// (99,074 dofs) for that. The peak holds only because the default Contact
// zone depth refines the body beneath the pressed zone; without it the peak
// is 0.11 % off. The converged values are the uniform 10 refinements'
// (6,297,602 dofs, doc/adaptivity.md).

#include <deal.II/base/mpi.h>

#include <hrcontact/adaptivity/adaptive_run.h>

#include "tests.h"

using namespace hrcontact_tests;

// The uniform 10 refinements (2 processes, 2026-11-28).
const double converged_zone_end = 0.00500503129,
             converged_peak     = 1.150993803e10;

hrcontact::Summary
hertz(const std::string &extra)
{
  dealii::ParameterHandler prm;
  hrcontact::declare_all_parameters(prm);
  prm.parse_input_from_string(
    condensed_scene("hertz.prm", extra) +
    "subsection Postprocess\n  set Pressure plot = false\nend\n"
    "subsection Output\n  set Print timing = false\nend\n");
  std::ostringstream quiet;
  hrcontact::Summary summary;
  hrcontact::run_adaptive_cycles<2>(prm, quiet, MPI_COMM_SELF, &summary);
  return summary;
}

struct Errors
{
  unsigned int dofs;
  double       zone_end, peak;
};

Errors
errors(const hrcontact::Summary &s)
{
  return {static_cast<unsigned int>(s.get_double("displacement_dofs")),
          std::abs(s.get_double("contact_zone_x_max") / converged_zone_end - 1),
          std::abs(s.get_double("peak_pressure") / converged_peak - 1)};
}

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const Errors                             uniform =
    errors(hertz("subsection Geometry\n  set Global refinements = 6\nend\n"));
  const Errors adaptive =
    errors(hertz("subsection Mesh refinement\n  set Adaptive cycles = 5\n"
                 "  set Estimator = contact residual\n"
                 "  set Marking = fixed fraction\n"
                 "  set Refine fraction = 0.5\nend\n"));
  const Errors without_zone =
    errors(hertz("subsection Mesh refinement\n  set Adaptive cycles = 5\n"
                 "  set Estimator = contact residual\n"
                 "  set Marking = fixed fraction\n"
                 "  set Refine fraction = 0.5\n"
                 "  set Contact zone depth = 0\nend\n"));
  std::cout << std::setprecision(3) << "uniform 6 refinements: " << uniform.dofs
            << " dofs, zone end error " << uniform.zone_end << ", peak error "
            << uniform.peak << "\n"
            << "adaptive, 5 cycles: " << adaptive.dofs
            << " dofs, zone end error " << adaptive.zone_end << ", peak error "
            << adaptive.peak << "\n"
            << "adaptive with fewer dofs: "
            << (adaptive.dofs < uniform.dofs ? "yes" : "NO")
            << "\nits zone end error below the uniform one's: "
            << (adaptive.zone_end < uniform.zone_end ? "yes" : "NO")
            << "\nand within the 0.2 % target: "
            << check(adaptive.zone_end, 2e-3)
            << "\nthe peak within the 0.05 % target: "
            << check(adaptive.peak, 5e-4) << "\n"
            << "Contact zone depth = 0: " << without_zone.dofs
            << " dofs, peak error " << without_zone.peak
            << ", above the target: "
            << (without_zone.peak > 5e-4 ? "yes" : "NO") << std::endl;
}
