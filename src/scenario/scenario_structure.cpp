// The `particles` and `bonds` sections of a scenario: where the particles are and which pairs are
// bonded. Each bond's constants come from its material through the model registry (Chen Table 9)
// once, here, at creation.
#include <fmt/core.h>

#include <cmath>
#include <functional>
#include <limits>
#include <utility>

#include "bonds/bond_model.hpp"
#include "core/error.hpp"
#include "io/bond_pair_set.hpp"
#include "io/csv_table.hpp"
#include "spatial/pairs_within_gap.hpp"
#include "io/parse_number.hpp"
#include "scenario/scenario_builder.hpp"
#include "io/structure_table.hpp"
#include "model/spatial_order.hpp"

namespace bpm::scenario_detail {

std::optional<std::int32_t> find_name(const std::vector<std::string>& names, const std::string& name) {
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name) return static_cast<std::int32_t>(i);
  }
  return std::nullopt;
}

std::string list_names(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
  return s.empty() ? "(none defined)" : s;
}

namespace {

/// Material named in a YAML field (`section` is the defining section, for the message).
std::int32_t material_at(const YamlField& field, const std::vector<std::string>& names, std::string_view section) {
  const std::string name = field.text();
  if (const auto index = find_name(names, name)) return *index;
  field.fail(fmt::format("unknown material '{}'", name), fmt::format("use one defined in {}: {}", section, list_names(names)));
}

/// Material named in a CSV field.
std::int32_t material_at(const CsvTable& table, const CsvRow& row, std::size_t column,
                         const std::vector<std::string>& names, std::string_view section) {
  const std::string name(row.fields[column]);
  if (const auto index = find_name(names, name)) return *index;
  throw InputError(table.where(row), fmt::format("unknown material '{}'", name),
                   fmt::format("use one defined in {}: {}", section, list_names(names)));
}

/// A binary table's material names as the scenario's indices; nullopt for a name the scenario does
/// not define (an error only where a row uses it, as in a CSV file).
std::vector<std::optional<std::int32_t>> material_indices(const std::vector<std::string>& table_names,
                                                          const std::vector<std::string>& names) {
  std::vector<std::optional<std::int32_t>> indices;
  for (const std::string& n : table_names) indices.push_back(find_name(names, n));
  return indices;
}

/// "PATH, row K" (1-based): where a row of a binary table is. Formatted only for a message (once
/// per row it cost 1 s on the 8.1e6-bond box).
std::string table_row(const std::string& path, std::size_t k) { return fmt::format("{}, row {}", path, k + 1); }

/// Row k's material in the binary table at `path` (rows index `material`, names `table_names`).
std::optional<std::int32_t> table_material(const std::vector<std::uint32_t>& material,
                                           const std::vector<std::string>& table_names,
                                           const std::vector<std::optional<std::int32_t>>& indices,
                                           std::size_t k, const std::vector<std::string>& names,
                                           std::string_view section, const std::string& path) {
  if (material.empty()) return std::nullopt;
  const auto index = indices[material[k]];
  if (!index) {
    throw InputError(table_row(path, k), fmt::format("unknown material '{}'", table_names[material[k]]),
                     fmt::format("use one defined in {}: {}", section, list_names(names)));
  }
  return index;
}

/// The section's `material` key if given; else the only material defined, if there is exactly one.
std::optional<std::int32_t> default_material(const YamlMap& section, const std::vector<std::string>& names,
                                             std::string_view defining_section) {
  if (const auto field = section.find("material")) return material_at(*field, names, defining_section);
  if (names.size() == 1) return 0;
  return std::nullopt;
}

std::string csv_path(const ScenarioBuilder& b, const YamlField& field) {
  const std::filesystem::path given = field.text();
  return (given.is_absolute() ? given : b.folder / given).lexically_normal().string();
}

// ---------------------------------------------------------------------------------------------
// Particles

struct ParticleInput {
  std::int64_t id = 0;
  Vec3 position;
  double radius = 0.0;
  std::optional<std::int32_t> material;
};

/// Validates one particle and adds it; `where()` names its row or item, called only for a message.
template <class Where>
void add_particle(ScenarioBuilder& b, const ParticleInput& in, std::optional<std::int32_t> default_mat,
                  const Where& where) {
  if (!(in.radius > 0.0)) {
    throw InputError(where(), fmt::format("particle {} has radius {}; it must be greater than 0", in.id, in.radius),
                     "give a positive radius in metres");
  }
  const auto material = in.material ? in.material : default_mat;
  if (!material) {
    throw InputError(where(), fmt::format("particle {} has no material", in.id),
                     "give it a material, or set the default 'particles.material'");
  }
  ParticleStore& p = b.scenario.model.particles;
  if (p.size() >= static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max())) {
    throw InputError(where(), "too many particles", "bpmkit indexes particles with 32-bit integers");
  }
  if (!b.index_of_id.emplace(in.id, static_cast<std::int32_t>(p.size())).second) {
    throw InputError(where(), fmt::format("duplicate particle id {}", in.id), "give every particle a unique id");
  }
  p.add(in.id, in.position, in.radius, b.scenario.particle_densities[static_cast<std::size_t>(*material)], *material);
}

/// particles.bpk (io/structure_table.hpp): the same rows as particles.csv, already numbers.
void read_particle_table_file(ScenarioBuilder& b, const std::string& path, std::optional<std::int32_t> default_mat) {
  const auto& names = b.scenario.particle_material_names;
  const ParticleTable t = read_particle_table(path);
  if (t.id.empty()) throw InputError(path, "no particle rows", "write the table again with `bpmkit generate`");
  const auto indices = material_indices(t.material_names, names);
  for (std::size_t k = 0; k < t.id.size(); ++k) {
    const auto material = table_material(t.material, t.material_names, indices, k, names, "particle_materials", path);
    add_particle(b, {t.id[k], t.position[k], t.radius[k], material}, default_mat, [&] { return table_row(path, k); });
  }
}

void read_particle_file(ScenarioBuilder& b, const YamlField& field, std::optional<std::int32_t> default_mat) {
  const auto& names = b.scenario.particle_material_names;
  const std::string path = csv_path(b, field);
  if (is_structure_table(path)) return read_particle_table_file(b, path, default_mat);
  CsvTable table = read_csv(path, field.where());
  const std::vector<std::string> columns{"id", "x", "y", "z", "radius", "material"};
  if (!table.header.empty()) {
    const bool ok = (table.header.size() == 5 || table.header.size() == 6) &&
                    std::equal(table.header.begin(), table.header.end(), columns.begin());
    if (!ok) {
      throw InputError(fmt::format("{}:{}", table.path, table.header_line), "unexpected header line",
                       "the columns are id,x,y,z,radius[,material] in this order");
    }
  }
  if (table.size() == 0)
    throw InputError(table.path, "no particle rows", "add lines 'id,x,y,z,radius[,material]'");
  // The rows are converted in parallel (csv_table.hpp), then added in file order.
  std::vector<ParticleInput> inputs(table.size());
  const CsvRowError error = table.convert_rows([&](std::size_t k, const CsvRow& row) {
    const std::size_t n = row.fields.size();
    if (n != 5 && n != 6) {
      throw InputError(table.where(row), fmt::format("expected 5 or 6 columns, got {}", n),
                       "write id,x,y,z,radius[,material]");
    }
    ParticleInput& in = inputs[k];
    in.id = table.integer(row, 0, "id");
    in.position = {table.number(row, 1, "x"), table.number(row, 2, "y"), table.number(row, 3, "z")};
    in.radius = table.number(row, 4, "radius");
    if (n == 6) in.material = material_at(table, row, 5, names, "particle_materials");
  });
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    error.rethrow_at(k);
    add_particle(b, inputs[k], default_mat, [&] { return table.where(k); });
  }
}

void read_particle_list(ScenarioBuilder& b, const YamlField& field, std::optional<std::int32_t> default_mat) {
  for (const YamlField& item : field.items()) {
    const YamlMap m = item.map({"id", "position", "radius", "material"});
    ParticleInput in;
    in.id = m.require("id", "give each particle a unique integer id").integer();
    in.position = m.require("position", "give the centre as [x, y, z] in metres").vec3();
    in.radius = m.require("radius", "give the radius in metres").positive();
    if (const auto mat = m.find("material")) in.material = material_at(*mat, b.scenario.particle_material_names, "particle_materials");
    add_particle(b, in, default_mat, [&] { return item.where(); });
  }
}

/// `row`: count particles spaced evenly along a direction; ids 0 .. count-1.
constexpr std::int64_t kMaxRowParticles = 100'000'000;
void read_particle_row(ScenarioBuilder& b, const YamlField& field, std::optional<std::int32_t> default_mat) {
  const YamlMap m = field.map({"count", "spacing", "radius", "start", "direction"});
  const YamlField count_field = m.require("count", "give the number of particles");
  const std::int64_t count = count_field.integer();
  if (count < 1) count_field.fail(fmt::format("must be at least 1, got {}", count));
  // Checked before the loop: 4294967296 particles took minutes and all memory before failing.
  if (count > kMaxRowParticles) {
    count_field.fail(fmt::format("{} particles are more than the limit of {:.0e} for a row (the limit of bpmkit "
                                 "generate too)", count, static_cast<double>(kMaxRowParticles)),
                     "a row of that many particles would not fit in memory; use fewer");
  }
  const double spacing = m.require("spacing", "give the centre-to-centre distance in metres").positive();
  const double radius = m.require("radius", "give the particle radius in metres").positive();
  const Vec3 start = m.has("start") ? m.find("start")->vec3() : Vec3{};
  Vec3 direction{1.0, 0.0, 0.0};
  if (const auto d = m.find("direction")) {
    direction = d->vec3();
    if (!(norm(direction) > 0.0)) d->fail("the direction must not be zero", "write e.g. [1, 0, 0]");
    direction = direction / norm(direction);
  }
  for (std::int64_t i = 0; i < count; ++i) {
    add_particle(b, {i, start + (static_cast<double>(i) * spacing) * direction, radius, std::nullopt}, default_mat,
                 [&] { return field.where(); });
  }
}

// ---------------------------------------------------------------------------------------------
// Bonds

struct BondInput {
  std::int64_t id_i = 0, id_j = 0;
  std::optional<double> radius;  ///< r_b for this bond only
  std::optional<std::int32_t> material;
};

/// A bond checked and with its constants, ready to add.
struct NewBond {
  std::int32_t i = 0, j = 0;
  BondConstants constants;
  double r_b = 0.0, length = 0.0;
  std::int32_t material = 0;
};

/// Validates one bond and computes its constants from its material (Chen Table 9). With `bonded`,
/// a pair bonded before is refused, in the place a reader meets it; without, nothing is changed
/// (for the CSV reader's parallel pass). Not inlined: -march=native contracts a * b + c into FMAs
/// per call site, and the bond constants must not depend on which reader computed them.
[[gnu::noinline]] NewBond make_bond(const ScenarioBuilder& b, BondPairSet* bonded,
                                    const BondInput& in, std::optional<std::int32_t> default_mat,
                                    const std::string& where) {
  const Model& model = b.scenario.model;
  auto index = [&](std::int64_t id) {
    const auto it = b.index_of_id.find(id);
    if (it == b.index_of_id.end()) {
      throw InputError(where, fmt::format("bond {}-{} names particle id {}, which does not exist", in.id_i, in.id_j, id),
                       "use ids defined in the particles section");
    }
    return it->second;
  };
  const std::int32_t i = index(in.id_i), j = index(in.id_j);
  if (i == j) throw InputError(where, fmt::format("particle {} is bonded to itself", in.id_i), "a bond joins two different particles");
  if (bonded && !bonded->insert(i, j)) {
    throw InputError(where, fmt::format("duplicate bond {}-{}", in.id_i, in.id_j),
                     "bond each pair once (i-j and j-i are the same bond)");
  }
  const auto material = in.material ? in.material : default_mat;
  if (!material) {
    throw InputError(where, fmt::format("bond {}-{} has no material", in.id_i, in.id_j),
                     "give it a material, or set the default 'bonds.material'");
  }
  const BondMaterial& mat = b.scenario.bond_materials[static_cast<std::size_t>(*material)];
  const ParticleStore& p = model.particles;
  const double length = norm(p.position[j] - p.position[i]);
  if (!(length > 0.0)) {
    throw InputError(where, fmt::format("bond {}-{} has zero length (the particles share a centre)", in.id_i, in.id_j),
                     "move one particle or drop the bond");
  }
  // r_b: the bond's own radius, else the material's, else a multiple of the smaller particle.
  const double r_b = in.radius.value_or(mat.radius.value_or(mat.radius_multiplier * std::min(p.radius[i], p.radius[j])));
  const BondGeometry geometry{r_b, length, p.radius[i], p.radius[j]};
  const BondConstants constants = make_bond_constants(mat, geometry);
  const BondStiffness& k = constants.stiffness;
  if (!std::isfinite(k.k_n) || !std::isfinite(k.k_s) || !std::isfinite(k.k_tor) || !std::isfinite(k.k_ben) ||
      !std::isfinite(constants.arm_offset)) {
    throw InputError(where, fmt::format("bond {}-{} gets a non-finite stiffness", in.id_i, in.id_j),
                     "check the bond material and the particle positions");
  }
  return {i, j, constants, r_b, length, *material};
}

/// Validates one bond, computes its constants and adds it.
void add_bond(ScenarioBuilder& b, BondPairSet& bonded, const BondInput& in,
              std::optional<std::int32_t> default_mat, const std::string& where) {
  const NewBond bond = make_bond(b, &bonded, in, default_mat, where);
  b.scenario.model.bonds.add(bond.i, bond.j, bond.constants, bond.r_b, bond.length, bond.material);
}

/// make_bond without the duplicate check, for many bonds at once in parallel; nullopt where it
/// throws (add_bond then runs again, in order, for the message).
std::optional<NewBond> try_make_bond(const ScenarioBuilder& b, const BondInput& in,
                                     std::optional<std::int32_t> default_mat) {
  try {
    return make_bond(b, nullptr, in, default_mat, {});
  } catch (const InputError&) {
    return std::nullopt;
  }
}

void add_bonds(ScenarioBuilder& b, const std::vector<BondInput>& inputs, std::optional<std::int32_t> default_mat,
               const CsvRowError& error, const std::function<std::string(std::size_t)>& where);
void read_bond_table_file(ScenarioBuilder& b, const std::string& path, std::optional<std::int32_t> default_mat);

void read_bond_file(ScenarioBuilder& b, const YamlField& field, std::optional<std::int32_t> default_mat) {
  const auto& names = b.scenario.bond_material_names;
  const std::string path = csv_path(b, field);
  // No bonds is a legitimate model, but from a file it is more often a failed export or a wrong
  // path, so it has to be said explicitly.
  const std::string no_bonds =
      "if the model has no bonds, write 'bonds: {list: []}' instead of a file";
  if (std::filesystem::is_directory(path)) {
    field.fail("'" + path + "' is a folder, not a bonds CSV file",
               "name the CSV file inside it; " + no_bonds);
  }
  if (is_structure_table(path)) return read_bond_table_file(b, path, default_mat);
  CsvTable table = read_csv(path, field.where());
  if (table.size() == 0) {
    throw InputError(table.path, "no bond rows (the file is empty or holds only a header)",
                     "add lines 'i,j[,radius][,material]'; " + no_bonds);
  }
  // Column positions; with a header they are fixed by it, without one they are guessed per row.
  std::optional<std::size_t> radius_col, material_col;
  if (!table.header.empty()) {
    const auto& h = table.header;
    bool ok = h.size() >= 2 && h.size() <= 4 && h[0] == "i" && h[1] == "j";
    for (std::size_t c = 2; ok && c < h.size(); ++c) {
      if (h[c] == "radius" && !radius_col && !material_col) radius_col = c;
      else if (h[c] == "material" && !material_col) material_col = c;
      else ok = false;
    }
    if (!ok) {
      throw InputError(fmt::format("{}:{}", table.path, table.header_line), "unexpected header line",
                       "the columns are i,j[,radius][,material] in this order");
    }
  }
  // The rows are converted in parallel (csv_table.hpp), then added in file order.
  std::vector<BondInput> inputs(table.size());
  const CsvRowError error = table.convert_rows([&](std::size_t k, const CsvRow& row) {
    const std::size_t n = row.fields.size();
    const bool width_ok = table.header.empty() ? (n >= 2 && n <= 4) : n == table.header.size();
    if (!width_ok) {
      throw InputError(table.where(row), fmt::format("expected {} columns, got {}", table.header.empty() ? "2 to 4" : std::to_string(table.header.size()), n),
                       "write i,j[,radius][,material]");
    }
    auto r_col = radius_col, m_col = material_col;
    if (table.header.empty() && n == 4) {
      r_col = 2;
      m_col = 3;
    } else if (table.header.empty() && n == 3) {
      // Without a header the third column is a radius if it is a number, else a material name.
      if (parse_double(row.fields[2])) {
        r_col = 2;
      } else {
        m_col = 2;
      }
    }
    BondInput& in = inputs[k];
    in.id_i = table.integer(row, 0, "i");
    in.id_j = table.integer(row, 1, "j");
    if (r_col) {
      in.radius = table.number(row, *r_col, "radius");
      if (!(*in.radius > 0.0)) {
        throw InputError(table.where(row), fmt::format("bond radius {} must be greater than 0", *in.radius),
                         "give r_b in metres, or leave the column out to use the material's");
      }
    }
    if (m_col) in.material = material_at(table, row, *m_col, names, "bond_materials");
  });
  add_bonds(b, inputs, default_mat, error, [&](std::size_t k) { return table.where(k); });
}

/// bonds.bpk (io/structure_table.hpp): the same rows as bonds.csv, already numbers.
void read_bond_table_file(ScenarioBuilder& b, const std::string& path, std::optional<std::int32_t> default_mat) {
  const auto& names = b.scenario.bond_material_names;
  const BondTable t = read_bond_table(path);
  if (t.i.empty()) {
    throw InputError(path, "no bond rows", "if the model has no bonds, write 'bonds: {list: []}' instead of a file");
  }
  const auto indices = material_indices(t.material_names, names);
  std::vector<BondInput> inputs(t.i.size());
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    BondInput& in = inputs[k];
    in.id_i = t.i[k];
    in.id_j = t.j[k];
    if (!t.radius.empty()) {
      in.radius = t.radius[k];
      if (!(t.radius[k] > 0.0)) {
        throw InputError(table_row(path, k), fmt::format("bond radius {} must be greater than 0", t.radius[k]),
                         "give r_b in metres, or leave the column out to use the material's");
      }
    }
    if (!t.material.empty()) {
      in.material = table_material(t.material, t.material_names, indices, k, names, "bond_materials", path);
    }
  }
  add_bonds(b, inputs, default_mat, CsvRowError{}, [&](std::size_t k) { return table_row(path, k); });
}

void add_bonds(ScenarioBuilder& b, const std::vector<BondInput>& inputs, std::optional<std::int32_t> default_mat,
               const CsvRowError& error, const std::function<std::string(std::size_t)>& where) {
  // The bonds' particles and constants in parallel, a block at a time (a buffer of all 8e6
  // would take 0.6 GB); then, in file order, the duplicate check and the add. A row refused in
  // either goes through add_bond in its place, which throws what a sequential read throws.
  BondPairSet bonded(inputs.size());
  constexpr std::size_t kBlock = std::size_t{1} << 16;
  std::vector<std::optional<NewBond>> block(std::min(kBlock, inputs.size()));
  constexpr std::size_t kAhead = 16;  // the set's memory is random access: fetch it early
  for (std::size_t first = 0; first < inputs.size(); first += kBlock) {
    const std::size_t count = std::min(kBlock, inputs.size() - first);
#pragma omp parallel for schedule(static)
    for (std::int64_t k = 0; k < static_cast<std::int64_t>(count); ++k) {
      const auto row = first + static_cast<std::size_t>(k);
      block[static_cast<std::size_t>(k)] = try_make_bond(b, inputs[row], default_mat);
    }
    for (std::size_t k = 0; k < count; ++k) {
      error.rethrow_at(first + k);
      if (k + kAhead < count && block[k + kAhead])
        bonded.prefetch(block[k + kAhead]->i, block[k + kAhead]->j);
      const std::optional<NewBond>& bond = block[k];
      if (!bond || !bonded.insert(bond->i, bond->j)) {
        add_bond(b, bonded, inputs[first + k], default_mat, where(first + k));
        continue;  // not reached: add_bond throws
      }
      b.scenario.model.bonds.add(bond->i, bond->j, bond->constants, bond->r_b, bond->length,
                                 bond->material);
    }
  }
}

void read_bond_list(ScenarioBuilder& b, const YamlField& field, std::optional<std::int32_t> default_mat) {
  BondPairSet bonded;
  for (const YamlField& item : field.items()) {
    BondInput in;
    if (item.is_sequence()) {  // [i, j]
      const auto ends = item.items();
      if (ends.size() != 2) item.fail(fmt::format("a bond names 2 particle ids, got {}", ends.size()), "write [i, j]");
      in.id_i = ends[0].integer();
      in.id_j = ends[1].integer();
    } else {  // {i, j, radius, material}
      const YamlMap m = item.map({"i", "j", "radius", "material"});
      in.id_i = m.require("i", "give the first particle id").integer();
      in.id_j = m.require("j", "give the second particle id").integer();
      if (const auto r = m.find("radius")) in.radius = r->positive();
      if (const auto mat = m.find("material")) in.material = material_at(*mat, b.scenario.bond_material_names, "bond_materials");
    }
    add_bond(b, bonded, in, default_mat, item.where());
  }
}

/// `auto`: bond every pair whose surface gap is at most max_gap.
void read_bond_auto(ScenarioBuilder& b, const YamlField& field, std::optional<std::int32_t> default_mat) {
  const YamlMap m = field.map({"max_gap"});
  const double max_gap = m.require("max_gap", "give the largest surface gap to bond, in metres (0: touching)").non_negative();
  const ParticleStore& p = b.scenario.model.particles;
  BondPairSet bonded;
  for (const auto& [i, j] : pairs_within_gap(p.position, p.radius, max_gap)) {
    add_bond(b, bonded, {p.id[static_cast<std::size_t>(i)], p.id[static_cast<std::size_t>(j)], std::nullopt, std::nullopt},
             default_mat, field.where());
  }
}

/// Puts the particles in the canonical order (model/spatial_order.hpp), so that the run depends
/// on the model and not on the order of its rows. This happens before anything else is read: every
/// later index (bonds, boundary conditions, loads, probes) is taken from index_of_id or from the
/// sorted store, so nothing needs renumbering.
void put_particles_in_canonical_order(ScenarioBuilder& b) {
  ParticleStore& p = b.scenario.model.particles;
  const std::vector<std::int32_t> old_at = canonical_particle_order(p.position, p.id);
  p.reorder(old_at);
  const std::vector<std::int32_t> new_of = inverse_permutation(old_at);
  for (auto& entry : b.index_of_id) entry.second = new_of[static_cast<std::size_t>(entry.second)];
}

}  // namespace

void read_particles(ScenarioBuilder& b, const YamlField& section) {
  const YamlMap m = section.map({"material", "file", "list", "row"});
  const auto default_mat = default_material(m, b.scenario.particle_material_names, "particle_materials");
  const auto [kind, field] = m.one_of({"file", "list", "row"});
  if (kind == "file") read_particle_file(b, field, default_mat);
  if (kind == "list") read_particle_list(b, field, default_mat);
  if (kind == "row") read_particle_row(b, field, default_mat);
  if (b.scenario.model.particles.size() == 0) section.fail("defines no particles", "add at least one particle");
  put_particles_in_canonical_order(b);
}

void read_bonds(ScenarioBuilder& b, const YamlField& section) {
  const YamlMap m = section.map({"material", "file", "list", "auto"});
  const auto default_mat = default_material(m, b.scenario.bond_material_names, "bond_materials");
  const auto [kind, field] = m.one_of({"file", "list", "auto"});
  if (kind == "file") read_bond_file(b, field, default_mat);
  if (kind == "list") read_bond_list(b, field, default_mat);
  if (kind == "auto") read_bond_auto(b, field, default_mat);
  // Bonds by their (canonical) particles: the bond loop then walks the particles in memory order.
  // Each keeps the orientation it was given (the law tells alpha from beta) and its input row.
  BondStore& bonds = b.scenario.model.bonds;
  bonds.reorder(canonical_bond_order(bonds.alpha, bonds.beta));
}

}  // namespace bpm::scenario_detail
