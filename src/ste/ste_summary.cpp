#include "ste/ste_summary.hpp"

namespace bpm::ste {

nlohmann::json summary_json(const SteResult& r) {
  using nlohmann::json;
  json c = json::array();
  for (int i = 0; i < 6; ++i) {
    json row = json::array();
    for (int j = 0; j < 6; ++j) row.push_back(r.stiffness(i, j));
    c.push_back(row);
  }
  const EngineeringConstants& e = r.constants;
  json out = {
      {"voigt_order", "11 22 33 23 13 12 (engineering shear strains)"},
      {"C_Pa", c},
      {"asymmetry", r.asymmetry},
      {"E_Pa", {{"x", e.E_x}, {"y", e.E_y}, {"z", e.E_z}, {"axis", r.youngs_modulus_axis}}},
      {"nu", {{"xy", e.nu_xy}, {"xz", e.nu_xz}, {"yx", e.nu_yx}, {"yz", e.nu_yz}, {"zx", e.nu_zx}, {"zy", e.nu_zy}}},
      {"G_Pa", {{"yz", e.G_yz}, {"xz", e.G_xz}, {"xy", e.G_xy}}},
      {"axis", {r.axis.x, r.axis.y, r.axis.z}},
      {"length_m", r.sample.length},
      {"area_m2", r.sample.area},
      {"solid_fraction", r.solid_fraction},
      {"stiffness_uniform_N_per_m", r.stiffness_uniform},
      {"stiffness_N_per_m", r.sample_stiffness()},
      {"particles", r.particles},
      {"particles_used", r.used},
      {"excluded_singular", r.excluded_singular},
      {"excluded_no_volume", r.excluded_no_volume},
      {"bonds", r.bonds},
      {"contacts", r.contacts},
      {"volume_used_m3", r.volume_used},
      {"volume_total_m3", r.volume_total},
      {"seconds", r.seconds},
      {"seconds_parts", {{"volumes", r.parts.volumes}, {"tensors", r.parts.tensors}, {"average", r.parts.average},
                         {"local_map", r.parts.local_map}}},
  };
  if (r.layered) {
    json layers = json::array();
    for (const Layer& l : r.layered->layers) {
      layers.push_back({{"bottom_m", l.bottom}, {"top_m", l.top}, {"particles", l.particles}, {"used", l.used},
                        {"area_m2", l.area}, {"E_Pa", l.youngs_modulus}, {"stiffness_N_per_m", l.stiffness}});
    }
    out["layered"] = {{"height_m", r.layered->height}, {"stiffness_N_per_m", r.layered->stiffness}, {"layers", layers}};
  }
  if (r.walls) {
    const WallSeries& w = *r.walls;
    auto platen = [](const PlatenContacts& p) {
      return json{{"particles", p.particles}, {"overlap_m", p.overlap}, {"secant_N_per_m", p.secant},
                  {"tangent_N_per_m", p.tangent}};
    };
    out["walls"] = {{"sample_stiffness_N_per_m", w.sample_stiffness}, {"displacement_m", w.displacement},
                    {"force_N", w.force}, {"bottom", platen(w.bottom)}, {"top", platen(w.top)},
                    {"secant_N_per_m", w.secant}, {"tangent_N_per_m", w.tangent}, {"total_N_per_m", w.total},
                    {"iterations", w.iterations}};
  }
  if (r.local) {
    out["local_map"] = {{"sphere_diameter_m", r.local->sphere_diameter}, {"particles", r.local->valid_count},
                        {"mean_E_Pa", {r.local->mean.x, r.local->mean.y, r.local->mean.z}}};
  }
  return out;
}

}  // namespace bpm::ste
