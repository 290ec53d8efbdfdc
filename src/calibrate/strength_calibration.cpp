#include "calibrate/strength_calibration.hpp"

#include <fmt/core.h>
#include <omp.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <thread>

#include "calibrate/broyden.hpp"
#include "core/error.hpp"

namespace bpm {
namespace {

constexpr double kMinScale = 1e-3, kMaxScale = 1e3;  // a, within the scenario's strengths x this
constexpr double kMaxRatio = 16.0;                   // r within [1/16, 16]

/// Every drawn strength of a material times c (the spread of a normal distribution too).
void scale(StrengthDistribution& d, double c) {
  d.value *= c;
  if (d.kind == StrengthDistribution::Kind::normal) d.spread *= c;
}

/// The test run on a copy of its model with its strengths drawn from the scaled materials.
CompressionResult run_scaled(const StrengthTest& test, double tensile_scale, double shear_scale) {
  Model model = *test.model;
  std::vector<BondMaterial> materials = test.materials;
  for (BondMaterial& m : materials) scale_strengths(m, tensile_scale, shear_scale);
  model.bonds.draw_strengths(materials, test.seed);
  return run_uniaxial_compression(model, test.settings);
}

}  // namespace

double strength_of(const std::optional<CompressionResult>& r) {
  return r ? r->strength : 0.0;
}

void scale_strengths(BondMaterial& material, double tensile_scale, double shear_scale) {
  scale(material.tensile_strength, tensile_scale);
  scale(material.shear_strength, shear_scale);
}

StrengthEvaluator dem_strength_evaluator(const std::optional<StrengthTest>& ucs,
                                         const std::optional<StrengthTest>& bts) {
  return [ucs, bts](double tensile_scale, double shear_scale) {
    const auto begin = std::chrono::steady_clock::now();
    StrengthEvaluation e;
    e.tensile_scale = tensile_scale;
    e.shear_scale = shear_scale;
    if (ucs && bts) {  // side by side, each on half the cores
      const int threads = std::max(1, omp_get_max_threads() / 2);
      std::exception_ptr failure;
      std::thread other([&] {
        omp_set_num_threads(threads);
        try {
          e.bts = run_scaled(*bts, tensile_scale, shear_scale);
        } catch (...) {
          failure = std::current_exception();
        }
      });
      const int previous = omp_get_max_threads();
      omp_set_num_threads(threads);
      try {
        e.ucs = run_scaled(*ucs, tensile_scale, shear_scale);
      } catch (...) {
        other.join();
        omp_set_num_threads(previous);
        throw;
      }
      other.join();
      omp_set_num_threads(previous);
      if (failure) std::rethrow_exception(failure);
    } else if (ucs) {
      e.ucs = run_scaled(*ucs, tensile_scale, shear_scale);
    } else if (bts) {
      e.bts = run_scaled(*bts, tensile_scale, shear_scale);
    }
    e.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    return e;
  };
}

StrengthCalibrationResult calibrate_bond_strengths(
    const StrengthEvaluator& evaluate, const StrengthCalibrationSettings& s,
    const std::function<void(const StrengthEvaluation&)>& observer) {
  const bool fit_ucs = s.target_ucs > 0.0, fit_bts = s.target_bts > 0.0;
  if (!fit_ucs && !fit_bts)
    throw InputError("calibrate", "no strength target", "give --target-ucs and/or --target-bts");
  const bool both = fit_ucs && fit_bts;
  StrengthCalibrationResult result;
  // x = (ln a, ln r); residuals ln(S / S_target) of the targets given.
  auto run = [&](double log_a, double log_r) {
    const StrengthEvaluation e = evaluate(std::exp(log_a), std::exp(log_a + log_r));
    for (const auto& r : {e.ucs, e.bts}) {
      if (r && !(r->strength > 0.0)) {
        throw InputError("calibrate",
                         fmt::format("the {} test carried no load", to_string(r->test)),
                         "check its scenario: the sample between the platens, bonds present");
      }
    }
    result.evaluations.push_back(e);
    if (observer) observer(e);
    return e;
  };
  auto residual = [&](const StrengthEvaluation& e) {
    std::array<double, 2> f{0.0, 0.0};
    if (fit_ucs) f[0] = std::log(strength_of(e.ucs) / s.target_ucs);
    if (fit_bts) f[fit_ucs ? 1 : 0] = std::log(strength_of(e.bts) / s.target_bts);
    return f;
  };
  auto converged = [&](const std::array<double, 2>& f) {
    return std::abs(std::expm1(f[0])) <= s.tolerance && std::abs(std::expm1(f[1])) <= s.tolerance;
  };

  double log_a = 0.0, log_r = 0.0;
  // Rows (first target, second target), columns (ln a, ln r); d ln S / d ln a = 1 to start.
  Jacobian2 j{1.0, 0.0, 1.0, 0.0};
  StrengthEvaluation current = run(log_a, log_r);
  std::array<double, 2> f = residual(current);
  if (both && !converged(f) && static_cast<int>(result.evaluations.size()) < s.max_evaluations) {
    const double h = std::log(1.5);  // the ratio column by one difference
    const StrengthEvaluation d = run(log_a, log_r + h);
    const std::array<double, 2> g = residual(d);
    j[1] = (g[0] - f[0]) / h;
    j[3] = (g[1] - f[1]) / h;
  }
  const double max_log_r = std::log(kMaxRatio);
  bool ratio_stuck = false;
  while (!converged(f) && static_cast<int>(result.evaluations.size()) < s.max_evaluations) {
    const auto [da, dr] = newton_step(j, f, both, 1e-9);
    const double next_a = std::clamp(log_a + std::clamp(da, -std::log(4.0), std::log(4.0)),
                                     std::log(kMinScale), std::log(kMaxScale));
    // The ratio moves at most x2 a step: the DEM's strengths are noisy (a few bonds set a peak),
    // and where the UCS hardly depends on the shear strength the Newton step in r is long.
    const double next_r =
        std::clamp(log_r + std::clamp(dr, -std::log(2.0), std::log(2.0)), -max_log_r, max_log_r);
    ratio_stuck = both && std::abs(next_r) == max_log_r && std::abs(log_r) == max_log_r;
    if (next_a == log_a && next_r == log_r) break;
    const StrengthEvaluation e = run(next_a, next_r);
    const std::array<double, 2> g = residual(e);
    // Broyden's update; with one target the secant slope.
    if (broyden_update(j, {next_a - log_a, next_r - log_r}, {g[0] - f[0], g[1] - f[1]})) {
      j[0] = std::clamp(j[0], 0.1, 3.0);
    }
    log_a = next_a, log_r = next_r, f = g, current = e;
    if (ratio_stuck) break;
  }
  if (both && !converged(f) && std::abs(log_r) == max_log_r) {
    // At a bound of r: the ratio the packing produces there and at the other bound.
    const StrengthEvaluation other = run(log_a, -log_r);
    auto ratio = [](const StrengthEvaluation& e) {
      return strength_of(e.ucs) / strength_of(e.bts);
    };
    const double low = std::min(ratio(current), ratio(other)),
                 high = std::max(ratio(current), ratio(other));
    throw InputError(
        "--target-ucs, --target-bts",
        fmt::format(
            "UCS / BTS = {:.3g} is out of the range these bonds produce: {:.3g} to {:.3g} as the "
            "shear-to-tensile strength ratio goes from 1/{:g} to {:g} times the scenario's",
            s.target_ucs / s.target_bts, low, high, kMaxRatio, kMaxRatio),
        "the UCS / BTS of a bonded packing is set by its bonds' strength ratio, its packing and "
        "the "
        "contacts beside the bonds: a target outside this range needs another packing or bond "
        "model");
  }
  // The answer: the evaluation closest to the targets (the largest of its errors the smallest).
  auto worst = [&](const StrengthEvaluation& e) {
    const std::array<double, 2> g = residual(e);
    return std::max(std::abs(g[0]), std::abs(g[1]));
  };
  const StrengthEvaluation& best =
      *std::min_element(result.evaluations.begin(), result.evaluations.end(),
                        [&](const StrengthEvaluation& x, const StrengthEvaluation& y) {
                          return worst(x) < worst(y);
                        });
  result.tensile_scale = best.tensile_scale;
  result.shear_scale = best.shear_scale;
  result.converged = converged(residual(best));
  return result;
}

}  // namespace bpm
