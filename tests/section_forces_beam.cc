// Section forces N, V, M against beam statics on a straight beam: the
// cantilever scene (end shear P, Timoshenko-Goodier clamp) with an axial
// force N0 and a moment M0 added on the free end, so that N = N0,
// V = P and M = P (L - x) + M0 (M > 0 stretches the lower, "inner" fibre:
// the section's `across` direction points up).
// - At the middle of an element column N and V are exact: a Q1 ramp test
//   function across the column turns the discrete equilibrium C s = f into
//   "column average of N (resp. V) = end load", and N, V are linear in x
//   within a column of rectangles. Checked to 1e-10.
// - M carries the Q1 parasitic shear: checked against statics to a bound.
// - Sections off the column middles and a section through a mesh line
//   (counted once, not twice) keep N within the same bounds.

#include <hrcontact/postprocess/section_forces.h>

#include "tests.h"

int
main()
{
  const double L = 10, D = 1, I = D * D * D / 12, P = -1e6;
  const double N0 = 3e6, M0 = 2e6;
  std::string  text =
    hrcontact_tests::read_file(std::string(SOURCE_DIR) +
                               "/../parameters/cantilever.prm") +
    // DGQ1: the moment error's second order below is that element's.
    "subsection Finite elements\n  set Stress element = DGQ1\nend\n";
  std::ostringstream extra;
  extra << std::setprecision(17)
        << "subsection Loads\n  set Tractions = 1: " << N0 / D << " - "
        << M0 / I << "*y; P/(2*I)*(D^2/4 - y^2)\nend\n";
  auto stations_at = [](const std::vector<double> &xs) {
    std::vector<hrcontact::SectionStation> stations;
    for (const double x : xs)
      {
        hrcontact::SectionStation s;
        s.point  = dealii::Point<2>(x, 0.1); // anywhere on the section
        s.across = dealii::Tensor<1, 2>({0., 1.});
        s.s      = x;
        stations.push_back(s);
      }
    return stations;
  };
  auto statics_M = [&](const double x) { return P * (L - x) + M0; };

  std::unique_ptr<hrcontact::HRProblem<2>> problem;
  double                                   previous_err_M = 0;
  for (unsigned int r = 2; r <= 3; ++r)
    {
      problem = hrcontact_tests::solve_from_text<2>(
        text + extra.str() +
        "subsection Geometry\n  set Global refinements = " + std::to_string(r) +
        "\nend\n");
      const unsigned int  columns = 10 << r;
      const double        h       = L / columns;
      std::vector<double> middles;
      for (unsigned int k = 0; k < columns; ++k)
        middles.push_back((k + 0.5) * h);
      const auto forces =
        hrcontact::compute_section_forces(problem->results().spaces,
                                          problem->results().stress,
                                          problem->results().displacement,
                                          stations_at(middles));
      double err_N = 0, err_V = 0, err_M = 0, err_thickness = 0;
      for (const auto &f : forces)
        {
          err_N = std::max(err_N, std::abs(f.N - N0) / std::abs(N0));
          err_V = std::max(err_V, std::abs(f.V - P) / std::abs(P));
          err_M =
            std::max(err_M, std::abs(f.M - statics_M(f.station.s)) / (-P * L));
          err_thickness = std::max(err_thickness, std::abs(f.thickness - D));
        }
      std::cout << columns << " x " << (1 << r) << " cells, sections at the "
                << forces.size() << " column middles\n"
                << "  thickness D:         "
                << hrcontact_tests::check(err_thickness, 1e-12) << "\n"
                << "  N = N0 to 1e-10:     "
                << hrcontact_tests::check(err_N, 1e-10) << "\n"
                << "  V = P to 1e-10:      "
                << hrcontact_tests::check(err_V, 1e-10) << "\n"
                << "  max |M - P (L - x) - M0| / |P L| = "
                << std::setprecision(2) << std::scientific << err_M
                << std::defaultfloat << "\n";
      if (r == 3)
        std::cout << "  M error falls by more than 3 under refinement: "
                  << hrcontact_tests::check(err_M, previous_err_M / 3) << "\n";
      previous_err_M = err_M;

      // Off the middles, and exactly on a mesh line (two cells share it).
      const auto others = hrcontact::compute_section_forces(
        problem->results().spaces,
        problem->results().stress,
        problem->results().displacement,
        stations_at({0.3 * h, 13.7 * h, 20 * h, L - 0.1 * h}));
      double err_N_off = 0, err_M_off = 0;
      for (const auto &f : others)
        {
          err_N_off = std::max(err_N_off, std::abs(f.N - N0) / std::abs(N0));
          err_M_off =
            std::max(err_M_off,
                     std::abs(f.M - statics_M(f.station.s)) / (-P * L));
        }
      std::cout << "  off the middles (one on a mesh line): max N error "
                << std::setprecision(2) << std::scientific << err_N_off
                << ", max M error " << err_M_off << std::defaultfloat << "\n";
      std::cout << "  N within 3e-2, M within 3e-2: "
                << hrcontact_tests::check(std::max(err_N_off, err_M_off), 3e-2)
                << std::endl;
    }

  // A station outside the body is an input error, not a crash.
  try
    {
      hrcontact::compute_section_forces(problem->results().spaces,
                                        problem->results().stress,
                                        problem->results().displacement,
                                        stations_at({L + 1}));
      std::cout << "station outside: NO error" << std::endl;
    }
  catch (const hrcontact::InputError &e)
    {
      std::cout << "station outside: " << e.what() << std::endl;
    }
}
