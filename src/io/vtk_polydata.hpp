#pragma once
/// The one VTK XML PolyData (.vtp) writer of bpmkit: the DEM frames and their walls
/// (io/vtk_writer.hpp, io/vtk_walls.hpp), the STE stiffness map (ste/ste_vtk.hpp) and generate's
/// structure.vtp build a VtkPolyData and serialise it here.
///
/// By default the arrays are binary appended data, zlib-compressed (VTK XML `format="appended"`,
/// raw encoding, vtkZLibDataCompressor, header_type UInt64; io/vtk_zlib.hpp): a DEM frame of 1e5
/// particles is a third of the old ASCII file's size and written 1.6x faster (BENCHMARKS.md, "VTK
/// frames"). VtkEncoding::ascii writes the same file as text (shortest round-trip numbers) for
/// comparisons and debugging.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/vec3.hpp"

namespace bpm {

enum class VtkEncoding { zlib, ascii };

struct VtkArray {
  enum class Type { float64, int32, int64, string };
  std::string name;
  Type type = Type::float64;
  int components = 1;
  std::size_t tuples = 0;
  std::string bytes;  ///< the values, little-endian (strings: each followed by '\0')
};

/// The arrays of one section (point data, cell data or field data), in the order added.
class VtkArrays {
 public:
  void scalars(std::string name, std::span<const double> values);
  void vectors(std::string name, std::span<const Vec3> values);
  void int32s(std::string name, std::span<const std::int32_t> values);
  void int64s(std::string name, std::span<const std::int64_t> values);
  /// A string array (VTK type "String"), e.g. the names that an index array refers to.
  void strings(std::string name, const std::vector<std::string>& values);
  /// The arrays ParaView colours and glyphs by first (attributes Scalars=, Vectors=).
  void set_active(std::string scalars, std::string vectors = {});

  const std::vector<VtkArray>& arrays() const { return arrays_; }
  const std::string& active_scalars() const { return scalars_; }
  const std::string& active_vectors() const { return vectors_; }

 private:
  std::vector<VtkArray> arrays_;
  std::string scalars_, vectors_;
};

/// Points, line and polygon cells, and their data. Cell data lists the lines first, then the
/// polygons (VTK's order).
class VtkPolyData {
 public:
  explicit VtkPolyData(std::span<const Vec3> points);

  /// Two-point lines: alpha[k] to beta[k] (point indices).
  void lines(std::span<const std::int32_t> alpha, std::span<const std::int32_t> beta);
  /// One polygon: its point indices in order.
  void polygon(std::span<const std::int64_t> points);

  VtkArrays& point_data() { return point_data_; }
  VtkArrays& cell_data() { return cell_data_; }
  VtkArrays& field_data() { return field_data_; }

  std::size_t points() const { return points_.tuples; }
  std::size_t line_count() const { return line_offsets_.size(); }
  std::size_t polygon_count() const { return poly_offsets_.size(); }

  /// The .vtp file. `level`: zlib level for VtkEncoding::zlib (1 fastest .. 9 smallest).
  std::string vtp(VtkEncoding encoding = VtkEncoding::zlib, int level = 1) const;

 private:
  VtkArray points_;
  std::vector<std::int64_t> line_connectivity_, line_offsets_, poly_connectivity_, poly_offsets_;
  VtkArrays point_data_, cell_data_, field_data_;
};

}  // namespace bpm
