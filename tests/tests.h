// Small helpers shared by the test programs (deal.II's own tests.h is not
// installed with the library).
#ifndef hrcontact_tests_h
#define hrcontact_tests_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <hrcontact/core/hr_problem.h>
#include <hrcontact/core/input.h>
#include <hrcontact/core/run.h>
#include <hrcontact/material/stress_constraint.h>
#include <hrcontact/postprocess/field_values.h>
#include <hrcontact/postprocess/section_forces.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace hrcontact_tests
{
  /**
   * The largest principal stress at the Gauss points of every cell, where
   * the cone is imposed, over the largest stress norm there (the scale of
   * the stress tolerance). Serial runs.
   */
  inline double
  largest_gauss_point_stress(const hrcontact::Results<2> &res)
  {
    const auto             &fe = *res.spaces.fe_stress;
    const dealii::QGauss<2> points(2);
    dealii::FEValues<2>     fv(fe, points, dealii::update_values);
    dealii::Vector<double>  values(fe.n_dofs_per_cell());
    double                  largest = -1e300, scale = 0;
    for (const auto &cell :
         res.spaces.dof_handler_stress.active_cell_iterators())
      {
        fv.reinit(cell);
        res.spaces.cell_values(cell, res.stress, values);
        for (unsigned int t = 0; t < points.size(); ++t)
          {
            dealii::SymmetricTensor<2, 2> sigma;
            for (unsigned int j = 0; j < values.size(); ++j)
              sigma += values[j] * fv.shape_value(j, t) *
                       hrcontact::MixedSpaces<2>::stress_basis_tensor(
                         fe.system_to_component_index(j).first);
            largest = std::max(largest, dealii::eigenvalues(sigma)[0]);
            scale   = std::max(scale, sigma.norm());
          }
      }
    return largest / scale;
  }

  /**
   * max |a - b| / max |b| over the entries of two vectors of the same
   * numbering (serial runs).
   */
  inline double
  relative(const hrcontact::FieldVector &a, const hrcontact::FieldVector &b)
  {
    double diff = 0, scale = 0;
    for (unsigned int i = 0; i < a.size(); ++i)
      {
        diff  = std::max(diff, std::abs(a[i] - b[i]));
        scale = std::max(scale, std::abs(b[i]));
      }
    return diff / scale;
  }

  /**
   * max |a - b| / max |b| of two runs' final Q-row reactions and of their
   * displacements (owned entries, the largest over the processes): the same
   * answer reached two ways.
   */
  template <int dim>
  std::array<double, 2>
  answer_differences(const hrcontact::Results<dim> &a,
                     const hrcontact::Results<dim> &b)
  {
    double p_difference = 0, p_scale = 0;
    for (unsigned int i = 0; i < a.contact->p.size(); ++i)
      {
        p_difference =
          std::max(p_difference, std::abs(a.contact->p[i] - b.contact->p[i]));
        p_scale = std::max(p_scale, std::abs(b.contact->p[i]));
      }
    double u_difference = 0, u_scale = 0;
    for (const auto i : a.displacement.locally_owned_elements())
      {
        u_difference =
          std::max(u_difference,
                   std::abs(a.displacement(i) - b.displacement(i)));
        u_scale = std::max(u_scale, std::abs(b.displacement(i)));
      }
    const MPI_Comm comm = MPI_COMM_WORLD;
    return {{p_difference / p_scale,
             dealii::Utilities::MPI::max(u_difference, comm) /
               dealii::Utilities::MPI::max(u_scale, comm)}};
  }

  /**
   * subsection Supports prescribing u = eps x on every boundary id 0 ..
   * 2 dim - 1 of a colorized box (eps in its upper-left dim x dim block),
   * to 17 digits: the displacement patch test.
   */
  template <int dim>
  std::string
  linear_displacement_supports(const double eps[3][3])
  {
    std::ostringstream t;
    t << std::setprecision(17) << "subsection Supports\n"
      << "  set Prescribed displacements = ";
    for (unsigned int id = 0; id < 2 * dim; ++id)
      {
        t << (id ? " | " : "") << id << ": ";
        for (unsigned int i = 0; i < dim; ++i)
          {
            t << (i ? "; " : "");
            for (unsigned int j = 0; j < dim; ++j)
              t << (j ? " + " : "") << "(" << eps[i][j] << ")*"
                << "xyz"[j];
          }
      }
    t << "\nend\n";
    return t.str();
  }

  /**
   * The stress-constraint patch tests' body: a box of 4^dim cells
   * distorted by 0.3, E = 1000, nu = 0.3 (plane stress in 2D), Material/
   * Admissible stresses = @p constraint, u = eps x on its whole boundary;
   * @p extra appended (a Method, say).
   */
  template <int dim>
  std::string
  constraint_patch(const std::string &constraint,
                   const double       eps[3][3],
                   const std::string &extra = "")
  {
    std::ostringstream t;
    t << std::setprecision(17) << "set Dimension = " << dim
      << "\nsubsection Geometry\n"
         "  set Grid generator = subdivided_hyper_cube\n"
         "  set Grid arguments = 4 : 0 : 1 : true\n"
         "  set Distortion = 0.3\n"
         "end\n"
         "subsection Material\n"
         "  set Young's modulus = 1000\n"
         "  set Poisson's ratio = 0.3\n"
      << (dim == 2 ? "  set Plane condition = plane stress\n" : "")
      << "  set Admissible stresses = " << constraint
      << "\nend\nsubsection Output\n  set Write solution = false\n"
         "  set Output directory = results\nend\n"
      << linear_displacement_supports<dim>(eps) << extra;
    return t.str();
  }

  /** t = R diag(e1, e2) R^T in the x-y plane, R the rotation by
   * @p degrees (the rest of t zero). */
  inline void
  rotated(const double e1,
          const double e2,
          const double degrees,
          double       t[3][3])
  {
    const double a = degrees * M_PI / 180, c = std::cos(a), s = std::sin(a);
    t[0][0] = c * c * e1 + s * s * e2;
    t[1][1] = s * s * e1 + c * c * e2;
    t[0][1] = t[1][0] = c * s * (e1 - e2);
    t[0][2] = t[2][0] = t[1][2] = t[2][1] = t[2][2] = 0;
  }

  /** One homogeneous state of the cone patch tests: its name, cone and
   * dimension, the strain, the closed form's stress, cracked fraction and
   * largest fracture strain. */
  struct ConePatchState
  {
    std::string  name, constraint;
    unsigned int dim;
    double       eps[3][3], sigma[3][3];
    double       cracked, opening;
  };

  /**
   * What a cone patch state's stress errors are divided by, and |eps|:
   * stress_errors is relative to the closed form's norms (1), except where
   * the closed form's stress is zero (a homogeneous tension), where it is
   * absolute and measured against E |eps|.
   */
  inline std::pair<double, double>
  patch_error_scales(const ConePatchState &state, const double E)
  {
    double scale = 0, strain = 0;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        {
          scale  = std::max(scale, std::abs(state.sigma[i][j]));
          strain = std::max(strain, std::abs(state.eps[i][j]));
        }
    return {(scale > 0) ? 1. : E * strain, strain};
  }

  /**
   * The cone patch tests' states for the law (E, nu), plane stress in 2D:
   * a stretch-and-squeeze strain with its crack at 0 and 30 degrees (the
   * uniaxial stress E eps_2 n_2 n_2, fracture strain (eps_1 + nu eps_2) n_1
   * n_1) and its no-compression mirror, compressed both ways (elastic,
   * nothing cracked), stretched both ways (no stress); in 3D stretched
   * along x and compressed along y and z, and stretched every way.
   */
  inline std::vector<ConePatchState>
  cone_patch_states(const double E, const double nu)
  {
    std::vector<ConePatchState> states;
    const auto                  add = [&](const std::string &name,
                         const std::string &constraint,
                         const unsigned int dim,
                         const double       cracked,
                         const double       opening) -> ConePatchState                  &{
      states.push_back({name, constraint, dim, {}, {}, cracked, opening});
      return states.back();
    };
    const double e1 = 1e-3, e2 = -2e-3;
    for (const double degrees : {0., 30.})
      {
        const std::string at =
          " at " + std::to_string(int(degrees)) + " degrees";
        auto &crack = add("crack" + at, "no tension", 2, 1, e1 + nu * e2);
        rotated(e1, e2, degrees, crack.eps);
        rotated(0, E * e2, degrees, crack.sigma);
        auto &wrinkle =
          add("wrinkle" + at, "no compression", 2, 1, e1 + nu * e2);
        rotated(-e1, -e2, degrees, wrinkle.eps);
        rotated(0, -E * e2, degrees, wrinkle.sigma);
      }
    auto &both = add("compressed both ways", "no tension", 2, 0, 0);
    rotated(-1e-3, -2e-3, 30, both.eps);
    rotated(E / (1 - nu * nu) * (-1e-3 + nu * -2e-3),
            E / (1 - nu * nu) * (-2e-3 + nu * -1e-3),
            30,
            both.sigma);
    auto &stretched = add("stretched both ways", "no tension", 2, 1, 2e-3);
    rotated(2e-3, 1e-3, 30, stretched.eps);
    // 3D: sigma_xx = 0 and the plane-stress answer in y, z; mu_xx = eps_xx
    // + nu (s_yy + s_zz) / E.
    const double eps3[3][3] = {{2e-3, 0, 0}, {0, -2e-3, 0}, {0, 0, -1e-3}};
    const double s_yy = E / (1 - nu * nu) * (eps3[1][1] + nu * eps3[2][2]),
                 s_zz = E / (1 - nu * nu) * (eps3[2][2] + nu * eps3[1][1]);
    auto &across      = add("3D crack across x",
                       "no tension",
                       3,
                       1,
                       eps3[0][0] + nu * (s_yy + s_zz) / E);
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        across.eps[i][j] = eps3[i][j];
    across.sigma[1][1] = s_yy;
    across.sigma[2][2] = s_zz;
    auto &every     = add("3D stretched every way", "no tension", 3, 1, 3e-3);
    every.eps[0][0] = 2e-3, every.eps[1][1] = 1e-3, every.eps[2][2] = 3e-3;
    return states;
  }

  /**
   * The patch tests' uniform stress state s (plane strain: s_zz = nu (s_xx +
   * s_yy)) and its strain eps for the isotropic law (E, nu), computed here
   * independently of the library's compliance.
   */
  template <int dim>
  void
  patch_state(const double E, const double nu, double s[3][3], double eps[3][3])
  {
    const double state[3][3] = {{3., 1.5, -0.7},
                                {1.5, -2., 0.4},
                                {-0.7, 0.4, 0.5}};
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int b = 0; b < 3; ++b)
        s[a][b] = state[a][b];
    if (dim == 2)
      s[2][2] = nu * (s[0][0] + s[1][1]); // plane strain: eps_zz = 0
    const double trace = s[0][0] + s[1][1] + s[2][2];
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int b = 0; b < 3; ++b)
        eps[a][b] = ((1 + nu) * s[a][b] - (a == b ? nu * trace : 0.)) / E;
  }

  /** Postprocess/Reference stress of s (MixedSpaces order), to 17 digits;
   * with @p normal_only its normal components only. */
  template <int dim>
  std::string
  stress_reference(const double s[3][3], const bool normal_only = false)
  {
    std::ostringstream reference;
    reference << std::setprecision(17);
    for (unsigned int c = 0;
         c < hrcontact::MixedSpaces<dim>::n_stress_components;
         ++c)
      {
        const auto ab =
          hrcontact::MixedSpaces<dim>::stress_component_indices(c);
        reference << (c ? "; " : "")
                  << (normal_only ? (c < dim ? s[c][c] : 0.) :
                                    s[ab.first][ab.second]);
      }
    return reference.str();
  }

  /** The max and L2 relative errors of a run's stresses against the
   * expressions of @p reference (Postprocess/Reference stress syntax). */
  template <int dim>
  std::pair<double, double>
  stress_errors(const hrcontact::Results<dim> &r, const std::string &reference)
  {
    const auto exact = hrcontact::make_function<dim>(
      reference,
      hrcontact::MixedSpaces<dim>::n_stress_components,
      {},
      "reference");
    return hrcontact::stress_error(r.spaces, r.stress, *exact);
  }

  /**
   * Rollers on the faces x = 0, y = 0 (z = 0) of a colorized box and the
   * tractions of the normal stresses of s on x = 1, y = 1 (z = 1), to 17
   * digits: the traction patch test.
   */
  template <int dim>
  std::string
  normal_traction_supports(const double s[3][3])
  {
    std::ostringstream t;
    t << std::setprecision(17) << "subsection Supports\n"
      << "  set Prescribed displacements = 0 x: 0 | 2 y: 0"
      << (dim == 3 ? " | 4 z: 0" : "") << "\nend\n"
      << "subsection Loads\n  set Tractions = ";
    for (unsigned int d = 0; d < dim; ++d)
      {
        t << (d ? " | " : "") << 2 * d + 1 << ": ";
        for (unsigned int a = 0; a < dim; ++a)
          t << (a ? "; " : "") << (a == d ? s[d][d] : 0.);
      }
    t << "\nend\n";
    return t.str();
  }

  /** Build and solve a problem from parameter text (no files written). */
  template <int dim>
  std::unique_ptr<hrcontact::HRProblem<dim>>
  solve_from_text(const std::string &text,
                  const MPI_Comm     communicator = MPI_COMM_WORLD)
  {
    dealii::ParameterHandler prm;
    hrcontact::declare_all_parameters(prm);
    prm.parse_input_from_string(text);
    auto problem =
      std::make_unique<hrcontact::HRProblem<dim>>(prm, communicator);
    std::ostringstream quiet;
    problem->solve(quiet);
    return problem;
  }

  /** Read a file into a string. */
  inline std::string
  read_file(const std::string &name)
  {
    std::ifstream      in(name);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }

  /**
   * The text of parameters/SCENE with `extra` appended, on the condensed
   * path, writing no solution (results/ for the summary).
   */
  inline std::string
  condensed_scene(const std::string &scene, const std::string &extra)
  {
    return read_file(std::string(SOURCE_DIR) + "/../parameters/" + scene) +
           extra +
           "subsection Equilibrium reduction\n  set Path = condensed\nend\n"
           "subsection Output\n  set Write solution = false\n"
           "  set Output directory = results\nend\n";
  }

  /** "yes" if value <= bound: prints a check that can fail. */
  inline std::string
  check(const double value, const double bound)
  {
    std::ostringstream s;
    s << std::scientific << std::setprecision(3) << value;
    return (value <= bound) ? "yes" : "NO (value " + s.str() + ")";
  }
  /** How two augmented Lagrangian histories compare. */
  struct HistoryComparison
  {
    bool   same_alpha = false, same_sets = false;
    double p_difference = 0; // max |p_a - p_b| / max |p| over all updates
  };

  inline HistoryComparison
  compare_histories(const hrcontact::ContactIteration &a,
                    const hrcontact::ContactIteration &b)
  {
    HistoryComparison c;
    c.same_alpha = a.alpha_history.size() == b.alpha_history.size();
    c.same_sets  = c.same_alpha;
    double p_max = 0;
    for (unsigned int k = 0; c.same_alpha && k < a.alpha_history.size(); ++k)
      {
        c.same_alpha &= (a.alpha_history[k] == b.alpha_history[k]);
        c.same_sets &= (a.released_history[k] == b.released_history[k]);
        for (unsigned int i = 0; i < a.p_history[k].size(); ++i)
          {
            p_max = std::max(p_max, std::abs(a.p_history[k][i]));
            c.p_difference =
              std::max(c.p_difference,
                       std::abs(a.p_history[k][i] - b.p_history[k][i]));
          }
      }
    if (p_max > 0)
      c.p_difference /= p_max;
    return c;
  }

  /**
   * parameters/NAME.prm with its `Global refinements = FROM` set to
   * REFINEMENTS, no solution file, results in ./results: a shipped scene
   * at another mesh.
   */
  inline std::string
  scene_at_refinement(const std::string &name,
                      const unsigned int from,
                      const unsigned int refinements)
  {
    std::string text =
      read_file(std::string(SOURCE_DIR) + "/../parameters/" + name + ".prm");
    const std::string entry =
      "set Global refinements = " + std::to_string(from);
    text.replace(text.find(entry),
                 entry.size(),
                 "set Global refinements = " + std::to_string(refinements));
    return text + "subsection Output\n  set Write solution = false\n"
                  "  set Output directory = results\nend\n";
  }

  /** Runs @p text (solve and results) where an InputError is due: prints
   * "WHAT: refused: <its message>" or "WHAT: NOT refused". */
  template <int dim = 2>
  void
  print_input_refusal(const std::string &what, const std::string &text)
  {
    try
      {
        const auto         problem = solve_from_text<dim>(text);
        std::ostringstream quiet;
        problem->output_results(quiet);
        std::cout << what << ": NOT refused" << std::endl;
      }
    catch (const hrcontact::InputError &e)
      {
        std::cout << what << ": refused: " << e.what() << std::endl;
      }
  }
} // namespace hrcontact_tests

namespace hrcontact_tests
{
  /**
   * Signorini and equilibrium checks of a converged contact solution, from
   * the global displacement (not from the multipliers): w_n = u.n at each
   * unilateral row, p from Q s - q. Prints yes/NO lines. The equilibrium,
   * balance and tension checks use @p round_off (a power of ten): 1e-10,
   * more for an ill-conditioned problem, whose solve loses more digits.
   */
  template <int dim>
  void
  print_kkt(const hrcontact::HRProblem<dim> &problem,
            const double                     round_off = 1e-10)
  {
    const std::string tol =
      "1e" +
      std::to_string(static_cast<int>(std::round(std::log10(round_off))));
    const auto &sys = problem.results().system;
    // Force and length scales for the tolerances.
    double force = 0, length = 0;
    for (unsigned int k = 0; k < sys.contact_rows.size(); ++k)
      force = std::max(force, std::abs(problem.results().reactions.contact[k]));
    for (unsigned int i = 0; i < problem.results().displacement.size(); ++i)
      length = std::max(length, std::abs(problem.results().displacement[i]));
    double       max_p = -1e300, max_pen = -1e300, max_compl = 0;
    unsigned int pressed = 0, open = 0;
    for (unsigned int k = 0; k < sys.contact_rows.size(); ++k)
      {
        const auto &row = sys.rows[sys.contact_rows[k]];
        if (!row.unilateral)
          continue;
        double w = 0;
        for (const auto &[dof, c] : row.combination)
          w += c * problem.results().displacement[dof];
        const double p = problem.results().reactions.contact[k];
        max_p          = std::max(max_p, p / force);
        max_pen        = std::max(max_pen, (w - row.value) / length);
        max_compl =
          std::max(max_compl, std::abs(p * (w - row.value)) / (force * length));
        (p < -1e-6 * force ? pressed : open) += 1;
      }
    // Equilibrium of the free rows: C s = f.
    double                 eq = 0, f_scale = force;
    dealii::Vector<double> residual;
    // Complete: a serial run.
    const auto &s = problem.results().stress_unknowns();
    sys.equilibrium_residual(dealii::Vector<double>(s.begin(), s.end()),
                             residual);
    for (const unsigned int r : sys.free_rows)
      {
        double row_residual = 0;
        for (const auto &[dof, c] : sys.rows[r].combination)
          row_residual += c * residual[dof];
        eq      = std::max(eq, std::abs(row_residual));
        f_scale = std::max(f_scale, std::abs(sys.row_load(sys.rows[r])));
      }
    std::cout << "  contact constraints: " << pressed << " pressed, " << open
              << " open\n"
              << "  equilibrium max |C s - f| / force scale < " << tol << ": "
              << check(eq / f_scale, round_off) << "\n"
              << "  global balance |total load + total reaction| / |load| < "
              << tol << ": "
              << check(problem.results().summary.get_double(
                         "equilibrium_imbalance"),
                       round_off)
              << "\n  max p / max |p| <= " << tol
              << " (compressive reactions): " << check(max_p, round_off)
              << "\n  max (w_n - g) / max |u| <= 1e-8 (no penetration): "
              << check(max_pen, 1e-8)
              << "\n  max |p (w_n - g)| / (max |p| max |u|) <= 1e-8: "
              << check(max_compl, 1e-8) << std::endl;
  }
} // namespace hrcontact_tests

#include <deal.II/base/function_parser.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_matrix.h>

namespace hrcontact_tests
{
  /**
   * The standard Q1 displacement stiffness of linear plane-strain elasticity
   * (Lame constants) and the load vector of a body force and per-boundary
   * tractions, assembled independently of the library, constraints applied
   * as deal.II does (distribute_local_to_global). Several bodies: a
   * modulus per cell material id in `E_by_body` (E is then not used).
   */
  inline void
  assemble_q1_elasticity(
    const dealii::DoFHandler<2>                             &dh,
    const double                                             E,
    const double                                             nu,
    const std::string                                       &body_force,
    const std::map<dealii::types::boundary_id, std::string> &tractions,
    const dealii::AffineConstraints<double>                 &constraints,
    dealii::SparseMatrix<double>                            &K,
    dealii::Vector<double>                                  &rhs,
    const std::vector<double>                               &E_by_body = {})
  {
    using namespace dealii;
    const auto       &fe = dh.get_fe();
    FunctionParser<2> body(2);
    body.initialize("x,y", body_force, {});
    std::map<types::boundary_id, std::unique_ptr<FunctionParser<2>>> traction;
    for (const auto &[id, text] : tractions)
      {
        traction[id] = std::make_unique<FunctionParser<2>>(2);
        traction[id]->initialize("x,y", text, {});
      }
    const QGauss<2>                      quadrature(3);
    const QGauss<1>                      face_quadrature(3);
    FEValues<2>                          fv(fe,
                   quadrature,
                   update_values | update_gradients | update_quadrature_points |
                     update_JxW_values);
    FEFaceValues<2>                      ff(fe,
                       face_quadrature,
                       update_values | update_quadrature_points |
                         update_JxW_values);
    const unsigned int                   n = fe.n_dofs_per_cell();
    FullMatrix<double>                   Kc(n, n);
    Vector<double>                       fc(n), b(2);
    std::vector<types::global_dof_index> dofs(n);
    K   = 0;
    rhs = 0;
    for (const auto &cell : dh.active_cell_iterators())
      {
        const double e =
          E_by_body.empty() ? E : E_by_body.at(cell->material_id());
        const double lambda =
          e * nu / ((1 + nu) * (1 - 2 * nu)); // plane strain
        const double mu = e / (2 * (1 + nu));
        fv.reinit(cell);
        Kc = 0;
        fc = 0;
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          {
            body.vector_value(fv.quadrature_point(q), b);
            for (unsigned int i = 0; i < n; ++i)
              {
                const unsigned int ci = fe.system_to_component_index(i).first;
                for (unsigned int j = 0; j < n; ++j)
                  {
                    const unsigned int cj =
                      fe.system_to_component_index(j).first;
                    const auto gi = fv.shape_grad(i, q),
                               gj = fv.shape_grad(j, q);
                    Kc(i, j) +=
                      (lambda * gi[ci] * gj[cj] + mu * gi[cj] * gj[ci] +
                       (ci == cj ? mu * (gi * gj) : 0.)) *
                      fv.JxW(q);
                  }
                fc(i) += fv.shape_value(i, q) * b(ci) * fv.JxW(q);
              }
          }
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              traction.count(cell->face(f)->boundary_id()))
            {
              ff.reinit(cell, f);
              for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                {
                  traction[cell->face(f)->boundary_id()]->vector_value(
                    ff.quadrature_point(q), b);
                  for (unsigned int i = 0; i < n; ++i)
                    fc(i) += ff.shape_value(i, q) *
                             b(fe.system_to_component_index(i).first) *
                             ff.JxW(q);
                }
            }
        cell->get_dof_indices(dofs);
        constraints.distribute_local_to_global(Kc, fc, dofs, K, rhs);
      }
  }
} // namespace hrcontact_tests

namespace hrcontact_tests
{
  /**
   * The force a row's value (reaction) exerts, by component, summed over
   * all of the row's dofs: a contact pair's row spans two bodies, and its
   * force sums to zero (the balance report sums alike).
   */
  inline std::array<double, 3>
  row_force(const hrcontact::EquilibriumSystem &system,
            const hrcontact::EquilibriumRow    &row,
            const double                        value)
  {
    std::array<double, 3> force = {{0., 0., 0.}};
    for (unsigned int k = 0; k < row.combination.size(); ++k)
      force[system.dof_component(row.combination[k].first)] +=
        value * row.direction_component(k);
    return force;
  }

  /** The forces on the horizontal section of a 2D body through `point`
   * (compute_section_forces, `across` along x). */
  inline hrcontact::SectionForce
  horizontal_section(const hrcontact::Results<2> &res,
                     const dealii::Point<2>      &point)
  {
    hrcontact::SectionStation station;
    station.point  = point;
    station.across = dealii::Tensor<1, 2>({1., 0.});
    return hrcontact::compute_section_forces<2>(res.spaces,
                                                res.stress,
                                                res.displacement,
                                                {station})
      .front();
  }

  /** The stress constraint Material/Admissible stresses = name makes. */
  template <int dim>
  std::unique_ptr<hrcontact::StressConstraint<dim>>
  make_stress_constraint(const std::string &name)
  {
    dealii::ParameterHandler prm;
    hrcontact::StressConstraintFactory<dim>::declare_parameters(prm);
    prm.parse_input_from_string(
      "subsection Material\n  set Admissible stresses = " + name + "\nend\n");
    return hrcontact::StressConstraintFactory<dim>::create(prm);
  }

  /**
   * The in-plane Lame constants (lambda, G) of E = 1000, nu = 0.3, which
   * the point-law tests use: plane stress reduces lambda.
   */
  inline std::pair<double, double>
  test_lame_constants(const std::string &plane)
  {
    const double E = 1000, nu = 0.3;
    const double G      = E / (2 * (1 + nu));
    double       lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
    if (plane == "plane stress")
      lambda = 2 * lambda * G / (lambda + 2 * G);
    return {lambda, G};
  }

  /**
   * The manufactured no-tension pier's text (parameters/no-tension-
   * manufactured-pier.prm) turned into its no-compression mirror: the top
   * pulled by the same triangle, the base held both ways instead of
   * @p support (a membrane is not pushed by a foundation), no obstacle.
   */
  inline std::string
  no_compression_mirror(std::string text, const std::string &support)
  {
    for (const auto &[from, to] :
         std::vector<std::pair<std::string, std::string>>{
           {"= no tension", "= no compression"},
           {"3: 0; -q*", "3: 0; q*"},
           {"Reference stress = 0; -q*", "Reference stress = 0; q*"},
           {support, "Prescribed displacements = 2: 0; 0"},
           {"set Obstacles = 2: 0, 0 : 0, -1", ""}})
      text.replace(text.find(from), from.size(), to);
    return text;
  }

  /** max |a_k - b_k| of two step histories; 1 if their lengths differ. */
  inline double
  history_difference(const std::vector<double> &a, const std::vector<double> &b)
  {
    if (a.size() != b.size())
      return 1;
    double d = 0;
    for (unsigned int k = 0; k < a.size(); ++k)
      d = std::max(d, std::abs(a[k] - b[k]));
    return d;
  }

  /**
   * constraint_patch in 2D under "no tension" with @p extra, held by rollers
   * on x = 0 and y = 0 and pulled by a traction on x = 1 that only tension
   * could carry: "refused, naming the cause: yes" when the run stops with
   * the named cause, else what happened.
   */
  inline std::string
  tension_traction_refusal(const std::string &extra)
  {
    const double      eps[3][3] = {};
    const std::string text =
      constraint_patch<2>("no tension", eps, extra) +
      "subsection Supports\n"
      "  set Prescribed displacements = 0 x: 0 | 2 y: 0\nend\n"
      "subsection Loads\n  set Tractions = 1: 1; 0\nend\n";
    try
      {
        solve_from_text<2>(text);
        return "NOT refused";
      }
    catch (const hrcontact::NotConvergedError &e)
      {
        const std::string what = e.what();
        return std::string("refused, naming the cause: ") +
               (what.find("no admissible stress field") != std::string::npos ?
                  "yes" :
                  "NO: " + what);
      }
  }
} // namespace hrcontact_tests

#endif
