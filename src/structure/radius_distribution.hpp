#pragma once
/// Particle radius distributions for random packings. Radii are drawn one at a time from a seeded
/// std::mt19937_64, so a packing is reproducible for a given seed (and standard library).
///
/// | kind          | parameters (m)              | radius drawn                                           |
/// | ------------- | --------------------------- | ------------------------------------------------------ |
/// | monodisperse  | radius                      | always `radius`                                        |
/// | uniform       | min, max                    | uniform in [min, max]                                  |
/// | normal        | mean, std, [min, max]       | normal(mean, std), truncated to [min, max] by redrawing |
/// | lognormal     | mean, std, [min, max]       | ln R normal with E[R] = mean, SD[R] = std, truncated   |
/// | table         | rows (radius, fraction)     | one of the listed radii                                |
///
/// Truncation bounds default to mean -/+ 3 std, the lower one at least 1e-3 mean (radii are always
/// > 0). Truncation redraws rather than clips, so no radius piles up at a bound. A table's
/// fractions are by number (probability of each radius) or by volume (share of the solid volume:
/// number fraction proportional to fraction / R^3); they are normalised to sum to 1.
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace bpm {

struct RadiusDistribution {
  enum class Kind { monodisperse, uniform, normal, lognormal, table };
  Kind kind = Kind::monodisperse;
  double a = 0.0, b = 0.0;            ///< monodisperse: a = R; uniform: [a, b]; (log)normal: mean a, std b
  double min = 0.0, max = 0.0;        ///< truncation bounds (normal, lognormal)
  std::vector<double> table_radius;   ///< table: radii, m
  std::vector<double> table_number;   ///< table: number fractions, summing to 1

  static RadiusDistribution monodisperse(double radius);
  static RadiusDistribution uniform(double min, double max);
  /// min/max <= 0 means the default bounds (see above).
  static RadiusDistribution normal(double mean, double std, double min = 0.0, double max = 0.0);
  static RadiusDistribution lognormal(double mean, double std, double min = 0.0, double max = 0.0);
  /// `volume_fractions`: fractions are by volume, else by number.
  static RadiusDistribution table(std::vector<double> radius, std::vector<double> fraction, bool volume_fractions);

  double largest() const;  ///< the largest radius that can be drawn, m
  std::string describe() const;
};

/// Draws radii from one distribution; holds the distribution objects between calls.
class RadiusSampler {
 public:
  explicit RadiusSampler(const RadiusDistribution& dist);
  double operator()(std::mt19937_64& rng);

 private:
  RadiusDistribution dist_;
  double mu_ = 0.0, sigma_ = 0.0;  ///< parameters of the underlying normal
  std::discrete_distribution<std::size_t> pick_;
};

}  // namespace bpm
