#ifndef hrcontact_postprocessor_h
#define hrcontact_postprocessor_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <deal.II/lac/vector.h>

#include <hrcontact/core/scene.h>
#include <hrcontact/discretisation/dof_partition.h>
#include <hrcontact/discretisation/equilibrium_system.h>
#include <hrcontact/discretisation/mixed_spaces.h>

#include <memory>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace hrcontact
{
  /** Ordered "key = value" lines of summary.txt. */
  class Summary
  {
  public:
    void
    add(const std::string &key, const std::string &value);
    void
    add(const std::string &key, const double value);
    /** Value of a key; throws if absent. */
    std::string
    get(const std::string &key) const;
    double
    get_double(const std::string &key) const;
    /** Write atomically (temporary file, then rename). */
    void
    write(const std::string &filename) const;

    std::vector<std::pair<std::string, std::string>> entries;
  };

  /** Write a file atomically: whole or not at all. */
  void
  write_file_atomically(const std::string                         &filename,
                        const std::function<void(std::ostream &)> &writer);

  /**
   * The same on process 0 of the communicator only: every process holds the
   * replicated results, one writes them.
   */
  void
  write_file_atomically(const MPI_Comm                             communicator,
                        const std::string                         &filename,
                        const std::function<void(std::ostream &)> &writer);

  /**
   * Everything computed after the solve: global balance, probes at points,
   * comparison with reference values and a reference stress field, and the
   * output files of design.md section 6 (summary.txt, solution.vtu).
   */
  template <int dim>
  class Postprocessor
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm, const Constants &constants);

    /** A displacement or stress quantity at a point. */
    double
    point_value(const MixedSpaces<dim>       &spaces,
                const Scene<dim>             &scene,
                const dealii::Vector<double> &u,
                const dealii::Vector<double> &s,
                const dealii::Point<dim>     &point,
                const std::string            &quantity) const;

    /**
     * Max and L2 norms of sigma_h - sigma_ref over the mesh, each relative
     * to the same norm of sigma_ref (Frobenius norm pointwise).
     */
    std::pair<double, double>
    stress_error(const MixedSpaces<dim>       &spaces,
                 const dealii::Vector<double> &s) const;

    /** Fill the summary with probes, references, errors. */
    void
    evaluate(const MixedSpaces<dim>       &spaces,
             const Scene<dim>             &scene,
             const dealii::Vector<double> &u,
             const dealii::Vector<double> &s,
             Summary                      &summary,
             std::ostream                 &log) const;

    /**
     * solution.vtu, or with several processes solution.pvtu and one piece
     * solution_NNNN.vtu per process with the cells it owns (and a
     * "subdomain" field). Returns the name written.
     */
    std::string
    write_solution(const MixedSpaces<dim>       &spaces,
                   const Scene<dim>             &scene,
                   const dealii::Vector<double> &u,
                   const dealii::Vector<double> &s,
                   const DofPartition           &partition,
                   const std::string            &directory) const;

    struct Probe
    {
      std::string        name;
      dealii::Point<dim> point;
      std::string        quantity;
    };
    std::vector<Probe>                           probes;
    std::vector<std::pair<std::string, double>>  reference_values;
    std::unique_ptr<dealii::FunctionParser<dim>> reference_stress;
  };
} // namespace hrcontact

#endif
