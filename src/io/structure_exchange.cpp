#include "io/structure_exchange.hpp"

#include <fmt/core.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unordered_map>
#include <unordered_set>

#include "core/error.hpp"
#include "io/csv_table.hpp"
#include "io/parse_number.hpp"

namespace bpm {
namespace {

namespace fs = std::filesystem;

/// The index of `name` in `names`, appended if new.
std::uint32_t name_index(std::vector<std::string>& names,
                         std::unordered_map<std::string, std::uint32_t>& index,
                         const std::string& name) {
  const auto [it, added] = index.emplace(name, static_cast<std::uint32_t>(names.size()));
  if (added) names.push_back(name);
  return it->second;
}

/// The file's path in dir: NAME, else its binary twin NAME with .bpk for .csv, else "".
std::string table_file(const std::string& dir, const std::string& csv_name) {
  const fs::path csv = fs::path(dir) / csv_name;
  if (fs::exists(csv)) return csv.string();
  const fs::path binary = fs::path(csv).replace_extension(".bpk");
  return fs::exists(binary) ? binary.string() : std::string();
}

ParticleTable read_particles_csv(const std::string& path) {
  CsvTable table = read_csv(path, "bpmkit convert");
  const std::vector<std::string> columns{"id", "x", "y", "z", "radius", "material"};
  if (!table.header.empty() &&
      !((table.header.size() == 5 || table.header.size() == 6) &&
        std::equal(table.header.begin(), table.header.end(), columns.begin()))) {
    throw InputError(fmt::format("{}:{}", path, table.header_line), "unexpected header line",
                     "the columns are id,x,y,z,radius[,material] in this order");
  }
  ParticleTable t;
  const std::size_t n = table.size();
  t.id.resize(n);
  t.position.resize(n);
  t.radius.resize(n);
  std::vector<std::string> material(n);
  const CsvRowError error = table.convert_rows([&](std::size_t k, const CsvRow& row) {
    if (row.fields.size() != 5 && row.fields.size() != 6) {
      throw InputError(table.where(row),
                       fmt::format("expected 5 or 6 columns, got {}", row.fields.size()),
                       "write id,x,y,z,radius[,material]");
    }
    t.id[k] = table.integer(row, 0, "id");
    t.position[k] = {table.number(row, 1, "x"), table.number(row, 2, "y"),
                     table.number(row, 3, "z")};
    t.radius[k] = table.number(row, 4, "radius");
    if (row.fields.size() == 6) material[k] = std::string(row.fields[5]);
  });
  for (std::size_t k = 0; k < n; ++k) error.rethrow_at(k);
  const bool named = std::any_of(material.begin(), material.end(),
                                 [](const std::string& m) { return !m.empty(); });
  if (named) {
    std::unordered_map<std::string, std::uint32_t> index;
    for (std::size_t k = 0; k < n; ++k) {
      if (material[k].empty()) {
        throw InputError(table.where(k), "this row has no material while others have one",
                         "give every row a material, or none");
      }
      t.material.push_back(name_index(t.material_names, index, material[k]));
    }
  }
  return t;
}

BondTable read_bonds_csv(const std::string& path) {
  CsvTable table = read_csv(path, "bpmkit convert");
  std::optional<std::size_t> radius_col, material_col;
  if (!table.header.empty()) {
    const auto& h = table.header;
    bool ok = h.size() >= 2 && h.size() <= 4 && h[0] == "i" && h[1] == "j";
    for (std::size_t c = 2; ok && c < h.size(); ++c) {
      if (h[c] == "radius" && !radius_col && !material_col)
        radius_col = c;
      else if (h[c] == "material" && !material_col)
        material_col = c;
      else
        ok = false;
    }
    if (!ok) {
      throw InputError(fmt::format("{}:{}", path, table.header_line), "unexpected header line",
                       "the columns are i,j[,radius][,material] in this order");
    }
  } else if (table.size() > 0) {
    throw InputError(path, "bonds.csv has no header line", "start it with i,j[,radius][,material]");
  }
  BondTable t;
  const std::size_t n = table.size();
  t.i.resize(n);
  t.j.resize(n);
  if (radius_col) t.radius.resize(n);
  std::vector<std::string> material(material_col ? n : 0);
  const CsvRowError error = table.convert_rows([&](std::size_t k, const CsvRow& row) {
    if (row.fields.size() != table.header.size()) {
      throw InputError(
          table.where(row),
          fmt::format("expected {} columns, got {}", table.header.size(), row.fields.size()),
          "write i,j[,radius][,material]");
    }
    t.i[k] = table.integer(row, 0, "i");
    t.j[k] = table.integer(row, 1, "j");
    if (radius_col) t.radius[k] = table.number(row, *radius_col, "radius");
    if (material_col) material[k] = std::string(row.fields[*material_col]);
  });
  for (std::size_t k = 0; k < n; ++k) error.rethrow_at(k);
  std::unordered_map<std::string, std::uint32_t> index;
  for (const std::string& m : material)
    t.material.push_back(name_index(t.material_names, index, m));
  return t;
}

/// The lines of a text file without comments ('#' to the end) and blank lines, with their numbers.
std::vector<std::pair<int, std::vector<std::string>>> text_rows(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "cannot open the file", "check the path");
  std::vector<std::pair<int, std::vector<std::string>>> rows;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    line = line.substr(0, line.find('#'));
    std::istringstream words(line);
    std::vector<std::string> fields;
    for (std::string w; words >> w;) fields.push_back(w);
    if (!fields.empty()) rows.emplace_back(number, std::move(fields));
  }
  return rows;
}

double text_number(const std::string& path, int line, const std::string& text, const char* what) {
  const auto value = parse_double(text);
  if (!value)
    throw InputError(fmt::format("{}:{}", path, line),
                     fmt::format("{} '{}' is not a finite number", what, text));
  return *value;
}

std::int64_t text_integer(const std::string& path, int line, const std::string& text,
                          const char* what) {
  const auto value = parse_int64(text);
  if (!value)
    throw InputError(fmt::format("{}:{}", path, line),
                     fmt::format("{} '{}' is not an integer", what, text));
  return *value;
}

}  // namespace

void check_exchange_structure(const ExchangeStructure& s, const std::string& source) {
  const ParticleTable& p = s.particles;
  std::unordered_set<std::int64_t> ids;
  for (std::size_t k = 0; k < p.id.size(); ++k) {
    if (!ids.insert(p.id[k]).second) {
      throw InputError(source, fmt::format("particle id {} appears twice", p.id[k]),
                       "give every particle a unique id");
    }
    if (!(p.radius[k] > 0.0) || !std::isfinite(p.radius[k])) {
      throw InputError(source, fmt::format("particle {} has radius {}", p.id[k], p.radius[k]),
                       "every radius must be a positive number of metres");
    }
  }
  for (std::size_t b = 0; b < s.bonds.i.size(); ++b) {
    for (const std::int64_t id : {s.bonds.i[b], s.bonds.j[b]}) {
      if (!ids.contains(id)) {
        throw InputError(source,
                         fmt::format("bond {} joins particle {}, which is not listed", b + 1, id),
                         "list the particle or remove the bond");
      }
    }
  }
}

ExchangeStructure read_bpmkit_structure(const std::string& dir) {
  const std::string particles = table_file(dir, "particles.csv");
  if (particles.empty()) {
    throw InputError(
        dir, "no particles.csv (or particles.bpk) in this folder",
        "give the folder `bpmkit generate` wrote, or --from lammps/yade for other formats");
  }
  ExchangeStructure s;
  s.particles = is_structure_table(particles) ? read_particle_table(particles)
                                              : read_particles_csv(particles);
  const std::string bonds = table_file(dir, "bonds.csv");
  if (!bonds.empty())
    s.bonds = is_structure_table(bonds) ? read_bond_table(bonds) : read_bonds_csv(bonds);
  check_exchange_structure(s, dir);
  return s;
}

ExchangeFiles bpmkit_structure_files(const ExchangeStructure& s) {
  ExchangeFiles out;
  out.files.emplace_back("particles.csv", particle_table_csv(s.particles));
  out.files.emplace_back("bonds.csv", bond_table_csv(s.bonds));
  if (!s.density.empty()) {
    out.dropped.push_back(
        "particle densities (particles.csv has none: give them in the scenario's "
        "particle_materials)");
  }
  return out;
}

ExchangeStructure read_yade_structure(const std::string& dir) {
  const std::string spheres = (fs::path(dir) / "spheres.txt").string();
  const std::string bonds = (fs::path(dir) / "bonds.txt").string();
  ExchangeStructure s;
  ParticleTable& p = s.particles;
  for (const auto& [line, f] : text_rows(spheres)) {
    if (f.size() != 4) {
      throw InputError(fmt::format("{}:{}", spheres, line),
                       fmt::format("expected 4 columns, got {}", f.size()),
                       "write 'x y z r' per sphere, as yade.export.text does");
    }
    p.id.push_back(static_cast<std::int64_t>(p.id.size()));
    p.position.push_back({text_number(spheres, line, f[0], "x"),
                          text_number(spheres, line, f[1], "y"),
                          text_number(spheres, line, f[2], "z")});
    p.radius.push_back(text_number(spheres, line, f[3], "r"));
  }
  if (p.id.empty()) throw InputError(spheres, "no spheres", "write 'x y z r' per sphere");
  if (fs::exists(bonds)) {
    for (const auto& [line, f] : text_rows(bonds)) {
      if (f.size() != 2) {
        throw InputError(fmt::format("{}:{}", bonds, line),
                         fmt::format("expected 2 columns, got {}", f.size()),
                         "write 'i j' per bond, 0-based rows of spheres.txt");
      }
      s.bonds.i.push_back(text_integer(bonds, line, f[0], "i"));
      s.bonds.j.push_back(text_integer(bonds, line, f[1], "j"));
    }
  }
  check_exchange_structure(s, dir);
  return s;
}

ExchangeFiles yade_structure_files(const ExchangeStructure& s) {
  ExchangeFiles out;
  const ParticleTable& p = s.particles;
  std::unordered_map<std::int64_t, std::size_t> row_of;
  bool renumbered = false;
  std::string spheres = "#format x_y_z_r\n";
  for (std::size_t k = 0; k < p.id.size(); ++k) {
    row_of.emplace(p.id[k], k);
    renumbered = renumbered || p.id[k] != static_cast<std::int64_t>(k);
    const Vec3& x = p.position[k];
    spheres += fmt::format("{} {} {} {}\n", x.x, x.y, x.z, p.radius[k]);
  }
  std::string bonds;
  for (std::size_t k = 0; k < s.bonds.i.size(); ++k) {
    bonds += fmt::format("{} {}\n", row_of.at(s.bonds.i[k]), row_of.at(s.bonds.j[k]));
  }
  out.files.emplace_back("spheres.txt", std::move(spheres));
  out.files.emplace_back("bonds.txt", std::move(bonds));
  if (renumbered)
    out.dropped.push_back("particle ids (YADE numbers the spheres by their row: 0, 1, 2, ...)");
  if (!p.material.empty()) out.dropped.push_back("particle materials");
  if (!s.density.empty()) out.dropped.push_back("particle densities");
  if (!s.bonds.radius.empty()) out.dropped.push_back("bond radii r_b");
  if (!s.bonds.material.empty()) out.dropped.push_back("bond materials");
  return out;
}

}  // namespace bpm
