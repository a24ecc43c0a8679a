#include <deal.II/base/utilities.h>

#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <hrcontact/adaptivity/refinement_indicator.h>
#include <hrcontact/discretisation/stress_constraint_field.h>
#include <hrcontact/postprocess/contact_fields.h>
#include <hrcontact/postprocess/field_values.h>
#include <hrcontact/postprocess/solution_output.h>

#include <optional>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  void
  SolutionOutput<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry("Write solution",
                      "true",
                      Patterns::Bool(),
                      "Write solution.vtu (displacement, stress tensor, "
                      "principal stresses, von Mises) for ParaView.");
    prm.declare_entry(
      "Solution compression",
      "best speed",
      Patterns::Selection("best speed|best compression|default|none"),
      "zlib level of the data in solution.vtu (lossless either way): best "
      "compression writes files 2 % smaller but took 4.3 s instead of 0.7 "
      "s at Hertz refinement 7 (49k cells), most of the run "
      "(doc/benchmarks.md).");
    prm.leave_subsection();
  }

  template <int dim>
  void
  SolutionOutput<dim>::parse_parameters(ParameterHandler &prm,
                                        const Constants &)
  {
    using Flags = DataOutBase::VtkFlags;
    prm.enter_subsection("Output");
    write       = prm.get_bool("Write solution");
    compression = get_selection<Flags::ZlibCompressionLevel>(
      prm,
      "Solution compression",
      {{"best speed", Flags::best_speed},
       {"best compression", Flags::best_compression},
       {"default", Flags::default_compression},
       {"none", Flags::no_compression}});
    prm.leave_subsection();
  }

  template <int dim>
  std::string
  SolutionOutput<dim>::skip_reason(const Results<dim> &) const
  {
    return write ? "" : "Output/Write solution = false";
  }

  namespace
  {
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
        const auto body = inputs.template get_cell<dim>()->material_id();
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
            out[k++] =
              von_mises<dim>(sigma, scene.out_of_plane_stress(sigma, body));
            // The directions of the largest and the smallest principal
            // stress (for a no-tension body: the crack normal and the
            // strut), as vectors for ParaView's glyphs.
            const auto e =
              eigenvectors(sigma, SymmetricTensorEigenvectorMethod::jacobi);
            for (const unsigned int d : {0u, dim - 1u})
              for (unsigned int a = 0; a < dim; ++a)
                out[k++] = e[d].second[a];
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
        for (unsigned int a = 0; a < dim; ++a)
          names.push_back("principal_direction_1");
        for (unsigned int a = 0; a < dim; ++a)
          names.push_back("principal_direction_" + std::to_string(dim));
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
        interpretation.resize(dim * dim + dim + 1,
                              DataComponentInterpretation::component_is_scalar);
        interpretation.resize(
          dim * dim + dim + 1 + 2 * dim,
          DataComponentInterpretation::component_is_part_of_vector);
        interpretation.resize(dim * dim + dim + 1 + 2 * dim +
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

    template <int dim>
    std::string
    write_solution(
      const Results<dim>                               &results,
      const std::map<std::string, Vector<float>>       &cell_fields,
      const std::string                                &directory,
      const DataOutBase::VtkFlags::ZlibCompressionLevel compression)
    {
      const MixedSpaces<dim> &spaces    = results.spaces;
      const Scene<dim>       &scene     = results.scene;
      const FieldVector      &u         = results.displacement;
      const FieldVector      &s         = results.stress;
      const DofPartition     &partition = results.partition;
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

      // The contact pressure, gap and status as nodal fields (declared
      // before data_out, which refers to their DoFHandler).
      std::optional<ContactFields<dim>> contact_fields;
      if (results.contact)
        contact_fields.emplace(results);
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
      // A stress constraint: the largest fracture (crack-opening) strain of
      // each cell's constraint points, per cell.
      Vector<float> fracture;
      if (results.stress_constraint.field)
        {
          fracture = results.stress_constraint.field->cell_openings();
          data_out.add_data_vector(fracture, "fracture_strain");
        }
      // Adaptive cycles: each cell's indicator, where the next cycle would
      // refine.
      Vector<float> indicators;
      if (scene.adaptive.active())
        {
          RefinementIndicatorFactory<dim>::create(scene.adaptive.estimator)
            ->estimate(results, indicators);
          data_out.add_data_vector(indicators, "refinement_indicator");
        }
      if (contact_fields)
        contact_fields->add_to(data_out);
      // What earlier postprocessors computed per cell (the error bound).
      for (const auto &[name, field] : cell_fields)
        data_out.add_data_vector(field, name);
      data_out.build_patches();
      DataOutBase::VtkFlags vtk_flags;
      vtk_flags.compression_level = compression;
      data_out.set_flags(vtk_flags);
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
                            [&](std::ostream &out) {
                              data_out.write_vtu(out);
                            });
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

  } // namespace

  template <int dim>
  void
  SolutionOutput<dim>::execute(const Results<dim> &results,
                               PostprocessOutput  &output)
  {
    output.mentioned_files.push_back(write_solution(
      results, output.cell_fields, output.directory, compression));
  }

  template class SolutionOutput<2>;
  template class SolutionOutput<3>;

  HRCONTACT_REGISTER_POSTPROCESSOR(
    SolutionOutput,
    "solution",
    30,
    "solution.vtu (or .pvtu) with displacements and stresses for ParaView")
} // namespace hrcontact
