// A material whose compliance changes with its state (MaterialLaw): after
// HRAssembler::refresh_flexibility and NewtonStepPath::flexibility_changed,
// each Newton-step path solves with the new cell flexibilities F_c. The law
// here scales the plane-strain compliance by lambda; the block of
// parameters/block.prm is driven by a prescribed displacement alone, so
// lambda = 2 must halve every stress and keep the displacements, and agree
// with a fresh assembly at lambda = 2. A path that is not told keeps the
// old compliance: its support reactions do not change (the check can
// fail).

#include <deal.II/base/mpi.h>

#include <deal.II/grid/tria.h>

#include <hrcontact/core/scene.h>
#include <hrcontact/discretisation/dof_partition.h>
#include <hrcontact/discretisation/hr_assembler.h>
#include <hrcontact/discretisation/mixed_spaces.h>
#include <hrcontact/material/material_law.h>
#include <hrcontact/solvers/condensed/condensed_step.h>
#include <hrcontact/solvers/equilibrium_reduction.h>
#include <hrcontact/solvers/null_space_step.h>

#include "tests.h"

using namespace dealii;
using namespace hrcontact;

/** Plane strain isotropic compliance times a scale the test changes. */
class ScaledCompliance : public MaterialLaw<2>
{
public:
  void
  parse_parameters(ParameterHandler &, const Constants &) override
  {}
  SymmetricTensor<2, 2>
  strain(const SymmetricTensor<2, 2> &sigma, const Point<2> &) const override
  {
    // E' = E/(1 - nu^2), nu' = nu/(1 - nu) in plane strain.
    const double Ep = E / (1 - nu * nu), nup = nu / (1 - nu);
    return scale * ((1 + nup) / Ep * sigma -
                    nup / Ep * trace(sigma) * unit_symmetric_tensor<2>());
  }
  SymmetricTensor<2, 2>
  compliance_times(const SymmetricTensor<2, 2> &,
                   const SymmetricTensor<2, 2> &tau,
                   const Point<2>              &x) const override
  {
    return strain(tau, x);
  }
  bool
  is_linear() const override
  {
    return false;
  }
  double
  nodal_compliance(const Triangulation<2> &) const override
  {
    return scale * (1 - nu * nu) / E;
  }
  double
  out_of_plane_stress(const SymmetricTensor<2, 2> &sigma) const override
  {
    return nu * trace(sigma);
  }
  std::string
  plane_condition_name() const override
  {
    return "plane strain";
  }

  double E = 30e9, nu = 0.2, scale = 1;
};

struct Fields
{
  Vector<double> s, u;
};

Fields
solve(NewtonStepPath &path, const EquilibriumSystem &system)
{
  const unsigned int  nq = system.contact_rows.size();
  std::vector<double> p;
  path.solve(std::vector<bool>(nq, false),
             std::vector<double>(nq, 0.),
             std::vector<double>(nq, 1.),
             p);
  Fields                 f;
  hrcontact::FieldVector s(system.n_stress_dofs); // complete: serial mesh
  path.stresses(s);
  f.s = Vector<double>(s.begin(), s.end());
  std::vector<double> w(nq);
  for (unsigned int k = 0; k < nq; ++k)
    w[k] = system.rows[system.contact_rows[k]].value;
  hrcontact::FieldVector u(system.n_displacement_dofs); // complete
  path.displacements(w, u);
  f.u = Vector<double>(u.begin(), u.end());
  return f;
}

/** The support reactions r = H s - f_H (from the stored cells only). */
Vector<double>
reactions(const EquilibriumSystem &system, const Vector<double> &s)
{
  Vector<double> r(system.prescribed_rows.size());
  for (unsigned int k = 0; k < r.size(); ++k)
    {
      const EquilibriumRow &row = system.rows[system.prescribed_rows[k]];
      r[k] = system.row_times(row, s) - system.row_load(row);
    }
  return r;
}

double
relative(const Vector<double> &a, const Vector<double> &b)
{
  Vector<double> d = a;
  d -= b;
  return d.linfty_norm() / b.linfty_norm();
}

int
main(int argc, char **argv)
{
  // Trilinos (the CG + AMG variant) needs MPI.
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ParameterHandler                         prm;
  declare_all_parameters(prm);
  prm.parse_input_from_string(hrcontact_tests::read_file(
    std::string(SOURCE_DIR) + "/../parameters/block.prm"));
  Scene<2> scene;
  scene.parse_parameters(prm);
  auto law       = std::make_shared<ScaledCompliance>();
  scene.material = law;
  Triangulation<2> tria;
  scene.create_mesh(tria);
  MixedSpaces<2> spaces;
  spaces.parse_parameters(prm);
  spaces.setup(tria);

  // The condensed path with CG + AMG and a kept hierarchy too: the refresh
  // rebuilds K, and the hierarchy ML built on the old matrix must go first.
  for (const std::string name : {"null-space", "condensed", "condensed-cg"})
    {
      law->scale = 1;
      HRAssembler<2>    assembler(scene, spaces);
      EquilibriumSystem system;
      assembler.classify_rows(system);
      const DofPartition serial =
        serial_partition(system.n_displacement_dofs, tria.n_active_cells());
      const bool condensed = (name != "null-space");
      const bool cg        = (name == "condensed-cg");
      // The condensed path on a lean system: the refresh must reach the
      // cells whose blocks are recomputed on demand too.
      assembler.assemble_blocks(system, condensed ? &serial : nullptr);
      EquilibriumReduction            reduction;
      std::unique_ptr<NewtonStepPath> path;
      LinearSolverSettings            settings;
      if (cg)
        {
          settings.solver = hrcontact::LinearSolverSettings::Choice::cg_amg;
          settings.reuse_preconditioner =
            hrcontact::LinearSolverSettings::Reuse::always;
        }
      if (condensed)
        path = std::make_unique<CondensedStep>(system, settings);
      else
        {
          reduction.initialize(system);
          path = std::make_unique<NullSpaceStep>(reduction);
        }
      const Fields first = solve(*path, system);

      law->scale         = 2;
      const Fields stale = solve(*path, system);
      assembler.refresh_flexibility(system, first.s);
      path->flexibility_changed();
      const Fields second = solve(*path, system);

      // A fresh assembly at lambda = 2.
      HRAssembler<2>    fresh_assembler(scene, spaces);
      EquilibriumSystem fresh_system;
      fresh_assembler.classify_rows(fresh_system);
      fresh_assembler.assemble_blocks(fresh_system,
                                      condensed ? &serial : nullptr);
      EquilibriumReduction            fresh_reduction;
      std::unique_ptr<NewtonStepPath> fresh_path;
      if (condensed)
        fresh_path = std::make_unique<CondensedStep>(fresh_system);
      else
        {
          fresh_reduction.initialize(fresh_system);
          fresh_path = std::make_unique<NullSpaceStep>(fresh_reduction);
        }
      const Fields reference = solve(*fresh_path, fresh_system);

      Vector<double> half = first.s;
      half *= 0.5;
      // CG to 1e-12 of the right-hand side: agreement to 1e-8 there.
      const double      exact = cg ? 1e-8 : 1e-12;
      const std::string tol   = cg ? "1e-8" : "1e-12";
      std::cout
        << name << " path, " << tria.n_active_cells() << " cells"
        << (condensed ? " (lean storage)" : "") << ":\n"
        << "  without flexibility_changed the support reactions stay "
           "those of lambda = 1: "
        << hrcontact_tests::check(relative(reactions(system, stale.s),
                                           reactions(system, first.s)),
                                  exact)
        << "\n  after the refresh the stresses halve ("
        << (cg ? "1e-8" : "1e-10") << "): "
        << hrcontact_tests::check(relative(second.s, half), cg ? 1e-8 : 1e-10)
        << "\n  and the displacements stay (" << (cg ? "1e-8" : "1e-10")
        << "): "
        << hrcontact_tests::check(relative(second.u, first.u),
                                  cg ? 1e-8 : 1e-10)
        << "\n  stresses equal a fresh assembly at lambda = 2 (" << tol << "): "
        << hrcontact_tests::check(relative(second.s, reference.s), exact)
        << "\n  displacements too (" << tol << "): "
        << hrcontact_tests::check(relative(second.u, reference.u), exact)
        << std::endl;
    }
}
