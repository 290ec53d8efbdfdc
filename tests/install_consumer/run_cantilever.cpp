// Loads a scenario with the installed bpmkit, runs it and prints the displacement of one particle:
// run_cantilever SCENARIO OUT_DIR PARTICLE_ID EXPECTED_Y_M TOLERANCE. Exits 1 when the run does not
// come to rest or the particle's y displacement differs from EXPECTED_Y_M by more than TOLERANCE
// (relative), 2 on bad input.
#include <bpmkit/scenario/scenario.hpp>
#include <bpmkit/scenario/scenario_run.hpp>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>

int main(int argc, char** argv) {
  if (argc != 6) {
    std::fprintf(stderr, "usage: %s SCENARIO OUT_DIR PARTICLE_ID EXPECTED_Y_M TOLERANCE\n",
                 argv[0]);
    return 2;
  }
  try {
    bpm::Scenario scenario = bpm::load_scenario(argv[1]);
    const bpm::ScenarioRunResult result = bpm::run_scenario(scenario, argv[2]);
    const long long id = std::stoll(argv[3]);
    const double expected = std::stod(argv[4]), tolerance = std::stod(argv[5]);
    const bpm::ParticleStore& p = scenario.model.particles;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.id[i] != id) continue;
      const double y = p.position[i].y - p.reference_position[i].y;
      const bool rest = result.summary.reason == bpm::StopReason::rest;
      const bool close = std::abs(y - expected) <= tolerance * std::abs(expected);
      std::printf("%s after %lld steps: particle %lld moved %.6g m in y (expected %.6g m)\n",
                  std::string(bpm::to_string(result.summary.reason)).c_str(),
                  static_cast<long long>(result.summary.steps), id, y, expected);
      return rest && close ? 0 : 1;
    }
    std::fprintf(stderr, "%s has no particle with id %lld\n", argv[1], id);
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
}
