#include <hrcontact/solvers/condensed/mumps_factor.h>

#include <algorithm>
#include <numeric>

#include <Epetra_CrsMatrix.h>
#include <Epetra_MultiVector.h>
#include <dmumps_c.h>

namespace hrcontact
{
  struct MumpsFactor::Instance
  {
    DMUMPS_STRUC_C id;
  };

  MumpsFactor::MumpsFactor(const MPI_Comm communicator)
    : instance(std::make_unique<Instance>())
    , communicator(communicator)
  {
    DMUMPS_STRUC_C &id = instance->id;
    id.comm_fortran    = static_cast<MUMPS_INT>(MPI_Comm_c2f(communicator));
    id.par             = 1; // the first process works too
    id.sym             = 1; // symmetric positive definite: LDL^T
    id.job             = -1;
    dmumps_c(&id);
    // Silent; distributed assembled input, centralised b and x.
    id.icntl[0]  = -1;
    id.icntl[1]  = -1;
    id.icntl[2]  = -1;
    id.icntl[3]  = 0;
    id.icntl[4]  = 0;
    id.icntl[17] = 3;
    id.icntl[19] = 0;
    id.icntl[20] = 0;
  }

  MumpsFactor::~MumpsFactor()
  {
    instance->id.job = -2;
    dmumps_c(&instance->id);
  }

  bool
  MumpsFactor::call(const int job)
  {
    DMUMPS_STRUC_C &id = instance->id;
    id.job             = job;
    dmumps_c(&id);
    // Too little working space for the pivots' fill-in (INFOG(1) = -8, -9,
    // -14, -15, -17 to -20): the numerical phases again with ICNTL(14), the
    // estimate's margin, doubled, up to 640 %. INFOG(1) is the same on
    // every process.
    const auto short_of_space = [&]() {
      const int e = id.infog[0];
      return e == -8 || e == -9 || e == -14 || e == -15 ||
             (e <= -17 && e >= -20);
    };
    while (job >= 2 && short_of_space() && id.icntl[13] < 640)
      {
        id.icntl[13] = 2 * std::max(id.icntl[13], 20);
        id.job       = job;
        dmumps_c(&id);
      }
    return id.infog[0] >= 0;
  }

  int
  MumpsFactor::error() const
  {
    return instance->id.infog[0];
  }

  bool
  MumpsFactor::factorise(const Epetra_CrsMatrix &matrix)
  {
    DMUMPS_STRUC_C &id = instance->id;
    if (!analysed)
      {
        rows.clear();
        columns.clear();
        kept.clear();
        for (int i = 0; i < matrix.NumMyRows(); ++i)
          {
            int     n = 0;
            double *v = nullptr;
            int    *j = nullptr;
            matrix.ExtractMyRowView(i, n, v, j);
            const long long row = matrix.RowMap().GID64(i);
            for (int k = 0; k < n; ++k)
              {
                const long long column = matrix.ColMap().GID64(j[k]);
                kept.push_back(column >= row);
                if (column < row)
                  continue;
                rows.push_back(static_cast<int>(row + 1));
                columns.push_back(static_cast<int>(column + 1));
              }
          }
        values.resize(rows.size());
        own_rows.resize(matrix.NumMyRows());
        for (int i = 0; i < matrix.NumMyRows(); ++i)
          own_rows[i] = static_cast<int>(matrix.RowMap().GID64(i));
        // Who holds which rows, on the first process.
        const int n_processes =
                    dealii::Utilities::MPI::n_mpi_processes(communicator),
                  rank = dealii::Utilities::MPI::this_mpi_process(communicator);
        const int own  = static_cast<int>(own_rows.size());
        counts.assign(n_processes, 0);
        MPI_Gather(
          &own, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, communicator);
        offsets.assign(n_processes, 0);
        if (rank == 0)
          std::partial_sum(counts.begin(),
                           counts.end() - 1,
                           offsets.begin() + 1);
        all_rows.resize(
          rank == 0 ? std::accumulate(counts.begin(), counts.end(), 0) : 0);
        MPI_Gatherv(own_rows.data(),
                    own,
                    MPI_INT,
                    all_rows.data(),
                    counts.data(),
                    offsets.data(),
                    MPI_INT,
                    0,
                    communicator);
        full.resize(all_rows.size());

        id.n       = static_cast<MUMPS_INT>(matrix.NumGlobalRows64());
        id.nz_loc  = static_cast<MUMPS_INT>(rows.size());
        id.nnz_loc = static_cast<MUMPS_INT8>(rows.size());
        id.irn_loc = rows.data();
        id.jcn_loc = columns.data();
        if (!call(1))
          return false;
        analysed = true;
      }
    // The values in the analysed positions (the pattern is the same).
    std::size_t entry = 0, m = 0;
    for (int i = 0; i < matrix.NumMyRows(); ++i)
      {
        int     n = 0;
        double *v = nullptr;
        matrix.ExtractMyRowView(i, n, v);
        for (int k = 0; k < n; ++k)
          if (kept[entry++])
            values[m++] = v[k];
      }
    id.a_loc = values.data();
    return call(2);
  }

  bool
  MumpsFactor::solve(const Epetra_MultiVector &b, Epetra_MultiVector &x)
  {
    DMUMPS_STRUC_C &id  = instance->id;
    const int       own = static_cast<int>(own_rows.size());
    const int rank = dealii::Utilities::MPI::this_mpi_process(communicator);
    std::vector<double> gathered(all_rows.size());
    MPI_Gatherv(b[0],
                own,
                MPI_DOUBLE,
                gathered.data(),
                counts.data(),
                offsets.data(),
                MPI_DOUBLE,
                0,
                communicator);
    if (rank == 0)
      for (std::size_t k = 0; k < all_rows.size(); ++k)
        full[all_rows[k]] = gathered[k];
    id.rhs        = full.data();
    id.nrhs       = 1;
    id.lrhs       = id.n;
    const bool ok = call(3);
    if (rank == 0)
      for (std::size_t k = 0; k < all_rows.size(); ++k)
        gathered[k] = full[all_rows[k]];
    MPI_Scatterv(gathered.data(),
                 counts.data(),
                 offsets.data(),
                 MPI_DOUBLE,
                 x[0],
                 own,
                 MPI_DOUBLE,
                 0,
                 communicator);
    return ok;
  }
} // namespace hrcontact
