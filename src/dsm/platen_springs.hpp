#pragma once
/// The platens of the DSM as moving imaginary walls (Jarolin section 3.1.3), with the DEM's
/// particle-platen contact law (R* = R against the rigid wall): the lower wall held, the upper one
/// travelling w along -axis. Jarolin's walls are ideal ("no friction exists"); the DEM's platens
/// slide with the grain-platen pair's friction (its mixing rule), and so do these walls: normal and
/// tangential springs, slip and history as every contact of statics/static_problem.hpp.
#include <cstdint>
#include <vector>

#include "compress/platen_loading.hpp"
#include "dsm/platen_constraints.hpp"
#include "statics/static_contact.hpp"

namespace bpm {

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

/// The platens as wall contacts (statics/static_contact.hpp) of every particle not held by
/// `constraints` (detached particles are) whose gap to a platen is below `band` (m): the lower
/// platen held, the upper one moving along -axis by the travel. Throws InputError naming the platen
/// if the loaded cluster has no particle within the band of one.
std::vector<StaticContact> platen_contacts(const Model& model, const PlatenLoading& load,
                                           const DofConstraints& constraints, double band);

}  // namespace bpm
