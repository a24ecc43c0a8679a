#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <deal.II/grid/grid_generator.h>

#include <hrcontact/geometry/mesh_generator.h>

#include <sstream>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  std::string
  MeshGenerator<dim>::fixed_geometry_reason() const
  {
    return "";
  }

  template <int dim>
  std::map<types::boundary_id, std::string>
  MeshGenerator<dim>::boundary_names() const
  {
    return {};
  }

  template <int dim>
  bool
  MeshGenerator<dim>::create_coarse(Triangulation<dim> &) const
  {
    return false;
  }

  template <int dim>
  typename MeshGenerator<dim>::VertexMap
  MeshGenerator<dim>::refined_vertex_map() const
  {
    return [](const Point<dim> &x, const types::material_id) { return x; };
  }

  template <int dim>
  void
  MeshGenerator<dim>::move_refined_vertices(Triangulation<dim> &triangulation,
                                            const VertexMap    &map)
  {
    std::vector<bool> moved(triangulation.n_vertices(), false);
    for (const auto &cell : triangulation.cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        if (!moved[cell->vertex_index(v)])
          {
            cell->vertex(v) = map(cell->vertex(v), cell->material_id());
            moved[cell->vertex_index(v)] = true;
          }
    triangulation.signals.mesh_movement();
  }

  namespace
  {
    /** Any deal.II GridGenerator function by name and arguments. */
    template <int dim>
    class DealIIGrid : public MeshGenerator<dim>
    {
    public:
      DealIIGrid(const std::string &name, const std::string &arguments)
        : name(name)
        , arguments(arguments)
      {}

      void
      create(Triangulation<dim> &triangulation,
             const unsigned int  refinements) const override
      {
        create_coarse(triangulation);
        triangulation.refine_global(refinements);
      }

      bool
      create_coarse(Triangulation<dim> &triangulation) const override
      {
        try
          {
            GridGenerator::generate_from_name_and_arguments(triangulation,
                                                            name,
                                                            arguments);
          }
        catch (const ExceptionBase &e)
          {
            std::ostringstream s;
            e.print_info(s);
            throw InputError("Geometry: cannot create the grid '" + name +
                             "' from the arguments '" + arguments +
                             "': " + Utilities::trim(s.str()));
          }
        catch (const std::exception &e)
          {
            throw InputError("Geometry: cannot create the grid '" + name +
                             "' from the arguments '" + arguments +
                             "': " + e.what());
          }
        if (triangulation.n_active_cells() == 0)
          throw InputError("Geometry: the grid has no cells.");
        return true;
      }

    private:
      const std::string name, arguments;
    };
  } // namespace

  template <int dim>
  std::vector<
    std::pair<std::string, typename MeshGeneratorFactory<dim>::Factory>> &
  MeshGeneratorFactory<dim>::registry()
  {
    // Function-local: filled by static initialisers of other files.
    static std::vector<std::pair<std::string, Factory>> entries;
    return entries;
  }

  template <int dim>
  bool
  MeshGeneratorFactory<dim>::register_generator(const std::string &name,
                                                const Factory     &factory)
  {
    for (const auto &e : registry())
      AssertThrow(e.first != name,
                  ExcMessage("grid '" + name + "' is registered twice"));
    registry().emplace_back(name, factory);
    return true;
  }

  template <int dim>
  std::unique_ptr<MeshGenerator<dim>>
  MeshGeneratorFactory<dim>::create(const std::string &name,
                                    const std::string &arguments,
                                    const Constants   &constants)
  {
    for (const auto &[registered, factory] : registry())
      if (registered == name)
        return factory(arguments, constants);
    return std::make_unique<DealIIGrid<dim>>(name, arguments);
  }

  template class MeshGenerator<2>;
  template class MeshGenerator<3>;
  template class MeshGeneratorFactory<2>;
  template class MeshGeneratorFactory<3>;
} // namespace hrcontact
