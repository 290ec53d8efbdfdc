#pragma once
/// The loading that the fast methods and the explicit DEM share (Jarolin section 4.2): a sample
/// between two platens normal to `axis`, the lower one held, the upper one moved towards it by
/// `displacement`. The platens touch the sample's extremes, as in run_uniaxial_compression.
///
/// For the linear DSM the platens act as kinematic constraints on the particles that touch them:
/// the particles whose gap to a platen closes before the middle of the DEM's fit window
/// (gap <= (fit_from + fit_to)/2 * target displacement) are held (bottom) or moved (top) along the
/// axis. A frictionless platen leaves them free across the axis; with friction they are held
/// across it too (no slip). The nonlinear DSM instead puts a Hertz spring between every particle
/// near a platen and the moving wall (Jarolin section 3.1.3), so that the gaps close as in the DEM.
#include <cstdint>
#include <vector>

#include "compress/sample_geometry.hpp"
#include "compress/uniaxial_compression.hpp"
#include "model/model.hpp"

namespace bpm {

struct PlatenLoading {
  Vec3 axis{0.0, 0.0, 1.0};  ///< unit loading axis; the upper platen moves along -axis
  SampleGeometry sample;     ///< l and A from the particle body (measure_sample)
  double displacement = 0.0; ///< of the upper platen towards the lower one, m (target strain * l)
  std::int32_t platen_material = 0;  ///< contact material of the platens
  /// Every grain-platen pair's friction (the mixed value the DEM applies) is zero: contact particles
  /// slide across the axis.
  bool frictionless = true;
  /// The DEM's fit window as fractions of the displacement: a method whose force is not linear in
  /// the displacement reports the chord over it, as the DEM's fitted slope does.
  double fit_from = 0.2, fit_to = 1.0;
  /// Particles treated as touching each platen in the linear DSM.
  std::vector<std::int32_t> bottom, top;
  /// Gap to each platen, m (the surface distance at the start, >= 0 up to round-off).
  std::vector<double> gap_bottom, gap_top;
};

/// The loading of a compression test on `model` (which need not have the platens yet).
PlatenLoading make_platen_loading(const Model& model, const UniaxialCompression& settings);

}  // namespace bpm
