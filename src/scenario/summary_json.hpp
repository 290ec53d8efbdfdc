#pragma once
/// The run summary as JSON: what ran (scenario, counts, time step and its stability limit), how it
/// ended (stop reason, steps, simulated and wall time, bond updates per second) and the final
/// energies. Keys carry their units (`_s`, `_J`, ...).
#include <nlohmann/json.hpp>

#include "dem/simulation.hpp"
#include "scenario/scenario.hpp"

namespace bpm {

nlohmann::json summary_json(const Scenario& scenario, const RunSummary& run, const Energies& energies);

}  // namespace bpm
