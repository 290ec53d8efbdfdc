#pragma once
// The bonded lattice the compression tests load: its stiffness and strength have closed forms.
#include <cstdint>

#include "bonds/bond_model.hpp"
#include "model/contact_material.hpp"
#include "model/model.hpp"

namespace bpm::test {

/// A simple cubic lattice nx x ny x nz of steel spheres (R = 1 mm) at spacing 2R, nearest
/// neighbours bonded (TBBM, E_b = 200 GPa, r_b = R); contact material 0 for particles and platens,
/// frictionless linear springs of k_c; particle-particle contacts off.
inline Model lattice(int nx, int ny, int nz, double k_c) {
  Model model;
  const double R = 1e-3;
  auto index = [&](int i, int j, int k) {
    return static_cast<std::int32_t>((i * ny + j) * nz + k);
  };
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k)
        model.particles.add(index(i, j, k), {2 * R * i, 2 * R * j, 2 * R * k}, R, 7850.0);
  BondMaterial m;
  m.model = "tbbm";
  m.youngs_modulus = 200e9;
  m.poisson_ratio = 0.3;
  auto bond = [&](std::int32_t a, std::int32_t b) {
    const BondGeometry g{R, 2 * R, R, R};
    model.bonds.add(a, b, make_bond_constants(m, g), R, 2 * R);
  };
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k) {
        if (i + 1 < nx) bond(index(i, j, k), index(i + 1, j, k));
        if (j + 1 < ny) bond(index(i, j, k), index(i, j + 1, k));
        if (k + 1 < nz) bond(index(i, j, k), index(i, j, k + 1));
      }
  ContactMaterial c;
  c.name = "platen";
  c.law = ContactLaw::linear;
  c.k_n = 2.0 * k_c;  // two equal materials in series give k_c
  c.k_t = 2.0 * k_c;
  c.restitution = 0.5;
  model.contacts.materials = {c};
  model.damping.particle = 0.7;  // local damping: reaches the static response, does not change it
  model.finalize();
  return model;
}

}  // namespace bpm::test
