#include "structure/structure_writer.hpp"

#include <fmt/core.h>

#include "io/vtk_polydata.hpp"

namespace bpm {

namespace {

/// The body of a single-quoted YAML scalar: quotes doubled.
std::string yaml_single_quoted(const std::string& text) {
  std::string s;
  for (const char c : text) s += c == '\'' ? std::string("''") : std::string(1, c);
  return s;
}

}  // namespace

// Text is built with fmt::format and appended, not fmt::format_to into a back-inserter: the
// latter fails to link with clang against a GCC-built libfmt 9.

ParticleTable particle_table(const Packing& p) {
  ParticleTable t;
  t.id.resize(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) t.id[i] = static_cast<std::int64_t>(i);
  t.position = p.position;
  t.radius = p.radius;
  return t;
}

BondTable bond_table(const GenerateSpec& spec, const GeneratedStructure& g) {
  BondTable t;
  t.i.reserve(g.bonds.size());
  t.j.reserve(g.bonds.size());
  for (const auto& [i, j] : g.bonds) {
    t.i.push_back(i);
    t.j.push_back(j);
  }
  t.radius = g.bond_radius;
  for (const auto& m : spec.bond_materials) t.material_names.push_back(m.name);
  t.material.assign(g.bond_material.begin(), g.bond_material.end());
  return t;
}

std::string structure_vtp(const GenerateSpec& spec, const GeneratedStructure& g) {
  const Packing& p = g.packing;
  VtkPolyData d(p.position);
  std::vector<std::int64_t> ids(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) ids[i] = static_cast<std::int64_t>(i);
  d.point_data().set_active("radius");
  d.point_data().int64s("id", ids);
  d.point_data().scalars("radius", p.radius);
  std::vector<std::int32_t> alpha, beta;
  alpha.reserve(g.bonds.size());
  beta.reserve(g.bonds.size());
  for (const auto& [i, j] : g.bonds) {
    alpha.push_back(i);
    beta.push_back(j);
  }
  d.lines(alpha, beta);
  d.cell_data().set_active("material");
  d.cell_data().int32s("material", g.bond_material);
  std::vector<std::string> names;
  for (const auto& m : spec.bond_materials) names.push_back(m.name);
  if (spec.bonds && !names.empty()) d.field_data().strings("bond_material_names", names);
  return d.vtp();
}

nlohmann::json structure_summary(const GenerateSpec& spec, const GeneratedStructure& g) {
  using nlohmann::json;
  const PackingStats& st = g.stats;
  json materials = json::object();
  std::vector<std::size_t> counts(spec.bond_materials.size(), 0);
  for (const auto m : g.bond_material) ++counts[static_cast<std::size_t>(m)];
  for (std::size_t k = 0; k < spec.bond_materials.size() && spec.bonds; ++k) {
    materials[spec.bond_materials[k].name] = {
        {"fraction_requested", spec.bond_materials[k].fraction},
        {"bonds", counts[k]},
        {"fraction_achieved",
         g.bonds.empty() ? 0.0
                         : static_cast<double>(counts[k]) / static_cast<double>(g.bonds.size())}};
  }
  json j = {
      {"spec", spec.path},
      {"description", spec.description},
      {"seed", spec.seed},
      {"container", spec.container->describe()},
      {"container_volume", st.container_volume},
      {"radii", spec.radii.describe()},
      {"particles", st.particles},
      {"bonds", g.bonds.size()},
      {"bonds_per_particle",
       st.particles > 0 ? static_cast<double>(g.bonds.size()) / static_cast<double>(st.particles)
                        : 0.0},
      {"bond_materials", materials},
      {"porosity", st.porosity},
      {"porosity_target", spec.target.count > 0 ? json(nullptr) : json(spec.target.porosity)},
      {"solid_volume", st.solid_volume},
      {"coordination_number", st.coordination_number},
      {"coordination_contact_radius_multiplier", st.contact_radius_multiplier},
      {"max_overlap", st.max_overlap},
      {"overlap_tolerance", spec.relaxation.overlap_tolerance},
      {"relaxation_iterations", g.relaxation.iterations},
      {"relaxation_converged", g.relaxation.converged},
      {"radius_min", st.min_radius},
      {"radius_mean", st.mean_radius},
      {"radius_max", st.max_radius},
      {"wall_seconds",
       {{"insert", g.insert_seconds},
        {"relax", g.relax_seconds},
        {"bond", g.bond_seconds},
        {"total", g.total_seconds}}},
      {"threads", g.threads},
  };
  return j;
}

std::string scenario_stub(const GenerateSpec& spec, const GeneratedStructure& g) {
  std::string s = fmt::format(
      "# bpmkit run scenario stub written by `bpmkit generate {}`.\n"
      "# The structure (particles.csv, bonds.csv) is final; the material constants below are\n"
      "# PLACEHOLDERS: set them, then add boundary_conditions and loads (docs/scenario.md).\n"
      "description: 'structure from {}'\n"
      "particle_materials:\n"
      "  particle: {{density: 2500}}   # placeholder, kg/m^3\n",
      spec.path, yaml_single_quoted(spec.path));
  if (spec.bonds) {
    s += "bond_materials:   # placeholders: model, E_b (Pa), nu_b\n";
    const double mult = spec.bond_radius_multiplier.value_or(1.0);
    for (const auto& m : spec.bond_materials) {
      s += fmt::format(
          "  {}: {{model: tbbm, youngs_modulus: 1e9, poisson_ratio: 0.25, radius_multiplier: "
          "{}}}\n",
          m.name, mult);
    }
  } else {
    s += "bond_materials: {}\n";
  }
  // The binary twins load fastest; the CSV files hold the same rows.
  const std::string ext = spec.write_binary ? "bpk" : "csv";
  s += fmt::format("particles:\n  file: particles.{}\n", ext);
  // A scenario refuses a bonds file without rows; no bonds has to be said with an empty list.
  s += g.bonds.empty() ? "bonds: {list: []}   # bonds.csv is empty\n"
                       : fmt::format("bonds:\n  file: bonds.{}\n", ext);
  s += "damping:\n  particle: 0.7\n";
  if (g.bonds.empty())
    s += "integrator:\n  time_step: 1e-6   # no bonds: no stability limit to derive\n";
  s += "stop:\n  max_steps: 1000\n";
  s += "output:\n  vtk: false\n";
  return s;
}

std::vector<std::string> structure_outputs(const GenerateSpec& spec) {
  std::vector<std::string> names{"particles.csv", "bonds.csv"};
  if (spec.write_binary) names.insert(names.end(), {"particles.bpk", "bonds.bpk"});
  if (spec.write_vtk) names.push_back("structure.vtp");
  if (spec.write_scenario) names.push_back("scenario.yaml");
  return staged_outputs(std::move(names), kStructureStaging);
}

std::pair<std::vector<std::string>, nlohmann::json> write_structure(const GenerateSpec& spec,
                                                                    const GeneratedStructure& g,
                                                                    const OutputFolder& folder) {
  // One set: particles beside bonds of another structure (or none) would load as a wrong model.
  StagedFiles set(folder, kStructureStaging);
  const ParticleTable particles = particle_table(g.packing);
  const BondTable bonds = bond_table(spec, g);
  set.write("particles.csv", particle_table_csv(particles));
  set.write("bonds.csv", bond_table_csv(bonds));
  if (spec.write_binary) {
    set.write("particles.bpk", particle_table_bytes(particles));
    set.write("bonds.bpk", bond_table_bytes(bonds));
  }
  if (spec.write_vtk) set.write("structure.vtp", structure_vtp(spec, g));
  if (spec.write_scenario) set.write("scenario.yaml", scenario_stub(spec, g));
  std::vector<std::string> files = set.commit();
  nlohmann::json summary = structure_summary(spec, g);
  files.push_back(folder.path("summary.json"));  // written by OutputFolder::run
  summary["files"] = files;
  return {files, summary};
}

std::vector<std::string> write_structure(const GenerateSpec& spec, const GeneratedStructure& g,
                                         const std::string& out_dir) {
  OutputFolder folder(out_dir, "generate", structure_outputs(spec), false);
  std::vector<std::string> files;
  folder.run([&] {
    auto [written, summary] = write_structure(spec, g, folder);
    files = std::move(written);
    return summary;
  });
  return files;
}

}  // namespace bpm
