#include "ste/layered_stiffness.hpp"

#include <algorithm>
#include <cmath>

#include "ste/elastic_constants.hpp"

namespace bpm::ste {

LayeredStiffness layered_stiffness(const ParticleStore& p, const ParticleTensors& tensors,
                                   const std::vector<double>& volume, const Vec3& axis,
                                   const SampleGeometry& sample, double layer_height) {
  const Vec3 a = axis / norm(axis);
  const auto count = static_cast<std::size_t>(std::max(1.0, std::round(sample.length / layer_height)));
  LayeredStiffness out;
  out.height = sample.length / static_cast<double>(count);
  out.layers.resize(count);
  std::vector<Voigt6> weighted(count, Voigt6::Zero());  // sum V^n C^n per layer
  for (std::size_t k = 0; k < count; ++k) {
    out.layers[k].bottom = sample.bottom + out.height * static_cast<double>(k);
    out.layers[k].top = k + 1 == count ? sample.top : sample.bottom + out.height * static_cast<double>(k + 1);
  }
  // Serial, in particle order: the sums do not depend on the thread count.
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double s = (dot(p.position[i], a) - sample.bottom) / out.height;
    const auto k = static_cast<std::size_t>(std::clamp(std::floor(s), 0.0, static_cast<double>(count - 1)));
    Layer& layer = out.layers[k];
    ++layer.particles;
    if (tensors.use[i] != ParticleUse::used) continue;
    ++layer.used;
    layer.volume += volume[i];
    weighted[k] += volume[i] * tensors.stiffness[i];
  }
  double compliance = 0.0;
  bool carries = true;
  for (std::size_t k = 0; k < count; ++k) {
    Layer& layer = out.layers[k];
    if (layer.volume > 0.0) {
      layer.area = layer.volume / out.height;
      layer.youngs_modulus = directional_modulus(weighted[k] / layer.volume, a);
      layer.stiffness = layer.youngs_modulus * layer.area / out.height;
    }
    if (layer.stiffness > 0.0) {
      compliance += 1.0 / layer.stiffness;
    } else {
      carries = false;
    }
  }
  out.stiffness = carries ? 1.0 / compliance : 0.0;
  return out;
}

}  // namespace bpm::ste
