#pragma once
/// The ranks of a run started by mpirun (issue 14: the DSM across processes). MPI is optional at
/// run time: without a launcher nothing starts here, and every command runs as one process (hypre
/// still starts MPI as a singleton for the AMG solver, hypre_support.hpp).
#include <cstdint>
#include <vector>

namespace bpm::mpi {

struct World {
  int rank = 0;
  int size = 1;
  bool root() const { return rank == 0; }
  bool distributed() const { return size > 1; }
};

/// True when an MPI launcher started this process: OpenMPI's OMPI_COMM_WORLD_SIZE, PMIx's
/// PMIX_RANK or MPICH's PMI_SIZE is set.
bool launched_by_mpirun();

/// {0, 1} without a launcher (and MPI is not started). Under mpirun MPI and hypre start (once,
/// hypre::start) and this is MPI_COMM_WORLD's rank and size.
World world();

/// Ends the whole run with `status` (MPI_Abort) when it has several ranks, so that an error on one
/// rank does not leave the others waiting in a collective; otherwise returns.
void abort_if_distributed(int status);

/// Replaces each entry of v with its sum over the ranks (MPI_Allreduce); nothing without mpirun.
void sum_in_place(std::vector<double>& v);

/// The peak resident memory of each rank (getrusage), bytes, in rank order; one entry without
/// mpirun.
std::vector<std::int64_t> peak_memory_per_rank();

}  // namespace bpm::mpi
