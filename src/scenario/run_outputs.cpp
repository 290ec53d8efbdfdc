#include "scenario/run_outputs.hpp"

#include <fmt/core.h>

#include "core/error.hpp"
#include "io/result_tables.hpp"
#include "io/vtk_walls.hpp"

namespace bpm {
namespace {
constexpr const char* kProbes = "probes.csv";
constexpr const char* kWalls = "walls.csv";
constexpr const char* kBreaks = "bond_breaks.csv";
constexpr const char* kCurve = "force_displacement.csv";

std::string frame_name(std::size_t index) {
  return fmt::format("frames/frame_{:06d}.vtp", index);
}

std::string walls_name(std::size_t index) {
  return fmt::format("frames/walls_{:06d}.vtp", index);
}
}  // namespace

bool has_wall_frames(const Scenario& scenario) {
  return scenario.output.vtk && (!scenario.model.walls.empty() || scenario.compression);  // platens
}

RunOutputs::RunOutputs(const Scenario& scenario, const OutputFolder& folder,
                       std::vector<std::string>& files)
    : scenario_(scenario),
      folder_(folder),
      files_(files),
      probe_rows_(scenario.probes),
      names_{scenario.particle_material_names, scenario.bond_material_names} {}

void RunOutputs::start() {
  if (!scenario_.probes.empty()) probes_.create(folder_.output_path(kProbes), probe_rows_.header());
  if (scenario_.model.bonds.breakable)
    breaks_.create(folder_.output_path(kBreaks), bond_breaks_header());
  if (scenario_.compression)
    curve_.create(folder_.output_path(kCurve), force_displacement_header());
}

void RunOutputs::resume(const OutputProgress& progress) {
  for (const auto& [name, bytes] : progress.table_bytes) {
    TableStream* table = name == kProbes   ? &probes_
                         : name == kWalls  ? &walls_
                         : name == kBreaks ? &breaks_
                         : name == kCurve  ? &curve_
                                           : nullptr;
    if (table == nullptr)
      throw InputError(name, "is not a table of this run",
                       "the checkpoint is damaged: run again with --overwrite");
    table->resume(folder_.output_path(name), bytes);
  }
  last_output_step_ = progress.last_output_step;
  output_times_ = progress.output_times;
  breaks_written_ = progress.breaks_written;
  frames_.clear();
  for (const double t : progress.frame_times) {
    const std::size_t k = frames_.size();
    frames_.push_back({t, frame_name(k), has_wall_frames(scenario_) ? walls_name(k) : ""});
  }
  if (scenario_.output.vtk) folder_.write("frames.pvd", collection_pvd(frames_));
}

void RunOutputs::output(const Simulation& sim) {
  if (sim.steps() == last_output_step_) return;
  last_output_step_ = sim.steps();
  ++output_times_;
  const Model& model = sim.model();
  if (probes_.is_open()) probes_.append(probe_rows_.row(sim.time(), model.particles));
  if (!model.walls.empty()) {
    const bool first = !walls_.is_open();
    if (first) walls_.create(folder_.output_path(kWalls), "");
    walls_.append(walls_row(model.walls, sim.time(), first));
  }
  write_breaks(model, sim.dt());
  if (scenario_.output.bond_csv) {
    // Numbered by output time (0 at t = 0), as a resumed run continues counting.
    const std::string file = fmt::format("bonds/bonds_{:06d}.csv", output_times_ - 1);
    files_.push_back(folder_.write(file, bond_state_csv(model)));
  }
  if (scenario_.output.vtk) {
    VtkFrame frame{sim.time(), frame_name(frames_.size()), ""};
    files_.push_back(folder_.write(frame.file, polydata_vtp(model, names_)));
    if (!model.walls.empty()) {
      frame.walls_file = walls_name(frames_.size());
      files_.push_back(folder_.write(frame.walls_file, walls_vtp(model.walls, model.particles)));
    }
    frames_.push_back(frame);
    folder_.write("frames.pvd", collection_pvd(frames_));  // atomically: always a valid collection
  }
}

void RunOutputs::curve_point(const CompressionPoint& point, double area) {
  curve_.append(force_displacement_row(point, area));
}

void RunOutputs::finish(const Model& model, double dt) {
  write_breaks(model, dt);
}

void RunOutputs::write_breaks(const Model& model, double dt) {
  if (!breaks_.is_open() || breaks_written_ == model.bonds.breaks.size()) return;
  breaks_.append(bond_breaks_rows(model, dt, breaks_written_));
  breaks_written_ = model.bonds.breaks.size();
}

OutputProgress RunOutputs::progress() const {
  OutputProgress p;
  p.last_output_step = last_output_step_;
  p.output_times = output_times_;
  for (const VtkFrame& f : frames_) p.frame_times.push_back(f.time);
  p.breaks_written = breaks_written_;
  for (const auto& [name, table] : {std::pair{kProbes, &probes_}, std::pair{kWalls, &walls_},
                                    std::pair{kBreaks, &breaks_}, std::pair{kCurve, &curve_}}) {
    if (table->is_open()) p.table_bytes.emplace_back(name, table->bytes());
  }
  return p;
}

std::vector<std::string> RunOutputs::table_paths() const {
  std::vector<std::string> paths;
  for (const TableStream* table : {&probes_, &walls_, &breaks_, &curve_}) {
    if (table->is_open()) paths.push_back(table->path());
  }
  return paths;
}

}  // namespace bpm
