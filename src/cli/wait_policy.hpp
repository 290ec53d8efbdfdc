#pragma once
/// OpenMP threads that wait by sleeping, not spinning. libgomp's default spins a while at every
/// barrier; when another process shares the cores, the spinning thread takes the core its partner
/// needs, and a DEM step (several parallel loops) with 2 threads was 3-30x slower than with one
/// (BENCHMARKS.md, "Threads on shared cores"). OMP_WAIT_POLICY=passive fixes that, but libgomp
/// reads it once, when it is loaded, before main(): so main() re-executes bpmkit once with it set.
/// A user's own OMP_WAIT_POLICY or GOMP_SPINCOUNT is left alone.

namespace bpm::cli {

/// Returns if nothing is to be done or the re-execution failed (bpmkit then runs on with the
/// runtime's default); otherwise does not return.
void reexec_with_passive_wait_policy(char** argv);

}  // namespace bpm::cli
