#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/mapping_q1.h>

#include <hrcontact/adaptivity/triangle_split.h>

#include <cmath>
#include <map>

namespace hrcontact
{
  using namespace dealii;

  namespace
  {
    double
    power(const double x, const unsigned int n)
    {
      double r = 1;
      for (unsigned int i = 0; i < n; ++i)
        r *= x;
      return r;
    }
  } // namespace

  template <int dim>
  FullMatrix<double>
  component_compliance(const MaterialLaw<dim> &law)
  {
    constexpr unsigned int n = MixedSpaces<dim>::n_stress_components;
    FullMatrix<double>     S(n, n);
    for (unsigned int a = 0; a < n; ++a)
      {
        const auto e =
          law.strain(MixedSpaces<dim>::stress_basis_tensor(a), Point<dim>());
        for (unsigned int b = 0; b < n; ++b)
          S(b, a) = MixedSpaces<dim>::stress_basis_tensor(b) * e;
      }
    return S;
  }

  template FullMatrix<double>
  component_compliance(const MaterialLaw<2> &);
  template FullMatrix<double>
  component_compliance(const MaterialLaw<3> &);

  TriangleSplit::TriangleSplit(
    const Triangulation<2>::active_cell_iterator &cell)
  {
    for (unsigned int k = 0; k < 4; ++k)
      centre += cell->vertex(corner[k]) / 4.;
    h = cell->diameter();
    for (unsigned int k = 0; k < 4; ++k)
      {
        const unsigned int f    = face_under_edge[k];
        const auto         face = cell->face(f);
        P.push_back(cell->vertex(corner[k]));
        if (!face->has_children())
          {
            segment.push_back(face->index());
            continue;
          }
        // The child that starts at this corner first (a line's direction
        // need not follow the cell's).
        split_faces |= 1u << f;
        const unsigned int first =
          face->child(0)->vertex_index(0) == cell->vertex_index(corner[k]) ||
              face->child(0)->vertex_index(1) == cell->vertex_index(corner[k]) ?
            0 :
            1;
        segment.push_back(face->child(first)->index());
        P.push_back(face->child(0)->vertex(1));
        segment.push_back(face->child(1 - first)->index());
      }
    P.push_back(P[0]);
  }

  bool
  TriangleSplit::parallelogram() const
  {
    // The corners' differences, whatever hanging nodes lie between.
    std::array<Point<2>, 4> c;
    for (unsigned int k = 0, i = 0; k < 4; ++k, ++i)
      {
        c[k] = P[i];
        if (split_faces & (1u << face_under_edge[k]))
          ++i;
      }
    return (c[2] - c[3] - (c[1] - c[0])).norm() <= 1e-12 * h;
  }

  void
  TriangleSplit::rule(const unsigned int     n,
                      std::vector<Point<2>> &points,
                      std::vector<double>   &weights) const
  {
    // Kept per order: QGauss finds its points by Newton's method.
    static std::map<unsigned int, QGauss<1>> rules;
    const QGauss<1> &g = rules.try_emplace(n, n).first->second;
    for (unsigned int k = 0; k < n_triangles(); ++k)
      {
        const Point<2> &a = centre, &b = P[k], &c = P[k + 1];
        const double    area2 = std::abs((b[0] - a[0]) * (c[1] - a[1]) -
                                      (b[1] - a[1]) * (c[0] - a[0]));
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            {
              const double u = g.point(i)[0], v = g.point(j)[0] * (1 - u);
              points.push_back(a + u * (b - a) + v * (c - a));
              weights.push_back(g.weight(i) * g.weight(j) * (1 - u) * area2);
            }
      }
  }

  TrianglePolynomials::TrianglePolynomials(const unsigned int degree)
    : degree(degree)
  {
    for (unsigned int d = 0; d <= degree; ++d)
      for (unsigned int a = 0; a <= d; ++a)
        monomials.push_back({{d - a, a}});
  }

  double
  TrianglePolynomials::value(const TriangleSplit &split,
                             const Point<2>      &x,
                             const unsigned int   m) const
  {
    const Tensor<1, 2> xi = (x - split.centre) / split.h;
    return power(xi[0], monomials[m][0]) * power(xi[1], monomials[m][1]);
  }

  Tensor<1, 2>
  TrianglePolynomials::gradient(const TriangleSplit &split,
                                const Point<2>      &x,
                                const unsigned int   m) const
  {
    const Tensor<1, 2> xi = (x - split.centre) / split.h;
    const auto [a, b]     = monomials[m];
    Tensor<1, 2> g;
    if (a > 0)
      g[0] = a * power(xi[0], a - 1) * power(xi[1], b) / split.h;
    if (b > 0)
      g[1] = b * power(xi[0], a) * power(xi[1], b - 1) / split.h;
    return g;
  }

  SymmetricTensor<2, 2>
  TrianglePolynomials::stress(const Vector<double> &x,
                              const TriangleSplit  &split,
                              const unsigned int    k,
                              const Point<2>       &point) const
  {
    SymmetricTensor<2, 2> t;
    for (unsigned int m = 0; m < monomials.size(); ++m)
      {
        const double v = value(split, point, m);
        t[0][0] += x(index(k, 0, m)) * v;
        t[1][1] += x(index(k, 1, m)) * v;
        t[0][1] += x(index(k, 2, m)) * v;
      }
    return t;
  }

  CellSampler::CellSampler(const Results<2> &results)
    : results(results)
    , fe_u(*results.spaces.fe_displacement)
    , fe_s(*results.spaces.fe_stress)
    , u_dofs(fe_u.n_dofs_per_cell())
    , s_dofs(fe_s.n_dofs_per_cell())
    , u_values(fe_u.n_dofs_per_cell())
    , s_values(fe_s.n_dofs_per_cell())
  {
    for (unsigned int i = 0; i < fe_u.n_dofs_per_cell(); ++i)
      u_component.push_back(fe_u.system_to_component_index(i).first);
    for (unsigned int j = 0; j < fe_s.n_dofs_per_cell(); ++j)
      s_tensor.push_back(MixedSpaces<2>::stress_basis_tensor(
        fe_s.system_to_component_index(j).first));
    // Vertex values, and whether they reproduce the elements inside.
    const auto vertex_values = [](const FiniteElement<2>             &fe,
                                  std::vector<std::array<double, 4>> &values) {
      values.resize(fe.n_dofs_per_cell());
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        for (unsigned int v = 0; v < 4; ++v)
          values[i][v] =
            fe.shape_value(i, GeometryInfo<2>::unit_cell_vertex(v));
    };
    vertex_values(fe_u, u_vertex);
    vertex_values(fe_s, s_vertex);
    in_q1 = true;
    for (const Point<2> p : {Point<2>(0.3, 0.7), Point<2>(0.81, 0.13)})
      {
        const double hat[4] = {(1 - p[0]) * (1 - p[1]),
                               p[0] * (1 - p[1]),
                               (1 - p[0]) * p[1],
                               p[0] * p[1]};
        for (unsigned int i = 0; i < fe_u.n_dofs_per_cell(); ++i)
          {
            double sum = 0;
            for (unsigned int v = 0; v < 4; ++v)
              sum += u_vertex[i][v] * hat[v];
            in_q1 = in_q1 && std::abs(sum - fe_u.shape_value(i, p)) < 1e-12;
          }
        for (unsigned int j = 0; j < fe_s.n_dofs_per_cell(); ++j)
          {
            double sum = 0;
            for (unsigned int v = 0; v < 4; ++v)
              sum += s_vertex[j][v] * hat[v];
            in_q1 = in_q1 && std::abs(sum - fe_s.shape_value(j, p)) < 1e-12;
          }
      }
  }

  void
  CellSampler::tabulate(Table &t) const
  {
    static const FE_Q<2> hat(1);
    const unsigned int   n = t.unit.size();
    t.u_grad.assign(n, std::vector<Tensor<1, 2>>(u_dofs.size()));
    t.hat_grad.assign(n, std::vector<Tensor<1, 2>>(4));
    t.s_value.assign(n, std::vector<double>(s_dofs.size()));
    for (unsigned int q = 0; q < n && in_q1; ++q)
      {
        const double x = t.unit[q][0], y = t.unit[q][1];
        const double hat[4] = {(1 - x) * (1 - y),
                               x * (1 - y),
                               (1 - x) * y,
                               x * y};
        t.hat_grad[q]       = {Tensor<1, 2>({y - 1, x - 1}),
                               Tensor<1, 2>({1 - y, -x}),
                               Tensor<1, 2>({-y, 1 - x}),
                               Tensor<1, 2>({y, x})};
        for (unsigned int i = 0; i < u_dofs.size(); ++i)
          for (unsigned int v = 0; v < 4; ++v)
            t.u_grad[q][i] += u_vertex[i][v] * t.hat_grad[q][v];
        for (unsigned int j = 0; j < s_dofs.size(); ++j)
          for (unsigned int v = 0; v < 4; ++v)
            t.s_value[q][j] += s_vertex[j][v] * hat[v];
      }
    for (unsigned int q = 0; q < n && !in_q1; ++q)
      {
        for (unsigned int i = 0; i < u_dofs.size(); ++i)
          t.u_grad[q][i] = fe_u.shape_grad(i, t.unit[q]);
        for (unsigned int v = 0; v < 4; ++v)
          t.hat_grad[q][v] = hat.shape_grad(v, t.unit[q]);
        for (unsigned int j = 0; j < s_dofs.size(); ++j)
          t.s_value[q][j] = fe_s.shape_value(j, t.unit[q]);
      }
  }

  void
  CellSampler::operator()(const DoFHandler<2>::active_cell_iterator &cell,
                          const TriangleSplit                       &split,
                          const std::vector<Point<2>>               &points,
                          std::vector<SymmetricTensor<2, 2>>        &eps,
                          std::vector<SymmetricTensor<2, 2>>        &sigma)
  {
    const bool parallelogram = split.parallelogram();
    cell->get_dof_indices(u_dofs);
    const DoFHandler<2>::active_cell_iterator s_cell(
      &results.triangulation(),
      cell->level(),
      cell->index(),
      &results.spaces.dof_handler_stress);
    s_cell->get_dof_indices(s_dofs);
    const Point<2>     v0 = cell->vertex(0);
    const Tensor<1, 2> e1 = cell->vertex(1) - v0, e2 = cell->vertex(2) - v0;
    Tensor<2, 2>       J;
    for (unsigned int d = 0; d < 2; ++d)
      {
        J[d][0] = e1[d];
        J[d][1] = e2[d];
      }
    const Tensor<2, 2> J_inv = invert(J), J_inv_T = transpose(J_inv);
    const Table       *table = &own;
    if (parallelogram)
      {
        Table &t = tables[{points.size(), split.split_faces}];
        if (t.unit.empty())
          {
            for (const Point<2> &x : points)
              t.unit.emplace_back(J_inv * (x - v0));
            tabulate(t);
          }
        table = &t;
      }
    else
      {
        // The bilinear map x = v0 + e1 a + e2 b + e3 a b inverted by
        // Newton's method from the affine guess (a few iterations, in
        // closed form: deal.II's general inverse was a seventh of the
        // bound on the Hertz mesh); a point it does not map to round-off
        // takes deal.II's transform, which throws a named error if it
        // fails too.
        own.unit.resize(points.size());
        const Tensor<1, 2> e3 = cell->vertex(3) - cell->vertex(1) -
                                cell->vertex(2) + Tensor<1, 2>(v0);
        const double tolerance = 1e-14 * cell->diameter();
        for (unsigned int q = 0; q < points.size(); ++q)
          {
            Point<2> a(J_inv * (points[q] - v0));
            bool     mapped = false;
            for (unsigned int k = 0; k < 12 && !mapped; ++k)
              {
                const Tensor<1, 2> r =
                  v0 + e1 * a[0] + e2 * a[1] + e3 * (a[0] * a[1]) - points[q];
                if (r.norm() <= tolerance)
                  mapped = true;
                else
                  {
                    Tensor<2, 2> Jk;
                    for (unsigned int d = 0; d < 2; ++d)
                      {
                        Jk[d][0] = e1[d] + e3[d] * a[1];
                        Jk[d][1] = e2[d] + e3[d] * a[0];
                      }
                    a -= invert(Jk) * r;
                  }
              }
            own.unit[q] =
              mapped ? a :
                       StaticMappingQ1<2>::mapping.transform_real_to_unit_cell(
                         cell, points[q]);
          }
        tabulate(own);
      }
    // The cell's values once (global lookups cost), then per point the
    // reference gradient of u, mapped by J^-T.
    for (unsigned int i = 0; i < u_dofs.size(); ++i)
      u_values[i] = results.displacement(u_dofs[i]);
    for (unsigned int j = 0; j < s_dofs.size(); ++j)
      s_values[j] = results.stress(s_dofs[j]);
    eps.resize(points.size());
    sigma.resize(points.size());
    for (unsigned int q = 0; q < points.size(); ++q)
      {
        Tensor<2, 2> Jq_inv_T = J_inv_T;
        if (!parallelogram)
          {
            Tensor<2, 2> Jq;
            for (unsigned int v = 0; v < 4; ++v)
              Jq += outer_product(cell->vertex(v), table->hat_grad[q][v]);
            Jq_inv_T = transpose(invert(Jq));
          }
        Tensor<2, 2> reference_grad;
        for (unsigned int i = 0; i < u_dofs.size(); ++i)
          reference_grad[u_component[i]] += u_values[i] * table->u_grad[q][i];
        Tensor<2, 2> grad;
        for (unsigned int c = 0; c < 2; ++c)
          grad[c] = Jq_inv_T * reference_grad[c];
        eps[q] = symmetrize(grad);
        SymmetricTensor<2, 2> s;
        for (unsigned int j = 0; j < s_dofs.size(); ++j)
          s += (s_values[j] * table->s_value[q][j]) * s_tensor[j];
        sigma[q] = s;
      }
  }
} // namespace hrcontact
