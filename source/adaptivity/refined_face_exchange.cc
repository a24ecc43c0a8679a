#include <deal.II/grid/grid_tools.h>

#include <deal.II/distributed/tria_base.h>

#include <hrcontact/adaptivity/refined_face_exchange.h>

#include <optional>
#include <vector>

namespace hrcontact
{
  using namespace dealii;

  void
  exchange_from_coarse_cells(
    const Triangulation<2>                        &triangulation,
    const MPI_Comm                                 communicator,
    std::map<unsigned int, std::array<double, 2>> &values)
  {
    using Tria       = parallel::TriangulationBase<2>;
    const auto *tria = dynamic_cast<const Tria *>(&triangulation);
    if (tria == nullptr || tria->n_global_active_cells() == 0 ||
        Utilities::MPI::n_mpi_processes(communicator) == 1)
      return;
    using Cell = Triangulation<2>::active_cell_iterator;
    // Per refined face of an owned cell: its number and its halves'
    // moments.
    GridTools::exchange_cell_data_to_ghosts<std::vector<double>,
                                            Triangulation<2>>(
      triangulation,
      [&](const Cell &cell) -> std::optional<std::vector<double>> {
        std::vector<double> data;
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->has_children())
            {
              data.push_back(f);
              for (unsigned int half = 0; half < 2; ++half)
                for (unsigned int c = 0; c < 2; ++c)
                  data.push_back(
                    values[cell->face(f)->child(half)->index()][c]);
            }
        if (data.empty())
          return {};
        return data;
      },
      [&](const Cell &cell, const std::vector<double> &data) {
        for (unsigned int i = 0; i + 5 <= data.size(); i += 5)
          {
            const auto face = cell->face(static_cast<unsigned int>(data[i]));
            // Where the fine side is artificial here the face is whole: no
            // problem here needs its halves.
            if (!face->has_children())
              continue;
            for (unsigned int half = 0; half < 2; ++half)
              for (unsigned int c = 0; c < 2; ++c)
                values[face->child(half)->index()][c] =
                  data[i + 1 + 2 * half + c];
          }
      });
  }
} // namespace hrcontact
