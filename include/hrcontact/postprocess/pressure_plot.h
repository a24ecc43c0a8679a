#ifndef hrcontact_pressure_plot_h
#define hrcontact_pressure_plot_h

#include <deal.II/base/mpi.h>

#include <ostream>
#include <string>
#include <vector>

namespace hrcontact
{
  /** One contact node of a 2D pressure profile (ContactPressure). */
  struct PressurePoint
  {
    double x = 0, y = 0;
    /** Nodal pressure, positive in compression. */
    double pressure = 0;
    bool   pressed  = false;
  };

  /** Hertz's pressure p0 sqrt(1 - x^2/a^2) for |x| < a; a = 0: no
   * comparison. */
  struct HertzEllipse
  {
    double half_width = 0, peak = 0;
    double
    pressure(const double x) const;
  };

  /**
   * The picture of a 2D contact pressure: pressure.csv (x, y, pressure,
   * status, hertz_pressure), the gnuplot script pressure.gp that draws it
   * against Hertz's ellipse, and pressure.png, drawn by running gnuplot on
   * the script (written whole or not at all). Without gnuplot on the PATH,
   * or when it fails, the log gets a note and there is no picture: the plot
   * is a view of the results, never a reason to fail the run. Process 0 of
   * the communicator writes. Returns the files written.
   */
  std::vector<std::string>
  write_pressure_plot(const std::vector<PressurePoint> &profile,
                      const HertzEllipse               &hertz,
                      const std::string                &directory,
                      const MPI_Comm                    communicator,
                      std::ostream                     &log);
} // namespace hrcontact

#endif
