#pragma once
/// The platens of the DSM as moving imaginary walls (Jarolin section 3.1.3): "we assume the wall
/// to be ideal, i.e., no friction exists, only normal forces are acting between the wall and the
/// particles". Each particle of the loaded cluster whose gap to a platen is within a band gets a
/// spring along the axis with the particle-platen contact law (contact_law::linearise: Hertz or
/// linear, R* = R against the rigid wall). The lower wall is held, the upper one travels w along
/// -axis. The linear DSM linearises these springs at their operating point, the nonlinear DSM
/// evaluates them as they are.
#include <cstdint>
#include <vector>

#include "compress/platen_loading.hpp"
#include "contacts/contact_law.hpp"
#include "dsm/dsm_constraints.hpp"

namespace bpm {

struct PlatenSpring {
  std::int32_t particle = 0;
  bool top = false;
  double gap = 0.0;  ///< surface gap to the platen at the start, m
  ContactPairParameters params;
  contact_law::PairInertia inertia;
};

struct PlatenSprings {
  int dofs = 6;
  int ax = 2;         ///< the axial DOF (x, y or z)
  double sign = 1.0;  ///< axis = sign e_ax
  std::vector<PlatenSpring> springs;

  /// Global DOF of the spring's particle along the axis.
  std::size_t axial_dof(const PlatenSpring& s) const {
    return static_cast<std::size_t>(dofs) * static_cast<std::size_t>(s.particle) + static_cast<std::size_t>(ax);
  }
  /// Overlap with the platen at the displacement field x (dofs per particle) and travel w:
  /// bottom -(gap + u.axis), top w + u.axis - gap.
  double overlap(const PlatenSpring& s, const double* x, double w) const {
    const double along = sign * x[axial_dof(s)];
    return s.top ? w + along - s.gap : -(s.gap + along);
  }
  /// The platen force on the particle along e_ax per newton of contact force (the lower platen
  /// pushes along +axis, the upper along -axis).
  double direction(const PlatenSpring& s) const { return s.top ? -sign : sign; }
};

/// The mean particle radius, m.
double mean_particle_radius(const ParticleStore& particles);

/// The slack both bands below add to what can close, m: a tenth of the mean radius.
double listing_slack(const Model& model);

/// Particles this close to a platen (gap, m) get a platen spring in the nonlinear DSM: the platen
/// travel plus the slack. It also bounds contact_listing_band: no pair closes by more than the
/// travel.
double platen_listing_band(const Model& model, const PlatenLoading& load);

/// Particle pairs this close (surface gap, m) are listed once as potential contacts by both DSMs:
/// the relative approach a pair can reach, 20 times the sample's strain over a particle diameter
/// (2 R_max) but at most the platen travel, plus the slack. The DSM results report
/// the largest approach the listed pairs reached (max_pair_approach_m), which stays far inside it.
double contact_listing_band(const Model& model, const PlatenLoading& load);

/// The springs of every particle not held by `constraints` (detached particles are) whose gap to
/// a platen is below `band` (m). Throws InputError naming the platen if the loaded cluster has no
/// particle within the band of one.
PlatenSprings list_platen_springs(const Model& model, const PlatenLoading& load, const DofConstraints& constraints,
                                  double band);

}  // namespace bpm
