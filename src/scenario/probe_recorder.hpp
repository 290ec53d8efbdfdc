#pragma once
/// Time series of the scenario's probes as CSV: one row per output time, with for each probe the
/// mean displacement (m) and mean velocity (m/s) of its particles and the sum of their forces (N).
/// Columns: time, then NAME_ux, NAME_uy, NAME_uz, NAME_vx, NAME_vy, NAME_vz, NAME_fx, NAME_fy,
/// NAME_fz for each probe in order. On fixed particles the force is what the bonds and loads put on
/// the support; the support reaction is its negative.
#include <string>
#include <vector>

#include "model/particle_store.hpp"
#include "scenario/scenario.hpp"

namespace bpm {

class ProbeRecorder {
 public:
  explicit ProbeRecorder(std::vector<Probe> probes);

  /// The header line, and the row for the current state at time t (s) (the run streams them).
  const std::string& header() const { return header_; }
  std::string row(double t, const ParticleStore& particles) const;

 private:
  std::vector<Probe> probes_;
  std::string header_;
};

}  // namespace bpm
