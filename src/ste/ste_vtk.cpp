#include "ste/ste_vtk.hpp"

#include <fmt/core.h>

#include "io/atomic_file.hpp"
#include "io/vtk_polydata.hpp"

namespace bpm::ste {

std::string ste_polydata_vtp(const ParticleStore& p, const SteResult& r) {
  const std::size_t n = p.size();
  VtkPolyData d(p.position);
  VtkArrays& a = d.point_data();
  a.set_active("radius");
  auto scalar = [&](const std::string& name, auto&& get) {
    std::vector<double> v(n);
    for (std::size_t i = 0; i < n; ++i) v[i] = get(i);
    a.scalars(name, v);
  };
  auto integer = [&](const std::string& name, auto&& get) {
    std::vector<std::int32_t> v(n);
    for (std::size_t i = 0; i < n; ++i) v[i] = get(i);
    a.int32s(name, v);
  };
  a.scalars("radius", p.radius);
  // The user's ids: the points come in bpmkit's canonical order, not the file's.
  a.int64s("id", p.id);
  a.scalars("volume", r.particle_volume);
  integer("used", [&](std::size_t i) { return r.particle_use[i] == ParticleUse::used ? 1 : 0; });
  integer("use", [&](std::size_t i) { return static_cast<int>(r.particle_use[i]); });
  integer("coordination", [&](std::size_t i) { return r.coordination[i]; });
  static constexpr int kEntries[9][2] = {{0, 0}, {1, 1}, {2, 2}, {3, 3}, {4, 4},
                                         {5, 5}, {0, 1}, {0, 2}, {1, 2}};
  for (const auto& e : kEntries) {
    scalar(fmt::format("C{}{}", e[0] + 1, e[1] + 1),
           [&](std::size_t i) { return r.particle_stiffness[i](e[0], e[1]); });
  }
  if (r.local) {
    const LocalMap& m = *r.local;
    static constexpr const char* kAxes[3] = {"x", "y", "z"};
    for (int k = 0; k < 3; ++k)
      scalar(fmt::format("E_local_{}", kAxes[k]), [&](std::size_t i) { return m.modulus[i][k]; });
    for (int k = 0; k < 3; ++k)
      scalar(fmt::format("E_excess_{}", kAxes[k]), [&](std::size_t i) { return m.excess[i][k]; });
  }
  return d.vtp();
}

void write_ste_vtp(const std::string& path, const ParticleStore& particles,
                   const SteResult& result) {
  write_file_atomic(path, ste_polydata_vtp(particles, result));
}

}  // namespace bpm::ste
