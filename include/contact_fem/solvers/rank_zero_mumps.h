// MUMPS on the first process, on the matrix gathered there.
#ifndef contact_fem_rank_zero_mumps_h
#define contact_fem_rank_zero_mumps_h

#include <array>
#include <memory>
#include <vector>

class Epetra_CrsMatrix;
class Epetra_Import;
class Epetra_Map;
class Epetra_MultiVector;

namespace contact_fem
{
  /**
   * MUMPS (dmumps_c) on process 0 alone, with the matrix and the right-hand
   * side gathered there and the solution scattered back.
   *
   * Why not MUMPS on all processes: its parallel factorisation is
   * asynchronous (dynamically scheduled fronts, contribution blocks
   * assembled in the order their messages arrive), so that two runs of the
   * same system on 2 processes returned solutions that differed in the last
   * bits (the same matrix and right-hand side, bit for bit), and outputs of
   * the same scene differed between reruns (doc/stability.md,
   * "Reproducibility"). On one process MUMPS is deterministic. Amesos_Mumps
   * cannot restrict MUMPS to a subset of the processes here (Debian's
   * Trilinos is built without MPI_Comm_c2f: it always hands MUMPS
   * MPI_COMM_WORLD), hence this driver.
   *
   * The control parameters are those Amesos_Mumps set before (verified
   * field by field in a serial run), plus the caller's (set_icntl(),
   * set_cntl()): a serial run factorises exactly as it did with Amesos.
   *
   * Collective: every process calls every member function; only process 0
   * calls MUMPS. The status (info()) is broadcast to all processes.
   */
  class RankZeroMumps
  {
  public:
    RankZeroMumps();
    ~RankZeroMumps();

    /// Set before analyse() (MUMPS' 1-based numbering).
    void
    set_icntl(int index, int value);
    void
    set_cntl(int index, double value);

    /// Gathers the pattern of @p matrix and computes its symbolic
    /// factorisation (job 1). Returns INFOG(1) (0: success).
    int
    analyse(const Epetra_CrsMatrix &matrix);
    /// Gathers the values of @p matrix (the pattern analysed last) and
    /// factorises them (job 2). Returns INFOG(1).
    int
    factorise(const Epetra_CrsMatrix &matrix);
    /// x = A^-1 b with the last factors (job 3); x and b are distributed
    /// like the matrix' rows. Returns INFOG(1).
    int
    solve(Epetra_MultiVector &x, const Epetra_MultiVector &b);

    /// INFOG(1), INFOG(2) and INFOG(28) (null pivots) of the last call, on
    /// every process.
    std::array<int, 3>
    info() const
    {
      return last_info;
    }

  private:
    struct Instance; // dmumps_c's structure, kept out of this header
    std::unique_ptr<Instance>           mumps;
    std::vector<std::pair<int, int>>    icntl;
    std::vector<std::pair<int, double>> cntl;
    /// Rows of the matrix, all on process 0; the importer from the
    /// caller's row map.
    std::unique_ptr<Epetra_Map>    gathered_map;
    std::unique_ptr<Epetra_Import> importer;
    /// The matrix in coordinate format on process 0 (1-based).
    std::vector<int>    rows, columns;
    std::vector<double> values;
    std::array<int, 3>  last_info{{0, 0, 0}};

    /// Copies the (gathered) matrix into rows, columns, values.
    void
    gather(const Epetra_CrsMatrix &matrix, bool pattern);
    /// Runs @p job on process 0 and broadcasts its status.
    int
    run(int job, const Epetra_CrsMatrix &matrix);
    void
    destroy();
  };
} // namespace contact_fem

#endif
