#include "io/structure_table.hpp"

#include <fmt/core.h>

#include <bit>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string_view>

#include "core/error.hpp"
#include "io/byte_codec.hpp"

namespace bpm {
namespace {

constexpr std::string_view kMagic{"BPMKTAB\n", 8};  // the newline: a text tool sees one line
constexpr std::uint32_t kVersion = 1;
constexpr std::uint8_t kParticles = 1, kBonds = 2;

const char* kind_name(std::uint8_t kind) { return kind == kParticles ? "particles" : "bonds"; }

void header(ByteWriter& w, std::uint8_t kind, std::size_t rows, const std::vector<std::string>& names) {
  for (const char c : kMagic) w.u8(static_cast<std::uint8_t>(c));
  w.u32(kVersion);
  w.u8(kind);
  w.u64(rows);
  w.list(names, [](ByteWriter& o, const std::string& n) { o.text(n); });
}

template <class T, class Put>
void column(ByteWriter& w, const std::vector<T>& v, Put put) {
  for (const T& x : v) put(w, x);
}

std::string close(ByteWriter& w) {
  const std::uint64_t sum = fnv1a64(w.bytes());
  w.u64(sum);
  return w.take();
}

std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw InputError(path, "cannot open the file", "check the path");
  // One read into a buffer of the file's size (an istreambuf_iterator copy of the 230 MB bonds
  // table grew its string some 20 times).
  const std::streamoff size = in.tellg();
  if (size < 0) throw InputError(path, "cannot read the file's size", "give a regular file");
  std::string bytes(static_cast<std::size_t>(size), '\0');
  in.seekg(0);
  if (!in.read(bytes.data(), size)) throw InputError(path, "the file cannot be read", "check that it is a readable file");
  return bytes;
}

[[noreturn]] void corrupt(const std::string& path, const std::string& what) {
  throw InputError(path, what, "write the file again with `bpmkit generate`, or use the CSV twin");
}

/// Runs `decode` on the payload; a read past the end becomes the file's error.
template <class Decode>
void decode_table(const std::string& path, std::uint8_t kind, Decode decode) {
  const std::string bytes = read_all(path);
  if (bytes.size() < kMagic.size() + 8 || std::string_view(bytes).substr(0, kMagic.size()) != kMagic)
    corrupt(path, "not a bpmkit structure table (the first bytes differ)");
  const std::string_view payload = std::string_view(bytes).substr(0, bytes.size() - 8);
  try {
    ByteReader sum(std::string_view(bytes).substr(bytes.size() - 8));
    if (sum.u64() != fnv1a64(payload)) corrupt(path, "checksum mismatch: the file is damaged or cut short");
    ByteReader r(payload.substr(kMagic.size()));
    if (const std::uint32_t v = r.u32(); v != kVersion)
      corrupt(path, fmt::format("table format version {}, this bpmkit reads version {}", v, kVersion));
    if (const std::uint8_t k = r.u8(); k != kind) {
      throw InputError(path, fmt::format("a {} table where {} are expected", k == kParticles || k == kBonds ? kind_name(k) : "unknown", kind_name(kind)),
                       fmt::format("name the {} file here", kind_name(kind)));
    }
    const std::uint64_t rows = r.u64();
    if (rows > r.left() / 8) corrupt(path, "a row count beyond the end of the file");
    std::vector<std::string> names = r.list<std::string>(8, [](ByteReader& in) { return in.text(); });
    decode(r, static_cast<std::size_t>(rows), names);
    if (r.left() != 0) corrupt(path, "bytes after the last column");
  } catch (const std::out_of_range&) {
    corrupt(path, "the file ends early");
  }
}

/// A column of rows values of T. The layout is little-endian: on a little-endian machine the bytes
/// are the values, copied at once; elsewhere each is decoded by `get`.
template <class T, class Get>
std::vector<T> read_column(ByteReader& r, std::size_t rows, Get get) {
  std::vector<T> v(rows);
  if constexpr (std::endian::native == std::endian::little) {
    if (rows > r.left() / sizeof(T)) throw std::out_of_range("a column beyond the end of the data");
    if (rows > 0) std::memcpy(v.data(), r.raw(rows * sizeof(T)).data(), rows * sizeof(T));  // no null memcpy
  } else {
    for (T& x : v) x = get(r);
  }
  return v;
}

std::vector<std::uint32_t> read_materials(const std::string& path, ByteReader& r, std::size_t rows,
                                          const std::vector<std::string>& names) {
  if (names.empty()) return {};
  std::vector<std::uint32_t> m = read_column<std::uint32_t>(r, rows, [](ByteReader& in) { return in.u32(); });
  for (const std::uint32_t k : m)
    if (k >= names.size()) corrupt(path, fmt::format("material index {} beyond the {} names", k, names.size()));
  return m;
}

}  // namespace

std::string particle_table_csv(const ParticleTable& t) {
  const bool material = !t.material_names.empty() && t.material.size() == t.id.size();
  std::string s = material ? "id,x,y,z,radius,material\n" : "id,x,y,z,radius\n";
  s.reserve(t.id.size() * 90);
  for (std::size_t k = 0; k < t.id.size(); ++k) {
    const Vec3& x = t.position[k];
    s += fmt::format("{},{},{},{},{}", t.id[k], x.x, x.y, x.z, t.radius[k]);
    s += material ? "," + t.material_names[t.material[k]] + "\n" : "\n";
  }
  return s;
}

std::string bond_table_csv(const BondTable& t) {
  const bool radius = !t.radius.empty(), material = !t.material_names.empty() && t.material.size() == t.i.size();
  std::string s = std::string("i,j") + (radius ? ",radius" : "") + (material ? ",material" : "") + "\n";
  s.reserve(t.i.size() * (radius ? 48 : 24));
  for (std::size_t k = 0; k < t.i.size(); ++k) {
    s += fmt::format("{},{}", t.i[k], t.j[k]);
    if (radius) s += fmt::format(",{}", t.radius[k]);
    s += material ? "," + t.material_names[t.material[k]] + "\n" : "\n";
  }
  return s;
}

std::string particle_table_bytes(const ParticleTable& t) {
  ByteWriter w;
  header(w, kParticles, t.id.size(), t.material_names);
  column(w, t.id, [](ByteWriter& o, std::int64_t v) { o.i64(v); });
  column(w, t.position, [](ByteWriter& o, const Vec3& x) { o.f64(x.x); });
  column(w, t.position, [](ByteWriter& o, const Vec3& x) { o.f64(x.y); });
  column(w, t.position, [](ByteWriter& o, const Vec3& x) { o.f64(x.z); });
  column(w, t.radius, [](ByteWriter& o, double v) { o.f64(v); });
  if (!t.material_names.empty()) column(w, t.material, [](ByteWriter& o, std::uint32_t v) { o.u32(v); });
  return close(w);
}

std::string bond_table_bytes(const BondTable& t) {
  ByteWriter w;
  header(w, kBonds, t.i.size(), t.material_names);
  column(w, t.i, [](ByteWriter& o, std::int64_t v) { o.i64(v); });
  column(w, t.j, [](ByteWriter& o, std::int64_t v) { o.i64(v); });
  w.u8(t.radius.empty() ? 0 : 1);
  column(w, t.radius, [](ByteWriter& o, double v) { o.f64(v); });
  if (!t.material_names.empty()) column(w, t.material, [](ByteWriter& o, std::uint32_t v) { o.u32(v); });
  return close(w);
}

bool is_structure_table(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char first[kMagic.size()] = {};
  return in.read(first, static_cast<std::streamsize>(kMagic.size())) && std::string_view(first, kMagic.size()) == kMagic;
}

ParticleTable read_particle_table(const std::string& path) {
  ParticleTable t;
  decode_table(path, kParticles, [&](ByteReader& r, std::size_t rows, std::vector<std::string>& names) {
    t.id = read_column<std::int64_t>(r, rows, [](ByteReader& in) { return in.i64(); });
    const auto get_f64 = [](ByteReader& in) { return in.f64(); };
    const std::vector<double> x = read_column<double>(r, rows, get_f64), y = read_column<double>(r, rows, get_f64),
                              z = read_column<double>(r, rows, get_f64);
    t.position.resize(rows);
    for (std::size_t k = 0; k < rows; ++k) t.position[k] = {x[k], y[k], z[k]};
    t.radius = read_column<double>(r, rows, get_f64);
    t.material = read_materials(path, r, rows, names);
    t.material_names = std::move(names);
  });
  return t;
}

BondTable read_bond_table(const std::string& path) {
  BondTable t;
  decode_table(path, kBonds, [&](ByteReader& r, std::size_t rows, std::vector<std::string>& names) {
    t.i = read_column<std::int64_t>(r, rows, [](ByteReader& in) { return in.i64(); });
    t.j = read_column<std::int64_t>(r, rows, [](ByteReader& in) { return in.i64(); });
    if (r.u8() != 0) t.radius = read_column<double>(r, rows, [](ByteReader& in) { return in.f64(); });
    t.material = read_materials(path, r, rows, names);
    t.material_names = std::move(names);
  });
  return t;
}

}  // namespace bpm
