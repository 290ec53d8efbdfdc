#include "bonds/bond_strength.hpp"

#include <algorithm>

namespace bpm {

double StrengthDistribution::draw(std::mt19937_64& rng) const {
  switch (kind) {
    case Kind::constant: return value;
    case Kind::normal: {
      std::normal_distribution<double> normal(value, spread);
      return std::max(normal(rng), 0.0);
    }
    case Kind::weibull: {
      std::weibull_distribution<double> weibull(spread, value);  // (shape m, scale)
      return weibull(rng);
    }
  }
  return value;
}

}  // namespace bpm
