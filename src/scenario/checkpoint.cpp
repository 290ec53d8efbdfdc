#include "scenario/checkpoint.hpp"

#include <fmt/core.h>

#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string_view>

#include "core/error.hpp"
#include "io/byte_codec.hpp"
#include "io/output_folder.hpp"

namespace bpm {
namespace {

constexpr std::string_view kMagic = "BPMKCKPT";

void put_vec3(ByteWriter& w, const Vec3& v) {
  w.vec3(v);
}
void put_f64(ByteWriter& w, double v) {
  w.f64(v);
}
void put_i32(ByteWriter& w, std::int32_t v) {
  w.i32(v);
}
void put_u8(ByteWriter& w, std::uint8_t v) {
  w.u8(v);
}
Vec3 get_vec3(ByteReader& r) {
  return r.vec3();
}
double get_f64(ByteReader& r) {
  return r.f64();
}
std::int32_t get_i32(ByteReader& r) {
  return r.i32();
}
std::uint8_t get_u8(ByteReader& r) {
  return r.u8();
}

/// A restored array must have the size the model gives it.
template <class T>
void assign_sized(std::vector<T>& target, std::vector<T> source, std::size_t size,
                  const char* what) {
  if (source.size() != size) {
    throw std::out_of_range(
        fmt::format("{} has {} entries, the model {}", what, source.size(), size));
  }
  target = std::move(source);
}

void hash_doubles(std::uint64_t& h, const std::vector<double>& v) {
  ByteWriter w;
  w.list(v, put_f64);
  h = fnv1a64(w.bytes(), h);
}
void hash_vec3s(std::uint64_t& h, const std::vector<Vec3>& v) {
  ByteWriter w;
  w.list(v, put_vec3);
  h = fnv1a64(w.bytes(), h);
}
void hash_ints(std::uint64_t& h, const std::vector<std::int32_t>& v) {
  ByteWriter w;
  w.list(v, put_i32);
  h = fnv1a64(w.bytes(), h);
}

void write_compression(ByteWriter& w, const CompressionProgress& c) {
  w.list(c.curve, [](ByteWriter& out, const CompressionPoint& pt) {
    for (const double v :
         {pt.time, pt.displacement, pt.strain, pt.force, pt.force_top, pt.force_bottom, pt.kinetic,
          pt.elastic, pt.gauge.axial, pt.gauge.lateral}) {
      out.f64(v);
    }
    out.u64(pt.bonds_broken);
    out.u64(pt.bonds_broken_tension);
  });
  w.f64(c.peak_stress);
  w.f64(c.peak_strain);
}

CompressionProgress read_compression(ByteReader& r) {
  CompressionProgress c;
  c.curve = r.list<CompressionPoint>(96, [](ByteReader& in) {
    CompressionPoint pt;
    for (double* v :
         {&pt.time, &pt.displacement, &pt.strain, &pt.force, &pt.force_top, &pt.force_bottom,
          &pt.kinetic, &pt.elastic, &pt.gauge.axial, &pt.gauge.lateral}) {
      *v = in.f64();
    }
    pt.bonds_broken = in.u64();
    pt.bonds_broken_tension = in.u64();
    return pt;
  });
  c.peak_stress = r.f64();
  c.peak_strain = r.f64();
  return c;
}

void write_payload(ByteWriter& w, const Model& model, const Simulation& sim,
                   const OutputProgress& outputs) {
  w.f64(sim.time());
  w.i64(sim.steps());
  w.f64(sim.max_speed());

  const ParticleStore& p = model.particles;
  w.list(p.position, put_vec3);
  w.list(p.velocity, put_vec3);
  w.list(p.angular_velocity, put_vec3);
  w.list(p.orientation, [](ByteWriter& out, const Quat& q) { out.quat(q); });
  w.list(p.force, put_vec3);
  w.list(p.torque, put_vec3);

  const BondStore& b = model.bonds;
  w.list(b.intact, put_u8);
  w.list(b.break_mode, put_u8);
  for (const auto* field : {&b.force, &b.moment, &b.axis, &b.end_force_alpha, &b.end_moment_alpha,
                            &b.end_moment_beta}) {
    w.list(*field, put_vec3);
  }
  w.i64(b.updates);
  w.list(b.breaks, [](ByteWriter& out, const BondStore::Break& e) {
    out.i32(e.bond);
    out.i64(e.update);
    out.u8(static_cast<std::uint8_t>(e.mode));
    out.vec3(e.position);
  });

  w.list(model.walls, [](ByteWriter& out, const Wall& wall) {
    out.vec3(wall.point);
    out.vec3(wall.velocity);
    out.vec3(wall.displacement);
    out.vec3(wall.force);
    out.list(wall.spring, put_vec3);
  });

  w.u8(sim.contacts_on() ? 1 : 0);
  if (sim.contacts_on()) {
    const ContactForces::History h = sim.contacts().history();
    w.list(h.list.row_start, put_i32);
    w.list(h.list.first, put_i32);
    w.list(h.list.second, put_i32);
    w.list(h.list.position_at_build, put_vec3);
    w.f64(h.list.skin);
    w.i64(h.list.builds);
    for (const auto* field : {&h.spring, &h.force_i, &h.torque_i, &h.torque_j})
      w.list(*field, put_vec3);
    w.list(h.normal_force, put_f64);
    w.list(h.overlap, put_f64);
  }

  w.i64(outputs.last_output_step);
  w.u64(outputs.output_times);
  w.list(outputs.frame_times, put_f64);
  w.u64(outputs.breaks_written);
  w.list(outputs.table_bytes, [](ByteWriter& out, const std::pair<std::string, std::uint64_t>& t) {
    out.text(t.first);
    out.u64(t.second);
  });
}

OutputProgress read_payload(ByteReader& r, Model& model, Simulation& sim) {
  const double time = r.f64();
  const std::int64_t steps = r.i64();
  const double max_speed = r.f64();

  ParticleStore& p = model.particles;
  const std::size_t n = p.size();
  assign_sized(p.position, r.list<Vec3>(24, get_vec3), n, "position");
  assign_sized(p.velocity, r.list<Vec3>(24, get_vec3), n, "velocity");
  assign_sized(p.angular_velocity, r.list<Vec3>(24, get_vec3), n, "angular_velocity");
  assign_sized(p.orientation, r.list<Quat>(32, [](ByteReader& in) { return in.quat(); }), n,
               "orientation");
  assign_sized(p.force, r.list<Vec3>(24, get_vec3), n, "force");
  assign_sized(p.torque, r.list<Vec3>(24, get_vec3), n, "torque");

  BondStore& b = model.bonds;
  const std::size_t m = b.size();
  assign_sized(b.intact, r.list<std::uint8_t>(1, get_u8), m, "bond intact");
  assign_sized(b.break_mode, r.list<std::uint8_t>(1, get_u8), m, "bond break_mode");
  for (auto* field : {&b.force, &b.moment, &b.axis, &b.end_force_alpha, &b.end_moment_alpha,
                      &b.end_moment_beta}) {
    assign_sized(*field, r.list<Vec3>(24, get_vec3), m, "bond load");
  }
  b.updates = r.i64();
  b.breaks = r.list<BondStore::Break>(37, [m](ByteReader& in) {
    BondStore::Break e{};
    e.bond = in.i32();
    e.update = in.i64();
    e.mode = static_cast<BreakMode>(in.u8());
    e.position = in.vec3();
    if (e.bond < 0 || static_cast<std::size_t>(e.bond) >= m)
      throw std::out_of_range("a break names no bond");
    return e;
  });

  const std::uint64_t walls = r.u64();
  if (walls != model.walls.size()) throw std::out_of_range("the wall count differs");
  for (Wall& wall : model.walls) {
    wall.point = r.vec3();
    wall.velocity = r.vec3();
    wall.displacement = r.vec3();
    wall.force = r.vec3();
    assign_sized(wall.spring, r.list<Vec3>(24, get_vec3), n, "wall spring");
  }

  ContactForces::History h;
  const bool contacts = r.u8() != 0;
  if (contacts != sim.contacts_on())
    throw std::out_of_range("contacts are on in one and off in the other");
  if (contacts) {
    h.list.row_start = r.list<std::int32_t>(4, get_i32);
    h.list.first = r.list<std::int32_t>(4, get_i32);
    h.list.second = r.list<std::int32_t>(4, get_i32);
    h.list.position_at_build = r.list<Vec3>(24, get_vec3);
    h.list.skin = r.f64();
    h.list.builds = r.i64();
    for (auto* field : {&h.spring, &h.force_i, &h.torque_i, &h.torque_j})
      *field = r.list<Vec3>(24, get_vec3);
    h.normal_force = r.list<double>(8, get_f64);
    h.overlap = r.list<double>(8, get_f64);
    // The list must index this model's particles before anything reads through it.
    const std::size_t pairs = h.list.second.size();
    bool valid = h.list.row_start.size() == n + 1 && h.list.first.size() == pairs &&
                 h.spring.size() == pairs && h.force_i.size() == pairs &&
                 h.torque_i.size() == pairs && h.torque_j.size() == pairs &&
                 h.normal_force.size() == pairs && h.overlap.size() == pairs &&
                 h.list.position_at_build.size() == n;
    for (std::size_t k = 0; valid && k < pairs; ++k) {
      valid = h.list.first[k] >= 0 && h.list.second[k] >= 0 &&
              static_cast<std::size_t>(h.list.first[k]) < n &&
              static_cast<std::size_t>(h.list.second[k]) < n;
    }
    for (std::size_t i = 0; valid && i < n; ++i) {
      valid = h.list.row_start[i] >= 0 && h.list.row_start[i] <= h.list.row_start[i + 1];
    }
    if (!valid || (n > 0 && static_cast<std::size_t>(h.list.row_start[n]) != pairs)) {
      throw std::out_of_range("the contact list does not fit the model");
    }
  }
  sim.restore(time, steps, max_speed, std::move(h));

  OutputProgress o;
  o.last_output_step = r.i64();
  o.output_times = r.u64();
  o.frame_times = r.list<double>(8, get_f64);
  o.breaks_written = r.u64();
  o.table_bytes = r.list<std::pair<std::string, std::uint64_t>>(16, [](ByteReader& in) {
    std::string name = in.text();
    return std::pair<std::string, std::uint64_t>(std::move(name), in.u64());
  });
  if (o.breaks_written > b.breaks.size())
    throw std::out_of_range("more breaks written than logged");
  return o;
}

}  // namespace

std::uint64_t scenario_file_hash(const Scenario& scenario) {
  std::ifstream in(scenario.path, std::ios::binary);
  const std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return fnv1a64(content);
}

std::uint64_t model_hash(const Scenario& scenario, double dt) {
  const Model& model = scenario.model;
  const ParticleStore& p = model.particles;
  const BondStore& b = model.bonds;
  ByteWriter w;
  w.f64(dt);
  w.list(p.id, [](ByteWriter& out, std::int64_t id) { out.i64(id); });
  for (const auto* field : {&p.radius, &p.mass, &p.inertia}) w.list(*field, put_f64);
  w.list(p.material, put_i32);
  for (const auto* field : {&p.reference_position, &p.translation_free, &p.rotation_free})
    w.list(*field, put_vec3);
  std::uint64_t h = fnv1a64(w.bytes());
  hash_ints(h, b.alpha);
  hash_ints(h, b.beta);
  // The rows name the bonds in bond_breaks.csv: a reordered bond file is another run's file.
  hash_ints(h, b.input_row);
  hash_ints(h, b.material);
  for (const auto* field :
       {&b.arm_offset, &b.radius, &b.rest_length, &b.damping_force, &b.damping_moment}) {
    hash_doubles(h, *field);
  }
  std::vector<double> constants;
  for (std::size_t i = 0; i < b.size(); ++i) {
    const BondStiffness& k = b.stiffness[i];
    constants.insert(constants.end(), {k.k_n, k.k_s, k.k_tor, k.k_ben});
    if (i < b.strength.size())
      constants.insert(constants.end(), {b.strength[i].tensile, b.strength[i].shear});
  }
  hash_doubles(h, constants);
  std::vector<Vec3> wall_geometry;
  for (const Wall& wall : model.walls) {
    h = fnv1a64(wall.name, h);
    wall_geometry.insert(wall_geometry.end(), {wall.normal, wall.edge});
  }
  hash_vec3s(h, wall_geometry);
  return h;
}

CheckpointIdentity checkpoint_identity(const Scenario& scenario, double dt) {
  return {scenario_file_hash(scenario), model_hash(scenario, dt)};
}

std::string checkpoint_bytes(const CheckpointIdentity& identity, const Simulation& sim,
                             CheckpointKind kind, const OutputProgress& outputs,
                             const CompressionProgress* compression) {
  ByteWriter payload;
  write_payload(payload, sim.model(), sim, outputs);
  if (compression != nullptr) write_compression(payload, *compression);
  ByteWriter w;
  for (const char c : kMagic) w.u8(static_cast<std::uint8_t>(c));
  w.u32(kCheckpointFormat);
  w.text(bpmkit_version());
  w.u64(identity.scenario_file);
  w.u64(identity.model);
  w.u8(static_cast<std::uint8_t>(kind));
  w.u8(compression != nullptr ? 1 : 0);
  w.i64(sim.steps());
  w.f64(sim.time());
  w.u64(payload.bytes().size());
  w.u64(fnv1a64(payload.bytes()));
  return w.take() + payload.bytes();
}

namespace {

constexpr const char* kFresh =
    "run the scenario from the start instead: without --resume, with --overwrite";

/// A checkpoint continues only the kind of run that wrote it: a compression test's holds its
/// curve, and its model has the platens and the scaled masses.
void check_run_kind(const std::string& path, const Scenario& scenario, std::uint8_t test) {
  if (test > 1) throw InputError(path, "is damaged (unknown kind of run)", kFresh);
  const bool written_by_test = test == 1;
  if (written_by_test == scenario.compression.has_value()) return;
  const std::string writer = written_by_test ? "a compression test" : "a plain run";
  const std::string reader = scenario.compression
                                 ? "a compression test (it has a compression section)"
                                 : "a plain run (it has no compression section)";
  throw InputError(
      path, "was written by " + writer + ", but " + scenario.path + " is " + reader,
      "resume with the scenario file the run started with, unchanged; or " + std::string(kFresh));
}

/// The file's bytes, after checking everything but the payload's fit to the model; `payload_at`
/// is set to where the payload starts.
std::string read_checked(const std::string& path, const Scenario& scenario,
                         const CheckpointIdentity& identity, std::size_t& payload_at) {
  const std::string fresh = kFresh;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw InputError(
        path, "no checkpoint to resume from",
        "a run writes one every output.checkpoint_every and when stopped by Ctrl-C or SIGTERM; " +
            fresh);
  }
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ByteReader r(bytes);
  try {
    std::string magic;
    for (std::size_t i = 0; i < kMagic.size(); ++i) magic += static_cast<char>(r.u8());
    if (magic != kMagic) throw InputError(path, "is not a bpmkit checkpoint", fresh);
    const std::uint32_t format = r.u32();
    const std::string version = r.text();
    if (format != kCheckpointFormat || version != bpmkit_version()) {
      throw InputError(
          path,
          fmt::format(
              "was written by bpmkit {} (checkpoint format {}); this is bpmkit {} (format {}), "
              "which may not continue it bit for bit",
              version, format, bpmkit_version(), kCheckpointFormat),
          "resume it with bpmkit " + version + ", or " + fresh);
    }
    const std::uint64_t scenario_hash = r.u64(), hash = r.u64();
    const auto kind = static_cast<CheckpointKind>(r.u8());
    const std::uint8_t test = r.u8();
    const std::int64_t steps = r.i64();
    const double time = r.f64();
    const std::uint64_t size = r.u64(), checksum = r.u64();
    payload_at = bytes.size() - r.left();
    if (size != r.left() || fnv1a64(std::string_view(bytes).substr(payload_at)) != checksum) {
      throw InputError(path, "is damaged (its checksum does not match: cut short or altered)",
                       fresh);
    }
    check_run_kind(path, scenario, test);
    if (scenario_hash != identity.scenario_file) {
      throw InputError(
          path,
          "was written for another scenario: " + scenario.path +
              " differs from the file that run read",
          "resume with the scenario file the run started with, unchanged; or " + fresh);
    }
    if (hash != identity.model) {
      throw InputError(
          path,
          "was written for another model: the particles, bonds, walls or time step that " +
              scenario.path +
              " gives now differ from that run's (a particle or bond file changed?)",
          "resume with the input files the run started with; or " + fresh);
    }
    if (kind == CheckpointKind::diverged) {
      throw InputError(
          path,
          fmt::format("holds the state of a run that diverged at step {} (t = {:.6g} s), kept for "
                      "inspection; resuming it would diverge again",
                      steps, time),
          "change the scenario (integrator.time_step, loads) and " + fresh);
    }
    if (kind != CheckpointKind::periodic && kind != CheckpointKind::interrupted) {
      throw InputError(path, "is damaged (unknown kind)", fresh);
    }
  } catch (const std::out_of_range& e) {
    throw InputError(path, std::string("is damaged: ") + e.what(), fresh);
  }
  return bytes;
}

}  // namespace

void check_checkpoint(const std::string& path, const Scenario& scenario) {
  std::size_t payload_at = 0;
  read_checked(path, scenario, checkpoint_identity(scenario, scenario.time_step), payload_at);
}

OutputProgress restore_checkpoint(const std::string& path, const CheckpointIdentity& identity,
                                  Scenario& scenario, Simulation& sim,
                                  CompressionProgress* compression) {
  std::size_t payload_at = 0;
  const std::string bytes = read_checked(path, scenario, identity, payload_at);
  try {
    ByteReader payload(std::string_view(bytes).substr(payload_at));
    OutputProgress o = read_payload(payload, scenario.model, sim);
    // read_checked made sure that the section is there exactly for a compression test.
    if (scenario.compression) {
      CompressionProgress progress = read_compression(payload);
      if (compression != nullptr) *compression = std::move(progress);
    }
    if (payload.left() != 0) throw std::out_of_range("bytes left after the payload");
    return o;
  } catch (const std::out_of_range& e) {
    throw InputError(path, std::string("is damaged or does not fit this model: ") + e.what(),
                     kFresh);
  }
}

}  // namespace bpm
