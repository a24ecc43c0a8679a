#include <hrcontact/core/input.h>
#include <hrcontact/discretisation/dof_partition.h>
#include <hrcontact/postprocess/summary.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace hrcontact
{
  void
  Summary::add(const std::string &key, const std::string &value)
  {
    entries.emplace_back(key, value);
  }

  void
  Summary::add(const std::string &key, const double value)
  {
    std::ostringstream s;
    s << std::setprecision(10) << value;
    entries.emplace_back(key, s.str());
  }

  std::string
  Summary::get(const std::string &key) const
  {
    for (const auto &[k, v] : entries)
      if (k == key)
        return v;
    throw std::runtime_error("summary has no key '" + key + "'");
  }

  double
  Summary::get_double(const std::string &key) const
  {
    return std::stod(get(key));
  }

  void
  write_file_atomically(const std::string                         &filename,
                        const std::function<void(std::ostream &)> &writer)
  {
    const std::string tmp = filename + ".tmp";
    {
      std::ofstream out(tmp);
      if (!out)
        throw InputError("Output: cannot write '" + tmp +
                         "' (check Output directory).");
      writer(out);
      out.flush();
      if (!out)
        throw InputError("Output: writing '" + tmp + "' failed.");
    }
    std::filesystem::rename(tmp, filename);
  }

  void
  write_file_atomically(const MPI_Comm                             communicator,
                        const std::string                         &filename,
                        const std::function<void(std::ostream &)> &writer)
  {
    if (is_root_process(communicator))
      write_file_atomically(filename, writer);
  }

  void
  Summary::write(const std::string &filename) const
  {
    write_file_atomically(filename, [this](std::ostream &out) {
      for (const auto &[k, v] : entries)
        out << k << " = " << v << '\n';
    });
  }
} // namespace hrcontact
