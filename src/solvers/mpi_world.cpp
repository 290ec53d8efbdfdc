#include "solvers/mpi_world.hpp"

#include <sys/resource.h>

#include <cstdlib>

#include "solvers/hypre_support.hpp"

namespace bpm::mpi {

bool launched_by_mpirun() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE"}) {
    if (std::getenv(name) != nullptr) return true;
  }
  return false;
}

World world() {
  static const World w = [] {
    World out;
    if (!launched_by_mpirun()) return out;
    hypre::start();
    MPI_Comm_rank(MPI_COMM_WORLD, &out.rank);
    MPI_Comm_size(MPI_COMM_WORLD, &out.size);
    return out;
  }();
  return w;
}

void abort_if_distributed(int status) {
  if (world().distributed()) MPI_Abort(MPI_COMM_WORLD, status);
}

void sum_in_place(std::vector<double>& v) {
  if (!world().distributed()) return;
  MPI_Allreduce(MPI_IN_PLACE, v.data(), static_cast<int>(v.size()), MPI_DOUBLE, MPI_SUM,
                MPI_COMM_WORLD);
}

std::vector<std::int64_t> peak_memory_per_rank() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const std::int64_t own = static_cast<std::int64_t>(usage.ru_maxrss) * 1024;  // Linux: kB
  const World w = world();
  std::vector<std::int64_t> all(static_cast<std::size_t>(w.size), own);
  if (w.distributed())
    MPI_Allgather(&own, 1, MPI_INT64_T, all.data(), 1, MPI_INT64_T, MPI_COMM_WORLD);
  return all;
}

}  // namespace bpm::mpi
