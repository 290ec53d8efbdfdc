#include "io/lammps_data.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>

#include "core/error.hpp"
#include "io/output_folder.hpp"
#include "io/parse_number.hpp"
#include "spatial/aabb.hpp"

namespace bpm {
namespace {

/// The white space of `words` (std::isspace in the C locale), so that a line left non-empty by
/// trim has a first word (a line of only '\v' once reached past the end of an empty word list).
constexpr std::string_view kSpace = " \t\r\n\v\f";

std::string trim(std::string_view s) {
  const auto first = s.find_first_not_of(kSpace);
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(kSpace);
  return std::string(s.substr(first, last - first + 1));
}

std::vector<std::string> words(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

/// The 1-based type of each row's material (1 for all without materials).
std::vector<int> types_of(const std::vector<std::uint32_t>& material, std::size_t rows) {
  std::vector<int> type(rows, 1);
  for (std::size_t k = 0; k < material.size(); ++k) type[k] = static_cast<int>(material[k]) + 1;
  return type;
}

/// One line of the file: its number, the text before any '#', and the comment after it.
struct DataLine {
  int number = 0;
  std::string text, comment;
};

class DataReader {
 public:
  explicit DataReader(std::string path) : path_(std::move(path)) {
    std::ifstream in(path_);
    if (!in) throw InputError(path_, "cannot open the LAMMPS data file", "check the path");
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
      const auto hash = line.find('#');
      DataLine l{number, trim(line.substr(0, hash)),
                 hash == std::string::npos ? "" : trim(line.substr(hash + 1))};
      lines_.push_back(std::move(l));
    }
  }

  ExchangeStructure read() {
    if (lines_.empty())
      fail(1, "the file is empty", "a data file starts with a title line, then the header");
    std::size_t k = 1;  // line 1 is the title
    for (; k < lines_.size(); ++k) {
      const DataLine& l = lines_[k];
      if (l.text.empty()) {
        read_name_comment(l);
        continue;
      }
      if (is_section(l.text)) break;
      read_header(l);
    }
    if (atoms_ <= 0) fail(lines_.size(), "the header gives no atoms", "add the line 'N atoms'");
    while (k < lines_.size()) k = read_section(k);
    if (s_.particles.id.empty()) fail(lines_.size(), "no Atoms section", "add the Atoms section");
    if (bonds_ > 0 && s_.bonds.i.empty())
      fail(lines_.size(), "the header gives bonds but there is no Bonds section");
    finish_materials();
    check_exchange_structure(s_, path_);
    return std::move(s_);
  }

  /// What the file held that bpmkit does not keep (after read()).
  const std::vector<std::string>& dropped() const { return dropped_; }

 private:
  [[noreturn]] void fail(std::size_t line, const std::string& what,
                         const std::string& fix = "") const {
    throw InputError(fmt::format("{}:{}", path_, line), what, fix);
  }

  static bool is_section(const std::string& text) {
    static const char* const kSections[] = {"Atoms",
                                            "Velocities",
                                            "Bonds",
                                            "Masses",
                                            "Pair Coeffs",
                                            "PairIJ Coeffs",
                                            "Bond Coeffs",
                                            "Atom Type Labels",
                                            "Bond Type Labels",
                                            "Angles",
                                            "Dihedrals",
                                            "Impropers",
                                            "Angle Coeffs",
                                            "Dihedral Coeffs",
                                            "Improper Coeffs",
                                            "Ellipsoids",
                                            "Lines",
                                            "Triangles",
                                            "Bodies"};
    return std::any_of(std::begin(kSections), std::end(kSections),
                       [&](const char* s) { return text == s; });
  }

  /// "atom type 1: rock" and "bond type 2: glue", as lammps_data_text writes them.
  void read_name_comment(const DataLine& l) {
    for (const auto& [prefix, names] :
         {std::pair{"atom type ", &atom_names_}, std::pair{"bond type ", &bond_names_}}) {
      if (l.comment.rfind(prefix, 0) != 0) continue;
      const std::string rest = l.comment.substr(std::string(prefix).size());
      const auto colon = rest.find(':');
      const auto type =
          colon == std::string::npos ? std::nullopt : parse_int64(trim(rest.substr(0, colon)));
      if (type) (*names)[static_cast<int>(*type)] = trim(rest.substr(colon + 1));
    }
  }

  std::int64_t count(const DataLine& l, const std::string& word) const {
    const auto value = parse_int64(word);
    if (!value || *value < 0) fail(l.number, fmt::format("'{}' is not a count", word));
    return *value;
  }

  void read_header(const DataLine& l) {
    const std::vector<std::string> w = words(l.text);
    const std::string rest = l.text.substr(w[0].size() + (l.text.size() > w[0].size() ? 1 : 0));
    if (rest == "atoms")
      atoms_ = count(l, w[0]);
    else if (rest == "bonds")
      bonds_ = count(l, w[0]);
    else if (rest == "atom types")
      atom_types_ = count(l, w[0]);
    else if (rest == "bond types")
      bond_types_ = count(l, w[0]);
    else if (rest == "angles" || rest == "dihedrals" || rest == "impropers") {
      if (count(l, w[0]) > 0) drop(rest);
    }
    // Everything else (box bounds, tilt factors, type counts of angles, extra bond per atom, ...)
    // describes what bpmkit does not keep.
  }

  void drop(const std::string& what) { dropped_.push_back(what); }

  /// Reads the section that starts at line k; returns the line after it.
  std::size_t read_section(std::size_t k) {
    const DataLine& head = lines_[k];
    if (head.text.empty()) return k + 1;
    if (!is_section(head.text))
      fail(head.number, fmt::format("'{}' is not a section of a data file", head.text));
    const std::string& name = head.text;
    std::int64_t rows = 0;
    if (name == "Atoms" || name == "Velocities")
      rows = atoms_;
    else if (name == "Bonds")
      rows = bonds_;
    else if (name == "Masses" || name == "Pair Coeffs" || name == "Atom Type Labels")
      rows = atom_types_;
    else if (name == "Bond Coeffs" || name == "Bond Type Labels")
      rows = bond_types_;
    else
      fail(head.number, fmt::format("the {} section is not supported", name),
           "bpmkit reads spheres and bonds only");
    if (name == "Atoms") style_ = atom_style(head);
    std::size_t i = k + 1;
    for (std::int64_t row = 0; row < rows; ++row) {
      while (i < lines_.size() && lines_[i].text.empty()) ++i;
      if (i >= lines_.size())
        fail(lines_.size(),
             fmt::format("the {} section ends after {} of {} rows", name, row, rows));
      const DataLine& l = lines_[i++];
      if (name == "Atoms")
        read_atom(l);
      else if (name == "Bonds")
        read_bond(l);
      else if (name == "Atom Type Labels" || name == "Bond Type Labels")
        read_label(l, name == "Atom Type Labels");
    }
    if (name == "Velocities") drop("velocities");
    if (name == "Bond Coeffs" || name == "Pair Coeffs" || name == "Masses") drop(name);
    return i;
  }

  LammpsAtomStyle atom_style(const DataLine& head) const {
    const std::vector<std::string> w = words(head.comment);
    if (w.size() == 1 && w[0] == "bpm/sphere") return LammpsAtomStyle::bpm_sphere;
    // write_data names any hybrid style "hybrid": read as hybrid sphere bond, the order bpmkit
    // writes (a file of `hybrid bond sphere` puts the molecule id before the diameter, which
    // nothing in the file tells apart).
    if ((w.size() == 3 && w[0] == "hybrid" && w[1] == "sphere" && w[2] == "bond") ||
        (w.size() == 1 && w[0] == "hybrid")) {
      return LammpsAtomStyle::hybrid_sphere_bond;
    }
    fail(head.number,
         fmt::format("the Atoms section is of style '{}'; bpmkit reads 'bpm/sphere' and 'hybrid "
                     "sphere bond'",
                     head.comment),
         "name the style after the section, as write_data does: 'Atoms # bpm/sphere'");
  }

  void read_label(const DataLine& l, bool atoms) {
    const std::vector<std::string> w = words(l.text);
    if (w.size() != 2) fail(l.number, "expected 'type label'");
    (atoms ? atom_names_ : bond_names_)[static_cast<int>(count(l, w[0]))] = w[1];
  }

  double number(const DataLine& l, const std::string& text, const char* what) const {
    const auto value = parse_double(text);
    if (!value) fail(l.number, fmt::format("{} '{}' is not a finite number", what, text));
    return *value;
  }

  void read_atom(const DataLine& l) {
    const std::vector<std::string> w = words(l.text);
    if (w.size() != 8 && w.size() != 11) {
      fail(l.number, fmt::format("expected 8 columns (11 with image flags), got {}", w.size()),
           style_ == LammpsAtomStyle::bpm_sphere
               ? "bpm/sphere: atom-ID molecule-ID atom-type diameter density x y z"
               : "hybrid sphere bond: atom-ID atom-type x y z diameter density molecule-ID");
    }
    const bool bpm = style_ == LammpsAtomStyle::bpm_sphere;
    const std::int64_t id = count(l, w[0]);
    if (id < 1) fail(l.number, fmt::format("atom id {} is not positive", id));
    const int type = static_cast<int>(count(l, w[bpm ? 2 : 1]));
    if (type < 1 || (atom_types_ > 0 && type > atom_types_))
      fail(l.number, fmt::format("atom type {} is not between 1 and {}", type, atom_types_));
    const std::size_t x = bpm ? 5 : 2, d = bpm ? 3 : 5, rho = bpm ? 4 : 6;
    ParticleTable& p = s_.particles;
    p.id.push_back(id - 1);
    p.position.push_back(
        {number(l, w[x], "x"), number(l, w[x + 1], "y"), number(l, w[x + 2], "z")});
    p.radius.push_back(0.5 * number(l, w[d], "diameter"));
    s_.density.push_back(number(l, w[rho], "density"));
    atom_type_.push_back(type);
    if (w.size() == 11 && (w[8] != "0" || w[9] != "0" || w[10] != "0") && !image_flags_) {
      image_flags_ = true;
      drop("image flags (bpmkit has no periodic box)");
    }
  }

  void read_bond(const DataLine& l) {
    const std::vector<std::string> w = words(l.text);
    if (w.size() != 4)
      fail(l.number, fmt::format("expected 4 columns, got {}", w.size()),
           "bond-ID bond-type atom-1 atom-2");
    const int type = static_cast<int>(count(l, w[1]));
    if (type < 1 || (bond_types_ > 0 && type > bond_types_))
      fail(l.number, fmt::format("bond type {} is not between 1 and {}", type, bond_types_));
    s_.bonds.i.push_back(count(l, w[2]) - 1);
    s_.bonds.j.push_back(count(l, w[3]) - 1);
    bond_type_.push_back(type);
    const std::vector<std::string> c = words(l.comment);
    if (c.size() == 2 && c[0] == "r_b") bond_radius_.push_back(number(l, c[1], "r_b"));
  }

  /// Types become materials named by the comments or labels ("type1", ... otherwise); a single
  /// unnamed type is no material at all, as in a structure without materials.
  void finish_materials() {
    const auto assign = [](const std::vector<int>& type, const std::map<int, std::string>& names,
                           std::int64_t types, std::vector<std::string>& material_names,
                           std::vector<std::uint32_t>& material) {
      if (names.empty() && types <= 1) return;
      const int top = std::max<int>(static_cast<int>(types),
                                    type.empty() ? 0 : *std::max_element(type.begin(), type.end()));
      for (int t = 1; t <= top; ++t) {
        const auto it = names.find(t);
        material_names.push_back(it != names.end() ? it->second : fmt::format("type{}", t));
      }
      for (const int t : type) material.push_back(static_cast<std::uint32_t>(t - 1));
    };
    assign(atom_type_, atom_names_, atom_types_, s_.particles.material_names,
           s_.particles.material);
    assign(bond_type_, bond_names_, bond_types_, s_.bonds.material_names, s_.bonds.material);
    if (!bond_radius_.empty() && bond_radius_.size() == bond_type_.size())
      s_.bonds.radius = std::move(bond_radius_);
  }

  std::string path_;
  std::vector<DataLine> lines_;
  std::int64_t atoms_ = 0, bonds_ = 0, atom_types_ = 0, bond_types_ = 0;
  LammpsAtomStyle style_ = LammpsAtomStyle::bpm_sphere;
  std::map<int, std::string> atom_names_, bond_names_;
  std::vector<int> atom_type_, bond_type_;
  std::vector<double> bond_radius_;
  bool image_flags_ = false;
  ExchangeStructure s_;
  std::vector<std::string> dropped_;
};

}  // namespace

std::string lammps_data_text(const ExchangeStructure& s, const LammpsDataOptions& options) {
  const ParticleTable& p = s.particles;
  const BondTable& b = s.bonds;
  if (s.density.empty() && !(options.density > 0.0)) {
    throw InputError("bpmkit convert", "LAMMPS needs a density per atom and the input has none",
                     "give --density in kg/m^3");
  }
  const std::vector<int> atom_type = types_of(p.material, p.id.size());
  const std::vector<int> bond_type =
      options.bond_type.empty() ? types_of(b.material, b.i.size()) : options.bond_type;
  const int atom_types = std::max<int>(1, static_cast<int>(p.material_names.size()));
  const int bond_types = options.bond_type.empty()
                             ? std::max<int>(1, static_cast<int>(b.material_names.size()))
                             : static_cast<int>(options.bond_coeffs.size());
  // A box around the particles with a margin of one largest diameter (the box only bounds the
  // atoms; boundary f f f in the deck).
  const Aabb box = bounding_box(p.position);
  const double margin =
      p.radius.empty() ? 0.0 : 2.0 * *std::max_element(p.radius.begin(), p.radius.end());
  const Vec3& lo = box.min;
  const Vec3& hi = box.max;

  std::string t = fmt::format("LAMMPS data file written by bpmkit {}\n\n", bpmkit_version());
  for (std::size_t m = 0; m < p.material_names.size(); ++m)
    t += fmt::format("# atom type {}: {}\n", m + 1, p.material_names[m]);
  if (options.bond_type.empty()) {
    for (std::size_t m = 0; m < b.material_names.size(); ++m)
      t += fmt::format("# bond type {}: {}\n", m + 1, b.material_names[m]);
  }
  t += fmt::format("{} atoms\n{} atom types\n{} bonds\n{} bond types\n\n", p.id.size(), atom_types,
                   b.i.size(), bond_types);
  t += fmt::format("{} {} xlo xhi\n{} {} ylo yhi\n{} {} zlo zhi\n", lo.x - margin, hi.x + margin,
                   lo.y - margin, hi.y + margin, lo.z - margin, hi.z + margin);
  if (!options.bond_coeffs.empty()) {
    t += fmt::format("\nBond Coeffs # {}\n\n", options.bond_style);
    for (std::size_t k = 0; k < options.bond_coeffs.size(); ++k)
      t += fmt::format("{} {}\n", k + 1, options.bond_coeffs[k]);
  }
  const bool bpm = options.style == LammpsAtomStyle::bpm_sphere;
  t += bpm ? "\nAtoms # bpm/sphere\n\n" : "\nAtoms # hybrid sphere bond\n\n";
  t.reserve(t.size() + p.id.size() * 100 + b.i.size() * 40);
  for (std::size_t k = 0; k < p.id.size(); ++k) {
    if (p.id[k] < 0) {
      throw InputError(
          "bpmkit convert",
          fmt::format("particle id {} is negative; LAMMPS ids are bpmkit ids + 1 >= 1", p.id[k]),
          "renumber the particles from 0");
    }
    const Vec3& x = p.position[k];
    const double rho = s.density.empty() ? options.density : s.density[k];
    if (bpm)
      t += fmt::format("{} 1 {} {} {} {} {} {}\n", p.id[k] + 1, atom_type[k], 2.0 * p.radius[k],
                       rho, x.x, x.y, x.z);
    else
      t += fmt::format("{} {} {} {} {} {} {} 1\n", p.id[k] + 1, atom_type[k], x.x, x.y, x.z,
                       2.0 * p.radius[k], rho);
  }
  if (!b.i.empty()) {
    t += "\nBonds\n\n";
    for (std::size_t k = 0; k < b.i.size(); ++k) {
      t += fmt::format("{} {} {} {}", k + 1, bond_type[k], b.i[k] + 1, b.j[k] + 1);
      t += b.radius.empty() ? "\n" : fmt::format(" # r_b {}\n", b.radius[k]);
    }
  }
  return t;
}

ExchangeStructure read_lammps_data(const std::string& path, std::vector<std::string>* dropped) {
  DataReader reader(path);
  ExchangeStructure s = reader.read();
  if (dropped) *dropped = reader.dropped();
  return s;
}

}  // namespace bpm
