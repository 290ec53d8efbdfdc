#pragma once
/// Checkpoints of `bpmkit run`: the complete state of a run, so that `bpmkit run SCENARIO --resume
/// DIR` continues it bit for bit as if it had never stopped (same final_state.csv, same tables).
///
/// The state: the clock (time, step, last max speed); per particle position, velocity, angular
/// velocity, orientation and the loads of the last evaluation (the next half kick uses them); per
/// bond the intact flag, break mode, stored elastic force and moment, axis and end loads, the break
/// log and the update count; per wall its point, velocity, displacement, force and tangential
/// springs; the contact history (the Verlet list as built, with the positions it was built at, and
/// per pair the tangential spring and last loads); how far the result files had got. What the
/// scenario defines (radii, masses, stiffnesses, strengths drawn from the seed, fixed DOFs, loads)
/// is not stored but hashed: a checkpoint resumes only the scenario and model it came from. The
/// run draws no random numbers after loading (strengths are drawn once, from the seed).
///
/// File layout (docs/scenario.md#checkpoints): magic "BPMKCKPT", format version (u32), bpmkit
/// version (string), FNV-1a 64 hashes of the scenario file and of the model's constants, kind,
/// test (0 plain run, 1 compression test), step, time, payload length and its FNV-1a 64 checksum,
/// then the payload (a compression test's ends with its CompressionProgress). Integers
/// little-endian, doubles as raw IEEE bits (io/byte_codec.hpp): the same bytes for any compiler or
/// thread count.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "dem/simulation.hpp"
#include "scenario/scenario.hpp"

namespace bpm {

/// 5: each point of a compression test's curve also holds how many of its broken bonds broke in
/// tension.
/// 4: each point of a compression test's curve holds its strain gauges' axial and lateral strain.
/// 3: the header says whether a plain run or a compression test wrote it, and a compression test's
/// payload ends with its progress (the curve so far and the peak).
/// 2: the particle and bond arrays are stored in the canonical order (model/spatial_order.hpp),
/// which loading the scenario again restores; format 1 held them in the rows' order.
inline constexpr std::uint32_t kCheckpointFormat = 5;
inline constexpr const char* kCheckpointFile = "checkpoint.bin";

/// Why it was written. A diverged state is kept for inspection and never resumed.
enum class CheckpointKind : std::uint8_t { periodic = 0, interrupted = 1, diverged = 2 };

/// How far the result files had got when the checkpoint was taken, so that a resumed run cuts off
/// what was written after it and continues them.
struct OutputProgress {
  std::int64_t last_output_step = -1;
  std::uint64_t output_times = 0;    ///< output times so far (probe rows, frames if VTK)
  std::vector<double> frame_times;   ///< s, of frames/frame_NNNNNN.vtp written so far
  std::uint64_t breaks_written = 0;  ///< rows of bond_breaks.csv
  std::vector<std::pair<std::string, std::uint64_t>> table_bytes;  ///< streamed table -> its length
};

/// What a checkpoint must belong to: hashes of the scenario file and of the model (below).
struct CheckpointIdentity {
  std::uint64_t scenario_file = 0;
  std::uint64_t model = 0;
};
/// Computed once per run (the model's constants do not change), from the model as loaded: a
/// compression test computes it before adding its platens and scaling the masses (both follow
/// from the scenario), at the start and at a resume alike.
CheckpointIdentity checkpoint_identity(const Scenario& scenario, double dt);

/// FNV-1a 64 of the scenario file's bytes.
std::uint64_t scenario_file_hash(const Scenario& scenario);
/// FNV-1a 64 of the model's constants and the time step: particles (ids, radii, masses, inertias,
/// materials, reference positions, free DOFs), bonds (pairs, input rows, stiffnesses, arms, radii,
/// lengths, materials, damping coefficients, strengths), wall names and shapes.
std::uint64_t model_hash(const Scenario& scenario, double dt);

/// The checkpoint file's bytes for the current state of `sim` (which runs scenario.model);
/// `compression`: the progress of a compression test, null for a plain run.
std::string checkpoint_bytes(const CheckpointIdentity& identity, const Simulation& sim,
                             CheckpointKind kind, const OutputProgress& outputs,
                             const CompressionProgress* compression = nullptr);

/// Reads the checkpoint at `path`, checks that this bpmkit wrote it for this scenario (a plain run
/// or a compression test, as scenario.compression says) and `identity`, and restores
/// scenario.model's state and sim's clock and contacts (sim must have been built on scenario.model
/// as the run builds it), and for a compression test *compression. Returns the outputs' progress.
/// Throws InputError naming the file and the fix: missing, not a checkpoint, damaged, another
/// format or version, another scenario, model or kind of run, or a diverged state.
OutputProgress restore_checkpoint(const std::string& path, const CheckpointIdentity& identity,
                                  Scenario& scenario, Simulation& sim,
                                  CompressionProgress* compression = nullptr);

/// The checks restore_checkpoint makes before restoring (for a run of `scenario` as loaded, at its
/// time step), so that a refused --resume is found before the folder is claimed and changed.
void check_checkpoint(const std::string& path, const Scenario& scenario);

}  // namespace bpm
