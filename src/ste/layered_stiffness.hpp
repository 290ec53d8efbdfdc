#pragma once
/// The layered springs-in-series model of the sample stiffness (Jarolin section 4.2, inverse opal):
/// the sample is cut into layers normal to the loading axis (height h, about two particle diameters,
/// adjusted so that the layers tile [bottom, top] exactly); each particle belongs to the layer of its
/// centre. Per layer the stiffness tensor is the volume-weighted average of its used particles'
/// C^n, E_layer its Young's modulus along the axis, and the layer a spring K_layer = E_layer A / h;
/// the sample is the layers in series, 1/K = sum 1/K_layer.
///
/// Cross-section A of a layer (a documented choice): the volume its used particles represent
/// divided by h, A = sum V^n / h. With Voronoi volumes the cells tile the clipped body, so this is
/// the body's area there (the layer's convex-hull area when every particle is used); and since
/// E_layer ~ sum V^n C^n / sum V^n, K_layer then hardly depends on how the volume is shared among
/// the particles, only on the bonds (sum V^n C^n = sum X^n / 2). Pores inside the layer (inverse
/// opal) count to the area, as they do in the sample's A of the uniform model.
#include <vector>

#include "compress/sample_geometry.hpp"
#include "model/particle_store.hpp"
#include "ste/misra_chang.hpp"

namespace bpm::ste {

struct Layer {
  double bottom = 0.0, top = 0.0;  ///< along the axis, m
  std::size_t particles = 0;       ///< centres in the layer
  std::size_t used = 0;            ///< of them in the average
  double volume = 0.0;             ///< sum V^n of the used ones, m^3
  double area = 0.0;               ///< volume / h, m^2
  double youngs_modulus = 0.0;     ///< along the axis, Pa
  double stiffness = 0.0;          ///< E A / h, N/m
};

struct LayeredStiffness {
  double height = 0.0;  ///< h, m
  std::vector<Layer> layers;  ///< bottom to top
  double stiffness = 0.0;     ///< the layers in series, N/m (0 if some layer carries nothing)
};

/// `layer_height` (m) is rounded so that a whole number of layers fills the sample length.
LayeredStiffness layered_stiffness(const ParticleStore& particles, const ParticleTensors& tensors,
                                   const std::vector<double>& volume, const Vec3& axis,
                                   const SampleGeometry& sample, double layer_height);

}  // namespace bpm::ste
