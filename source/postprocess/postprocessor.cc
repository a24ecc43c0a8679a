#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>

#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>

#include <deal.II/grid/grid_tools.h>

#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>
#include <deal.II/numerics/vector_tools.h>

#include <hrcontact/postprocess/postprocessor.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace hrcontact
{
  using namespace dealii;

  void
  Summary::add(const std::string &key, const std::string &value)
  {
    entries.emplace_back(key, value);
  }

  void
  Summary::add(const std::string &key, const double value)
  {
    std::ostringstream s;
    s << std::setprecision(10) << value;
    entries.emplace_back(key, s.str());
  }

  std::string
  Summary::get(const std::string &key) const
  {
    for (const auto &[k, v] : entries)
      if (k == key)
        return v;
    throw std::runtime_error("summary has no key '" + key + "'");
  }

  double
  Summary::get_double(const std::string &key) const
  {
    return std::stod(get(key));
  }

  void
  write_file_atomically(const std::string                         &filename,
                        const std::function<void(std::ostream &)> &writer)
  {
    const std::string tmp = filename + ".tmp";
    {
      std::ofstream out(tmp);
      if (!out)
        throw InputError("Output: cannot write '" + tmp +
                         "' (check Output directory).");
      writer(out);
      out.flush();
      if (!out)
        throw InputError("Output: writing '" + tmp + "' failed.");
    }
    std::filesystem::rename(tmp, filename);
  }

  void
  write_file_atomically(const MPI_Comm                             communicator,
                        const std::string                         &filename,
                        const std::function<void(std::ostream &)> &writer)
  {
    if (is_root_process(communicator))
      write_file_atomically(filename, writer);
  }

  void
  Summary::write(const std::string &filename) const
  {
    write_file_atomically(filename, [this](std::ostream &out) {
      for (const auto &[k, v] : entries)
        out << k << " = " << v << '\n';
    });
  }

  template <int dim>
  void
  Postprocessor<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Postprocess");
    prm.declare_entry(
      "Probes",
      "",
      Patterns::Anything(),
      "Quantities at points, reported in the log and summary.txt as "
      "probe.NAME: 'name: x, y [, z] : quantity', entries separated by '|'. "
      "Coordinates are expressions of the constants; quantity is one of ux, "
      "uy, uz, sxx, syy, szz, sxy, sxz, syz, von_mises. A stress at a point "
      "shared by cells is taken from the first cell found.");
    prm.declare_entry(
      "Reference values",
      "",
      Patterns::Anything(),
      "Reference values of probes, e.g. from beam theory: 'name: expression' "
      "with the name of a probe; summary.txt gets reference.NAME and "
      "relative_error.NAME.");
    prm.declare_entry(
      "Reference stress",
      "",
      Patterns::Anything(),
      "An exact stress field to measure the error against: expressions in "
      "x, y (, z) for sxx; syy; sxy (2D) or sxx; syy; szz; sxy; sxz; syz "
      "(3D). summary.txt gets stress_error_max and stress_error_l2, relative "
      "to the same norms of the reference. Empty: no comparison.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  Postprocessor<dim>::parse_parameters(ParameterHandler &prm,
                                       const Constants  &constants)
  {
    static const std::vector<std::string> quantities = {
      "ux", "uy", "uz", "sxx", "syy", "szz", "sxy", "sxz", "syz", "von_mises"};
    prm.enter_subsection("Postprocess");
    for (const auto &[name, text] :
         parse_named_list(prm.get("Probes"), "Postprocess/Probes"))
      {
        const auto        parts = split_and_trim(text, ':');
        const std::string where = "Postprocess/Probes, '" + name + "'";
        if (parts.size() != 2)
          throw InputError(where + ": expected 'name: x, y : quantity'.");
        const auto coords = split_and_trim(parts[0], ',');
        if (coords.size() != dim)
          throw InputError(where + ": expected " + std::to_string(dim) +
                           " coordinates separated by ','.");
        Probe probe;
        probe.name = name;
        for (unsigned int d = 0; d < dim; ++d)
          probe.point[d] =
            evaluate_constant_expression(coords[d], constants, where);
        probe.quantity = parts[1];
        bool known     = false;
        for (const auto &q : quantities)
          known |= (q == probe.quantity);
        if (!known ||
            (dim == 2 && probe.quantity.find('z') != std::string::npos))
          throw InputError(where + ": unknown quantity '" + probe.quantity +
                           "' in " + std::to_string(dim) + "D.");
        probes.push_back(probe);
      }
    for (const auto &[name, expr] :
         parse_named_list(prm.get("Reference values"),
                          "Postprocess/Reference values"))
      {
        bool found = false;
        for (const auto &p : probes)
          found |= (p.name == name);
        if (!found)
          throw InputError("Postprocess/Reference values: '" + name +
                           "' is not the name of a probe.");
        reference_values.emplace_back(
          name,
          evaluate_constant_expression(
            expr, constants, "Postprocess/Reference values, '" + name + "'"));
      }
    const std::string rs = prm.get("Reference stress");
    if (!Utilities::trim(rs).empty())
      reference_stress =
        make_function<dim>(rs,
                           MixedSpaces<dim>::n_stress_components,
                           constants,
                           "Postprocess/Reference stress");
    prm.leave_subsection();
  }

  namespace
  {
    template <int dim>
    SymmetricTensor<2, dim>
    stress_tensor(const Vector<double> &components)
    {
      SymmetricTensor<2, dim> sigma;
      for (unsigned int c = 0; c < MixedSpaces<dim>::n_stress_components; ++c)
        {
          const auto ab = MixedSpaces<dim>::stress_component_indices(c);
          sigma[ab.first][ab.second] = components[c];
        }
      return sigma;
    }

    /** von Mises stress including the out-of-plane component in 2D. */
    template <int dim>
    double
    von_mises(const SymmetricTensor<2, dim> &sigma, const double szz)
    {
      SymmetricTensor<2, 3> s3;
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = a; b < dim; ++b)
          s3[a][b] = sigma[a][b];
      if (dim == 2)
        s3[2][2] = szz;
      const SymmetricTensor<2, 3> dev = deviator(s3);
      return std::sqrt(1.5 * (dev * dev));
    }

    template <int dim>
    class StressOutput : public DataPostprocessor<dim>
    {
    public:
      explicit StressOutput(const Scene<dim> &scene)
        : scene(scene)
      {}

      void
      evaluate_vector_field(
        const DataPostprocessorInputs::Vector<dim> &inputs,
        std::vector<Vector<double>> &computed_quantities) const override
      {
        for (unsigned int q = 0; q < inputs.solution_values.size(); ++q)
          {
            const auto sigma    = stress_tensor<dim>(inputs.solution_values[q]);
            Vector<double> &out = computed_quantities[q];
            unsigned int    k   = 0;
            for (unsigned int a = 0; a < dim; ++a)
              for (unsigned int b = 0; b < dim; ++b)
                out[k++] = sigma[a][b];
            const auto ev = eigenvalues(sigma); // descending
            for (unsigned int d = 0; d < dim; ++d)
              out[k++] = ev[d];
            out[k++] = von_mises<dim>(sigma, scene.out_of_plane_stress(sigma));
            for (unsigned int c = 0; c < MixedSpaces<dim>::n_stress_components;
                 ++c)
              out[k++] = inputs.solution_values[q][c];
          }
      }

      std::vector<std::string>
      get_names() const override
      {
        std::vector<std::string> names(dim * dim, "stress");
        for (unsigned int d = 0; d < dim; ++d)
          names.push_back("principal_stress_" + std::to_string(d + 1));
        names.push_back("von_mises");
        for (unsigned int c = 0; c < MixedSpaces<dim>::n_stress_components; ++c)
          names.push_back(MixedSpaces<dim>::stress_component_name(c));
        return names;
      }

      std::vector<DataComponentInterpretation::DataComponentInterpretation>
      get_data_component_interpretation() const override
      {
        std::vector<DataComponentInterpretation::DataComponentInterpretation>
          interpretation(
            dim * dim,
            DataComponentInterpretation::component_is_part_of_tensor);
        interpretation.resize(dim * dim + dim + 1 +
                                MixedSpaces<dim>::n_stress_components,
                              DataComponentInterpretation::component_is_scalar);
        return interpretation;
      }

      UpdateFlags
      get_needed_update_flags() const override
      {
        return update_values;
      }

    private:
      const Scene<dim> &scene;
    };
  } // namespace

  template <int dim>
  double
  Postprocessor<dim>::point_value(const MixedSpaces<dim> &spaces,
                                  const Scene<dim>       &scene,
                                  const Vector<double>   &u,
                                  const Vector<double>   &s,
                                  const Point<dim>       &point,
                                  const std::string      &quantity) const
  {
    const MappingQ1<dim> mapping;
    const auto           found =
      GridTools::find_active_cell_around_point(mapping,
                                               spaces.dof_handler_stress,
                                               point);
    if (found.first.state() != IteratorState::valid)
      throw InputError("Postprocess/Probes: the point (" +
                       Utilities::to_string(point[0]) +
                       ", ...) is outside the mesh.");
    const Quadrature<dim> q(
      GeometryInfo<dim>::project_to_unit_cell(found.second));
    if (quantity[0] == 'u')
      {
        const unsigned int component = quantity[1] - 'x';
        typename DoFHandler<dim>::active_cell_iterator cell(
          &spaces.dof_handler_displacement.get_triangulation(),
          found.first->level(),
          found.first->index(),
          &spaces.dof_handler_displacement);
        FEValues<dim> fv(mapping, *spaces.fe_displacement, q, update_values);
        fv.reinit(cell);
        std::vector<Vector<double>> values(1, Vector<double>(dim));
        fv.get_function_values(u, values);
        return values[0][component];
      }
    FEValues<dim> fv(mapping, *spaces.fe_stress, q, update_values);
    fv.reinit(found.first);
    std::vector<Vector<double>> values(
      1, Vector<double>(MixedSpaces<dim>::n_stress_components));
    fv.get_function_values(s, values);
    const auto sigma = stress_tensor<dim>(values[0]);
    if (quantity == "von_mises")
      return von_mises<dim>(sigma, scene.out_of_plane_stress(sigma));
    const unsigned int a = quantity[1] - 'x', b = quantity[2] - 'x';
    if (a == 2 && dim == 2)
      return scene.out_of_plane_stress(sigma);
    return sigma[a][b];
  }

  template <int dim>
  std::pair<double, double>
  Postprocessor<dim>::stress_error(const MixedSpaces<dim> &spaces,
                                   const Vector<double>   &s) const
  {
    constexpr unsigned int      n_comp = MixedSpaces<dim>::n_stress_components;
    const QGauss<dim>           quadrature(3);
    FEValues<dim>               fv(*spaces.fe_stress,
                     quadrature,
                     update_values | update_quadrature_points |
                       update_JxW_values);
    std::vector<Vector<double>> values(quadrature.size(),
                                       Vector<double>(n_comp));
    Vector<double>              ref(n_comp);
    double max_err = 0, max_ref = 0, l2_err = 0, l2_ref = 0;
    for (const auto &cell : spaces.dof_handler_stress.active_cell_iterators())
      {
        fv.reinit(cell);
        fv.get_function_values(s, values);
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          {
            reference_stress->vector_value(fv.quadrature_point(q), ref);
            const auto   sh = stress_tensor<dim>(values[q]);
            const auto   sr = stress_tensor<dim>(ref);
            const double e = (sh - sr).norm(), r = sr.norm();
            max_err = std::max(max_err, e);
            max_ref = std::max(max_ref, r);
            l2_err += e * e * fv.JxW(q);
            l2_ref += r * r * fv.JxW(q);
          }
      }
    return {max_ref > 0 ? max_err / max_ref : max_err,
            l2_ref > 0 ? std::sqrt(l2_err / l2_ref) : std::sqrt(l2_err)};
  }

  template <int dim>
  void
  Postprocessor<dim>::evaluate(const MixedSpaces<dim> &spaces,
                               const Scene<dim>       &scene,
                               const Vector<double>   &u,
                               const Vector<double>   &s,
                               Summary                &summary,
                               std::ostream           &log) const
  {
    if (!probes.empty())
      log << "  probes:\n";
    for (const Probe &probe : probes)
      {
        const double value =
          point_value(spaces, scene, u, s, probe.point, probe.quantity);
        summary.add("probe." + probe.name, value);
        log << "    " << std::left << std::setw(20) << probe.name << std::right
            << std::setw(8) << probe.quantity << " = " << std::setw(14)
            << std::setprecision(6) << value;
        for (const auto &[name, ref] : reference_values)
          if (name == probe.name)
            {
              const double err =
                (ref != 0) ? (value - ref) / std::abs(ref) : value - ref;
              summary.add("reference." + name, ref);
              summary.add("relative_error." + name, err);
              log << "   reference " << std::setw(14) << ref
                  << "   relative error " << std::setprecision(3) << err;
            }
        log << '\n';
      }
    if (reference_stress)
      {
        const auto [max_err, l2_err] = stress_error(spaces, s);
        summary.add("stress_error_max", max_err);
        summary.add("stress_error_l2", l2_err);
        log << "  stress error against the reference field: max "
            << std::setprecision(3) << max_err << ", L2 " << l2_err
            << " (relative)\n";
      }
    log << std::flush;
  }

  template <int dim>
  std::string
  Postprocessor<dim>::write_solution(const MixedSpaces<dim> &spaces,
                                     const Scene<dim>       &scene,
                                     const Vector<double>   &u,
                                     const Vector<double>   &s,
                                     const DofPartition     &partition,
                                     const std::string      &directory) const
  {
    const auto &tria    = spaces.dof_handler_displacement.get_triangulation();
    using cell_iterator = typename Triangulation<dim>::cell_iterator;
    using active_cell_iterator =
      typename Triangulation<dim>::active_cell_iterator;
    const auto &owned = partition.owned_cell;
    auto        skip  = [&](active_cell_iterator cell) -> cell_iterator {
      while (cell != tria.end() && !owned[cell->active_cell_index()])
        ++cell;
      return cell;
    };

    DataOut<dim> data_out;
    data_out.attach_triangulation(tria);
    if (partition.distributed())
      data_out.set_cell_selection(
        [&](const Triangulation<dim> &) { return skip(tria.begin_active()); },
        [&](const Triangulation<dim> &, const cell_iterator &cell) {
          return skip(std::next(active_cell_iterator(cell)));
        });
    data_out.add_data_vector(
      spaces.dof_handler_displacement,
      u,
      std::vector<std::string>(dim, "displacement"),
      std::vector<DataComponentInterpretation::DataComponentInterpretation>(
        dim, DataComponentInterpretation::component_is_part_of_vector));
    StressOutput<dim> stress_output(scene);
    data_out.add_data_vector(spaces.dof_handler_stress, s, stress_output);
    Vector<float> subdomain(tria.n_active_cells());
    subdomain = partition.process;
    if (partition.distributed())
      data_out.add_data_vector(subdomain, "subdomain");
    data_out.build_patches();
    if (!partition.distributed())
      {
        write_file_atomically(directory + "/solution.vtu",
                              [&](std::ostream &out) {
                                data_out.write_vtu(out);
                              });
        return "solution.vtu";
      }

    auto piece = [](const unsigned int p) {
      return "solution_" + Utilities::int_to_string(p, 4) + ".vtu";
    };
    write_file_atomically(directory + "/" + piece(partition.process),
                          [&](std::ostream &out) { data_out.write_vtu(out); });
    // The record only once every piece is complete.
    const int ierr = MPI_Barrier(partition.communicator);
    AssertThrowMPI(ierr);
    std::vector<std::string> pieces;
    for (unsigned int p = 0; p < partition.n_processes; ++p)
      pieces.push_back(piece(p));
    write_file_atomically(partition.communicator,
                          directory + "/solution.pvtu",
                          [&](std::ostream &out) {
                            data_out.write_pvtu_record(out, pieces);
                          });
    return "solution.pvtu";
  }

  template class Postprocessor<2>;
  template class Postprocessor<3>;
} // namespace hrcontact
