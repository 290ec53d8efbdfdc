// `bpmkit verify cantilever`: Chen's cases 1-5 with PBM, EBBM and TBBM; prints the tip deflection
// table, Chen Fig. 8 (case 1 deflection along the beam) and Table 5 (case 3 stiffnesses), writes
// the same as JSON and CSV into --out, and fails (exit 1) if an accuracy check fails.
#include <fmt/core.h>

#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "io/output_folder.hpp"
#include "verify/cantilever.hpp"

namespace bpm::cli {
namespace {

using verify::CantileverResult;

constexpr double kTolerance = 1e-3;  // 0.1 %

/// The checks of the issue: DEM vs the exact discrete solution for every model; TBBM vs
/// Timoshenko; EBBM vs Euler-Bernoulli.
bool passes(const CantileverResult& r) {
  bool ok = std::abs(r.error_vs_discrete()) < kTolerance;
  if (r.model == "tbbm") ok = ok && std::abs(r.error_vs_timoshenko()) < kTolerance;
  if (r.model == "ebbm") ok = ok && std::abs(r.error_vs_euler_bernoulli()) < kTolerance;
  return ok;
}

std::string tips_csv(const std::vector<CantileverResult>& results) {
  std::string s =
      "case,variant,model,bonds,beam_length_m,tip_dem_m,tip_discrete_m,tip_timoshenko_m,"
      "tip_euler_bernoulli_m,large_deflection_factor,error_vs_discrete,error_vs_timoshenko,"
      "error_vs_euler_bernoulli,linear_error_vs_discrete,linear_error_vs_timoshenko,"
      "steps,simulated_time_s,stop_reason,time_step_s,wall_s\n";
  for (const auto& r : results) {
    s += fmt::format("{},{},{},{},{},{:.10e},{:.10e},{:.10e},{:.10e},{:.10f},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{},{},{},{:.6e},{:.4f}\n",
                     r.case_name, r.variant, r.model, r.bonds, r.beam_length, r.tip_dem, r.tip_discrete,
                     r.tip_timoshenko, r.tip_euler_bernoulli, r.large_deflection_factor, r.error_vs_discrete(),
                     r.error_vs_timoshenko(), r.error_vs_euler_bernoulli(), r.linear_error_vs_discrete(),
                     r.linear_error_vs_timoshenko(), r.run.steps, r.run.time,
                     to_string(r.run.reason), r.time_step, r.run.wall_seconds);
  }
  return s;
}

nlohmann::json result_json(const CantileverResult& r) {
  return {{"case", r.case_name},
          {"variant", r.variant},
          {"model", r.model},
          {"bonds", r.bonds},
          {"beam_length_m", r.beam_length},
          {"tip_dem_m", r.tip_dem},
          {"tip_discrete_m", r.tip_discrete},
          {"tip_timoshenko_m", r.tip_timoshenko},
          {"tip_euler_bernoulli_m", r.tip_euler_bernoulli},
          {"error_vs_discrete", r.error_vs_discrete()},
          {"error_vs_timoshenko", r.error_vs_timoshenko()},
          {"error_vs_euler_bernoulli", r.error_vs_euler_bernoulli()},
          {"large_deflection_factor", r.large_deflection_factor},
          {"linear_error_vs_discrete", r.linear_error_vs_discrete()},
          {"linear_error_vs_timoshenko", r.linear_error_vs_timoshenko()},
          {"steps", r.run.steps},
          {"simulated_time_s", r.run.time},
          {"stop_reason", to_string(r.run.reason)},
          {"time_step_s", r.time_step},
          {"wall_s", r.run.wall_seconds},
          {"pass", passes(r)}};
}

}  // namespace

namespace {

/// The suite into a claimed folder: sets `failed` (the failed checks), returns the summary.
nlohmann::json run_suite(const CantileverSuiteOptions& options, const OutputFolder& folder, int& failed) {
  const auto start = std::chrono::steady_clock::now();
  struct Job {
    verify::CantileverSpec spec;
    std::string model;
  };
  std::vector<Job> jobs;
  for (int c : options.cases) {
    for (const auto& spec : verify::cantilever_case(c)) {
      for (const auto& model : verify::cantilever_models()) jobs.push_back({spec, model});
    }
  }
  // The runs are independent and small: one per thread (each run's own loops stay serial).
  std::vector<CantileverResult> results(jobs.size());
#pragma omp parallel for schedule(dynamic)
  for (std::size_t i = 0; i < jobs.size(); ++i) results[i] = verify::run_cantilever(jobs[i].spec, jobs[i].model);

  fmt::print("Chen (2022) cantilever verification: E_b = 200 GPa, nu_b = 0.3, F = 100 kN, rest at 1e-9 m/s\n"
             "Tip deflections in mm. 'discrete' is the exact static solution of the same discrete model\n"
             "(linearised elements, direct solve). Errors are against references times the elastica\n"
             "large-deflection factor 'LD' (1 - 4e-6 except case 4, where F L^2/EI = 0.10).\n");
  fmt::print("{:<6} {:<18} {:<5} {:>12} {:>12} {:>12} {:>12} {:>9} {:>10} {:>10} {:>10} {:>8} {}\n", "case",
             "variant", "model", "DEM", "discrete", "Timoshenko", "Eul-Bern", "LD", "vs discr", "vs TB",
             "vs EB", "steps", "check");
  failed = 0;
  nlohmann::json runs = nlohmann::json::array();
  for (const auto& r : results) {
    const bool ok = passes(r);
    failed += ok ? 0 : 1;
    fmt::print("{:<6} {:<18} {:<5} {:>12.6f} {:>12.6f} {:>12.6f} {:>12.6f} {:>9.6f} {:>9.4f}% {:>9.4f}% {:>9.4f}% {:>8} {}\n",
               r.case_name, r.variant, r.model, 1e3 * r.tip_dem, 1e3 * r.tip_discrete,
               1e3 * r.tip_timoshenko, 1e3 * r.tip_euler_bernoulli, r.large_deflection_factor,
               100 * r.error_vs_discrete(),
               100 * r.error_vs_timoshenko(), 100 * r.error_vs_euler_bernoulli(), r.run.steps,
               ok ? "ok" : "FAIL");
    runs.push_back(result_json(r));
  }

  // Chen Fig. 8: deflection along the beam in case 1, for each model.
  nlohmann::json profile = nlohmann::json::array();
  std::string profile_csv = "x_m,timoshenko_m,euler_bernoulli_m,dem_pbm_m,dem_ebbm_m,dem_tbbm_m\n";
  const auto case1 = verify::cantilever_case(1).front();
  std::vector<const CantileverResult*> case1_runs;
  for (const auto& r : results) {
    if (r.case_name == "case1") case1_runs.push_back(&r);
  }
  if (case1_runs.size() == 3) {
    for (std::size_t i = 0; i < case1.x.size(); ++i) {
      const double s = case1.x[i] - case1.x[0];
      const double tb = verify::timoshenko_deflection(case1, s, true);
      const double eb = verify::timoshenko_deflection(case1, s, false);
      profile_csv += fmt::format("{},{:.10e},{:.10e},{:.10e},{:.10e},{:.10e}\n", s, tb, eb,
                                 case1_runs[0]->deflection_dem[i], case1_runs[1]->deflection_dem[i],
                                 case1_runs[2]->deflection_dem[i]);
      profile.push_back({{"x_m", s}, {"timoshenko_m", tb}, {"euler_bernoulli_m", eb},
                         {"dem_pbm_m", case1_runs[0]->deflection_dem[i]},
                         {"dem_ebbm_m", case1_runs[1]->deflection_dem[i]},
                         {"dem_tbbm_m", case1_runs[2]->deflection_dem[i]}});
    }
  }

  // Chen Table 5: bond stiffnesses of case 3, in GN/m (the paper's "GPa m").
  fmt::print("\nChen Table 5 (case 3 bond stiffnesses, GN/m)\n{:>6} {:>8} {:>10} {:>10} {:>10} {:>10}\n",
             "bonds", "Lb/L0", "k_n", "k_s PBM", "k_s EBBM", "k_s TBBM");
  nlohmann::json table5 = nlohmann::json::array();
  std::string table5_csv = "bonds,bond_to_beam_length,k_n_N_per_m,k_s_pbm_N_per_m,k_s_ebbm_N_per_m,k_s_tbbm_N_per_m\n";
  for (const auto& row : verify::case3_stiffness_table()) {
    fmt::print("{:>6} {:>8.3f} {:>10.4g} {:>10.4g} {:>10.4g} {:>10.4g}\n", row.bonds, row.bond_to_beam_length,
               row.k_n / 1e9, row.k_s_pbm / 1e9, row.k_s_ebbm / 1e9, row.k_s_tbbm / 1e9);
    table5_csv += fmt::format("{},{},{:.10e},{:.10e},{:.10e},{:.10e}\n", row.bonds, row.bond_to_beam_length,
                              row.k_n, row.k_s_pbm, row.k_s_ebbm, row.k_s_tbbm);
    table5.push_back({{"bonds", row.bonds}, {"k_n_N_per_m", row.k_n}, {"k_s_pbm_N_per_m", row.k_s_pbm},
                      {"k_s_ebbm_N_per_m", row.k_s_ebbm}, {"k_s_tbbm_N_per_m", row.k_s_tbbm}});
  }

  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const nlohmann::json doc = {{"suite", "chen2022-cantilever"},
                              {"tolerance", kTolerance},
                              {"runs", runs},
                              {"case1_deflection", profile},
                              {"case3_stiffness", table5},
                              {"failed_checks", failed},
                              {"wall_s", wall}};
  folder.write("cantilever.json", doc.dump(2) + "\n");
  folder.write("cantilever_tips.csv", tips_csv(results));
  if (!profile.empty()) folder.write("case1_deflection.csv", profile_csv);
  folder.write("case3_stiffness.csv", table5_csv);
  fmt::print("\n{} runs in {:.1f} s; {} passed, {} failed (|error| < {}%: every model vs its exact discrete "
             "solution, TBBM vs Timoshenko, EBBM vs Euler-Bernoulli)\n",
             results.size(), wall, static_cast<int>(results.size()) - failed, failed, 100 * kTolerance);
  fmt::print("wrote {}/cantilever.json and {{cantilever_tips,case1_deflection,case3_stiffness}}.csv\n", folder.dir());
  return {{"suite", "chen2022-cantilever"}, {"runs", results.size()}, {"failed_checks", failed}, {"wall_s", wall}};
}

}  // namespace

int run_cantilever_suite(const CantileverSuiteOptions& options) {
  OutputFolder folder(options.out_dir, "verify cantilever",
                      {"cantilever.json", "cantilever_tips.csv", "case1_deflection.csv", "case3_stiffness.csv"},
                      options.overwrite);
  int failed = 0;
  folder.run([&] { return run_suite(options, folder, failed); });
  return failed;
}

void add_verify_command(CLI::App& app) {
  auto* verify = app.add_subcommand("verify", "verification suites against analytical solutions");
  auto* cantilever = verify->add_subcommand("cantilever", "Chen (2022) cantilever cases 1-5, PBM/EBBM/TBBM");
  auto options = std::make_shared<CantileverSuiteOptions>();
  add_output_options(cantilever, options->out_dir, options->overwrite);
  cantilever->add_option("--cases", options->cases, "which cases to run (1-5)")
      ->check(CLI::Range(1, 5))->capture_default_str();
  cantilever->callback([options] {
    if (run_cantilever_suite(*options) > 0) throw CLI::RuntimeError(1);
  });
  verify->require_subcommand(1);
}

}  // namespace bpm::cli
