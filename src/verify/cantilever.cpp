#include "verify/cantilever.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/error.hpp"
#include "dem/contact_time_step.hpp"
#include "statics/static_solver.hpp"
#include "verify/elastica.hpp"

namespace bpm::verify {
namespace {

/// n bonds of equal length spanning L0, particles of radius R (a straight row from x = 0).
CantileverSpec row(std::string case_name, std::string variant, int bonds, double length,
                   double particle_radius, double bond_radius) {
  CantileverSpec s;
  s.case_name = std::move(case_name);
  s.variant = std::move(variant);
  for (int i = 0; i <= bonds; ++i) {
    s.x.push_back(length * i / bonds);
    s.radius.push_back(particle_radius);
  }
  s.bond_radius = bond_radius;
  return s;
}

std::string bonds_variant(int n) { return "bonds=" + std::to_string(n); }

}  // namespace

std::vector<CantileverSpec> cantilever_case(int case_number) {
  std::vector<CantileverSpec> specs;
  switch (case_number) {
    case 1:  // reference: 11 touching particles R = 0.2 m, L0 = 4 m, r_b = 0.2 m
      specs.push_back(row("case1", "reference", 10, 4.0, 0.2, 0.2));
      break;
    case 2:  // shortening the beam: 1..10 touching particles of R = 0.2 m (L0 = 0.4 .. 4 m)
      for (int n = 1; n <= 10; ++n) specs.push_back(row("case2", bonds_variant(n), n, 0.4 * n, 0.2, 0.2));
      break;
    case 3:  // refining the beam: n bonds over L0 = 4 m, R = 0.2 m, so with gaps
      for (int n : {1, 2, 4, 5, 6, 8, 10}) specs.push_back(row("case3", bonds_variant(n), n, 4.0, 0.2, 0.2));
      break;
    case 4:  // touching particles of R = 2/n over L0 = 4 m, r_b = 0.1 m
      for (int n : {1, 2, 4, 5, 10}) specs.push_back(row("case4", bonds_variant(n), n, 4.0, 2.0 / n, 0.1));
      break;
    case 5:  // three particles over 4 m, middle radius varied; PBM with k_s from Eq. 26
      for (double middle : {0.2, 0.4, 0.8}) {
        CantileverSpec s = row("case5", "", 2, 4.0, 0.2, 0.2);
        s.radius[1] = middle;
        s.variant = "middle_radius=" + std::to_string(middle).substr(0, 3);
        s.pbm_shear = ShearOverride::euler_bernoulli;
        specs.push_back(s);
      }
      break;
    default:
      throw InputError("verify cantilever", "no case " + std::to_string(case_number), "cases are 1 to 5");
  }
  return specs;
}

std::vector<std::string> cantilever_models() { return {"pbm", "ebbm", "tbbm"}; }

BondMaterial cantilever_material(const CantileverSpec& spec, const std::string& model_key) {
  BondMaterial m;
  m.name = model_key;
  m.model = model_key;
  m.youngs_modulus = spec.youngs_modulus;
  m.poisson_ratio = spec.poisson_ratio;
  m.radius = spec.bond_radius;
  if (model_key == "pbm") m.shear_override = spec.pbm_shear;
  return m;
}

Model build_cantilever(const CantileverSpec& spec, const std::string& model_key, double particle_damping) {
  Model model;
  for (std::size_t i = 0; i < spec.x.size(); ++i) {
    model.particles.add(static_cast<std::int64_t>(i), {spec.x[i], 0.0, 0.0}, spec.radius[i], spec.density);
  }
  const BondMaterial material = cantilever_material(spec, model_key);
  for (std::size_t i = 0; i + 1 < spec.x.size(); ++i) {
    const BondGeometry g{spec.bond_radius, spec.x[i + 1] - spec.x[i], spec.radius[i], spec.radius[i + 1]};
    model.bonds.add(static_cast<std::int32_t>(i), static_cast<std::int32_t>(i + 1),
                    make_bond_constants(material, g), g.radius, g.length);
  }
  model.fix(0, {1, 1, 1}, {1, 1, 1});
  const auto tip = static_cast<std::int32_t>(spec.x.size() - 1);
  model.loads.push_back({{tip}, {0.0, -spec.load, 0.0}, {}, spec.ramp_time});
  model.damping.particle = particle_damping;
  model.finalize();
  return model;
}

double load_parameter(const CantileverSpec& spec) {
  const double r = spec.bond_radius, L0 = spec.beam_length();
  return spec.load * L0 * L0 / (spec.youngs_modulus * 0.25 * std::numbers::pi * r * r * r * r);
}

double timoshenko_deflection(const CantileverSpec& spec, double s, bool include_shear) {
  const double r = spec.bond_radius, L0 = spec.beam_length(), F = spec.load;
  const double E = spec.youngs_modulus, G = E / (2.0 * (1.0 + spec.poisson_ratio));
  const double A = std::numbers::pi * r * r, I = 0.25 * std::numbers::pi * r * r * r * r;
  const double bending = F * s * s / (6.0 * E * I) * (3.0 * L0 - s);  // Chen Eq. 28, first term
  const double shear = 10.0 * F * s / (9.0 * G * A);                   // f_s = 10/9, circular section
  return include_shear ? bending + shear : bending;
}

CantileverResult run_cantilever(const CantileverSpec& spec, const std::string& model_key,
                                const CantileverRunOptions& options) {
  Model model = build_cantilever(spec, model_key, options.particle_damping);
  CantileverResult result;
  result.case_name = spec.case_name;
  result.variant = spec.variant;
  result.model = model_key;
  result.bonds = static_cast<int>(model.bonds.size());
  result.beam_length = spec.beam_length();
  result.tip_timoshenko = timoshenko_deflection(spec, spec.beam_length(), true);
  result.tip_euler_bernoulli = timoshenko_deflection(spec, spec.beam_length(), false);
  result.large_deflection_factor = elastica_tip_ratio(load_parameter(spec));

  const StaticSolution exact = solve_linear_static(model);
  for (const Vec3& u : exact.displacement) result.deflection_discrete.push_back(-u.y);
  result.tip_discrete = result.deflection_discrete.back();

  result.time_step = options.time_step_safety * stability_limit(model);
  Simulation sim(model, result.time_step);
  StopCriteria stop;
  stop.rest_speed = options.rest_speed;
  stop.rest_after = spec.ramp_time;
  stop.end_time = options.max_time;
  result.run = sim.run(stop);
  const ParticleStore& p = model.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    result.deflection_dem.push_back(-(p.position[i].y - p.reference_position[i].y));
  }
  result.tip_dem = result.deflection_dem.back();
  return result;
}

std::vector<StiffnessRow> case3_stiffness_table() {
  std::vector<StiffnessRow> rows;
  for (int n : {1, 2, 4, 6, 8, 10}) {
    const CantileverSpec spec = row("case3", bonds_variant(n), n, 4.0, 0.2, 0.2);
    const BondGeometry g{spec.bond_radius, spec.x[1] - spec.x[0], 0.2, 0.2};
    StiffnessRow r;
    r.bonds = n;
    r.bond_to_beam_length = 1.0 / n;
    r.k_n = make_bond_constants(cantilever_material(spec, "tbbm"), g).stiffness.k_n;
    r.k_s_pbm = make_bond_constants(cantilever_material(spec, "pbm"), g).stiffness.k_s;
    r.k_s_ebbm = make_bond_constants(cantilever_material(spec, "ebbm"), g).stiffness.k_s;
    r.k_s_tbbm = make_bond_constants(cantilever_material(spec, "tbbm"), g).stiffness.k_s;
    rows.push_back(r);
  }
  return rows;
}

}  // namespace bpm::verify
