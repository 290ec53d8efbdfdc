#pragma once
/// The uniaxial compression test (Jarolin section 4.2): the sample stands between two rigid plane
/// platens normal to the loading axis, touching its extremes; the lower one is held, the upper one
/// moves towards it at the constant speed strain_rate * l until the target strain (or, on request,
/// past the peak stress to failure). The platen force against the platen displacement gives the
/// sample stiffness K, the slope fitted by least squares over a strain window, and the Young's
/// modulus E = K l / A with l and A measured from the sample (sample_geometry.hpp).
///
/// The middle third's strains (virtual strain gauges, strain_gauge.hpp) give the body's E and nu
/// over the same window.
///
/// Quasi-static check: within the fit window the kinetic energy must stay small against the stored
/// elastic energy (bonds and contacts); the run reports the largest ratio, and the difference
/// between the forces on the two platens (which inertia makes unequal); both again at the peak
/// force.
///
/// The same machine runs the three laboratory strength tests (LabTest): the uniaxial compression
/// (UCS = F_peak / A), the Brazilian disc (a disc loaded across its diameter D between the same
/// platens, BTS = 2 F_peak / (pi D t), t its thickness) and the direct tension (the particles near
/// each end glued to a grip: the lower grip held, the upper one pulled along +axis at the same
/// speed; strength F_peak / A). In tension the displacement, strain and force are positive in
/// extension.
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "compress/sample_geometry.hpp"
#include "compress/strain_gauge.hpp"
#include "dem/simulation.hpp"
#include "model/model.hpp"

namespace bpm {

enum class LabTest { uniaxial, brazilian, tension };
/// "uniaxial", "brazilian", "tension".
std::string_view to_string(LabTest test);
/// How the test's strength follows from its peak force: "UCS = F / A", "BTS = 2 F / (pi D t)",
/// "tensile strength = F / A".
std::string_view strength_definition(LabTest test);

struct UniaxialCompression {
  LabTest test = LabTest::uniaxial;
  Vec3 axis{0.0, 0.0, 1.0};          ///< loading direction (the upper platen moves along -axis)
  std::int32_t platen_material = 0;  ///< contact material of both platens
  double strain_rate = 0.0;          ///< 1/s, > 0
  double target_strain = 0.0;        ///< compressive strain at which to stop, > 0
  double fit_from = 0.0;             ///< strain window for K, as fractions of target_strain
  double fit_to = 1.0;
  /// Continue beyond target_strain until the stress has dropped to this fraction of its peak
  /// (failure; the Brazilian test at its split, failure_fraction), up to max_strain. 0: stop at
  /// target_strain.
  double failure_drop = 0.0;
  double max_strain = 0.0;
  double time_step = 0.0;  ///< s; 0: safety_factor * the combined bond and contact limit
  double safety_factor = 0.5;
  std::int64_t curve_points =
      200;  ///< rows of the curve up to target_strain (about); the same spacing past it
  /// Density (mass) scaling for a quasi-static test, as PFC and YADE offer it: every particle's
  /// mass and rotational inertia times this factor f >= 1 during the test (its weight stays m g),
  /// so the stable time step grows by sqrt(f) and the test takes 1/sqrt(f) of the steps. The
  /// elastic stiffness does not depend on the mass; the test stays valid while it stays
  /// quasi-static, which the kinetic-energy and platen-balance checks report (docs/scenario.md).
  double mass_scaling = 1.0;
  Vec3 disc_axis{};  ///< brazilian: the disc's axis (normal to `axis`); t is measured along it
  double grip_depth =
      0.0;  ///< tension: grips hold the particles whose centre is this close to an end; 0: 2 R_max
};

/// The Brazilian disc's thickness t: the particles' extent along s.disc_axis, m.
double disc_thickness(const ParticleStore& particles, const UniaxialCompression& s);
/// The test's stress at platen force F (N): F / A, or 2 F / (pi D t) for the Brazilian disc
/// (D = length, the sample's extent along the loading axis; t its extent along disc_axis).
double test_stress(LabTest test, double force, double length, double area, double thickness);
/// The fraction of its peak force below which a test to failure ends: failure_drop, and for the
/// Brazilian test at least 0.8, its split (0 where failure_drop is 0: not to failure).
double failure_fraction(const UniaxialCompression& s);

struct CompressionPoint {
  double time = 0.0;                           ///< s
  double displacement = 0.0;                   ///< of the upper platen towards the lower one, m
  double strain = 0.0;                         ///< displacement / l
  double force = 0.0;                          ///< mean compressive force on the two platens, N
  double force_top = 0.0, force_bottom = 0.0;  ///< N, each compressive
  double kinetic = 0.0;                        ///< J
  double elastic = 0.0;                        ///< bonds plus contacts, J
  std::size_t bonds_broken = 0;
  std::size_t bonds_broken_tension =
      0;              ///< of bonds_broken, those broken in tension (the rest in shear)
  GaugeStrain gauge;  ///< the middle third's strain (strain_gauge.hpp); 0 without a gauge
};

struct CompressionResult {
  LabTest test = LabTest::uniaxial;
  double failure_drop = 0.0;  ///< the curve goes past the peak to this fraction of it
                              ///< (failure_fraction of the settings)
  SampleGeometry sample;
  double time_step = 0.0;
  double mass_scaling = 1.0;  ///< the factor the test ran with
  std::vector<CompressionPoint> curve;
  double stiffness = 0.0;       ///< K, N/m
  double youngs_modulus = 0.0;  ///< E = K l / A, Pa
  BodyModuli body;              ///< E and nu of the middle third over the fit window
  std::size_t gauge_particles = 0;
  double fit_r2 = 0.0;  ///< coefficient of determination of the fit
  std::size_t fit_points = 0;
  double fit_from_m = 0.0;  ///< the fit window in platen travel, m: [fit_from_m, fit_to_m]
  double fit_to_m = 0.0;
  double max_kinetic_ratio = 0.0;    ///< max kinetic / elastic energy within the fit window
  double max_force_imbalance = 0.0;  ///< max |F_top - F_bottom| / F within the fit window
  double peak_stress = 0.0;          ///< max F / A, Pa
  double peak_strain = 0.0;
  double peak_force = 0.0;  ///< N
  double strength = 0.0;    ///< UCS, BTS or the tensile strength from peak_force, Pa
  double thickness = 0.0;   ///< brazilian: the disc's t along disc_axis, m (D is sample.length)
  double peak_kinetic_ratio = 0.0;    ///< kinetic / elastic energy at the peak
  double peak_force_imbalance = 0.0;  ///< |F_top - F_bottom| / F at the peak
  std::size_t grip_particles = 0;     ///< tension: particles in the two grips
  std::string stop;                   ///< "target_strain", "failure" or "max_strain"
  RunSummary run;
  Energies final_energies;
};

/// How far a test has got besides the simulation's state: what a checkpoint of the test stores so
/// that a resumed test records the same curve and reports the same peak.
struct CompressionProgress {
  std::vector<CompressionPoint> curve;
  double peak_stress = 0.0;  ///< Pa
  double peak_strain = 0.0;
};

/// Checkpoints and interruption of a long test (scenario/checkpoint.hpp), without an io dependency
/// here. Per step: step, curve point (if due), end check, periodic checkpoint, interrupt check; so
/// a checkpoint is never taken at the step where the test ends, and one taken at step N holds
/// everything the loop did up to N.
struct CompressionHooks {
  std::int64_t checkpoint_every = 0;  ///< steps between checkpoints; 0: none
  /// Writes a checkpoint; called every checkpoint_every steps and when interrupted.
  std::function<void(const Simulation&, const CompressionProgress&)> checkpoint;
  /// Checked after each step; true ends the test with stop "interrupted" and no fit.
  std::function<bool(const Simulation&)> interrupted;
  /// Set: continue a test from a checkpoint instead of starting it. Called once the platens are
  /// added, the masses scaled and the Simulation built (the state the checkpoint was taken in);
  /// restores the model's state, the simulation's clock and the progress.
  std::function<void(Simulation&, CompressionProgress&)> resume;
};

/// Adds the two platens to the model (which must have contact materials and its bonds finalised)
/// and runs the test. The model is left in its final state. `observer` is called at every point of
/// the curve (including the first and the last; a resumed test only for the points after its
/// checkpoint). `hooks` add checkpoints, interruption and resuming.
CompressionResult run_uniaxial_compression(
    Model& model, const UniaxialCompression& settings,
    const std::function<void(const Simulation&, const CompressionPoint&)>& observer = {},
    const CompressionHooks& hooks = {});

/// The step a scenario derives at load for `model` (integrator.time_step: auto): safety_factor
/// times the stability limit with the test's scaled masses, before the platens are added. A
/// calibration that changes the bonds' stiffness derives it again from the changed model.
double scenario_time_step(Model& model, double mass_scaling, double safety_factor);

/// The sample the test measures (length along the axis, cross-section): what
/// run_uniaxial_compression reports as CompressionResult::sample, before it runs.
SampleGeometry compression_sample(const Model& model, const UniaxialCompression& settings);

/// Least-squares slope of y over x for the points with x in [x_min, x_max]; r2 and count returned.
struct LinearFit {
  double slope = 0.0, intercept = 0.0, r2 = 0.0;
  std::size_t points = 0;
};
LinearFit fit_line(const std::vector<double>& x, const std::vector<double>& y, double x_min,
                   double x_max);

}  // namespace bpm
