#pragma once
/// The stiffness tensor estimation (STE, Jarolin 2020 section 3.2): the sample's Hooke tensor from
/// the linearised interactions of each particle with its neighbours (Misra & Chang), without a
/// simulation or a linear solve, and from it the sample's Young's moduli and its stiffness along the
/// loading axis.
///
///   1. V^n per particle: radical Voronoi cells clipped to the sample (voro++), or the solid
///      fraction (cell_volumes.hpp).
///   2. C^n per particle (Jarolin Eq. 32, misra_chang.hpp) from the bonds' translational stiffness
///      (the unified bond law) and optionally the linearised particle contacts.
///   3. C = sum V^n C^n / sum V^n over the used particles; E_x, E_y, E_z, Poisson ratios and E along
///      the axis from its compliance (elastic_constants.hpp).
///   4. K = E_axis A / l with l, A from measure_sample (Jarolin 4.2); optionally the layered
///      springs-in-series K (layered_stiffness.hpp) and the platens in series (wall_series.hpp).
///   5. Optionally the local stiffness map (Jarolin 4.4, local_map.hpp), for ste_vtk.hpp.
///
/// Deterministic: bitwise the same result for any number of OpenMP threads.
#include <functional>
#include <optional>
#include <string_view>
#include <vector>

#include "compress/sample_geometry.hpp"
#include "model/model.hpp"
#include "ste/cell_volumes.hpp"
#include "ste/elastic_constants.hpp"
#include "ste/layered_stiffness.hpp"
#include "ste/local_map.hpp"
#include "ste/misra_chang.hpp"
#include "ste/voigt.hpp"
#include "ste/wall_series.hpp"

namespace bpm::ste {

enum class VolumeMethod : std::uint8_t { voronoi, solid_fraction };

struct SteOptions {
  Vec3 axis{0.0, 0.0, 1.0};  ///< loading axis (normalised here)
  /// Solid fraction by default: on this project's 2-core machine voro++ takes ~1.5 s of CPU for
  /// 1e5 cells against ~0.3 s for everything else; the sample C differs by ~0.2 % between the two
  /// (the volumes only enter its denominator), the local map and layers by more.
  VolumeMethod volumes = VolumeMethod::solid_fraction;
  /// Evenly spaced side planes that clip the Voronoi cells (>= 3), besides the planes of the flat
  /// faces found from the hull (cell_volumes.hpp).
  int hull_planes = 36;
  int geometry_directions = 360;  ///< directions of measure_sample for l and A
  /// Linearised particle contacts at the current overlaps; unset: on when the model has particle
  /// contacts (ContactModel::active). At zero overlap they add nothing.
  std::optional<bool> include_contacts;
  Fluctuation fluctuation = Fluctuation::paper;
  double singular_tolerance = 1e-8;  ///< relative smallest eigenvalue of sum_m K^nm
  bool layered = false;              ///< also the layered springs-in-series K
  double layer_height_diameters = 2.0;  ///< layer height in mean particle diameters (Jarolin: 2)
  bool local_map = false;            ///< the local stiffness map
  double local_diameter_factor = 3.0;   ///< sphere diameter in particle diameters (Jarolin: 3)
  bool local_own_diameter = false;      ///< d = the particle's diameter instead of the mean
  std::optional<WallSeriesOptions> walls;  ///< platens in series (Jarolin 3.2.3)
  /// Under mpirun (calibrate/stiffness_methods.cpp): this rank's share of the Voronoi cells, and
  /// the sum of per-particle values over the ranks (an MPI reduction). Each cell is computed on one
  /// rank and added to zeros on the others, so every rank has the whole result, bit for bit that of
  /// one process, and the rest of the estimation is the same arithmetic on every rank.
  WorkShare share;
  std::function<void(std::vector<double>&)> sum_over_shares;
};

/// Wall-clock seconds of the parts of one estimation.
struct SteTimings {
  double volumes = 0.0;    ///< V^n (Voronoi or solid fraction)
  double tensors = 0.0;    ///< interactions and C^n
  double average = 0.0;    ///< C, constants, geometry, layered, walls
  double local_map = 0.0;  ///< the local map (0 when off)
};

struct SteResult {
  Voigt6 stiffness = Voigt6::Zero();  ///< C, Voigt (voigt.hpp), symmetric part of the average, Pa
  double asymmetry = 0.0;  ///< max |C_IJ - C_JI| / max |C_IJ| of the raw average
  EngineeringConstants constants;
  Vec3 axis;                 ///< unit loading axis
  double youngs_modulus_axis = 0.0;  ///< E_a = 1 / (a a : S : a a), Pa
  SampleGeometry sample;     ///< l and A (measure_sample)
  double solid_fraction = 0.0;  ///< sum of sphere volumes / (l A)
  double stiffness_uniform = 0.0;  ///< K = E_a A / l, N/m
  std::optional<LayeredStiffness> layered;
  /// The platens in series with the sample: with K_sample = the layered K when `layered` is on,
  /// else the uniform K. Its `total` is K with the platens.
  std::optional<WallSeries> walls;

  std::size_t particles = 0, used = 0;
  std::size_t excluded_singular = 0;   ///< too few interactions (sum K singular)
  std::size_t excluded_no_volume = 0;  ///< empty Voronoi cell
  std::size_t bonds = 0, contacts = 0;  ///< interactions used (intact bonds, touching contacts)
  double volume_used = 0.0, volume_total = 0.0;  ///< sum V^n, m^3

  // Per particle (indexed like ParticleStore), for the VTK output and further analysis.
  std::vector<Voigt6> particle_stiffness;  ///< C^n, Pa; zero unless used
  std::vector<double> particle_volume;     ///< V^n, m^3
  std::vector<ParticleUse> particle_use;
  std::vector<std::int32_t> coordination;
  std::optional<LocalMap> local;

  double seconds = 0.0;  ///< wall-clock of the whole estimation, s
  SteTimings parts;

  /// The STE's answer for the sample: K with the platens if asked, else the layered K if asked,
  /// else the uniform K = E_a A / l; N/m.
  double sample_stiffness() const {
    return walls ? walls->total : (layered ? layered->stiffness : stiffness_uniform);
  }
};

/// "voronoi" or "solid_fraction" (also "solid-fraction"); InputError naming `where` otherwise.
VolumeMethod parse_volume_method(std::string_view name, std::string_view where);

/// Runs the STE on the model at its current positions. Throws InputError for an empty model, a
/// zero axis, bad options or (with contacts) particles without contact materials.
SteResult estimate_stiffness(const Model& model, const SteOptions& options = {});

}  // namespace bpm::ste
