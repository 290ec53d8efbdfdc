#include "io/result_tables.hpp"

#include <algorithm>

#include <fmt/core.h>

namespace bpm {

std::string bond_breaks_header() {
  return "bond,particle_alpha,particle_beta,time_s,mode,x,y,z\n";
}

std::string bond_breaks_rows(const Model& model, double dt, std::size_t from) {
  const BondStore& b = model.bonds;
  const ParticleStore& p = model.particles;
  std::string s;
  for (std::size_t k = from; k < b.breaks.size(); ++k) {
    const BondStore::Break& e = b.breaks[k];
    // The bond as the user numbers it (its input row), not bpmkit's internal (canonical) index.
    s +=
        fmt::format("{},{},{},{:.10g},{},{:.10g},{:.10g},{:.10g}\n", b.input_row[e.bond],
                    p.id[b.alpha[e.bond]], p.id[b.beta[e.bond]], static_cast<double>(e.update) * dt,
                    e.mode == BreakMode::tension ? "tension" : "shear", e.position.x, e.position.y,
                    e.position.z);
  }
  return s;
}

std::string bond_state_csv(const Model& model) {
  const BondStore& b = model.bonds;
  const ParticleStore& p = model.particles;
  std::vector<std::size_t> by_input(b.size());
  for (std::size_t k = 0; k < b.size(); ++k) by_input[k] = k;
  std::sort(by_input.begin(), by_input.end(),
            [&](std::size_t x, std::size_t y) { return b.input_row[x] < b.input_row[y]; });
  std::string s =
      "bond,i,j,intact,axial_force,force_x,force_y,force_z,moment_x,moment_y,moment_z\n";
  s.reserve(s.size() + b.size() * 160);
  for (const std::size_t k : by_input) {
    const bool intact = b.intact.size() != b.size() || b.intact[k] != 0;
    const Vec3& f = b.force[k];
    const Vec3& m = b.moment[k];
    s += fmt::format("{},{},{},{},{},{},{},{},{},{},{}\n", b.input_row[k], p.id[b.alpha[k]],
                     p.id[b.beta[k]], intact ? 1 : 0, dot(f, b.axis[k]), f.x, f.y, f.z, m.x, m.y,
                     m.z);
  }
  return s;
}

std::string walls_row(const std::vector<Wall>& walls, double t, bool header) {
  std::string s;
  if (header) {
    s = "time";
    for (const Wall& w : walls) {
      for (const char* c : {"ux", "uy", "uz", "fx", "fy", "fz"})
        s += fmt::format(",{}_{}", w.name, c);
    }
    s += "\n";
  }
  s += fmt::format("{:.10g}", t);
  for (const Wall& w : walls) {
    s += fmt::format(",{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g}", w.displacement.x,
                     w.displacement.y, w.displacement.z, w.force.x, w.force.y, w.force.z);
  }
  return s + "\n";
}

std::string force_displacement_header() {
  return "time_s,displacement_m,strain,force_N,stress_Pa,force_top_N,force_bottom_N,kinetic_J,"
         "elastic_J,bonds_broken,gauge_axial_strain,gauge_lateral_strain,bonds_broken_tension,"
         "bonds_broken_shear\n";
}

std::string force_displacement_row(const CompressionPoint& p, double area) {
  return fmt::format(
      "{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{},{:.10g},{:.10g},{"
      "},{}"
      "\n",
      p.time, p.displacement, p.strain, p.force, p.force / area, p.force_top, p.force_bottom,
      p.kinetic, p.elastic, p.bonds_broken, p.gauge.axial, p.gauge.lateral, p.bonds_broken_tension,
      p.bonds_broken - p.bonds_broken_tension);
}

nlohmann::json body_json(const BodyModuli& body, std::size_t gauge_particles) {
  auto value = [&](double v) { return body.valid ? nlohmann::json(v) : nlohmann::json(nullptr); };
  return {{"youngs_modulus_Pa", value(body.youngs_modulus)},
          {"poissons_ratio", value(body.poissons_ratio)},
          {"axial_strain_per_travel_1_per_m", body.axial_per_travel},
          {"lateral_strain_per_travel_1_per_m", body.lateral_per_travel},
          {"gauge_particles", gauge_particles}};
}

/// The test's strength (UCS, BTS or the direct tensile strength) from its peak force, with the
/// quasi-static check at the peak and the bonds broken by mode at the end.
nlohmann::json strength_json(const CompressionResult& r) {
  const CompressionPoint& last = r.curve.empty() ? CompressionPoint{} : r.curve.back();
  nlohmann::json j = {{"test", std::string(to_string(r.test))},
                      {"definition", std::string(strength_definition(r.test))},
                      {"strength_Pa", r.strength},
                      {"peak_force_N", r.peak_force},
                      {"peak_strain", r.peak_strain},
                      {"kinetic_to_elastic_energy_at_peak", r.peak_kinetic_ratio},
                      {"force_imbalance_at_peak", r.peak_force_imbalance},
                      {"post_peak_to_fraction_of_peak", r.failure_drop},
                      {"bonds_broken_tension", last.bonds_broken_tension},
                      {"bonds_broken_shear", last.bonds_broken - last.bonds_broken_tension}};
  if (r.test == LabTest::brazilian) {
    j["diameter_m"] = r.sample.length;
    j["thickness_m"] = r.thickness;
  }
  if (r.test == LabTest::tension) j["grip_particles"] = r.grip_particles;
  return j;
}

nlohmann::json compression_json(const CompressionResult& r) {
  return {{"sample_length_m", r.sample.length},
          {"sample_area_m2", r.sample.area},
          {"stiffness_N_per_m", r.stiffness},
          {"youngs_modulus_Pa", r.youngs_modulus},
          {"body", body_json(r.body, r.gauge_particles)},
          {"fit_r2", r.fit_r2},
          {"fit_points", r.fit_points},
          {"fit_window_m", {r.fit_from_m, r.fit_to_m}},
          {"max_kinetic_to_elastic_energy", r.max_kinetic_ratio},
          {"max_platen_force_imbalance", r.max_force_imbalance},
          {"peak_stress_Pa", r.peak_stress},
          {"peak_strain", r.peak_strain},
          {"strength", strength_json(r)},
          {"time_step_s", r.time_step},
          {"mass_scaling", r.mass_scaling},
          {"stop", r.stop}};
}

}  // namespace bpm
