#include "io/musen_text.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <unordered_map>

#include "core/error.hpp"
#include "io/parse_number.hpp"

namespace bpm {
namespace {

// MUSEN's command numbers (ETXTCommands, MUSENDefinitions.h) and object types.
enum Command : unsigned {
  kId = 0,
  kType = 1,
  kTime = 2,
  kGeometry = 5,
  kAccel = 10,
  kAngAccel = 11,
  kCoord = 12,
  kVelocity = 15,
  kAngVel = 16,
  kAngles = 17,
  kForceAmpl = 18,
  kForce = 20,
  kCompound = 23,
  kActivity = 24,
  kOrient = 31,
  kStressTensor = 36,
  kTemperature = 37,
  kPrincStress = 42,
  kTotTorque = 43,
  kPlaneCoord = 44,
  kTangOverlap = 45,
};
constexpr unsigned kSphere = 1, kSolidBond = 9, kLiquidBond = 13, kTriangularWall = 14;
constexpr unsigned kLastCommand = 1000;  // above any MUSEN command, so a number fits `unsigned`
constexpr double kActivityEnd = 1e300;   // MUSEN's DEFAULT_ACTIVITY_END: active for ever

/// The values after a time-dependent command, and what bpmkit calls it when it drops them.
struct TimeDependent {
  unsigned command;
  std::size_t values;
  const char* dropped;
};
constexpr TimeDependent kTimeDependent[] = {
    {kAccel, 3, "accelerations and angles (old MUSEN files)"},
    {kAngAccel, 3, "accelerations and angles (old MUSEN files)"},
    {kCoord, 3, nullptr},  // a sphere's centre is read; a bond's follows from its particles
    {kVelocity, 3, "velocities"},
    {kAngVel, 3, "angular velocities"},
    {kAngles, 3, "accelerations and angles (old MUSEN files)"},
    {kForceAmpl, 1, "forces"},
    {kForce, 3, "forces"},
    {kOrient, 4, "orientations (bpmkit starts unrotated)"},
    {kStressTensor, 9, "stresses"},
    {kTemperature, 1, "temperatures"},
    {kPrincStress, 3, "stresses"},
    {kTotTorque, 1, "bond torques and tangential overlaps"},
    {kPlaneCoord, 9, nullptr},  // walls are dropped whole
    {kTangOverlap, 3, "bond torques and tangential overlaps"},
};

const TimeDependent* time_dependent(unsigned command) {
  for (const TimeDependent& t : kTimeDependent)
    if (t.command == command) return &t;
  return nullptr;
}

/// What a line that is not an object holds (it starts with this command), "" if not MUSEN's.
const char* scene_line(unsigned command) {
  switch (command) {
    case 22:
      return "the simulation domain";
    case 28:
      return "periodic boundaries";
    case 29:
    case 30:
      return "scene options (anisotropy, contact radius)";
    case 25:
    case 26:
    case 27:
      return "geometries (names, motion, wall lists)";
    case 38:
      return "analysis volumes";
    case 32:
    case 33:
    case 34:
      return "the materials database (compounds, interactions, mixtures)";
    case 39:
    case 40:
    case 41:
    case 46:
      return "generators";
    default:
      return "";
  }
}

/// "1 sphere", "2 spheres".
std::string counted(std::size_t n, const char* noun) {
  return fmt::format("{} {}{}", n, noun, n == 1 ? "" : "s");
}

std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

/// A non-negative integer; MUSEN's importer also reads ids written as doubles ("1e+06").
std::optional<std::uint64_t> parse_count(const std::string& text) {
  if (const auto i = parse_int64(text)) {
    if (*i < 0) return std::nullopt;
    return static_cast<std::uint64_t>(*i);
  }
  const auto d = parse_double(text);
  if (!d || *d < 0 || *d > 9007199254740992.0 || std::floor(*d) != *d) return std::nullopt;
  return static_cast<std::uint64_t>(*d);
}

/// A sphere's and a bond's line, as read.
struct Sphere {
  int line = 0;
  std::int64_t id = 0;
  double radius = 0.0, contact_radius = 0.0;
  std::string compound;
  bool has_geometry = false, has_time = false, has_centre = false;
  double time = 0.0;  ///< the first time point's
  Vec3 centre;
};

struct SolidBond {
  int line = 0;
  std::int64_t id = 0, i = 0, j = 0;
  double diameter = 0.0, length = 0.0;
  std::string compound;
  bool has_geometry = false;
};

class MusenReader {
 public:
  explicit MusenReader(std::string path) : path_(std::move(path)) {}

  ExchangeStructure read() {
    std::ifstream in(path_);
    if (!in) throw InputError(path_, "cannot open the MUSEN text file", "check the path");
    std::string text;
    for (int number = 1; std::getline(in, text); ++number) {
      const std::vector<std::string> w = words(text);
      if (w.empty()) continue;
      const unsigned command = command_at(number, w[0]);
      if (command == kId)
        read_object(number, w);
      else
        read_other(number, command);
    }
    return finish();
  }

  const std::vector<std::string>& dropped() const { return dropped_; }

 private:
  [[noreturn]] void fail(int line, const std::string& what, const std::string& fix = "") const {
    throw InputError(fmt::format("{}:{}", path_, line), what, fix);
  }

  unsigned command_at(int line, const std::string& text) const {
    const auto value = parse_int64(text);
    if (!value || *value < 0 || *value > kLastCommand)
      fail(line, fmt::format("'{}' stands where a MUSEN command number should be", text),
           "lines are command numbers, each followed by its values; objects start with 0 ID 1 "
           "TYPE");
    return static_cast<unsigned>(*value);
  }

  /// Counts objects per dropped field, in the order first seen.
  void drop(const std::string& what) {
    if (drop_count_[what]++ == 0) drop_order_.push_back(what);
  }

  void read_other(int line, unsigned command) {
    if (command == kType || time_dependent(command) || command == kTime || command == kGeometry ||
        command == kCompound || command == kActivity) {
      fail(line, fmt::format("the line starts with command {}, not with the object's id", command),
           "objects start with 0 ID 1 TYPE: export with the id and type selected");
    }
    const std::string what = scene_line(command);
    const std::string line_drop =
        what.empty() ? fmt::format("lines of command {}, unknown to bpmkit", command) : what;
    if (std::find(scene_drops_.begin(), scene_drops_.end(), line_drop) == scene_drops_.end())
      scene_drops_.push_back(line_drop);
  }

  /// Reads the word at k, failing if the line ends before it; `what` names the value.
  const std::string& word(int line, const std::vector<std::string>& w, std::size_t k,
                          const std::string& what) const {
    if (k >= w.size())
      fail(line, fmt::format("the line ends before {}", what),
           "the line is cut short: export the file again");
    return w[k];
  }

  double number(int line, const std::vector<std::string>& w, std::size_t k,
                const std::string& what) const {
    const std::string& text = word(line, w, k, what);
    const auto value = parse_double(text);
    if (!value) fail(line, fmt::format("{} '{}' is not a finite number", what, text));
    return *value;
  }

  std::int64_t object_id(int line, const std::vector<std::string>& w, std::size_t k,
                         const std::string& what) const {
    const std::string& text = word(line, w, k, what);
    const auto value = parse_count(text);
    if (!value || *value > std::numeric_limits<std::uint32_t>::max())
      fail(line, fmt::format("{} '{}' is not an object id", what, text),
           "MUSEN's object ids are integers from 0 to 4294967295");
    return static_cast<std::int64_t>(*value);
  }

  void read_object(int line, const std::vector<std::string>& w) {
    const std::int64_t id = object_id(line, w, 1, "the object's id");
    if (word(line, w, 2, "the object's type (1 TYPE)") != "1")
      fail(line, fmt::format("the object's id is followed by '{}', not by its type", w[2]),
           "objects start with 0 ID 1 TYPE");
    const std::string& type_text = word(line, w, 3, "the object's type");
    const auto type_number = parse_int64(type_text);
    const unsigned type = type_number && *type_number > 0 && *type_number <= kLastCommand
                              ? static_cast<unsigned>(*type_number)
                              : 0u;
    if (type != kSphere && type != kSolidBond && type != kLiquidBond && type != kTriangularWall)
      fail(line, fmt::format("object type '{}' is not one of MUSEN's", type_text),
           "1 sphere, 9 solid bond, 13 liquid bond, 14 triangular wall");
    if (const auto [it, added] = object_line_.emplace(id, line); !added)
      fail(line, fmt::format("object id {} is given twice (also on line {})", id, it->second),
           "MUSEN's ids are unique over spheres, bonds and walls");

    Sphere sphere;
    SolidBond bond;
    sphere.line = bond.line = line;
    sphere.id = bond.id = id;
    bool activity_default = true;
    int time_points = 0;
    std::set<std::string> lost;  // this object's dropped fields, counted once per object
    for (std::size_t k = 4; k < w.size();) {
      const unsigned command = command_at(line, w[k++]);
      switch (command) {
        case kGeometry:
          if (type == kSphere) {
            sphere.radius = number(line, w, k++, "the radius");
            sphere.contact_radius = number(line, w, k++, "the contact radius");
            sphere.has_geometry = true;
          } else if (type == kSolidBond || type == kLiquidBond) {
            bond.i = object_id(line, w, k++, "the bond's first particle");
            bond.j = object_id(line, w, k++, "the bond's second particle");
            bond.diameter = number(line, w, k++, "the bond's diameter");
            bond.length = number(line, w, k++, "the bond's initial length");
            bond.has_geometry = true;
          }  // a wall's geometry text is empty
          break;
        case kCompound:
          sphere.compound = bond.compound = word(line, w, k++, "the compound key");
          break;
        case kActivity: {
          const double start = number(line, w, k++, "the activity start");
          const double end = number(line, w, k++, "the activity end");
          activity_default = start == 0.0 && end >= kActivityEnd;
          break;
        }
        case kTime: {
          const double t = number(line, w, k++, "the time");
          times_.insert(t);
          if (++time_points == 1) {
            sphere.time = t;
            sphere.has_time = true;
          }
          break;
        }
        default: {
          const TimeDependent* td = time_dependent(command);
          if (!td)
            fail(line, fmt::format("command {} is not one MUSEN writes for an object", command),
                 "bpmkit reads the commands of MUSEN's ExportAsText (docs/formats.md)");
          if (time_points == 0)
            fail(line, fmt::format("command {} comes before any time point", command),
                 "time-dependent values follow 2 TIME");
          if (type == kSphere && command == kCoord && time_points == 1) {
            sphere.centre = {number(line, w, k, "the centre's x"),
                             number(line, w, k + 1, "the centre's y"),
                             number(line, w, k + 2, "the centre's z")};
            sphere.has_centre = true;
          } else {
            (void)word(line, w, k + td->values - 1,
                       fmt::format("the {} values of command {}", td->values, command));
            if (td->dropped && (type == kSphere || type == kSolidBond) &&
                holds_information(w, k, *td))
              lost.insert(td->dropped);
          }
          k += td->values;
        }
      }
    }
    if (!activity_default) ++inactive_objects_;
    for (const std::string& what : lost) drop(what);

    if (type == kSphere) {
      if (!sphere.has_geometry)
        fail(line, fmt::format("sphere {} has no geometry", id), "write 5 RADIUS CONTACT_RADIUS");
      if (!sphere.has_time || !sphere.has_centre)
        fail(line, fmt::format("sphere {} has no centre", id),
             "write 2 TIME 12 X Y Z: export with the coordinates selected");
      spheres_.push_back(sphere);
    } else if (type == kSolidBond) {
      if (!bond.has_geometry)
        fail(line, fmt::format("solid bond {} has no geometry", id),
             "write 5 ID_LEFT ID_RIGHT DIAMETER INITIAL_LENGTH");
      bonds_.push_back(bond);
    } else if (type == kLiquidBond) {
      ++liquid_bonds_;
    } else {
      ++walls_;
    }
  }

  /// False for values that lose nothing: zeros, and the identity orientation bpmkit writes.
  static bool holds_information(const std::vector<std::string>& w, std::size_t k,
                                const TimeDependent& td) {
    for (std::size_t v = 0; v < td.values; ++v) {
      const auto value = parse_double(w[k + v]);
      const double expected = td.command == kOrient && v == 0 ? 1.0 : 0.0;
      if (!value || *value != expected) return true;
    }
    return false;
  }

  ExchangeStructure finish() {
    if (spheres_.empty())
      throw InputError(path_, "no spheres (objects of type 1)",
                       "export the particles with their id, type, geometry and coordinates");
    ExchangeStructure s;
    ParticleTable& p = s.particles;
    const double t0 = spheres_.front().time;
    std::unordered_map<std::int64_t, std::size_t> row;
    std::size_t other_contact_radius = 0;
    for (const Sphere& sp : spheres_) {
      if (sp.time != t0)
        fail(sp.line,
             fmt::format("sphere {} starts at time {}, the first sphere at {}", sp.id, sp.time, t0),
             "bpmkit reads one time point: export the same first time point for every object");
      if (!(sp.radius > 0.0))
        fail(sp.line, fmt::format("sphere {} has radius {}", sp.id, sp.radius),
             "every radius must be a positive number of metres");
      row.emplace(sp.id, p.id.size());
      p.id.push_back(sp.id);
      p.position.push_back(sp.centre);
      p.radius.push_back(sp.radius);
      // MUSEN reads a contact radius of 0 as the radius.
      if (sp.contact_radius != 0.0 && sp.contact_radius != sp.radius) ++other_contact_radius;
    }
    materials(spheres_, p.material_names, p.material);

    std::size_t other_length = 0;
    double largest_difference = 0.0;
    for (const SolidBond& b : bonds_) {
      for (const std::int64_t end : {b.i, b.j}) {
        if (!row.contains(end))
          fail(b.line,
               fmt::format("solid bond {} joins object {}, which is not a sphere here", b.id, end),
               "list the sphere in the file or remove the bond");
      }
      if (!(b.diameter > 0.0))
        fail(b.line, fmt::format("solid bond {} has diameter {}", b.id, b.diameter),
             "every bond diameter must be a positive number of metres");
      s.bonds.i.push_back(b.i);
      s.bonds.j.push_back(b.j);
      s.bonds.radius.push_back(0.5 * b.diameter);  // exact: a power of two
      const double distance = norm(p.position[row.at(b.j)] - p.position[row.at(b.i)]);
      if (b.length != distance) {
        ++other_length;
        largest_difference =
            std::max(largest_difference, std::abs(b.length - distance) / std::abs(b.length));
      }
    }
    materials(bonds_, s.bonds.material_names, s.bonds.material);

    if (times_.size() > 1)
      dropped_.push_back(
          fmt::format("time points other than t = {} s (the file holds {})", t0, times_.size()));
    for (const std::string& what : drop_order_)
      dropped_.push_back(fmt::format("{} ({})", what, counted(drop_count_.at(what), "object")));
    if (other_contact_radius > 0)
      dropped_.push_back(
          fmt::format("contact radii ({} with one other than the radius; bpmkit "
                      "has none)",
                      counted(other_contact_radius, "sphere")));
    if (other_length > 0)
      dropped_.push_back(fmt::format(
          "bond initial lengths ({} other than the distance between the centres, by up to "
          "{:.2g} of it; bpmkit's bonds start unstressed at that distance)",
          counted(other_length, "bond"), largest_difference));
    if (inactive_objects_ > 0)
      dropped_.push_back(
          fmt::format("activity intervals ({} not active from t = 0 on; bpmkit keeps every object)",
                      counted(inactive_objects_, "object")));
    if (liquid_bonds_ > 0) dropped_.push_back(fmt::format("liquid bonds ({})", liquid_bonds_));
    if (walls_ > 0) dropped_.push_back(fmt::format("triangular walls ({})", walls_));
    dropped_.insert(dropped_.end(), scene_drops_.begin(), scene_drops_.end());
    check_exchange_structure(s, path_);
    return s;
  }

  /// Compound keys as material names; none if no object names one ("Undefined" is MUSEN's word
  /// for none, and what an object without a key gets when others have one).
  template <class Object>
  static void materials(const std::vector<Object>& objects, std::vector<std::string>& names,
                        std::vector<std::uint32_t>& material) {
    bool named = false;
    for (const Object& o : objects)
      named = named || (!o.compound.empty() && o.compound != "Undefined");
    if (!named) return;
    std::map<std::string, std::uint32_t> index;
    for (const Object& o : objects) {
      const std::string key = o.compound.empty() ? "Undefined" : o.compound;
      const auto [it, added] = index.emplace(key, static_cast<std::uint32_t>(names.size()));
      if (added) names.push_back(key);
      material.push_back(it->second);
    }
  }

  std::string path_;
  std::vector<Sphere> spheres_;
  std::vector<SolidBond> bonds_;
  std::unordered_map<std::int64_t, int> object_line_;
  std::set<double> times_;
  std::size_t inactive_objects_ = 0, liquid_bonds_ = 0, walls_ = 0;
  std::map<std::string, std::size_t> drop_count_;  // objects per dropped field
  std::vector<std::string> drop_order_, scene_drops_;
  std::vector<std::string> dropped_;
};

/// A material name as a MUSEN compound key: one word (MUSEN reads it with >>), so whitespace
/// becomes '_' and an empty name "_", as MUSEN's own MakeSingleString does.
std::string compound_key(const std::string& name) {
  std::string key = name;
  for (char& c : key)
    if (std::isspace(static_cast<unsigned char>(c))) c = '_';
  return key.empty() ? "_" : key;
}

/// The compound key of every material name; a name that changed goes to `changed`.
std::vector<std::string> compound_keys(const std::vector<std::string>& names, const char* kind,
                                       std::vector<std::string>& changed) {
  std::vector<std::string> keys;
  std::map<std::string, std::string> name_of;
  for (const std::string& name : names) {
    const std::string key = compound_key(name);
    if (const auto [it, added] = name_of.emplace(key, name); !added && it->second != name) {
      throw InputError(
          fmt::format("{} materials", kind),
          fmt::format("'{}' and '{}' would both be MUSEN compound key '{}'", it->second, name, key),
          "rename one of them");
    }
    if (key != name) changed.push_back(fmt::format("'{}' as '{}'", name, key));
    keys.push_back(key);
  }
  return keys;
}

}  // namespace

ExchangeStructure read_musen_structure(const std::string& path, std::vector<std::string>* dropped) {
  MusenReader reader(path);
  ExchangeStructure s = reader.read();
  if (dropped) *dropped = reader.dropped();
  return s;
}

ExchangeFiles musen_structure_files(const ExchangeStructure& s) {
  ExchangeFiles out;
  const ParticleTable& p = s.particles;
  const BondTable& b = s.bonds;

  // MUSEN's ids are 32-bit unsigned, one number space for spheres and bonds: keep ours if they
  // fit with the bonds' after them, else number the particles by row.
  constexpr std::int64_t kMaxId = std::numeric_limits<std::uint32_t>::max();
  std::int64_t largest = -1;
  bool fits = true;
  for (const std::int64_t id : p.id) {
    fits = fits && id >= 0;
    largest = std::max(largest, id);
  }
  fits = fits && largest + static_cast<std::int64_t>(b.i.size()) <= kMaxId;
  std::unordered_map<std::int64_t, std::size_t> row;
  for (std::size_t k = 0; k < p.id.size(); ++k) row.emplace(p.id[k], k);
  const auto musen_id = [&](std::size_t k) {
    return fits ? p.id[k] : static_cast<std::int64_t>(k);
  };
  std::int64_t next_id = fits ? largest + 1 : static_cast<std::int64_t>(p.id.size());

  std::vector<std::string> renamed;
  const std::vector<std::string> particle_keys =
      compound_keys(p.material_names, "particle", renamed);
  const std::vector<std::string> bond_keys = compound_keys(b.material_names, "bond", renamed);

  const std::string activity = fmt::format("24 0 {}", kActivityEnd);
  std::string text;
  for (std::size_t k = 0; k < p.id.size(); ++k) {
    const Vec3& x = p.position[k];
    const std::string compound = p.material.empty() ? "" : " 23 " + particle_keys[p.material[k]];
    // Contact radius = radius; time 0 with the centre and MUSEN's identity orientation (its
    // importer would otherwise give (0, 1, 0, 0)).
    text += fmt::format("0 {} 1 {} 5 {} {}{} {} 2 0 12 {} {} {} 31 1 0 0 0\n", musen_id(k), kSphere,
                        p.radius[k], p.radius[k], compound, activity, x.x, x.y, x.z);
  }
  for (std::size_t k = 0; k < b.i.size(); ++k) {
    const std::size_t i = row.at(b.i[k]), j = row.at(b.j[k]);
    const double r_b = b.radius.empty() ? std::min(p.radius[i], p.radius[j]) : b.radius[k];
    const double length = norm(p.position[j] - p.position[i]);
    const std::string compound = b.material.empty() ? "" : " 23 " + bond_keys[b.material[k]];
    text += fmt::format("0 {} 1 {} 5 {} {} {} {}{} {}\n", next_id++, kSolidBond, musen_id(i),
                        musen_id(j), 2.0 * r_b, length, compound, activity);
  }
  out.files.emplace_back("musen.txt", std::move(text));

  if (!fits)
    out.dropped.push_back(
        "particle ids (MUSEN's are 32-bit unsigned and shared with the bonds: numbered by row, "
        "0, 1, ...)");
  if (!renamed.empty()) {
    std::string list;
    for (const std::string& r : renamed) list += (list.empty() ? "" : ", ") + r;
    out.dropped.push_back("material names with spaces (a MUSEN compound key is one word: " + list +
                          ")");
  }
  if (!s.density.empty())
    out.dropped.push_back(
        "particle densities (MUSEN keeps them in the compounds of its materials database, which "
        "this file does not hold)");
  if (b.radius.empty() && !b.i.empty())
    out.dropped.push_back(
        "bond radii from the scenario (the input has none and MUSEN needs a diameter per bond: "
        "written as 2 min(R_i, R_j), the scenario's default radius_multiplier 1)");
  return out;
}

bool is_musen_text(const std::string& path) {
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    const std::vector<std::string> w = words(line);
    if (w.empty()) continue;
    const auto digits = [](const std::string& t) {
      return !t.empty() && t.find_first_not_of("0123456789") == std::string::npos;
    };
    return w.size() >= 4 && w[0] == "0" && digits(w[1]) && w[2] == "1" && digits(w[3]);
  }
  return false;
}

}  // namespace bpm
