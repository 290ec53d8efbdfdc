#pragma once
// Helpers for the io tests: a scratch directory per test, files written into it, and the message
// of the InputError a scenario raises.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "common/test_files.hpp"
#include "core/error.hpp"
#include "scenario/scenario.hpp"

namespace bpm::test {


/// The message of the InputError that loading `path` raises; a test failure if it raises nothing
/// or something else.
inline std::string load_error(const std::string& path) {
  try {
    load_scenario(path);
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected InputError, got another exception: " << e.what();
    return {};
  }
  ADD_FAILURE() << "expected InputError from " << path << ", but it loaded";
  return {};
}

/// Expects every fragment in `message` (an error message), naming the missing ones.
inline void expect_contains(const std::string& message, const std::vector<std::string>& fragments) {
  for (const auto& f : fragments) EXPECT_NE(message.find(f), std::string::npos) << "expected '" << f << "' in: " << message;
}

/// A small valid scenario: three particles in a row along x (ids 0, 1, 2; R = 0.2 m, 0.4 m apart),
/// two TBBM bonds, particle 0 clamped, particle 2 loaded. Tests edit it into bad variants.
inline const std::string kGoodScenario = R"(particle_materials:
  steel:
    density: 7850
bond_materials:
  beam:
    model: tbbm
    youngs_modulus: 200e9
    poisson_ratio: 0.3
    radius: 0.2
particles:
  material: steel
  list:
    - {id: 0, position: [0, 0, 0], radius: 0.2}
    - {id: 1, position: [0.4, 0, 0], radius: 0.2}
    - {id: 2, position: [0.8, 0, 0], radius: 0.2}
bonds:
  material: beam
  list: [[0, 1], [1, 2]]
damping:
  particle: 0.7
boundary_conditions:
  - particles: [0]
    fix: all
loads:
  - particles: [2]
    force: [0, -1e5, 0]
    ramp_time: 0.01
integrator:
  time_step: auto
stop:
  max_steps: 200
output:
  every_steps: 50
  probes:
    - {name: tip, particles: [2]}
)";

/// Replaces the first occurrence of `from` in `text` by `to` (the test fails if absent).
inline void replace_once(std::string& text, const std::string& from, const std::string& to) {
  const auto pos = text.find(from);
  EXPECT_NE(pos, std::string::npos) << "'" << from << "' is not in the text";
  if (pos != std::string::npos) text.replace(pos, from.size(), to);
}

/// kGoodScenario with the first occurrence of `from` replaced by `to` (the test fails if absent).
inline std::string edited(const std::string& from, const std::string& to) {
  std::string s = kGoodScenario;
  replace_once(s, from, to);
  return s;
}

}  // namespace bpm::test
