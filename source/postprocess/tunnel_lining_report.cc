#include <deal.II/base/utilities.h>

#include <hrcontact/postprocess/section_forces.h>
#include <hrcontact/postprocess/tunnel_lining_report.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  void
  TunnelLiningReport<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Postprocess");
    prm.declare_entry(
      "Lining sections",
      "120",
      Patterns::Integer(2, 100000),
      "tunnel_lining grids: number of intervals between section stations "
      "along the mid-line (equally spaced in arc length; stations in the "
      "short stretch around the arcs' joint are skipped). lining.csv gets N, "
      "V, M and the displacement at each station.");
    prm.declare_entry(
      "Lining reference principal stresses",
      "",
      Patterns::Anything(),
      "tunnel_lining grids: extremes of principal stresses to compare with, "
      "'min of s_min : max of s_min : min of s_max : max of s_max', "
      "expressions of the constants in the scene's stress unit (e.g. the "
      "paper's Fig. 12 values converted). summary.txt lists them next to "
      "ours. Empty: no comparison.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  TunnelLiningReport<dim>::parse_parameters(ParameterHandler &prm,
                                            const Constants &)
  {
    prm.enter_subsection("Postprocess");
    n_sections = prm.get_integer("Lining sections");
    reference_principal_stresses =
      prm.get("Lining reference principal stresses");
    prm.leave_subsection();
  }

  template <int dim>
  std::string
  TunnelLiningReport<dim>::skip_reason(const Results<dim> &results) const
  {
    return (dim == 2 && results.scene.lining) ?
             "" :
             "the grid is not a tunnel_lining";
  }

  template <int dim>
  bool
  TunnelLiningReport<dim>::needs_replicated_mesh(const Scene<dim> &scene) const
  {
    return dim == 2 && scene.lining;
  }

  namespace
  {
    /** Section forces along the mid-line: lining.csv and the extremes of N
     * and M. */
    void
    report_section_forces(const Results<2>   &results,
                          const TunnelLining &lining,
                          const unsigned int  n_sections,
                          PostprocessOutput  &output)
    {
      Summary                        &summary = output.summary;
      std::ostream                   &log     = output.log;
      const std::vector<SectionForce> forces =
        compute_section_forces(results.spaces,
                               results.stress,
                               results.displacement,
                               lining.sections(n_sections));
      write_file_atomically(
        output.communicator,
        output.directory + "/lining.csv",
        [&](std::ostream &out) {
          out << "s,part,x,y,nx,ny,thickness,N,V,M,sigma_inner,sigma_outer,"
                 "ux,uy,u_n\n"
              << std::setprecision(10);
          for (const SectionForce &f : forces)
            {
              const Tensor<1, 2> n = f.station.across;
              out << f.station.s << "," << f.station.part << "," << f.centre[0]
                  << "," << f.centre[1] << "," << n[0] << "," << n[1] << ","
                  << f.thickness << "," << f.N << "," << f.V << "," << f.M
                  << "," << f.sigma_inner << "," << f.sigma_outer << ","
                  << f.displacement[0] << "," << f.displacement[1] << ","
                  << f.displacement * n << "\n";
            }
        });
      auto extreme = [&](const std::string &name,
                         double SectionForce::*member) {
        auto [lo, hi] = std::minmax_element(forces.begin(),
                                            forces.end(),
                                            [member](const SectionForce &a,
                                                     const SectionForce &b) {
                                              return a.*member < b.*member;
                                            });
        summary.add("lining_" + name + "_min", (*lo).*member);
        summary.add("lining_" + name + "_min_at_s", lo->station.s);
        summary.add("lining_" + name + "_max", (*hi).*member);
        summary.add("lining_" + name + "_max_at_s", hi->station.s);
        log << "  lining: " << name << " from " << std::setprecision(5)
            << (*lo).*member << " (s = " << lo->station.s << ") to "
            << (*hi).*member << " (s = " << hi->station.s << ")\n";
      };
      summary.add("lining_sections", forces.size());
      summary.add("lining_joint_gap_length", lining.joint_gap_length());
      extreme("N", &SectionForce::N);
      extreme("M", &SectionForce::M);
    }

    /** Principal stresses, next to the reference values if given. */
    void
    report_principal_stresses(const Results<2>   &results,
                              const TunnelLining &lining,
                              const std::string  &reference_principal_stresses,
                              PostprocessOutput  &output)
    {
      Summary                    &summary = output.summary;
      std::ostream               &log     = output.log;
      const std::array<double, 4> e =
        principal_stress_extremes(results.spaces, results.stress);
      const char *names[4] = {"principal_min_min",
                              "principal_min_max",
                              "principal_max_min",
                              "principal_max_max"};
      for (unsigned int k = 0; k < 4; ++k)
        summary.add(names[k], e[k]);
      // The extrados joint is a corner: its peak stresses grow without
      // bound under refinement. The same extremes without the cells within
      // one crown thickness of it converge.
      const std::array<double, 4> e_away = principal_stress_extremes(
        results.spaces, results.stress, lining.joint_out, lining.t_c);
      for (unsigned int k = 0; k < 4; ++k)
        summary.add(std::string(names[k]) + "_away_from_joint", e_away[k]);
      log << "  principal stresses: s_min in [" << std::setprecision(5) << e[0]
          << ", " << e[1] << "], s_max in [" << e[2] << ", " << e[3]
          << "]; away from the joint: s_min in [" << e_away[0] << ", "
          << e_away[1] << "], s_max in [" << e_away[2] << ", " << e_away[3]
          << "]\n";
      if (!Utilities::trim(reference_principal_stresses).empty())
        {
          const auto parts = split_and_trim(reference_principal_stresses, ':');
          if (parts.size() != 4)
            throw InputError("Postprocess/Lining reference principal "
                             "stresses: expected four values separated by "
                             "':'.");
          log << "  reference: s_min in [";
          for (unsigned int k = 0; k < 4; ++k)
            {
              const double r = evaluate_constant_expression(
                parts[k],
                results.scene.constants,
                "Postprocess/Lining reference principal stresses");
              summary.add("reference_" + std::string(names[k]), r);
              log << r
                  << (k == 0 ? ", " :
                      k == 1 ? "], s_max in [" :
                      k == 2 ? ", " :
                               "]\n");
            }
        }
    }

    /** Contact along the extrados, in arc length from the crown top:
     * pressed zones, peak pressure, lining-contact.csv. */
    void
    report_extrados_contact(const Results<2>   &results,
                            const TunnelLining &lining,
                            PostprocessOutput  &output)
    {
      Summary                                     &summary = output.summary;
      std::ostream                                &log     = output.log;
      const EquilibriumSystem                     &system  = results.system;
      std::vector<std::pair<double, unsigned int>> along;
      for (unsigned int k = 0; k < system.contact_rows.size(); ++k)
        if (system.rows[system.contact_rows[k]].unilateral)
          {
            const auto &c =
              system.node_coordinates[system.rows[system.contact_rows[k]].node];
            along.emplace_back(lining.extrados_arc_length(Point<2>(c[0], c[1])),
                               k);
          }
      std::sort(along.begin(), along.end());
      const unsigned int nc    = along.size();
      auto               point = [&](const unsigned int j) {
        const auto &c =
          system.node_coordinates
            [system.rows[system.contact_rows[along[j].second]].node];
        return Point<2>(c[0], c[1]);
      };
      std::vector<double> pressure(nc, 0.);
      double              peak = 0, peak_s = 0;
      for (unsigned int j = 0; j < nc; ++j)
        {
          const double tributary =
            0.5 * ((j > 0 ? point(j).distance(point(j - 1)) : 0.) +
                   (j + 1 < nc ? point(j).distance(point(j + 1)) : 0.));
          pressure[j] = -results.reactions.contact[along[j].second] / tributary;
          if (pressure[j] > peak)
            {
              peak   = pressure[j];
              peak_s = along[j].first;
            }
        }
      // Pressed zones: runs of pressed nodes, each ending halfway to the
      // next open node (or at the end of the extrados).
      std::ostringstream zones;
      double             pressed_length = 0;
      unsigned int       n_zones        = 0;
      for (unsigned int j = 0; j < nc;)
        {
          if (results.contact->released[along[j].second])
            {
              ++j;
              continue;
            }
          unsigned int l = j;
          while (l + 1 < nc && !results.contact->released[along[l + 1].second])
            ++l;
          const double a =
            (j == 0) ? 0. : 0.5 * (along[j - 1].first + along[j].first);
          const double b = (l + 1 == nc) ?
                             lining.extrados_length() :
                             0.5 * (along[l].first + along[l + 1].first);
          zones << (n_zones ? "; " : "") << std::setprecision(4) << a << " - "
                << b;
          pressed_length += b - a;
          ++n_zones;
          j = l + 1;
        }
      summary.add("lining_extrados_length", lining.extrados_length());
      summary.add("lining_pressed_zones", n_zones ? zones.str() : "none");
      summary.add("lining_pressed_length", pressed_length);
      summary.add("lining_max_contact_pressure", peak);
      summary.add("lining_max_contact_pressure_at_s", peak_s);
      log << "  extrados (length " << std::setprecision(5)
          << lining.extrados_length() << ") pressed on s in "
          << (n_zones ? zones.str() : "none") << "; peak contact pressure "
          << peak << " at s = " << peak_s << std::endl;

      write_file_atomically(
        output.communicator,
        output.directory + "/lining-contact.csv",
        [&](std::ostream &out) {
          out << "s,x,y,nx,ny,ux,uy,w_n,gap,p_n,pressure,status\n"
              << std::setprecision(10);
          for (unsigned int j = 0; j < nc; ++j)
            {
              const unsigned int    k   = along[j].second;
              const EquilibriumRow &row = system.rows[system.contact_rows[k]];
              out << along[j].first << "," << point(j)[0] << "," << point(j)[1]
                  << "," << row.combination[0].second << ","
                  << row.combination[1].second << ","
                  << results.displacement[row.combination[0].first] << ","
                  << results.displacement[row.combination[1].first] << ","
                  << results.reactions.contact_w[k] << "," << row.value << ","
                  << results.reactions.contact[k] << "," << pressure[j] << ","
                  << (results.contact->released[k] ? "open" : "contact")
                  << "\n";
            }
        });
    }
  } // namespace

  template <int dim>
  void
  TunnelLiningReport<dim>::execute(const Results<dim> &results,
                                   PostprocessOutput  &output)
  {
    if constexpr (dim == 2)
      {
        const TunnelLining &lining = *results.scene.lining;
        output.log << "  " << lining.describe() << '\n';
        report_section_forces(results, lining, n_sections, output);
        report_principal_stresses(results,
                                  lining,
                                  reference_principal_stresses,
                                  output);
        if (results.contact)
          report_extrados_contact(results, lining, output);
      }
    else
      {
        (void)results;
        (void)output;
      }
  }

  template class TunnelLiningReport<2>;
  template class TunnelLiningReport<3>;

  HRCONTACT_REGISTER_POSTPROCESSOR(
    TunnelLiningReport,
    "tunnel lining",
    50,
    "tunnel_lining grids: section forces (lining.csv), extremes, extrados "
    "contact (lining-contact.csv)")
} // namespace hrcontact
