#pragma once
/// The platens as springs in series with the sample (Jarolin section 3.2.3). In the compression
/// test the platen travel w is the sample's shortening plus the overlaps at the two platens, so
///     w = F / K_sample + delta_bottom(F) + delta_top(F),
/// solved for the platen force F by Newton's method (safeguarded by bisection; the paper's "iterate
/// since F depends on K_total", converged). Model of a platen's contact set (a documented choice):
/// the particles touching it (a given list, or those whose gap to the platen at the sample's
/// extreme is at most `band`) are pressed by the rigid platen to the same overlap delta and share F:
///     Hertz:  F = sum_i 4/3 E* sqrt(R_i) delta^1.5   (R* = R_i against a rigid wall)
///     linear: F = N k_n delta.
/// Reported: the secant stiffnesses F/delta and the total F/w (what a force over displacement at
/// the target strain gives), and the tangent ones dF/d delta (Hertz: 3/2 F/delta) combined as
/// 1/K = 1/K_sample + 1/k_bottom + 1/k_top (the slope at the target strain). `stiffness` picks which
/// is `total`; secant by default, the paper's "stiffness ... calculated with the displacement".
#include <cstdint>
#include <vector>

#include "compress/sample_geometry.hpp"
#include "model/contact_material.hpp"
#include "model/particle_store.hpp"

namespace bpm::ste {

enum class WallStiffness : std::uint8_t { secant, tangent };

struct WallSeriesOptions {
  ContactPairParameters contact;  ///< particle material against the platen material
  double displacement = 0.0;      ///< platen travel w = target strain * l, m (> 0)
  /// Particles touching each platen; when empty, those whose gap to the platen is <= band.
  std::vector<std::int32_t> bottom_particles, top_particles;
  double band = 0.0;  ///< m (a relative 1e-12 l is added for round-off)
  WallStiffness stiffness = WallStiffness::secant;
};

struct PlatenContacts {
  std::size_t particles = 0;
  double overlap = 0.0;  ///< delta at force F, m
  double secant = 0.0;   ///< F / delta, N/m
  double tangent = 0.0;  ///< dF/d delta, N/m
};

struct WallSeries {
  double sample_stiffness = 0.0;  ///< K_sample used, N/m
  double displacement = 0.0;      ///< w, m
  double force = 0.0;             ///< F, N
  PlatenContacts bottom, top;
  double secant = 0.0;   ///< F / w, N/m
  double tangent = 0.0;  ///< 1 / (1/K_sample + 1/k_bottom + 1/k_top) with tangent k, N/m
  double total = 0.0;    ///< secant or tangent, as asked
  int iterations = 0;
};

/// Throws InputError for a non-positive displacement or contact stiffness, or a platen without
/// particles.
WallSeries wall_series(const ParticleStore& particles, const Vec3& axis, const SampleGeometry& sample,
                       double sample_stiffness, const WallSeriesOptions& options);

}  // namespace bpm::ste
