// isosid._isosid: the library's run pipeline (run::run_scene) for the Python package isosid/.
// Errors become isosid.InputError (the command line's exit 2) and isosid.ComputationError
// (exit 1) with the command line's one-line message; Ctrl-C stops a run at its next step with
// the results so far written, then raises KeyboardInterrupt.
#include "isosid/common/toml_override.hpp"
#include "isosid/common/version.hpp"
#include "isosid/format/error.hpp"
#include "output/run_folder.hpp"
#include "pipeline/run_scene.hpp"

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;
using namespace isosid;

namespace {

/// Python runs its signal handlers only when it holds the interpreter: the run, which does
/// not, lets it do so at most every 50 ms and stops once a handler raised (Ctrl-C:
/// KeyboardInterrupt), keeping that exception to raise after the results are written.
class PythonSignals {
public:
  PythonSignals() = default;
  PythonSignals(const PythonSignals&) = delete;
  PythonSignals& operator=(const PythonSignals&) = delete;
  ~PythonSignals() {  // destroyed with the interpreter held (after the run's release of it)
    Py_XDECREF(type_);
    Py_XDECREF(value_);
    Py_XDECREF(trace_);
  }
  bool stop_requested() {
    if (raised_) return true;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_check_ < std::chrono::milliseconds(50)) return false;
    last_check_ = now;
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) {
      PyErr_Fetch(&type_, &value_, &trace_);
      raised_ = true;
    }
    return raised_;
  }
  /// With the interpreter held: raises what a signal handler raised during the run, if anything.
  void raise_pending() {
    if (!raised_) return;
    raised_ = false;
    PyErr_Restore(std::exchange(type_, nullptr), std::exchange(value_, nullptr), std::exchange(trace_, nullptr));
    throw py::error_already_set();
  }

private:
  bool raised_ = false;
  PyObject *type_ = nullptr, *value_ = nullptr, *trace_ = nullptr;
  std::chrono::steady_clock::time_point last_check_ = std::chrono::steady_clock::now();
};

using Settings = std::vector<std::pair<std::string, std::string>>;

/// `settings` (dotted key, TOML value text) as overrides.
std::vector<common::TomlOverride> overrides_of(const Settings& settings) {
  std::vector<common::TomlOverride> overrides;
  for (const auto& [key, value] : settings) overrides.push_back({key, value});
  return overrides;
}

/// Runs `scene` into `output`; returns status, failure, summary (JSON text) and end time.
/// Raises as described above.
py::dict run_in_process(run::Scene scene, const std::string& output, bool progress) {
  PythonSignals signals;
  run::RunResult result;
  try {
    py::gil_scoped_release release;
    // runs from several Python threads take turns on libhdf5 in Python (isosid/_hdf5.py)
    run::RunFolder folder(output, scene);
    result = run::run_scene(std::move(scene), folder, {!progress, [&signals] { return signals.stop_requested(); }});
  } catch (...) {
    signals.raise_pending();  // a Ctrl-C during the run wins over a failure it caused
    throw;
  }
  signals.raise_pending();
  py::dict out;
  out["status"] = result.started ? result.outcome.status : std::string("interrupted");
  out["failure"] = result.outcome.failure;
  out["summary"] = result.summary.is_null() ? std::string("{}") : result.summary.dump();
  out["end_time"] = result.end_time;
  return out;
}

/// Runs a scene file with `settings` set over it.
py::dict run_scene(const std::string& scene_file, const std::string& output, const Settings& settings, bool progress) {
  return run_in_process(run::read_scene_file(scene_file, overrides_of(settings)), output, progress);
}

/// Runs a scene given as TOML text, named `name` (errors name it, paths are relative to its
/// folder), with `settings` set over it.
py::dict run_scene_text(const std::string& text, const std::string& name, const std::string& output, const Settings& settings,
                        bool progress) {
  return run_in_process(run::read_scene_text(text, name, overrides_of(settings)), output, progress);
}

}  // namespace

PYBIND11_MODULE(_isosid, m) {
  m.doc() = "isosid's run pipeline; use the package isosid, not this module";
  static py::exception<format::InputError> input_error(m, "InputError", PyExc_ValueError);
  static py::exception<format::ComputationError> computation_error(m, "ComputationError", PyExc_RuntimeError);
  // as the command lines' run_guarded: bad input is InputError, every other failure ComputationError
  py::register_exception_translator([](std::exception_ptr caught) {
    try {
      if (caught) std::rethrow_exception(caught);
    } catch (const py::error_already_set&) {
      throw;  // a Python exception (KeyboardInterrupt) stays itself
    } catch (const py::builtin_exception&) {
      throw;
    } catch (const format::InputError& e) {
      input_error(e.what());
    } catch (const std::bad_alloc&) {
      computation_error("out of memory");
    } catch (const std::exception& e) {
      computation_error(e.what());
    }
  });
  m.def("run_scene", &run_scene, py::arg("scene_file"), py::arg("output"), py::arg("settings"), py::arg("progress"));
  m.def("run_scene_text", &run_scene_text, py::arg("text"), py::arg("name"), py::arg("output"), py::arg("settings"), py::arg("progress"));
  m.def("version", [] { return common::version_line("isosid"); });
}
