#include "calibrate/bond_youngs_modulus.hpp"

#include "bonds/bond_model.hpp"
#include "core/error.hpp"

namespace bpm {

void set_bond_youngs_moduli(Model& model, std::vector<BondMaterial>& materials, const std::vector<double>& youngs_moduli,
                            double bond_damping) {
  if (youngs_moduli.size() != materials.size()) {
    throw InputError("calibrate", "got " + std::to_string(youngs_moduli.size()) + " Young's moduli for " +
                                      std::to_string(materials.size()) + " bond materials",
                     "give one per bond material");
  }
  for (std::size_t m = 0; m < materials.size(); ++m) {
    if (!(youngs_moduli[m] > 0.0)) throw InputError("calibrate", "bond Young's modulus must be > 0", "");
    materials[m].youngs_modulus = youngs_moduli[m];
  }
  BondStore& b = model.bonds;
  const ParticleStore& p = model.particles;
  for (std::size_t i = 0; i < b.size(); ++i) {
    const BondGeometry g{b.radius[i], b.rest_length[i], p.radius[b.alpha[i]], p.radius[b.beta[i]]};
    b.stiffness[i] = make_bond_constants(materials[static_cast<std::size_t>(b.material[i])], g).stiffness;
  }
  // Refresh what depends on the stiffness (bond damping) while keeping the adjacency and axes.
  b.finalize(p, bond_damping);
}

std::vector<double> bond_youngs_moduli(const std::vector<BondMaterial>& materials) {
  std::vector<double> e;
  for (const auto& m : materials) e.push_back(m.youngs_modulus);
  return e;
}

}  // namespace bpm
