#pragma once
// A scenario for the checkpoint and resume tests: a jittered lattice of slightly overlapping
// bonded grains on a floor wall, its top layer pulled up and sideways at once, so that within a few
// dozen steps bonds break (Weibull strengths), contacts act (Hertz-Mindlin with friction, between
// the grains and with the floor) and the Verlet list is rebuilt.
#include <fmt/core.h>

#include <cstdint>
#include <string>

#include "common/test_files.hpp"

namespace bpm::test {

struct ResumeScenario {
  int nx = 6, ny = 6, nz = 6;
  std::int64_t max_steps = 200;
  std::int64_t every_steps = 10;
  std::int64_t checkpoint_every = 0;  ///< 0: none
  bool vtk = true;
};

/// Writes particles.csv and scenario.yaml into `dir`; returns the scenario's path.
inline std::string write_resume_scenario(const TempDir& dir, const ResumeScenario& s) {
  constexpr double radius = 1e-3, spacing = 1.995e-3, jitter = 5e-6;
  std::uint64_t state = 12345;
  auto noise = [&] {  // a fixed LCG: the same lattice on every machine
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return (static_cast<double>(state >> 11) / 9007199254740992.0 - 0.5) * 2.0 * jitter;
  };
  std::string csv = "id,x,y,z,radius\n";
  int id = 0;
  for (int k = 0; k < s.nz; ++k) {
    for (int j = 0; j < s.ny; ++j) {
      for (int i = 0; i < s.nx; ++i) {
        const double x = i * spacing + noise(), y = j * spacing + noise(),
                     z = k * spacing + noise();
        csv += fmt::format("{},{:.17g},{:.17g},{:.17g},{}\n", id++, x, y, z, radius);
      }
    }
  }
  dir.write("particles.csv", csv);
  const double top = (s.nz - 1) * spacing;
  const std::string checkpoint =
      s.checkpoint_every > 0
          ? fmt::format("\n  checkpoint_every: {{steps: {}}}", s.checkpoint_every)
          : "";
  return dir.write("scenario.yaml", fmt::format(R"(particle_materials:
  grain:
    density: 2500
    contact: {{youngs_modulus: 1e9, poisson_ratio: 0.25, restitution: 0.5, friction: 0.3}}
bond_materials:
  cement:
    model: tbbm
    youngs_modulus: 1e9
    poisson_ratio: 0.25
    radius: 5e-4
    tensile_strength: {{distribution: weibull, scale: 2e6, shape: 4}}
    shear_strength: 3e6
seed: 3
particles: {{material: grain, file: particles.csv}}
bonds: {{material: cement, auto: {{max_gap: 1e-4}}}}
contacts: {{particle_particle: true, bonded: superimpose}}
walls:
  - {{name: floor, shape: plane, point: [0, 0, -9.99e-4], normal: [0, 0, 1], material: grain}}
gravity: [0, 0, -9.81]
damping: {{particle: 0.05}}
loads:
  - region: {{box: {{min: [-1, -1, {}], max: [1, 1, 1]}}}}
    force: [0.4, 0.2, 2.5]
stop: {{max_steps: {}}}
output:
  every_steps: {}
  vtk: {}
  probes:
    - {{name: top, region: {{box: {{min: [-1, -1, {}], max: [1, 1, 1]}}}}}}{}
)",
                                                top - 5e-4, s.max_steps, s.every_steps, s.vtk,
                                                top - 5e-4, checkpoint));
}

}  // namespace bpm::test
