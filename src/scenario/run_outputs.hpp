#pragma once
/// The result files of `bpmkit run` written as the run goes (docs/scenario.md): at every output
/// time the tables (probes.csv, walls.csv, bond_breaks.csv, force_displacement.csv) get their new
/// rows, one write each (io/table_stream.hpp), and a VTK frame is written (the particles and
/// bonds, and the walls as a second part when the model has walls or platens: io/vtk_walls.hpp),
/// then frames.pvd is rewritten atomically. A run killed at any moment leaves valid files up to its
/// last output; a finished run's files are the same bytes as if each had been written once at the
/// end.
#include <cstdint>
#include <string>
#include <vector>

#include "compress/uniaxial_compression.hpp"
#include "dem/simulation.hpp"
#include "io/output_folder.hpp"
#include "io/table_stream.hpp"
#include "io/vtk_writer.hpp"
#include "scenario/checkpoint.hpp"
#include "scenario/probe_recorder.hpp"
#include "scenario/scenario.hpp"

namespace bpm {

/// The walls' frames, declared outputs when has_wall_frames (as frames/frame_*.vtp is with vtk).
inline constexpr const char* kWallFrames = "frames/walls_*.vtp";
bool has_wall_frames(const Scenario& scenario);

class RunOutputs {
 public:
  /// Paths of the files written are appended to `files`.
  RunOutputs(const Scenario& scenario, const OutputFolder& folder, std::vector<std::string>& files);

  /// A fresh run: every table starts with its header (walls.csv at the first output with walls).
  void start();
  /// A resumed run: the tables are cut back to their length at the checkpoint and continued,
  /// frames.pvd lists the frames up to it again.
  void resume(const OutputProgress& progress);

  /// One output time: probe and wall rows, the breaks so far, a VTK frame. A second call at the
  /// same step (run() ends with one) does nothing.
  void output(const Simulation& sim);
  /// One point of a compression test's curve; area (m^2) gives the stress.
  void curve_point(const CompressionPoint& point, double area);
  /// Writes the breaks since the last output (dt: the run's time step, s).
  void finish(const Model& model, double dt);

  OutputProgress progress() const;
  std::size_t output_times() const { return output_times_; }
  std::size_t frames() const { return frames_.size(); }
  /// The tables written, in the order summary.json lists them.
  std::vector<std::string> table_paths() const;

 private:
  void write_breaks(const Model& model, double dt);

  const Scenario& scenario_;
  const OutputFolder& folder_;
  std::vector<std::string>& files_;
  ProbeRecorder probe_rows_;
  TableStream probes_, walls_, breaks_, curve_;
  VtkMaterialNames names_;
  std::vector<VtkFrame> frames_;
  std::int64_t last_output_step_ = -1;
  std::size_t output_times_ = 0;
  std::size_t breaks_written_ = 0;
};

}  // namespace bpm
