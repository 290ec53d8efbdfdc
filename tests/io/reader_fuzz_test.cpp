// A seeded mutation fuzzer for the scenario reader (YAML -> Scenario) and the CSV reader (issue
// 11): the example scenarios and CSV files are mutated (byte changes, truncations, deletions,
// duplicated lines, special tokens such as NaN, 1e400, huge integers, quotes, `---`, tabs, a
// byte-order mark) and each input must either load or throw InputError. Every input runs in a
// forked child with an alarm, so a crash, a hang, another exception or a sanitizer report is a
// test failure whose message holds the mutated text.
//
// Deterministic: a fixed seed and a fixed number of inputs (BPMKIT_FUZZ_INPUTS overrides it, e.g.
// 100000 for a longer local run; BPMKIT_FUZZ_SEED changes the seed).
#include <gtest/gtest.h>

#include <omp.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iterator>
#include <random>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "common/test_files.hpp"
#include "core/error.hpp"
#include "io/csv_table.hpp"
#include "scenario/scenario.hpp"

namespace bpm {
namespace {

using test::TempDir;

constexpr unsigned kAlarmSeconds = 20;  // a load of these small inputs takes milliseconds

std::int64_t env_or(const char* name, std::int64_t fallback) {
  const char* value = std::getenv(name);
  return value != nullptr ? std::strtoll(value, nullptr, 10) : fallback;
}

/// Tokens that readers get wrong: non-finite and out-of-range numbers, integer overflow, quotes
/// and YAML structure, separators, control bytes, a byte-order mark.
// clang-format off
constexpr std::string_view kTokens[] = {
    "NaN", "nan", ".nan", ".inf", "-.inf", "inf", "1e400", "-1e400", "1e-400", "-", "--", "\n---\n",
    "\n...\n", "9223372036854775808", "-9223372036854775809", "99999999999999999999", "4294967296", "-1",
    "0", "-0", "\"", "'", "\t", "\xEF\xBB\xBF", "{", "}", "[", "]", ":", ": ", ",", "#", "&a ", "*a",
    "!!binary ", "|", ">", "? ", "%YAML 1.2\n", std::string_view("\0", 1), "\r", "\n", "~", "0x1F"};
// clang-format on

class Mutator {
 public:
  explicit Mutator(std::uint64_t seed) : random_(seed) {}

  std::string mutate(std::string text) {
    const int edits = 1 + static_cast<int>(below(4));
    for (int e = 0; e < edits; ++e) text = edit(std::move(text));
    return text;
  }

 private:
  std::size_t below(std::size_t n) {
    return n == 0 ? 0 : std::uniform_int_distribution<std::size_t>(0, n - 1)(random_);
  }
  std::string_view token() { return kTokens[below(std::size(kTokens))]; }

  std::string edit(std::string t) {
    const std::size_t at = below(t.size() + 1);
    switch (below(8)) {
      case 0:  // change a byte
        if (!t.empty()) t[below(t.size())] = static_cast<char>(below(256));
        break;
      case 1:  // truncate
        t.resize(at);
        break;
      case 2:  // insert a token
        t.insert(at, token());
        break;
      case 3:  // delete a few bytes
        t.erase(at, 1 + below(16));
        break;
      case 4: {  // duplicate a line
        const std::size_t start = t.rfind('\n', at == 0 ? 0 : at - 1);
        const std::size_t from = start == std::string::npos ? 0 : start + 1;
        const std::size_t end = t.find('\n', from);
        const std::size_t to = end == std::string::npos ? t.size() : end + 1;
        t.insert(from, t.substr(from, to - from));
        break;
      }
      case 5: {  // replace a value: after a ':' or ',' up to the end of the field
        const std::size_t sep = t.find_first_of(":,", at);
        if (sep == std::string::npos) break;
        const std::size_t end = t.find_first_of(",\n}]", sep + 1);
        std::string value(" ");
        value += token();
        t.replace(sep + 1, (end == std::string::npos ? t.size() : end) - sep - 1, value);
        break;
      }
      case 6:  // a byte-order mark, or a second one
        t.insert(0, "\xEF\xBB\xBF");
        break;
      default:  // swap two lines' worth of text: move a chunk
        if (t.size() > 2) {
          const std::size_t length = 1 + below(std::min<std::size_t>(64, t.size() - at + 1));
          const std::string chunk = t.substr(at, length);
          t.erase(at, length);
          t.insert(below(t.size() + 1), chunk);
        }
        break;
    }
    return t;
  }

  std::mt19937_64 random_;
};

enum class Outcome { loaded, input_error, other_exception, crashed, hung };

// The child's exit status for each outcome: not 0 or 1, which a sanitizer report (exit 1) or an
// abort could be mistaken for.
constexpr int kExitLoaded = 20, kExitInputError = 21, kExitOtherException = 22;

/// Runs `load` in a forked child: loaded or InputError are fine; anything else is reported.
template <typename Load>
Outcome run_isolated(const Load& load) {
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) return Outcome::crashed;
  if (pid == 0) {
    ::alarm(kAlarmSeconds);
    omp_set_num_threads(1);
    int code = kExitLoaded;
    try {
      load();
    } catch (const InputError&) {
      code = kExitInputError;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "exception: %s\n", e.what());
      code = kExitOtherException;
    } catch (...) {
      std::fprintf(stderr, "unknown exception\n");
      code = kExitOtherException;
    }
    std::fflush(nullptr);
    ::_exit(code);  // no gtest teardown in the child
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  if (WIFSIGNALED(status)) return WTERMSIG(status) == SIGALRM ? Outcome::hung : Outcome::crashed;
  switch (WEXITSTATUS(status)) {
    case kExitLoaded:
      return Outcome::loaded;
    case kExitInputError:
      return Outcome::input_error;
    case kExitOtherException:
      return Outcome::other_exception;
    default:
      return Outcome::crashed;  // a sanitizer report exits 1
  }
}

std::string_view name(Outcome o) {
  switch (o) {
    case Outcome::loaded:
      return "loaded";
    case Outcome::input_error:
      return "InputError";
    case Outcome::other_exception:
      return "an exception other than InputError";
    case Outcome::crashed:
      return "a crash or sanitizer report";
    case Outcome::hung:
      return "a hang";
  }
  return "?";
}

/// One seed: a scenario file and the CSV files it references (relative paths kept).
struct Seed {
  std::string scenario;                ///< path under examples/
  std::vector<std::string> csv_files;  ///< relative to the scenario's folder
  int weight = 1;                      ///< share of the inputs
};

std::string example(const std::string& relative) {
  return std::string(BPMKIT_EXAMPLES_DIR) + "/" + relative;
}

std::string folder_of(const std::string& path) {
  return path.substr(0, path.rfind('/') + 1);
}

/// Mutates the scenario (or one of its CSV files) `inputs` times; expects every load to end in
/// success or InputError and counts the outcomes.
void fuzz(const std::vector<Seed>& seeds, std::int64_t inputs, std::uint64_t seed) {
  TempDir dir;
  Mutator mutator(seed);
  int total_weight = 0;
  for (const Seed& s : seeds) total_weight += s.weight;
  std::array<std::int64_t, 5> counts{};
  int failures = 0;
  for (std::int64_t n = 0; n < inputs; ++n) {
    // Seeds by weight, round robin.
    const Seed* s = &seeds.front();
    for (int pick = static_cast<int>(n % total_weight), k = 0; k < static_cast<int>(seeds.size());
         ++k) {
      if (pick < seeds[k].weight) {
        s = &seeds[k];
        break;
      }
      pick -= seeds[k].weight;
    }
    // Mutate the YAML, or one CSV file it reads.
    const std::size_t target = s->csv_files.empty() ? 0 : n % (s->csv_files.size() + 1);
    std::string mutated_name;
    std::string mutated_text;
    for (std::size_t f = 0; f < s->csv_files.size(); ++f) {
      const std::string& csv = s->csv_files[f];
      std::filesystem::create_directories(std::filesystem::path(dir.path(csv)).parent_path());
      std::string text = test::read_text(folder_of(example(s->scenario)) + csv);
      if (target == f + 1) {
        text = mutator.mutate(std::move(text));
        mutated_name = csv;
        mutated_text = text;
      }
      dir.write(csv, text);
    }
    std::string yaml = test::read_text(example(s->scenario));
    if (target == 0) {
      yaml = mutator.mutate(std::move(yaml));
      mutated_name = "scenario.yaml";
      mutated_text = yaml;
    }
    const std::string path = dir.write("scenario.yaml", yaml);
    // The CSV reader alone as well, on the mutated CSV file.
    const Outcome o = run_isolated([&] {
      if (target != 0) read_csv(dir.path(mutated_name), "fuzz");
      load_scenario(path);
    });
    ++counts[static_cast<std::size_t>(o)];
    if (o != Outcome::loaded && o != Outcome::input_error && ++failures <= 5) {
      ADD_FAILURE() << "input " << n << " (seed " << seed << ", " << s->scenario << ", mutated "
                    << mutated_name << ") ended in " << name(o) << "; the mutated file:\n"
                    << mutated_text.substr(0, 4000);
    }
  }
  std::printf(
      "%lld inputs: %lld loaded, %lld InputError, %lld other exceptions, %lld crashes, %lld "
      "hangs\n",
      static_cast<long long>(inputs), static_cast<long long>(counts[0]),
      static_cast<long long>(counts[1]), static_cast<long long>(counts[2]),
      static_cast<long long>(counts[3]), static_cast<long long>(counts[4]));
  // The mutations must not all be rejected at the first byte: some inputs still load.
  EXPECT_GT(counts[0], 0) << "no mutated input loaded: the fuzzer only tests the first error";
}

/// The number of inputs per test: `release` in an optimised build (a few seconds each), a third
/// of it under AddressSanitizer, which is about 3x slower per input (CI's time limit).
std::int64_t fuzz_inputs(std::int64_t release) {
#if defined(__SANITIZE_ADDRESS__)
  release /= 3;
#endif
  return env_or("BPMKIT_FUZZ_INPUTS", release);
}

std::uint64_t fuzz_seed() {
  return static_cast<std::uint64_t>(env_or("BPMKIT_FUZZ_SEED", 20261202));
}

// The harness itself: a sanitizer report (exit status 1) or an abort is a crash, not an
// InputError; another exception is told apart.
TEST(ReaderFuzz, HarnessTellsTheOutcomesApart) {
  EXPECT_EQ(run_isolated([] {}), Outcome::loaded);
  EXPECT_EQ(run_isolated([] { throw InputError("here", "bad"); }), Outcome::input_error);
  EXPECT_EQ(run_isolated([] { throw std::out_of_range("vector"); }), Outcome::other_exception);
  EXPECT_EQ(run_isolated([] { ::_exit(1); }), Outcome::crashed);
  EXPECT_EQ(run_isolated([] { std::abort(); }), Outcome::crashed);
}

TEST(ReaderFuzz, ScenarioYamlMutationsLoadOrRaiseInputError) {
  fuzz({{"01_cantilever/case1_tbbm.yaml", {}, 2},
        {"03_breakage/pull_to_failure.yaml", {}, 2},
        {"01_cantilever/case5_polydisperse_pbm.yaml", {}, 1},
        {"01_cantilever/case3_gaps_pbm.yaml", {}, 1}},
       fuzz_inputs(1200), fuzz_seed());
}

TEST(ReaderFuzz, CsvMutationsLoadOrRaiseInputError) {
  fuzz({{"01_cantilever/case1_tbbm_csv.yaml", {"case1_particles.csv", "case1_bonds.csv"}, 4},
        {"04_compression/small_cylinder/compression.yaml",
         {"structure/particles.csv", "structure/bonds.csv"},
         1}},
       fuzz_inputs(600), fuzz_seed() + 1);
}

}  // namespace
}  // namespace bpm
