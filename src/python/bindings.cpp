// _bpmkit: the compiled part of the Python module (python/bpmkit/__init__.py is the API users see).
// Scenarios, a Simulation that steps and observes, the particle and bond state as NumPy arrays, a
// scenario run with its outputs, and any bpmkit command run in this process (cli/application.hpp),
// so that Python gets the command's own numbers. bpm::InputError becomes bpmkit.InputError (a
// ValueError) with the same message.
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <string>
#include <vector>

#include "cli/application.hpp"
#include "core/error.hpp"
#include "dem/simulation.hpp"
#include "scenario/scenario.hpp"
#include "scenario/scenario_run.hpp"

namespace py = pybind11;

namespace bpm {
namespace {

/// An (n, 3) array copy of a Vec3 column. Copies, not views: a snapshot that an observer can keep
/// while the simulation steps on, and that outlives the scenario.
py::array_t<double> vectors(const std::vector<Vec3>& v) {
  py::array_t<double> a({static_cast<py::ssize_t>(v.size()), py::ssize_t{3}});
  auto m = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < v.size(); ++i) {
    const auto r = static_cast<py::ssize_t>(i);
    m(r, 0) = v[i].x;
    m(r, 1) = v[i].y;
    m(r, 2) = v[i].z;
  }
  return a;
}

template <typename T>
py::array_t<T> column(const std::vector<T>& v) {
  return py::array_t<T>(static_cast<py::ssize_t>(v.size()), v.data());
}

/// The particles' state: id, position, displacement, velocity, angular_velocity, force, torque,
/// radius, mass, material (index into particle_material_names); rows in the store's order.
py::dict particle_state(const ParticleStore& p) {
  std::vector<Vec3> displacement(p.size());
  for (std::size_t i = 0; i < p.size(); ++i)
    displacement[i] = p.position[i] - p.reference_position[i];
  py::dict d;
  d["id"] = column(p.id);
  d["position"] = vectors(p.position);
  d["displacement"] = vectors(displacement);
  d["velocity"] = vectors(p.velocity);
  d["angular_velocity"] = vectors(p.angular_velocity);
  d["force"] = vectors(p.force);
  d["torque"] = vectors(p.torque);
  d["radius"] = column(p.radius);
  d["mass"] = column(p.mass);
  d["material"] = column(p.material);
  return d;
}

/// The bonds' state: the particle ids of both ends, intact (0/1), the elastic force and moment on
/// alpha (global frame), r_b, L_b, k_n, k_s, k_tor, k_ben, material.
py::dict bond_state(const ParticleStore& p, const BondStore& b) {
  std::vector<std::int64_t> alpha(b.size()), beta(b.size());
  std::vector<double> k_n(b.size()), k_s(b.size()), k_tor(b.size()), k_ben(b.size());
  for (std::size_t k = 0; k < b.size(); ++k) {
    alpha[k] = p.id[static_cast<std::size_t>(b.alpha[k])];
    beta[k] = p.id[static_cast<std::size_t>(b.beta[k])];
    k_n[k] = b.stiffness[k].k_n;
    k_s[k] = b.stiffness[k].k_s;
    k_tor[k] = b.stiffness[k].k_tor;
    k_ben[k] = b.stiffness[k].k_ben;
  }
  std::vector<std::uint8_t> intact = b.intact;
  if (intact.size() != b.size()) intact.assign(b.size(), 1);
  py::dict d;
  d["alpha"] = column(alpha);
  d["beta"] = column(beta);
  d["intact"] = column(intact);
  d["force"] = vectors(b.force);
  d["moment"] = vectors(b.moment);
  d["radius"] = column(b.radius);
  d["length"] = column(b.rest_length);
  d["k_n"] = column(k_n);
  d["k_s"] = column(k_s);
  d["k_tor"] = column(k_tor);
  d["k_ben"] = column(k_ben);
  d["material"] = column(b.material);
  return d;
}

py::dict run_summary(const RunSummary& s) {
  py::dict d;
  d["reason"] = std::string(to_string(s.reason));
  d["steps"] = s.steps;
  d["time"] = s.time;
  d["wall_seconds"] = s.wall_seconds;
  d["max_speed"] = s.max_speed;
  return d;
}

/// A Simulation with the scenario it runs (the Simulation holds a reference to its model).
struct PySimulation {
  std::shared_ptr<Scenario> scenario;
  Simulation simulation;
  explicit PySimulation(std::shared_ptr<Scenario> s)
      : scenario(std::move(s)), simulation(scenario->model, scenario->time_step) {}
};

}  // namespace
}  // namespace bpm

PYBIND11_MODULE(_bpmkit, m) {
  using namespace bpm;
  m.doc() = "bpmkit's compiled core; use the package bpmkit";
  py::register_exception<InputError>(m, "InputError", PyExc_ValueError);
  py::register_exception<DivergenceError>(m, "DivergenceError", PyExc_RuntimeError);
  // CLI11's errors: a bad command line, and a command that failed by its exit status.
  static py::exception<CLI::ParseError> usage_error(m, "UsageError", PyExc_ValueError);
  static py::exception<CLI::RuntimeError> command_failed(m, "CommandFailed", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const CLI::RuntimeError& e) {
      PyErr_SetString(
          command_failed.ptr(),
          ("the command failed with exit status " + std::to_string(e.get_exit_code())).c_str());
    } catch (const CLI::ParseError& e) {
      PyErr_SetString(usage_error.ptr(), e.what());
    }
  });

  py::class_<Scenario, std::shared_ptr<Scenario>>(m, "Scenario",
                                                  "a loaded scenario (bpmkit.load_scenario)")
      .def_readonly("path", &Scenario::path)
      .def_readonly("description", &Scenario::description)
      .def_readonly("time_step", &Scenario::time_step, "s, the step a run uses")
      .def_readonly("particle_material_names", &Scenario::particle_material_names)
      .def_readonly("bond_material_names", &Scenario::bond_material_names)
      .def_property_readonly("is_compression_test",
                             [](const Scenario& s) { return s.compression.has_value(); })
      .def_property_readonly("particle_count",
                             [](const Scenario& s) { return s.model.particles.size(); })
      .def_property_readonly("bond_count", [](const Scenario& s) { return s.model.bonds.size(); })
      .def(
          "particles", [](const Scenario& s) { return particle_state(s.model.particles); },
          "the particles' state as NumPy arrays (copies)")
      .def(
          "bonds", [](const Scenario& s) { return bond_state(s.model.particles, s.model.bonds); },
          "the bonds' state as NumPy arrays (copies)");

  m.def("load_scenario",
        [](const std::string& path) { return std::make_shared<Scenario>(load_scenario(path)); });
  m.def("load_scenario_text", [](const std::string& text, const std::string& path) {
    return std::make_shared<Scenario>(load_scenario_text(text, path));
  });
  m.def(
      "run_scenario",
      [](Scenario& s, const std::string& out_dir) {
        py::gil_scoped_release unlocked;
        run_scenario(s, out_dir);
      },
      "what `bpmkit run` does: runs the scenario (its state advances) and writes its outputs into "
      "out_dir");
  m.def(
      "run_command",
      [](const std::vector<std::string>& args) {
        py::gil_scoped_release unlocked;
        cli::run_in_process(args);
      },
      "runs a bpmkit command line in this process, e.g. ['stiffness', '--method', 'dsm', 's.yaml', "
      "'--out', 'DIR']");

  py::class_<PySimulation>(m, "Simulation",
                           "the explicit DEM of a scenario (not its compression test)")
      .def(py::init<std::shared_ptr<Scenario>>(), py::arg("scenario"))
      .def(
          "step",
          [](PySimulation& s, std::int64_t n) {
            py::gil_scoped_release unlocked;
            for (std::int64_t k = 0; k < n; ++k) s.simulation.step();
          },
          py::arg("n") = 1, "advances n time steps")
      .def(
          "run",
          [](PySimulation& s, const std::function<void()>& observer, std::int64_t every) {
            std::function<void(const Simulation&)> observe;
            if (observer) {
              observe = [&](const Simulation&) {
                py::gil_scoped_acquire locked;
                observer();
              };
            }
            py::gil_scoped_release unlocked;
            return s.simulation.run(s.scenario->stop, observe, observer ? every : 0);
          },
          py::arg("observer") = nullptr, py::arg("every") = 1000,
          "runs to the scenario's stop criteria; calls observer() every `every` steps and at the "
          "end")
      .def_property_readonly("time", [](const PySimulation& s) { return s.simulation.time(); })
      .def_property_readonly("steps", [](const PySimulation& s) { return s.simulation.steps(); })
      .def_property_readonly("dt", [](const PySimulation& s) { return s.simulation.dt(); })
      .def_property_readonly("max_speed",
                             [](const PySimulation& s) { return s.simulation.max_speed(); })
      .def_property_readonly("scenario", [](const PySimulation& s) { return s.scenario; })
      .def("energies",
           [](const PySimulation& s) {
             const Energies e = s.simulation.energies();
             py::dict d;
             d["kinetic"] = e.kinetic;
             d["elastic"] = e.elastic;
             d["contact"] = e.contact;
             return d;
           })
      .def("particles",
           [](const PySimulation& s) { return particle_state(s.simulation.model().particles); })
      .def("bonds", [](const PySimulation& s) {
        return bond_state(s.simulation.model().particles, s.simulation.model().bonds);
      });
  py::class_<RunSummary>(m, "RunSummary")
      .def_property_readonly("reason",
                             [](const RunSummary& s) { return std::string(to_string(s.reason)); })
      .def_readonly("steps", &RunSummary::steps)
      .def_readonly("time", &RunSummary::time)
      .def_readonly("wall_seconds", &RunSummary::wall_seconds)
      .def_readonly("max_speed", &RunSummary::max_speed)
      .def("as_dict", [](const RunSummary& s) { return run_summary(s); });
}
