#include "mpi_session.h"

#include <cstdlib>
#include <limits>

#include "modaltyre/core/errors.h"

#ifdef MODALTYRE_WITH_MPI
#include <mpi.h>
#endif

namespace modaltyre::app::mpi {
namespace {

// World-size variables of the launchers we know: OpenMPI, MPICH/Hydra and PMI-1/2 (srun),
// PMIx (srun --mpi=pmix, OpenMPI 5).
const char* const kSizeVariables[] = {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"};

}  // namespace

bool launched_by_mpi() {
  for (const char* v : kSizeVariables) {
    if (std::getenv(v)) return true;
  }
  return std::getenv("PMIX_RANK") != nullptr;
}

int launcher_world_size() {
  for (const char* v : kSizeVariables) {
    if (const char* s = std::getenv(v)) {
      const long n = std::strtol(s, nullptr, 10);
      if (n >= 1 && n <= std::numeric_limits<int>::max()) return static_cast<int>(n);
    }
  }
  return 1;
}

#ifdef MODALTYRE_WITH_MPI

Session::Session() {
  int provided = 0;
  if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
    throw ComputationError("MPI_Init_thread failed");
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks_);
  MPI_Comm node;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &node);
  MPI_Comm_size(node, &ranks_on_node_);
  MPI_Comm_free(&node);
}

Session::~Session() { MPI_Finalize(); }

Session::Outcome Session::agree(int code) const {
  int worst = 0;
  MPI_Allreduce(&code, &worst, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  int mine = code == worst ? rank_ : ranks_;
  int reporter = 0;
  MPI_Allreduce(&mine, &reporter, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  return {worst, worst != 0 && reporter == rank_};
}

std::size_t Session::sum(std::size_t value) const {
  unsigned long long in = value, out = 0;
  MPI_Allreduce(&in, &out, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
  return static_cast<std::size_t>(out);
}

std::vector<std::string> Session::gather(const std::string& text) const {
  // MPI counts are int. Every rank learns the total first, so that all refuse together rather
  // than rank 0 alone leaving the others waiting.
  long long size = static_cast<long long>(text.size()), total = 0;
  MPI_Allreduce(&size, &total, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
  if (total > std::numeric_limits<int>::max()) {
    throw ComputationError(
        "the sweep's rows exceed 2 GB, more than one MPI gather carries; "
        "split the sweep into several sweep files");
  }
  int my_size = static_cast<int>(size);
  std::vector<int> sizes(rank_ == 0 ? ranks_ : 0), offsets(sizes.size());
  MPI_Gather(&my_size, 1, MPI_INT, sizes.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::string all;
  if (rank_ == 0) {
    int at = 0;
    for (int r = 0; r < ranks_; ++r) {
      offsets[r] = at;
      at += sizes[r];
    }
    all.resize(static_cast<std::size_t>(total));
  }
  MPI_Gatherv(text.data(), my_size, MPI_CHAR, all.data(), sizes.data(), offsets.data(), MPI_CHAR, 0,
              MPI_COMM_WORLD);
  std::vector<std::string> parts;
  for (int r = 0; rank_ == 0 && r < ranks_; ++r) parts.push_back(all.substr(offsets[r], sizes[r]));
  return parts;
}

#endif

}  // namespace modaltyre::app::mpi
