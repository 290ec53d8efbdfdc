#pragma once
/// Density (mass) scaling for quasi-static runs (UniaxialCompression::mass_scaling): while a
/// ScaledMasses lives, every particle's mass and rotational inertia are f times their own and
/// gravity is 1/f of its own, so each weight stays m g. The stable time step grows by sqrt(f)
/// (the highest frequency of M^-1 K falls by sqrt(f)); the elastic response does not change. The
/// model gets its own values back, bit for bit, however the scope ends.
#include <utility>
#include <vector>

#include "model/model.hpp"

namespace bpm {

class ScaledMasses {
 public:
  ScaledMasses(Model& model, double f)
      : model_(model), mass_(model.particles.mass), inertia_(model.particles.inertia), gravity_(model.gravity) {
    if (f == 1.0) return;
    for (double& m : model_.particles.mass) m *= f;
    for (double& i : model_.particles.inertia) i *= f;
    model_.gravity = model_.gravity / f;
  }
  ~ScaledMasses() {
    model_.particles.mass = std::move(mass_);
    model_.particles.inertia = std::move(inertia_);
    model_.gravity = gravity_;
  }
  ScaledMasses(const ScaledMasses&) = delete;
  ScaledMasses& operator=(const ScaledMasses&) = delete;

 private:
  Model& model_;
  std::vector<double> mass_, inertia_;
  Vec3 gravity_;
};

}  // namespace bpm
