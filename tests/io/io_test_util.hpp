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

#include "core/error.hpp"
#include "io/scenario.hpp"

namespace bpm::test {

/// A fresh directory under the system temp dir, named after the running test, removed at the end.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() /
            ("bpmkit_io_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" +
             std::to_string(::getpid()));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  std::string path(const std::string& name) const { return (path_ / name).string(); }
  /// Writes `content` to `name` in this directory; returns the full path.
  std::string write(const std::string& name, const std::string& content) const {
    std::ofstream(path_ / name) << content;
    return path(name);
  }

 private:
  std::filesystem::path path_;
};

inline std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline std::vector<std::string> read_lines(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

/// 1-based number of the first line of `text` containing `needle` (0 if none).
inline int line_of(const std::string& text, const std::string& needle) {
  std::istringstream in(text);
  int n = 0;
  for (std::string line; std::getline(in, line);) {
    ++n;
    if (line.find(needle) != std::string::npos) return n;
  }
  return 0;
}

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
