#pragma once
/// Two settings of the runtime libraries that are read once, when they are loaded, before main():
/// so main() re-executes bpmkit once with them in its environment.
///
/// - OpenMP threads that wait by sleeping, not spinning (OMP_WAIT_POLICY=passive). libgomp's
///   default spins a while at every barrier; when another process shares the cores, the spinning
///   thread takes the core its partner needs, and a DEM step (several parallel loops) with 2
///   threads was 3-30x slower than with one (BENCHMARKS.md, "Threads on shared cores"). A user's
///   own OMP_WAIT_POLICY or GOMP_SPINCOUNT is left alone.
/// - Large allocations on transparent huge pages (GLIBC_TUNABLES=glibc.malloc.hugetlb=1: malloc
///   advises the kernel to back them with 2 MB pages where it is set to `madvise`, as Debian's
///   kernels are). The DSM allocates about 1.5 GB on the 1e5-particle cylinder; on a VM where a
///   page fault is expensive, faulting it in 4 KB at a time took a quarter of the run (BENCHMARKS.md,
///   "Page faults"). Appended to a user's own GLIBC_TUNABLES unless it sets hugetlb itself.

namespace bpm::cli {

/// Returns if nothing is to be done or the re-execution failed (bpmkit then runs on with the
/// runtimes' defaults); otherwise does not return.
void reexec_with_runtime_environment(char** argv);

}  // namespace bpm::cli
