#include "calibrate/stiffness_methods.hpp"

#include <chrono>
#include <string>

#include "core/error.hpp"
#include "model/contact_material.hpp"
#include "dsm/dsm_nonlinear.hpp"
#include "io/result_tables.hpp"
#include "solvers/mpi_world.hpp"
#include "ste/ste_summary.hpp"

namespace bpm {
namespace {

constexpr std::pair<StiffnessMethod, std::string_view> kNames[] = {
    {StiffnessMethod::ste, "ste"},
    {StiffnessMethod::dsm, "dsm"},
    {StiffnessMethod::dsm_kinematic, "dsm-kinematic"},
    {StiffnessMethod::dsm_nonlinear, "dsm-nonlinear"},
    {StiffnessMethod::dem, "dem"},
    {StiffnessMethod::dem_kinematic, "dem-kinematic"},
};

StiffnessEstimate from_dsm(const DsmResult& r, StiffnessMethod method) {
  StiffnessEstimate e;
  e.method = method;
  e.stiffness = r.stiffness;
  e.youngs_modulus = r.youngs_modulus;
  e.body = r.body;
  e.gauge_particles = r.gauge_particles;
  e.seconds = r.seconds;
  e.sample = r.loading.sample;
  e.displacement = r.displacement;
  e.details = {{"unknowns", r.unknowns},
               {"matrix_entries", r.nonzeros},
               {"solver", std::string(to_string(r.solve.used))},
               {"solver_iterations", r.solve.iterations},
               {"relative_residual", r.solve.relative_residual},
               {"assembly_s", r.assembly_seconds},
               {"solve_s", r.solve.seconds},
               {"solver_levels", r.solve.levels},
               {"solver_setup_s", r.solve.setup_seconds},
               {"force_top_N", r.force_top},
               {"force_bottom_N", r.force_bottom},
               {"platen_particles_bottom", r.loading.bottom.size()},
               {"platen_particles_top", r.loading.top.size()},
               {"detached_particles", r.detached_particles}};
  if (method == StiffnessMethod::dsm) {
    e.details["operating_travel_m"] = 0.5 * (r.loading.fit_from + r.loading.fit_to) * r.loading.displacement;
    e.details["newton_iterations"] = r.newton_iterations;
    e.details["krylov_iterations"] = r.krylov_iterations;
    e.details["contact_elements"] = r.potential_contacts;
    e.details["platen_springs"] = r.potential_wall_contacts;
    e.details["secant_stiffness_N_per_m"] = r.secant_stiffness;
    e.details["pair_band_m"] = r.pair_band;
    e.details["max_pair_approach_m"] = r.max_pair_approach;
  }
  if (method == StiffnessMethod::dsm_nonlinear) {
    e.details["newton_iterations"] = r.newton_iterations;
    e.details["krylov_iterations"] = r.krylov_iterations;
    e.details["newton_relative_residual"] = r.residual;
    e.details["potential_contacts"] = r.potential_contacts;
    e.details["potential_wall_contacts"] = r.potential_wall_contacts;
  }
  return e;
}

}  // namespace

std::string_view to_string(StiffnessMethod method) {
  for (const auto& [m, name] : kNames) {
    if (m == method) return name;
  }
  return "?";
}

StiffnessMethod parse_stiffness_method(std::string_view name, std::string_view where) {
  std::string names;
  for (const auto& [m, n] : kNames) {
    if (n == name) return m;
    names += (names.empty() ? "" : ", ") + std::string(n);
  }
  throw InputError(std::string(where), "unknown method '" + std::string(name) + "'", "use one of: " + names);
}

StiffnessEstimate estimate_sample_stiffness(const Model& model, StiffnessMethod method, const StiffnessSettings& s) {
  switch (method) {
    case StiffnessMethod::dsm:
      return from_dsm(solve_dsm_linear(model, make_platen_loading(model, s.compression), s.dsm), method);
    case StiffnessMethod::dsm_kinematic:
      return from_dsm(solve_dsm_kinematic(model, make_platen_loading(model, s.compression), s.dsm), method);
    case StiffnessMethod::dsm_nonlinear:
      return from_dsm(solve_dsm_nonlinear(model, make_platen_loading(model, s.compression), s.dsm), method);
    case StiffnessMethod::ste: {
      const PlatenLoading load = make_platen_loading(model, s.compression);
      ste::SteOptions options = s.ste;
      options.axis = load.axis;
      if (const mpi::World world = mpi::world(); world.distributed()) {  // the Voronoi cells divided
        options.share = {world.rank, world.size};
        options.sum_over_shares = mpi::sum_in_place;
      }
      StiffnessEstimate e;
      e.method = method;
      e.ste = ste::estimate_stiffness(model, options);
      const ste::SteResult& r = *e.ste;
      e.sample = r.sample;
      e.details = ste::summary_json(r);
      const double sample_stiffness = r.layered ? r.layered->stiffness : r.stiffness_uniform;
      e.stiffness = sample_stiffness;
      if (!model.contacts.materials.empty()) {
        // The platens in series (Jarolin 3.2.3), over the DEM's fit window: the chord between the
        // platen forces at its two ends, which is what the DEM's fitted slope measures.
        const ContactTable table(model.contacts);
        ste::WallSeriesOptions walls;
        walls.contact = table(model.particles.material[static_cast<std::size_t>(load.top.front())], load.platen_material);
        walls.bottom_particles = load.bottom;
        walls.top_particles = load.top;
        const auto t0 = std::chrono::steady_clock::now();
        auto platen_force = [&](double fraction) {
          walls.displacement = fraction * load.displacement;
          return ste::wall_series(model.particles, load.axis, r.sample, sample_stiffness, walls).force;
        };
        const double from = s.compression.fit_from, to = s.compression.fit_to;
        e.stiffness = (platen_force(to) - platen_force(from)) / ((to - from) * load.displacement);
        e.details["stiffness_without_platens_N_per_m"] = sample_stiffness;
        e.details["platen_series_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      }
      e.youngs_modulus = e.stiffness * r.sample.length / r.sample.area;
      // The body: the averaged tensor itself, without the platens (strain_gauge.hpp's E and nu).
      e.body.youngs_modulus = r.youngs_modulus_axis;
      e.body.poissons_ratio = ste::directional_poissons_ratio(r.stiffness, load.axis);
      e.body.valid = r.youngs_modulus_axis > 0.0;
      e.seconds = r.seconds;
      return e;
    }
    case StiffnessMethod::dem_kinematic: {
      const PlatenLoading load = make_platen_loading(model, s.compression);
      const KinematicCompressionResult r = run_kinematic_compression(model, load, s.kinematic);
      StiffnessEstimate e;
      e.method = method;
      e.stiffness = r.stiffness;
      e.youngs_modulus = r.youngs_modulus;
      e.seconds = r.seconds;
      e.sample = load.sample;
      e.displacement = r.displacement;
      e.details = {{"steps", r.steps}, {"time_step_s", r.time_step}, {"at_rest", r.at_rest},
                   {"max_speed_m_per_s", r.max_speed}, {"force_top_N", r.force_top}, {"force_bottom_N", r.force_bottom}};
      return e;
    }
    case StiffnessMethod::dem: {
      Model copy = model;
      const auto start = std::chrono::steady_clock::now();
      const CompressionResult r = run_uniaxial_compression(copy, s.compression);
      StiffnessEstimate e;
      e.method = method;
      e.stiffness = r.stiffness;
      e.youngs_modulus = r.youngs_modulus;
      e.body = r.body;
      e.gauge_particles = r.gauge_particles;
      e.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      e.sample = r.sample;
      e.displacement.resize(copy.particles.size());
      for (std::size_t i = 0; i < copy.particles.size(); ++i) {
        e.displacement[i] = copy.particles.position[i] - copy.particles.reference_position[i];
      }
      e.details = {{"steps", r.run.steps}, {"time_step_s", r.time_step}, {"fit_r2", r.fit_r2},
                   {"max_kinetic_to_elastic_energy", r.max_kinetic_ratio},
                   {"max_platen_force_imbalance", r.max_force_imbalance}};
      return e;
    }
  }
  throw InputError("method", "unknown stiffness method", "");
}

nlohmann::json to_json(const StiffnessEstimate& e) {
  return {{"method", std::string(to_string(e.method))},
          {"stiffness_N_per_m", e.stiffness},
          {"youngs_modulus_Pa", e.youngs_modulus},
          {"body", body_json(e.body, e.gauge_particles)},
          {"sample_length_m", e.sample.length},
          {"sample_area_m2", e.sample.area},
          {"wall_s", e.seconds},
          {"details", e.details}};
}

StiffnessEstimate stiffness_estimate_from_json(const nlohmann::json& j, const std::string& where) {
  StiffnessEstimate e;
  try {
    e.method = parse_stiffness_method(j.at("method").get<std::string>(), where + ": method");
    e.stiffness = j.at("stiffness_N_per_m").get<double>();
    e.youngs_modulus = j.at("youngs_modulus_Pa").get<double>();
    e.sample.length = j.value("sample_length_m", 0.0);
    e.sample.area = j.value("sample_area_m2", 0.0);
    e.seconds = j.at("wall_s").get<double>();
    e.details = j.value("details", nlohmann::json::object());
    if (const auto body = j.find("body"); body != j.end() && !body->at("youngs_modulus_Pa").is_null()) {
      e.body.youngs_modulus = body->at("youngs_modulus_Pa").get<double>();
      e.body.poissons_ratio = body->at("poissons_ratio").get<double>();
      e.body.axial_per_travel = body->value("axial_strain_per_travel_1_per_m", 0.0);
      e.body.lateral_per_travel = body->value("lateral_strain_per_travel_1_per_m", 0.0);
      e.body.valid = true;
      e.gauge_particles = body->value("gauge_particles", std::size_t{0});
    }
  } catch (const nlohmann::json::exception& ex) {
    throw InputError(where, std::string("lacks a field: ") + ex.what(), "give the stiffness.json written by `bpmkit stiffness`");
  }
  return e;
}

}  // namespace bpm
