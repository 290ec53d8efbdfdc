// Writing one DEM frame (io/vtk_writer.hpp) of the 1e5-particle bonded cylinder of
// bench_packing.hpp (~2e5 bonds), its state filled with random numbers of realistic magnitudes
// (a running sample's velocities, forces and bond loads have full random mantissas, which is what
// limits compression). Generation takes a while once per run; only the frame is timed.
//
// Benchmarks (the frame built from the model, serialised and written atomically to a temp dir):
//   VtkFrameAscii    - VtkEncoding::ascii (shortest round-trip numbers)
//   VtkFrameZlib/L   - VtkEncoding::zlib (appended binary) at zlib level L (1 the default, 6)
// Counters: file_MB (the .vtp's size), particles, bonds.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <memory>
#include <random>
#include <string>

#include "bench_packing.hpp"
#include "io/atomic_file.hpp"
#include "io/vtk_writer.hpp"

namespace {

constexpr int kParticles = 100000;

const bpm::Model& frame_model() {
  static const std::unique_ptr<bpm::Model> model = [] {
    auto m = std::make_unique<bpm::Model>(
        bench::bonded_model(bench::generate_cylinder(kParticles), bench::RowOrder::morton));
    m->finalize();
    std::mt19937_64 rng(3);
    auto vec = [&](double scale) {
      std::normal_distribution<double> n(0.0, scale);
      return bpm::Vec3{n(rng), n(rng), n(rng)};
    };
    bpm::ParticleStore& p = m->particles;
    for (std::size_t i = 0; i < p.size(); ++i) {
      p.position[i] += vec(1e-6);
      p.velocity[i] = vec(1e-3);
      p.angular_velocity[i] = vec(1.0);
      p.force[i] = vec(1e-2);
      p.orientation[i] = bpm::advance(p.orientation[i], vec(1e-3));
    }
    for (std::size_t k = 0; k < m->bonds.size(); ++k) {
      m->bonds.force[k] = vec(1e-2);
      m->bonds.moment[k] = vec(1e-6);
    }
    return m;
  }();
  return *model;
}

void write_frame(benchmark::State& state, bpm::VtkEncoding encoding, int level) {
  const bpm::Model& m = frame_model();
  const std::string path =
      (std::filesystem::temp_directory_path() / "bpmkit_bench_vtk_frame.vtp").string();
  std::size_t bytes = 0;
  for (auto _ : state) {
    const std::string vtp = bpm::frame_polydata(m, {{"grain"}, {"beam"}}).vtp(encoding, level);
    bpm::write_file_atomic(path, vtp);
    bytes = vtp.size();
  }
  std::filesystem::remove(path);
  state.counters["file_MB"] = static_cast<double>(bytes) / 1e6;
  state.counters["particles"] = static_cast<double>(m.particles.size());
  state.counters["bonds"] = static_cast<double>(m.bonds.size());
}

void VtkFrameAscii(benchmark::State& state) {
  write_frame(state, bpm::VtkEncoding::ascii, 0);
}

void VtkFrameZlib(benchmark::State& state) {
  write_frame(state, bpm::VtkEncoding::zlib, static_cast<int>(state.range(0)));
}

BENCHMARK(VtkFrameAscii)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(VtkFrameZlib)->Arg(0)->Arg(1)->Arg(6)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
