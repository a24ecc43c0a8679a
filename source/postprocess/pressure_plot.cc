#include <hrcontact/discretisation/dof_partition.h>
#include <hrcontact/postprocess/pressure_plot.h>
#include <hrcontact/postprocess/summary.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iomanip>

namespace hrcontact
{
  double
  HertzEllipse::pressure(const double x) const
  {
    return std::abs(x) < half_width ?
             peak * std::sqrt(1 - (x / half_width) * (x / half_width)) :
             0.;
  }

  namespace
  {
    /** A path as one word for the shell. */
    std::string
    shell_quoted(const std::string &text)
    {
      std::string quoted = "'";
      for (const char c : text)
        quoted += (c == '\'') ? std::string("'\\''") : std::string(1, c);
      return quoted + "'";
    }

    /** The script: pressure.csv against Hertz's ellipse; `outfile` may be
     * set on the command line (the run draws into a temporary file). */
    void
    write_script(std::ostream                     &out,
                 const std::vector<PressurePoint> &profile,
                 const HertzEllipse               &hertz)
    {
      // Hertz: twice its half width; otherwise half again the pressed zone.
      double x_min = profile.front().x, zone_end = x_min;
      for (const PressurePoint &p : profile)
        if (p.pressed)
          zone_end = std::max(zone_end, p.x);
      const double x_max = hertz.half_width > 0 ?
                             x_min + 2 * hertz.half_width :
                             x_min + 1.5 * (zone_end - x_min);
      out << std::setprecision(12)
          << "# The contact pressure hrcontact computed (pressure.csv) against "
             "Hertz's\n# ellipse. Redraw: gnuplot pressure.gp\n"
          << "if (!exists(\"outfile\")) outfile = 'pressure.png'\n"
          << "set terminal pngcairo size 900,560 font ',11'\n"
          << "set output outfile\n"
          << "set datafile separator ','\n"
          << "set key top right\nset grid\n"
          << "set xlabel 'x along the contact surface'\n"
          << "set ylabel 'contact pressure'\n"
          << "set samples 500\n";
      if (x_max > x_min)
        out << "set xrange [" << x_min << ":" << x_max << "]\n";
      out << "set yrange [0:*]\n";
      if (hertz.half_width > 0)
        out << "a = " << hertz.half_width << "\np0 = " << hertz.peak
            << "\nhertz(x) = abs(x) < a ? p0*sqrt(1 - (x/a)**2) : 0\n"
            << "set title sprintf('Hertz: a = %g, p0 = %g', a, p0)\n"
            << "plot hertz(x) with lines lw 2 lc rgb '#cc3311' title "
               "'Hertz (closed form)', \\\n"
            << "     'pressure.csv' using 1:3 skip 1 with linespoints pt 7 ps "
               "0.8 lc rgb '#0077bb' title 'hrcontact (nodal pressure)'\n";
      else
        out << "plot 'pressure.csv' using 1:3 skip 1 with linespoints pt 7 ps "
               "0.8 lc rgb '#0077bb' title 'hrcontact (nodal pressure)'\n";
    }
  } // namespace

  std::vector<std::string>
  write_pressure_plot(const std::vector<PressurePoint> &profile,
                      const HertzEllipse               &hertz,
                      const std::string                &directory,
                      const MPI_Comm                    communicator,
                      std::ostream                     &log)
  {
    if (profile.empty() || !is_root_process(communicator))
      return {};
    write_file_atomically(directory + "/pressure.csv", [&](std::ostream &out) {
      out << "x,y,pressure,status,hertz_pressure\n" << std::setprecision(12);
      for (const PressurePoint &p : profile)
        out << p.x << "," << p.y << "," << p.pressure << ","
            << (p.pressed ? "contact" : "open") << "," << hertz.pressure(p.x)
            << "\n";
    });
    write_file_atomically(directory + "/pressure.gp", [&](std::ostream &out) {
      write_script(out, profile, hertz);
    });
    std::vector<std::string> files = {"pressure.csv", "pressure.gp"};
    if (std::system("command -v gnuplot > /dev/null 2>&1") != 0)
      {
        log << "  no pressure.png: gnuplot is not installed (Debian: apt-get "
               "install gnuplot-nox); pressure.gp draws it from pressure.csv"
            << std::endl;
        return files;
      }
    const std::string png = directory + "/pressure.png";
    const int         status =
      std::system(("cd " + shell_quoted(directory) +
                   " && gnuplot -e \"outfile='pressure.png.tmp'\" pressure.gp "
                   "> /dev/null 2>&1")
                    .c_str());
    if (status == 0 && std::filesystem::exists(png + ".tmp"))
      {
        std::filesystem::rename(png + ".tmp", png);
        files.push_back("pressure.png");
      }
    else
      {
        std::filesystem::remove(png + ".tmp");
        log << "  no pressure.png: gnuplot failed on pressure.gp (run "
               "'gnuplot pressure.gp' in the output directory to see why)"
            << std::endl;
      }
    return files;
  }
} // namespace hrcontact
