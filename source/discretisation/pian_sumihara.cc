#include <deal.II/fe/fe_dgq.h>

#include <hrcontact/discretisation/mixed_spaces.h>
#include <hrcontact/discretisation/pian_sumihara.h>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  std::unique_ptr<FESystem<dim>>
  PianSumihara<dim>::value_element() const
  {
    return std::make_unique<FESystem<dim>>(
      FE_DGQ<dim>(1), MixedSpaces<dim>::n_stress_components);
  }

  template <int dim>
  std::unique_ptr<FESystem<dim>>
  PianSumihara<dim>::parameter_element() const
  {
    return std::make_unique<FESystem<dim>>(FE_DGQ<dim>(0), n_parameters);
  }

  template <int dim>
  std::array<Tensor<1, dim>, dim>
  PianSumihara<dim>::centre_tangents(
    const typename Triangulation<dim>::cell_iterator &cell)
  {
    // x(xhat) = sum_k v_k N_k(xhat): at the centre dx/dxhat_d is the mean of
    // the edge vectors along d, and dx/dxi_d half of it.
    std::array<Tensor<1, dim>, dim> t;
    for (const unsigned int k : cell->vertex_indices())
      for (unsigned int d = 0; d < dim; ++d)
        t[d] += ((k >> d) & 1 ? 1. : -1.) * cell->vertex(k);
    for (unsigned int d = 0; d < dim; ++d)
      t[d] /= t[d].norm();
    return t;
  }

  template <int dim>
  std::array<SymmetricTensor<2, dim>, PianSumihara<dim>::n_parameters>
  PianSumihara<dim>::fields(const std::array<Tensor<1, dim>, dim> &t,
                            const Point<dim>                      &xi)
  {
    constexpr unsigned int n_comp = MixedSpaces<dim>::n_stress_components;
    std::array<SymmetricTensor<2, dim>, n_parameters> psi;
    for (unsigned int c = 0; c < n_comp; ++c)
      psi[c] = MixedSpaces<dim>::stress_basis_tensor(c);
    // sym(t_i t_j), with t_i t_i for i = j.
    const auto tt = [&](const unsigned int i, const unsigned int j) {
      return symmetrize(outer_product(t[i], t[j]));
    };
    if constexpr (dim == 2)
      {
        psi[3] = xi[1] * tt(0, 0);
        psi[4] = xi[0] * tt(1, 1);
      }
    else
      {
        // S_11, S_22, S_33 each linear in the other two coordinates and
        // their product; S_12, S_23, S_13 linear in the third.
        unsigned int p = n_comp;
        for (unsigned int i = 0; i < 3; ++i)
          {
            const unsigned int j = (i + 1) % 3, k = (i + 2) % 3;
            psi[p++] = xi[j] * tt(i, i);
            psi[p++] = xi[k] * tt(i, i);
            psi[p++] = xi[j] * xi[k] * tt(i, i);
          }
        for (unsigned int i = 0; i < 3; ++i)
          {
            const unsigned int j = (i + 1) % 3, k = (i + 2) % 3;
            psi[p++] = xi[k] * tt(i, j);
          }
      }
    return psi;
  }

  template <int dim>
  void
  PianSumihara<dim>::expansion(
    const typename Triangulation<dim>::cell_iterator &cell,
    const FiniteElement<dim>                         &value_fe,
    FullMatrix<double>                               &T) const
  {
    const auto         t   = centre_tangents(cell);
    const unsigned int n_v = value_fe.n_dofs_per_cell();
    T.reinit(n_v, n_parameters);
    const FiniteElement<dim> &base = value_fe.base_element(0);
    for (unsigned int j = 0; j < n_v; ++j)
      {
        const auto [c, k] = value_fe.system_to_component_index(j);
        Point<dim> xi;
        for (unsigned int d = 0; d < dim; ++d)
          xi[d] = 2 * base.unit_support_point(k)[d] - 1;
        const auto psi = fields(t, xi);
        const auto ab  = MixedSpaces<dim>::stress_component_indices(c);
        for (unsigned int p = 0; p < n_parameters; ++p)
          T(j, p) = psi[p][ab.first][ab.second];
      }
  }

  namespace
  {
    template <int dim>
    bool
    register_element()
    {
      return StressElementFactory<dim>::register_element(
        "Pian-Sumihara",
        "the assumed-stress field of Pian and Sumihara (2D, 5 parameters a "
        "cell) or Pian and Tong (3D, 18): free of shear and volumetric "
        "locking, the choice for bending and nearly incompressible bodies "
        "(doc/stress-elements.md)",
        [] { return std::make_unique<PianSumihara<dim>>(); });
    }
    const bool registered_2d = register_element<2>();
    const bool registered_3d = register_element<3>();
  } // namespace

  template class PianSumihara<2>;
  template class PianSumihara<3>;
} // namespace hrcontact
