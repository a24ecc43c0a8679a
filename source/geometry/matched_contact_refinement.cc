#include <deal.II/base/mpi.h>

#include <deal.II/distributed/tria_base.h>

#include <hrcontact/geometry/matched_contact_refinement.h>

#include <algorithm>
#include <cmath>

namespace hrcontact
{
  using namespace dealii;

  namespace
  {
    /** A pair face in final coordinates: centre, unit normal, size, the
     * level of its cell and its boundary id; packed as doubles for the
     * gather without the normal, which only the face tested needs. */
    template <int dim>
    struct PairFace
    {
      Point<dim>         centre;
      Tensor<1, dim>     normal;
      double             h     = 0;
      int                level = 0;
      types::boundary_id id    = 0;

      static constexpr unsigned int n_packed = dim + 3;

      void
      pack(std::vector<double> &out) const
      {
        for (unsigned int d = 0; d < dim; ++d)
          out.push_back(centre[d]);
        out.push_back(h);
        out.push_back(level);
        out.push_back(id);
      }

      static PairFace
      unpack(const double *in)
      {
        PairFace f;
        for (unsigned int d = 0; d < dim; ++d)
          f.centre[d] = in[d];
        f.h     = in[dim];
        f.level = int(in[dim + 1]);
        f.id    = types::boundary_id(in[dim + 2]);
        return f;
      }
    };

    template <int dim, typename Face>
    PairFace<dim>
    pair_face(const Face                                   &face,
              const types::material_id                      body,
              const typename MeshGenerator<dim>::VertexMap &place)
    {
      std::vector<Point<dim>> v;
      for (const unsigned int k : face->vertex_indices())
        v.push_back(place(face->vertex(k), body));
      PairFace<dim> f;
      for (const auto &x : v)
        f.centre += x / double(v.size());
      if constexpr (dim == 2)
        {
          const Tensor<1, dim> t = v[1] - v[0];
          f.h                    = t.norm();
          f.normal               = Tensor<1, dim>({t[1], -t[0]}) / f.h;
        }
      else
        {
          // deal.II's quadrilateral vertex order: diagonals 0-3 and 1-2.
          const Tensor<1, dim> n = cross_product_3d(v[3] - v[0], v[2] - v[1]);
          f.h                    = std::sqrt(0.5 * n.norm());
          f.normal               = n / n.norm();
        }
      return f;
    }

    /** Whether g lies opposite f: its centre within half their sizes of
     * f's along f's surface (faces that only share an edge or a vertex do
     * not overlap), and within @p reach across it. */
    template <int dim>
    bool
    opposite(const PairFace<dim> &f, const PairFace<dim> &g, const double reach)
    {
      const Tensor<1, dim> d      = g.centre - f.centre;
      const double         across = d * f.normal;
      const double         along  = (d - across * f.normal).norm();
      return along < 0.49 * (f.h + g.h) && std::abs(across) <= reach;
    }
  } // namespace

  template <int dim>
  MatchedContactRefinement<dim>::MatchedContactRefinement(
    std::vector<Surfaces> pairs)
    : pairs(std::move(pairs))
  {}

  template <int dim>
  unsigned int
  MatchedContactRefinement<dim>::apply(
    Triangulation<dim>                           &triangulation,
    const typename MeshGenerator<dim>::VertexMap &place) const
  {
    if (pairs.empty())
      return 0;
    auto on_a_pair = [this](const types::boundary_id id) {
      for (const Surfaces &p : pairs)
        if (id == p.slave || id == p.master)
          return true;
      return false;
    };
    const auto *parallel =
      dynamic_cast<const parallel::TriangulationBase<dim> *>(&triangulation);
    unsigned int refined = 0;
    // Each round refines the faces coarser than a face opposite; the
    // refinement (and its 2:1 balance) may make faces opposite finer still,
    // so repeat until nothing is left.
    for (;;)
      {
        std::vector<double> own;
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned())
            for (const auto &face : cell->face_iterators())
              if (face->at_boundary() && on_a_pair(face->boundary_id()))
                {
                  PairFace<dim> f =
                    pair_face<dim>(face, cell->material_id(), place);
                  f.level = cell->level();
                  f.id    = face->boundary_id();
                  f.pack(own);
                }
        std::vector<double> all;
        if (parallel)
          for (const auto &part :
               Utilities::MPI::all_gather(parallel->get_communicator(), own))
            all.insert(all.end(), part.begin(), part.end());
        else
          all = own;
        std::vector<PairFace<dim>> faces;
        for (std::size_t k = 0; k < all.size(); k += PairFace<dim>::n_packed)
          faces.push_back(PairFace<dim>::unpack(all.data() + k));

        // Each pair's reach, as its rows take it: given, or a tenth of the
        // diagonal of the master faces' bounding box.
        std::vector<double> reach;
        for (const Surfaces &p : pairs)
          {
            Point<dim> low, high;
            bool       any = false;
            for (const auto &g : faces)
              if (g.id == p.master)
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    low[d] = any ? std::min(low[d], g.centre[d]) : g.centre[d];
                    high[d] =
                      any ? std::max(high[d], g.centre[d]) : g.centre[d];
                    any = any || d + 1 == dim;
                  }
            reach.push_back(p.reach > 0 ? p.reach : 0.1 * low.distance(high));
          }

        unsigned int flagged = 0;
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned())
            for (const auto &face : cell->face_iterators())
              {
                if (!face->at_boundary() || cell->refine_flag_set() ||
                    !on_a_pair(face->boundary_id()))
                  continue;
                const PairFace<dim> f =
                  pair_face<dim>(face, cell->material_id(), place);
                bool finer_opposite = false;
                for (unsigned int k = 0; k < pairs.size() && !finer_opposite;
                     ++k)
                  {
                    const types::boundary_id id = face->boundary_id();
                    if (id != pairs[k].slave && id != pairs[k].master)
                      continue;
                    const types::boundary_id other =
                      id == pairs[k].slave ? pairs[k].master : pairs[k].slave;
                    for (const auto &g : faces)
                      if (g.level > cell->level() && g.id == other &&
                          opposite(f, g, reach[k]))
                        {
                          finer_opposite = true;
                          break;
                        }
                  }
                if (finer_opposite)
                  {
                    cell->set_refine_flag();
                    ++flagged;
                  }
              }
        const unsigned int total =
          parallel ?
            Utilities::MPI::sum(flagged, parallel->get_communicator()) :
            flagged;
        if (total == 0)
          return refined;
        refined += total;
        triangulation.execute_coarsening_and_refinement();
      }
  }

  template class MatchedContactRefinement<2>;
  template class MatchedContactRefinement<3>;
} // namespace hrcontact
