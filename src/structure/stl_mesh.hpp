#pragma once
/// A triangulated surface read from an STL file (ASCII or binary; detected from the content, not
/// the extension). Vertices with identical coordinates are merged, so triangles share vertex
/// indices and edges can be matched (needed to check that the surface is closed).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/vec3.hpp"

namespace bpm {

struct TriangleMesh {
  std::vector<Vec3> vertices;                        ///< m (after scaling)
  std::vector<std::array<std::int32_t, 3>> triangles;  ///< vertex indices, as ordered in the file
};

/// Reads `path`, multiplying every coordinate by `scale` (e.g. 1e-3 for a file in mm). Throws
/// InputError naming the file if it cannot be read, is truncated, or holds no triangles;
/// `referenced_from` (e.g. "spec.yaml:4: container.stl.file") is named when the file is missing.
TriangleMesh read_stl(const std::string& path, double scale = 1.0, const std::string& referenced_from = "");

}  // namespace bpm
