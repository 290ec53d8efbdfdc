#include "scenario/summary_json.hpp"

#include <cmath>

namespace bpm {
namespace {
nlohmann::json broken_by_mode(const BondStore& bonds) {
  std::size_t tension = 0, shear = 0;
  for (const BondStore::Break& b : bonds.breaks) (b.mode == BreakMode::tension ? tension : shear) += 1;
  return {{"tension", tension}, {"shear", shear}};
}
}  // namespace

nlohmann::json summary_json(const Scenario& scenario, const RunSummary& run, const Energies& energies) {
  // JSON has no infinity: a limit that could not be derived (no bond on a free particle) is null.
  const nlohmann::json limit =
      std::isfinite(scenario.time_step_limit) ? nlohmann::json(scenario.time_step_limit) : nlohmann::json(nullptr);
  return {{"scenario", scenario.path},
          {"description", scenario.description},
          {"stop_reason", std::string(to_string(run.reason))},
          {"steps", run.steps},
          {"simulated_time_s", run.time},
          {"wall_s", run.wall_seconds},
          {"bond_updates_per_second", run.bond_updates_per_second},
          {"max_speed_m_per_s", run.max_speed},
          {"time_step_s", scenario.time_step},
          {"critical_time_step_s", limit},
          {"particles", scenario.model.particles.size()},
          {"bonds", scenario.model.bonds.size()},
          {"bonds_intact", scenario.model.bonds.intact_count()},
          {"bonds_broken", broken_by_mode(scenario.model.bonds)},
          {"seed", scenario.seed},
          {"energies", {{"kinetic_J", energies.kinetic}, {"elastic_J", energies.elastic}}}};
}

}  // namespace bpm
