#pragma once
// MPI for distributed sweeps (build option MODALTYRE_WITH_MPI): `mpirun -n K modaltyre sweep
// SWEEP.yaml` splits the cases over the ranks, OpenMP threads inside each rank, and rank 0
// writes the one CSV. Only the app knows about MPI; the libraries compute a share of a plan
// (studies::sweep_share) and format its rows, whoever runs them.
#include <cstddef>
#include <string>
#include <vector>

namespace modaltyre::app::mpi {

/// True when this process was started by an MPI launcher (mpirun/mpiexec of OpenMPI or MPICH,
/// srun with PMI/PMIx): the launcher's rank variables are in the environment.
bool launched_by_mpi();
/// The world size the launcher announces (1 when not launched by MPI).
int launcher_world_size();

#ifdef MODALTYRE_WITH_MPI
/// MPI_Init_thread (funneled: OpenMP threads never call MPI) / MPI_Finalize, for one command.
class Session {
 public:
  Session();
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  int rank() const { return rank_; }
  int ranks() const { return ranks_; }
  /// Ranks sharing this rank's node (to share its cores between them).
  int ranks_on_node() const { return ranks_on_node_; }

  /// Every rank passes its exit code (0 = fine); all get the largest, and the lowest rank with
  /// that code is the one that reports it (so the error is printed once).
  struct Outcome {
    int code = 0;
    bool report = false;
  };
  Outcome agree(int code) const;
  /// Sum over the ranks, result on every rank.
  std::size_t sum(std::size_t value) const;
  /// Rank 0 receives every rank's text, in rank order; the others get an empty vector.
  std::vector<std::string> gather(const std::string& text) const;

 private:
  int rank_ = 0, ranks_ = 1, ranks_on_node_ = 1;
};
#endif

}  // namespace modaltyre::app::mpi
