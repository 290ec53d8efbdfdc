#pragma once
/// The binary twins of particles.csv and bonds.csv (`bpmkit generate` writes both; every command
/// reads either, told apart by the first bytes, docs/scenario.md). The same rows and columns as
/// the CSV, stored column by column in the checkpoints' byte layout (io/byte_codec.hpp: integers
/// little-endian, doubles as their IEEE 754 bits, so they come back bit for bit) and closed by the
/// same FNV-1a checksum: one binary format family for structures and checkpoints. CSV stays the
/// exchange format; this one loads the 8.1e6-bond box without parsing 330 MB of text.
///
/// Layout: the 8-byte magic, u32 format version, u8 kind (1 particles, 2 bonds), u64 rows, the
/// material names (u64 count, then each as u64 length + bytes; none: the table has no material
/// column), then the columns (particles: id, x, y, z, radius, material; bonds: i, j, u8 has-radius
/// then radius, material), then u64 FNV-1a of everything before it. A material is a u32 index into
/// the names.
#include <cstdint>
#include <string>
#include <vector>

#include "core/vec3.hpp"

namespace bpm {

/// particles.csv's columns id,x,y,z,radius[,material].
struct ParticleTable {
  std::vector<std::int64_t> id;
  std::vector<Vec3> position;
  std::vector<double> radius;
  std::vector<std::string> material_names;  ///< empty: no material column
  std::vector<std::uint32_t> material;      ///< per row, an index into material_names (or empty)
};

/// bonds.csv's columns i,j[,radius][,material].
struct BondTable {
  std::vector<std::int64_t> i, j;
  std::vector<double> radius;  ///< r_b per row, or empty: no radius column
  std::vector<std::string> material_names;
  std::vector<std::uint32_t> material;
};

/// particles.csv and bonds.csv of the tables (a material column when the table names materials,
/// bonds' radius column when it has radii), numbers in their shortest exact form: what
/// `bpmkit generate` and `bpmkit convert` write.
std::string particle_table_csv(const ParticleTable& table);
std::string bond_table_csv(const BondTable& table);

std::string particle_table_bytes(const ParticleTable& table);
std::string bond_table_bytes(const BondTable& table);

/// True if the file starts with this format's magic (a CSV file never does).
bool is_structure_table(const std::string& path);

/// Reads a table written by the functions above; a short, corrupt or mismatched file (a bonds
/// table where particles are expected, a wrong checksum, a material index beyond the names) is an
/// InputError naming the file and the fix.
ParticleTable read_particle_table(const std::string& path);
BondTable read_bond_table(const std::string& path);

}  // namespace bpm
