#pragma once
/// Smaller samples cut from a larger one, for the scaling study of `bpmkit compare --sizes`
/// (Jarolin Fig. 5: three sizes, each twice the last): the particles whose centres lie in the lower
/// `fraction` of the sample's length along the axis, with the bonds among them. Cutting keeps the
/// packing, the bond parameters and the cross-section, so only the size changes.
#include "dem/model.hpp"

namespace bpm {

/// The particles with keep[i] and the bonds between two kept particles, finalised; materials,
/// contacts, damping and walls are copied, loads dropped.
Model model_subset(const Model& model, const std::vector<bool>& keep);

/// model_subset of the particles with x . axis <= bottom + fraction * length (centres).
Model lower_part(const Model& model, const Vec3& axis, double fraction);

}  // namespace bpm
