#ifndef hrcontact_postprocessor_h
#define hrcontact_postprocessor_h

#include <deal.II/base/parameter_handler.h>

#include <deal.II/lac/vector.h>

#include <hrcontact/core/input.h>
#include <hrcontact/core/results.h>
#include <hrcontact/postprocess/summary.h>

#include <functional>
#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace hrcontact
{
  /** Where a postprocessor puts what it computes. */
  struct PostprocessOutput
  {
    Summary      &summary;
    std::ostream &log;
    /** The Output directory (exists when postprocessors run). */
    std::string directory;
    /** Process 0 of it writes the replicated tables. */
    MPI_Comm communicator;
    /** Files to name in the run's last line beside summary.txt. */
    std::vector<std::string> mentioned_files;
    /**
     * Cell fields (one value per active cell) a postprocessor computed for
     * solution.vtu, by name: those that run before "solution" publish them
     * here (the error bound's indicators).
     */
    std::map<std::string, dealii::Vector<float>> cell_fields;
  };

  /**
   * One thing computed after the solve: a report in summary.txt and the
   * log, a table, a field file (ASPECT's postprocessor pattern). Each
   * implementation registers itself by name with
   * HRCONTACT_REGISTER_POSTPROCESSOR and declares its own parameters;
   * `Postprocess/List of postprocessors` chooses which run and in what
   * order (doc/design.md, "Adding a postprocessor").
   */
  template <int dim>
  class Postprocessor
  {
  public:
    virtual ~Postprocessor() = default;

    /** Read this postprocessor's parameters (declared by its static
     * declare_parameters). */
    virtual void
    parse_parameters(dealii::ParameterHandler &prm, const Constants &constants);

    /**
     * Why it has nothing to do for this run (e.g. no contact), or empty
     * when it applies. `all` skips it silently; a list that names it says so
     * in the log.
     */
    virtual std::string
    skip_reason(const Results<dim> &results) const;

    /** Compute and report. */
    virtual void
    execute(const Results<dim> &results, PostprocessOutput &output) = 0;
    /**
     * Whether it needs every cell of the mesh on every process for this
     * scene (a walk across the mesh), so that a parallel run keeps the
     * serial mesh. Most work on each process's own cells and sum.
     */
    virtual bool
    needs_replicated_mesh(const Scene<dim> &scene) const;
    /**
     * Check its input against the scene, the mesh and the classified rows
     * before the solve (a probe outside the body, a scene or a contact the
     * error bound does not cover), throwing InputError; collective.
     * Nothing by default.
     */
    virtual void
    check_input(const Scene<dim>                 &scene,
                const dealii::Triangulation<dim> &triangulation,
                const EquilibriumSystem          &system) const;
  };

  /**
   * The name -> factory registry of postprocessors and the list a run
   * executes. `all` (the default) runs every registered postprocessor that
   * applies, in the order of their registered positions: the order of the
   * keys in summary.txt.
   */
  template <int dim>
  class PostprocessorManager
  {
  public:
    using Factory = std::function<std::unique_ptr<Postprocessor<dim>>()>;

    /**
     * Register a postprocessor; called at start-up by
     * HRCONTACT_REGISTER_POSTPROCESSOR. `position` orders `all`.
     */
    static bool
    register_postprocessor(
      const std::string                                     &name,
      const std::string                                     &description,
      const unsigned int                                     position,
      const std::function<void(dealii::ParameterHandler &)> &declare,
      const Factory                                         &factory);

    /** The list entry and every registered postprocessor's parameters. */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** Create the listed postprocessors and let them read their
     * parameters; an unknown name is an InputError. */
    void
    parse_parameters(dealii::ParameterHandler &prm, const Constants &constants);

    /** Run them in order. */
    void
    execute(const Results<dim> &results, PostprocessOutput &output) const;
    /** Whether one of them needs every cell on every process. */
    bool
    needs_replicated_mesh(const Scene<dim> &scene) const;
    /** Each one's check_input. */
    void
    check_input(const Scene<dim>                 &scene,
                const dealii::Triangulation<dim> &triangulation,
                const EquilibriumSystem          &system) const;

    /** The names registered, in `all` order. */
    static std::vector<std::string>
    registered_names();

  private:
    struct Entry
    {
      std::string                                     name, description;
      unsigned int                                    position = 0;
      std::function<void(dealii::ParameterHandler &)> declare;
      Factory                                         factory;
    };
    static std::vector<Entry> &
    registry();

    /** Whether the list was `all` (skip silently what does not apply). */
    bool                                             run_all = true;
    std::vector<std::string>                         names;
    std::vector<std::unique_ptr<Postprocessor<dim>>> postprocessors;
  };
} // namespace hrcontact

/**
 * Register CLASSNAME<2> and CLASSNAME<3> as postprocessor NAME at POSITION
 * of `all`, in the class's source file.
 */
#define HRCONTACT_REGISTER_POSTPROCESSOR(classname, name, position, text) \
  namespace                                                               \
  {                                                                       \
    const bool classname##_registered_2d =                                \
      ::hrcontact::PostprocessorManager<2>::register_postprocessor(       \
        name,                                                             \
        text,                                                             \
        position,                                                         \
        &classname<2>::declare_parameters,                                \
        [] { return std::make_unique<classname<2>>(); });                 \
    const bool classname##_registered_3d =                                \
      ::hrcontact::PostprocessorManager<3>::register_postprocessor(       \
        name,                                                             \
        text,                                                             \
        position,                                                         \
        &classname<3>::declare_parameters,                                \
        [] { return std::make_unique<classname<3>>(); });                 \
  }

#endif
