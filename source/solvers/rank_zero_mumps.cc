#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <contact_fem/solvers/rank_zero_mumps.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Import.h>
#include <Epetra_Map.h>
#include <Epetra_MpiComm.h>
#include <Epetra_MultiVector.h>
#include <dmumps_c.h>
#include <mpi.h>

namespace contact_fem
{
  struct RankZeroMumps::Instance
  {
    DMUMPS_STRUC_C data;
  };

  namespace
  {
    MPI_Comm
    communicator(const Epetra_CrsMatrix &matrix)
    {
      return dynamic_cast<const Epetra_MpiComm &>(matrix.Comm()).Comm();
    }
  } // namespace

  RankZeroMumps::RankZeroMumps() = default;

  RankZeroMumps::~RankZeroMumps()
  {
    destroy();
  }

  void
  RankZeroMumps::destroy()
  {
    if (mumps)
      {
        mumps->data.job = -2;
        dmumps_c(&mumps->data);
        mumps.reset();
      }
  }

  void
  RankZeroMumps::set_icntl(const int index, const int value)
  {
    icntl.emplace_back(index, value);
  }

  void
  RankZeroMumps::set_cntl(const int index, const double value)
  {
    cntl.emplace_back(index, value);
  }

  void
  RankZeroMumps::gather(const Epetra_CrsMatrix &matrix, const bool pattern)
  {
    // One process: the caller's matrix as it is, rows and entries in the
    // order Amesos_Mumps passed them (the ordering, METIS, sees that order).
    std::unique_ptr<Epetra_CrsMatrix> gathered;
    const Epetra_CrsMatrix           *source = &matrix;
    if (matrix.Comm().NumProc() > 1)
      {
        if (pattern)
          {
            const int n = matrix.NumGlobalRows();
            gathered_map =
              std::make_unique<Epetra_Map>(n, matrix.Comm().MyPID() == 0 ? n : 0, 0, matrix.Comm());
            importer = std::make_unique<Epetra_Import>(*gathered_map, matrix.RowMap());
          }
        gathered = std::make_unique<Epetra_CrsMatrix>(Copy, *gathered_map, 0);
        AssertThrow(gathered->Import(matrix, *importer, Insert) == 0 &&
                      gathered->FillComplete() == 0,
                    dealii::ExcMessage("gathering the matrix on process 0 failed"));
        source = gathered.get();
      }
    if (pattern)
      {
        rows.resize(source->NumMyNonzeros());
        columns.resize(source->NumMyNonzeros());
      }
    values.resize(source->NumMyNonzeros());
    std::size_t count = 0;
    for (int row = 0; row < source->NumMyRows(); ++row)
      {
        int     n_entries;
        double *row_values;
        int    *indices;
        source->ExtractMyRowView(row, n_entries, row_values, indices);
        for (int j = 0; j < n_entries; ++j, ++count)
          {
            if (pattern)
              {
                rows[count]    = source->RowMap().GID(row) + 1;
                columns[count] = source->ColMap().GID(indices[j]) + 1;
              }
            values[count] = row_values[j];
          }
      }
  }

  int
  RankZeroMumps::run(const int job, const Epetra_CrsMatrix &matrix)
  {
    const MPI_Comm comm = communicator(matrix);
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      {
        mumps->data.job = job;
        dmumps_c(&mumps->data);
        last_info = {{mumps->data.infog[0], mumps->data.infog[1], mumps->data.infog[27]}};
      }
    last_info = dealii::Utilities::MPI::broadcast(comm, last_info, 0);
    return last_info[0];
  }

  int
  RankZeroMumps::analyse(const Epetra_CrsMatrix &matrix)
  {
    destroy();
    gather(matrix, true);
    const MPI_Comm comm = communicator(matrix);
    if (dealii::Utilities::MPI::this_mpi_process(comm) != 0)
      {
        last_info = dealii::Utilities::MPI::broadcast(comm, last_info, 0);
        return last_info[0];
      }
    mumps                = std::make_unique<Instance>();
    DMUMPS_STRUC_C &data = mumps->data;
    data                 = DMUMPS_STRUC_C{};
    data.comm_fortran    = static_cast<MUMPS_INT>(MPI_Comm_c2f(MPI_COMM_SELF));
    data.par             = 1; // the host works
    data.sym             = 0; // unsymmetric (the condensed system is)
    data.job             = -1;
    dmumps_c(&data);
    // The controls Amesos_Mumps set (Trilinos 13.2, Amesos_Mumps.cpp,
    // SetICNTLandCNTL) on one process; MUMPS' defaults otherwise.
    const std::array<std::pair<int, int>, 19> amesos = {{{1, -1},
                                                         {2, -1},
                                                         {3, -1},
                                                         {4, -1},
                                                         {5, 0},
                                                         {6, 7},
                                                         {7, 7},
                                                         {8, 7},
                                                         {9, 1},
                                                         {10, 0},
                                                         {11, 0},
                                                         {12, 0},
                                                         {13, 0},
                                                         {14, 20},
                                                         {15, 0},
                                                         {16, 0},
                                                         {17, 0},
                                                         {18, 0},
                                                         {19, 0}}};
    for (const auto &[index, value] : amesos)
      data.icntl[index - 1] = value;
    for (const auto &[index, value] : icntl)
      data.icntl[index - 1] = value;
    for (const auto &[index, value] : cntl)
      data.cntl[index - 1] = value;
    data.n   = matrix.NumGlobalRows();
    data.nz  = static_cast<MUMPS_INT>(rows.size());
    data.irn = rows.data();
    data.jcn = columns.data();
    data.a   = values.data();
    return run(1, matrix);
  }

  int
  RankZeroMumps::factorise(const Epetra_CrsMatrix &matrix)
  {
    gather(matrix, false);
    if (mumps)
      mumps->data.a = values.data();
    return run(2, matrix);
  }

  int
  RankZeroMumps::solve(Epetra_MultiVector &x, const Epetra_MultiVector &b)
  {
    const auto &matrix_map = x.Map();
    const bool  parallel   = matrix_map.Comm().NumProc() > 1;
    // One process: MUMPS overwrites its right-hand side with the solution,
    // x itself as with Amesos_Mumps.
    std::unique_ptr<Epetra_MultiVector> gathered;
    Epetra_MultiVector                 *work = &x;
    if (parallel)
      {
        gathered = std::make_unique<Epetra_MultiVector>(*gathered_map, b.NumVectors());
        AssertThrow(gathered->Import(b, *importer, Insert) == 0,
                    dealii::ExcMessage("gathering the right-hand side failed"));
        work = gathered.get();
      }
    else
      *work = b;
    const MPI_Comm comm = dynamic_cast<const Epetra_MpiComm &>(matrix_map.Comm()).Comm();
    for (int v = 0; v < b.NumVectors(); ++v)
      {
        if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
          {
            mumps->data.rhs = (*work)[v];
            mumps->data.job = 3;
            dmumps_c(&mumps->data);
            last_info = {{mumps->data.infog[0], mumps->data.infog[1], mumps->data.infog[27]}};
          }
        last_info = dealii::Utilities::MPI::broadcast(comm, last_info, 0);
        if (last_info[0] < 0)
          return last_info[0];
      }
    if (parallel)
      AssertThrow(x.Export(*gathered, *importer, Insert) == 0,
                  dealii::ExcMessage("scattering the solution failed"));
    return last_info[0];
  }
} // namespace contact_fem
