#include "scenario/lammps_export.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "io/lammps_data.hpp"

namespace bpm {
namespace {

/// A limit LAMMPS reads as a number but no bond reaches: bpm/rotational has no "unbreakable".
constexpr double kNeverBreaks = 1e300;

/// bpm/rotational's critical loads from our strengths (bond_strength.hpp): the axial force and the
/// bending moment that each alone reach sigma_t (F_r,c = sigma_t A, T_b,c = sigma_t I / r_b), and
/// likewise for tau_s (F_s,c = tau_s A, T_t,c = tau_s J / r_b). LAMMPS breaks a bond when the sum
/// of the four ratios reaches 1, we when the largest stress does: the same limit under one load,
/// more conservative in LAMMPS under combined loads.
struct CriticalLoads {
  double f_r = kNeverBreaks, f_s = kNeverBreaks, t_t = kNeverBreaks, t_b = kNeverBreaks;
};

CriticalLoads critical_loads(const StrengthLimits& limits, double r_b) {
  // limits hold sigma_t A_b and tau_s A_b (N); I / A = r_b^2 / 4, J / A = r_b^2 / 2.
  CriticalLoads c;
  if (std::isfinite(limits.tensile)) {
    c.f_r = limits.tensile;
    c.t_b = limits.tensile * r_b / 4.0;
  }
  if (std::isfinite(limits.shear)) {
    c.f_s = limits.shear;
    c.t_t = limits.shear * r_b / 2.0;
  }
  return c;
}

}  // namespace

BpmRotationalStiffness bpm_rotational_stiffness(const BondStiffness& k) {
  return {k.k_n, k.k_s, k.k_tor, k.k_ben};
}

LammpsExport export_lammps(const Scenario& scenario) {
  const Model& model = scenario.model;
  const ParticleStore& p = model.particles;
  const BondStore& b = model.bonds;
  LammpsExport out;

  ExchangeStructure s;
  s.particles.id = p.id;
  s.particles.position = p.position;
  s.particles.radius = p.radius;
  s.particles.material_names = scenario.particle_material_names;
  for (std::size_t k = 0; k < p.size(); ++k) {
    s.particles.material.push_back(static_cast<std::uint32_t>(p.material[k]));
    s.density.push_back(scenario.particle_densities[static_cast<std::size_t>(p.material[k])]);
  }

  // One bond type per distinct coefficient line (a lattice has few, a random packing about one
  // per bond, since k depends on L_b and r_b).
  LammpsDataOptions options;
  options.bond_style = "bpm/rotational";
  std::map<std::string, int> type_of_line;
  bool breakable = false;
  std::size_t off_midpoint = 0, broken = 0;
  double largest_offset = 0.0;
  for (std::size_t k = 0; k < b.size(); ++k) {
    if (b.intact.size() == b.size() && b.intact[k] == 0) {
      ++broken;
      continue;
    }
    s.bonds.i.push_back(p.id[static_cast<std::size_t>(b.alpha[k])]);
    s.bonds.j.push_back(p.id[static_cast<std::size_t>(b.beta[k])]);
    s.bonds.radius.push_back(b.radius[k]);
    const BpmRotationalStiffness kk = bpm_rotational_stiffness(b.stiffness[k]);
    const StrengthLimits limits = k < b.strength.size() ? b.strength[k] : StrengthLimits{};
    const CriticalLoads c = critical_loads(limits, b.radius[k]);
    breakable = breakable || std::isfinite(limits.tensile) || std::isfinite(limits.shear);
    if (b.arm_offset[k] != 0.0) {
      ++off_midpoint;
      largest_offset = std::max(largest_offset, std::abs(b.arm_offset[k]) / b.rest_length[k]);
    }
    // K_r K_s K_t K_b F_rc F_sc T_tc T_bc gamma_n gamma_s gamma_r gamma_t (damping: see notes).
    const std::string line = fmt::format("{} {} {} {} {} {} {} {} 0 0 0 0", kk.k_r, kk.k_s, kk.k_t,
                                         kk.k_b, c.f_r, c.f_s, c.t_t, c.t_b);
    const auto [it, added] =
        type_of_line.emplace(line, static_cast<int>(options.bond_coeffs.size()) + 1);
    if (added) options.bond_coeffs.push_back(line);
    options.bond_type.push_back(it->second);
  }
  if (options.bond_coeffs.empty()) {
    options.bond_coeffs.push_back(fmt::format("0 0 0 0 {0} {0} {0} {0} 0 0 0 0", kNeverBreaks));
  }
  out.bond_types = options.bond_coeffs.size();
  out.data = lammps_data_text(s, options);

  if (off_midpoint > 0) {
    out.notes.push_back(fmt::format(
        "{} bonds have their contact point off the midpoint of the centres (up to {:.3g} % of L_b: "
        "gap-centre models between unequal radii); LAMMPS couples their shear and rotation at the "
        "midpoint",
        off_midpoint, 100.0 * largest_offset));
  }
  if (broken > 0) out.notes.push_back(fmt::format("{} broken bonds left out", broken));
  if (model.damping.bond > 0.0) {
    out.notes.push_back(
        "bond damping (Chen Eq. 9-10) not carried over: gamma_n, gamma_s, gamma_r, gamma_t are 0; "
        "LAMMPS damps the relative velocities differently (Wang et al. 2015)");
  }
  if (model.damping.particle > 0.0)
    out.notes.push_back("local damping (Chen Eq. 11-12) has no LAMMPS fix: not carried over");
  if (breakable) {
    out.notes.push_back(
        "strengths mapped to F_rc = sigma_t A, F_sc = tau_s A, T_bc = sigma_t I / r_b, T_tc = "
        "tau_s J / r_b; LAMMPS breaks on the sum of the four ratios, bpmkit on the larger stress");
  }
  if (model.contacts.particle_particle)
    out.notes.push_back("particle contacts not carried over (pair_style zero in the deck)");
  if (!model.walls.empty()) out.notes.push_back("walls not carried over");
  if (!model.loads.empty())
    out.notes.push_back("loads not carried over (add fix addforce / fix setforce)");
  const auto held = [](const Vec3& free) {
    return free.x == 0.0 || free.y == 0.0 || free.z == 0.0;
  };
  if (std::any_of(p.translation_free.begin(), p.translation_free.end(), held) ||
      std::any_of(p.rotation_free.begin(), p.rotation_free.end(), held)) {
    out.notes.push_back(
        "boundary conditions (fixed particles) not carried over (add fix setforce on a group)");
  }

  double r_max = 0.0;
  for (const double r : p.radius) r_max = std::max(r_max, r);
  const double dt = scenario.time_step;
  const bool finite_end = std::isfinite(scenario.stop.end_time) && dt > 0.0;
  std::string deck = fmt::format(
      "# LAMMPS input written by bpmkit export lammps from {}\n"
      "# Needs LAMMPS with the BPM package (4 May 2022 or later). Units SI; ids = bpmkit ids + 1.\n"
      "units           si\n"
      "dimension       3\n"
      "boundary        f f f\n"
      "atom_style      bpm/sphere\n"
      "atom_modify     map array\n"
      "newton          on off            # bpm/rotational needs newton bond off\n"
      "comm_modify     vel yes cutoff {}\n"
      "special_bonds   lj 0 1 1 coul 1 1 1\n"
      "bond_style      bpm/rotational break {} smooth no\n"
      "read_data       structure.data\n"
      "pair_style      zero {}\n"
      "pair_coeff      * *\n"
      "neighbor        {} bin\n"
      "fix             integrate all nve/bpm/sphere\n"
      "timestep        {}\n"
      "thermo          1000\n",
      scenario.path, 4.0 * r_max, breakable ? "yes" : "no", 2.0 * r_max, 0.1 * r_max, dt);
  deck += finite_end ? fmt::format("run             {}\n",
                                   static_cast<long long>(std::ceil(scenario.stop.end_time / dt)))
                     : "# the scenario has no end time: give the number of steps\n# run N\n";
  for (const std::string& note : out.notes) deck += "# note: " + note + "\n";
  out.deck = std::move(deck);
  return out;
}

}  // namespace bpm
