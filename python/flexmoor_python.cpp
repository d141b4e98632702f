// The Python module `flexmoor` (pybind11) over the C interface (apps/capi/flexmoor.h): one life
// cycle for C hosts and Python alike. Arrays are NumPy arrays; a case is a path, a named case or
// a dict (written out as YAML); errors are exceptions carrying the C interface's message
// (FILE:LINE for a case's errors).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <yaml-cpp/yaml.h>

#include <memory>
#include <string>
#include <vector>

#include "apps/capi/flexmoor.h"

namespace py = pybind11;

namespace {

// flexmoor.Error and its kinds, made in the module's init.
PyObject* error_base = nullptr;
PyObject* case_error = nullptr;
PyObject* convergence_error = nullptr;
PyObject* call_error = nullptr;

// Raises the exception of a code, with the handle's message.
void check(flexmoor_t h, int code) {
  if (code == FLEXMOOR_OK) return;
  const std::string message = flexmoor_last_error(h);
  PyObject* kind = code == FLEXMOOR_BAD_INPUT       ? case_error
                   : code == FLEXMOOR_NOT_CONVERGED ? convergence_error
                   : code == FLEXMOOR_BAD_CALL      ? call_error
                                                    : error_base;
  PyErr_SetString(kind, message.c_str());
  throw py::error_already_set();
}

// A Python value (dict, list, str, number, bool) as YAML.
YAML::Node toYaml(const py::handle& value) {
  if (py::isinstance<py::dict>(value)) {
    YAML::Node map(YAML::NodeType::Map);
    for (const auto& [k, v] : py::reinterpret_borrow<py::dict>(value))
      map[py::str(k).cast<std::string>()] = toYaml(v);
    return map;
  }
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    YAML::Node list(YAML::NodeType::Sequence);
    for (const auto& v : value) list.push_back(toYaml(v));
    return list;
  }
  if (py::isinstance<py::bool_>(value)) return YAML::Node(value.cast<bool>() ? "true" : "false");
  if (value.is_none()) return YAML::Node(YAML::NodeType::Null);
  return YAML::Node(py::str(value).cast<std::string>());
}

std::vector<double> values(const py::object& array, int count, const char* what) {
  if (array.is_none()) {
    if (count == 0) return {};
    throw py::value_error(std::string(what) + ": None for " + std::to_string(count) +
                          " coupled dofs");
  }
  const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
  if (!a || a.ndim() != 1 || a.shape(0) != count)
    throw py::value_error(std::string(what) + ": expected " + std::to_string(count) +
                          " values in one dimension");
  return std::vector<double>(a.data(), a.data() + count);
}

std::string fspath(const py::object& path) {
  return py::str(py::module_::import("os").attr("fspath")(path));
}

class Checkpoint {
 public:
  explicit Checkpoint(flexmoor_checkpoint_t c) : c_(c, flexmoor_checkpoint_free) {}
  flexmoor_checkpoint_t get() const { return c_.get(); }

 private:
  std::shared_ptr<flexmoor_checkpoint> c_;
};

class Simulation {
 public:
  explicit Simulation(const py::object& source) {
    flexmoor_t h = nullptr;
    int code;
    if (py::isinstance<py::dict>(source)) {
      YAML::Emitter out;
      out << toYaml(source);
      const py::dict d = source;
      const std::string name = d.contains("name") ? py::str(d["name"]).cast<std::string>() : "case";
      code = flexmoor_create_from_yaml(out.c_str(), (name + ".yaml").c_str(), &h);
    } else {
      code = flexmoor_create(fspath(source).c_str(), &h);
    }
    h_.reset(h, flexmoor_close);
    check(h, code);
  }

  void couple(const std::string& name) { check(h(), flexmoor_couple(h(), name.c_str())); }
  void output(const py::object& directory) {
    check(h(), flexmoor_set_output(h(), fspath(directory).c_str()));
  }
  int coupledDofs() const {
    int n = 0;
    check(h(), flexmoor_coupled_dofs(h(), &n));
    return n;
  }
  void init(const py::object& x, const py::object& xd) {
    const int n = coupledDofs();
    const std::vector<double> px = values(x, n, "x"), pv = values(xd, n, "xd");
    check(h(), flexmoor_init(h(), n, n ? px.data() : nullptr, n ? pv.data() : nullptr));
  }
  py::array_t<double> step(const py::object& x, const py::object& xd, double dt,
                           const py::object& xdd) {
    const int n = coupledDofs();
    const std::vector<double> px = values(x, n, "x"), pv = values(xd, n, "xd");
    const std::vector<double> pa = xdd.is_none() ? std::vector<double>() : values(xdd, n, "xdd");
    py::array_t<double> f(n);
    double t = time();
    check(h(),
          flexmoor_step(h(), n, n ? px.data() : nullptr, n ? pv.data() : nullptr,
                        pa.empty() ? nullptr : pa.data(), n ? f.mutable_data() : nullptr, &t, dt));
    return f;
  }
  double time() const {
    double t = 0.0;
    check(h(), flexmoor_time(h(), &t));
    return t;
  }
  py::array_t<double> loads() const {
    py::array_t<double> f(coupledDofs());
    check(h(), flexmoor_coupled_loads(h(), f.mutable_data()));
    return f;
  }
  std::vector<std::string> lines() const {
    int n = 0;
    check(h(), flexmoor_line_count(h(), &n));
    std::vector<std::string> names;
    for (int k = 0; k < n; ++k) {
      const char* name = nullptr;
      check(h(), flexmoor_line_name(h(), k, &name));
      names.emplace_back(name);
    }
    return names;
  }
  // The line's nodes' positions (order 0) or velocities (1), (nodes, 3).
  py::array_t<double> lineNodes(const py::object& line, int order) const {
    const int l = lineIndex(line);
    int n = 0;
    check(h(), flexmoor_line_node_count(h(), l, &n));
    py::array_t<double> out({n, 3});
    for (int k = 0; k < n; ++k)
      check(h(), order == 0 ? flexmoor_line_node_position(h(), l, k, out.mutable_data(k, 0))
                            : flexmoor_line_node_velocity(h(), l, k, out.mutable_data(k, 0)));
    return out;
  }
  double endTension(const py::object& line, const std::string& end) const {
    if (end != "start" && end != "end")
      throw py::value_error("end: '" + end + "' (expected 'start' or 'end')");
    double tension = 0.0;
    check(h(), flexmoor_line_end_tension(h(), lineIndex(line), end == "end" ? 1 : 0, &tension));
    return tension;
  }
  py::array_t<double> nodePositions() const {
    int n = 0;
    check(h(), flexmoor_node_count(h(), &n));
    py::array_t<double> out({n, 3});
    check(h(), flexmoor_node_positions(h(), out.mutable_data()));
    return out;
  }
  Checkpoint save() {
    flexmoor_checkpoint_t c = nullptr;
    check(h(), flexmoor_save(h(), &c));
    return Checkpoint(c);
  }
  void restore(const Checkpoint& c) { check(h(), flexmoor_restore(h(), c.get())); }
  void saveFile(const py::object& path) {
    check(h(), flexmoor_save_file(h(), fspath(path).c_str()));
  }
  void restoreFile(const py::object& path) {
    check(h(), flexmoor_restore_file(h(), fspath(path).c_str()));
  }
  py::dict finish() {
    check(h(), flexmoor_finish(h()));
    return summary();
  }
  py::dict run() {
    check(h(), flexmoor_run(h()));
    return summary();
  }

 private:
  flexmoor_t h() const { return h_.get(); }
  py::dict summary() const {
    int n = 0;
    check(h(), flexmoor_summary_count(h(), &n));
    py::dict out;
    for (int k = 0; k < n; ++k) {
      const char* name = nullptr;
      double value = 0.0;
      check(h(), flexmoor_summary_value(h(), k, &name, &value));
      out[name] = value;
    }
    return out;
  }
  int lineIndex(const py::object& line) const {
    if (py::isinstance<py::int_>(line)) return line.cast<int>();
    const std::string name = py::str(line);
    const std::vector<std::string> names = lines();
    for (size_t k = 0; k < names.size(); ++k)
      if (names[k] == name) return static_cast<int>(k);
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
    throw py::key_error("no line '" + name + "' (the case's lines: " + list + ")");
  }
  std::shared_ptr<flexmoor_simulation> h_;
};

}  // namespace

PYBIND11_MODULE(flexmoor, m) {
  m.doc() =
      "flexmoor: nonlinear finite-element mooring lines and cables, run or stepped by a host.\n\n"
      "Simulation(case) reads a case (a path, a named case or a dict of the YAML case format);\n"
      "run() runs it as `flexmoor run` does; or couple(name), init(x, xd), step(x, xd, dt) ...,\n"
      "finish() step it with the host's motions (docs/library.md states the semantics).";
  m.attr("__version__") = flexmoor_version();
  static py::exception<std::runtime_error> base(m, "Error");
  static py::exception<std::runtime_error> cases(m, "CaseError", base.ptr());
  static py::exception<std::runtime_error> convergence(m, "ConvergenceError", base.ptr());
  static py::exception<std::runtime_error> calls(m, "CallError", base.ptr());
  error_base = base.ptr();
  case_error = cases.ptr();
  convergence_error = convergence.ptr();
  call_error = calls.ptr();

  py::class_<Checkpoint>(m, "Checkpoint",
                         "Everything a simulation needs to go on from where save() was called.");
  py::class_<Simulation>(m, "Simulation")
      .def(py::init<const py::object&>(), py::arg("case"),
           "Reads and checks a case: a path, a named case ('oc4-semi-surge') or a dict.")
      .def("couple", &Simulation::couple, py::arg("name"),
           "The host drives this rigid body (six dofs: surge, sway, heave, roll, pitch, yaw) or "
           "point (a line's end, 'LINE.fairlead': three dofs, its position x, y, z).")
      .def("output", &Simulation::output, py::arg("directory"),
           "Write the results files into this directory (at finish or run).")
      .def_property_readonly("coupled_dofs", &Simulation::coupledDofs)
      .def("init", &Simulation::init, py::arg("x") = py::none(), py::arg("xd") = py::none(),
           "Statics with the coupled dofs at x, xd; starts the dynamic step.")
      .def("step", &Simulation::step, py::arg("x"), py::arg("xd"), py::arg("dt"),
           py::arg("xdd") = py::none(),
           "Advances by dt with the coupled dofs at x, xd (xdd) at the step's end; returns the "
           "loads on the coupled bodies there.")
      .def_property_readonly("time", &Simulation::time)
      .def_property_readonly("loads", &Simulation::loads)
      .def_property_readonly("lines", &Simulation::lines)
      .def(
          "line_positions",
          [](const Simulation& s, const py::object& line) { return s.lineNodes(line, 0); },
          py::arg("line"), "The line's node positions now, (nodes, 3).")
      .def(
          "line_velocities",
          [](const Simulation& s, const py::object& line) { return s.lineNodes(line, 1); },
          py::arg("line"), "The line's node velocities now, (nodes, 3).")
      .def("end_tension", &Simulation::endTension, py::arg("line"), py::arg("end") = "end",
           "The tension at the line's 'start' or 'end' now.")
      .def("node_positions", &Simulation::nodePositions, "Every node's position, (nodes, 3).")
      .def("save", &Simulation::save)
      .def("restore", &Simulation::restore, py::arg("checkpoint"))
      .def("save_file", &Simulation::saveFile, py::arg("path"),
           "A checkpoint in a file, for a simulation of the same case to go on from.")
      .def("restore_file", &Simulation::restoreFile, py::arg("path"))
      .def("finish", &Simulation::finish,
           "Closes the run, writes the results files; returns the summary.")
      .def("run", &Simulation::run,
           "Runs the whole case as `flexmoor run` does; returns the summary.");
}
