#pragma once
/// The STE result as JSON (for summary files and the calibration report): the Voigt C, the
/// engineering constants, the sample stiffnesses, the particle counts and the timings. Units in
/// the key names (_Pa, _N_per_m, _m, _s).
#include <nlohmann/json.hpp>

#include "ste/stiffness_tensor_estimation.hpp"

namespace bpm::ste {

nlohmann::json summary_json(const SteResult& result);

}  // namespace bpm::ste
