// isosid._isosid_prep: isosid-prep's preparation and modal analysis in-process, for the Python
// package's isosid.prepare and isosid.modes. A module of its own, loaded on their first call:
// the preparation links gmsh and CHOLMOD, whose loading would otherwise cost every
// `import isosid` about 0.2 s. Its errors are _isosid's InputError and ComputationError.
#include "isosid/format/error.hpp"
#include "model/model_file.hpp"
#include "pipeline/prep_report.hpp"
#include "pipeline/prepare.hpp"

#include <pybind11/pybind11.h>

#include <string>

namespace py = pybind11;
using namespace isosid;

namespace {

/// isosid-prep's work on a model file in-process: its SID written to `output` (the model's
/// name with .sid.h5 if empty), sized for `contact_radius` (m; 0: the model's own) where the
/// model asks for one; returns isosid-prep's JSON report as text.
std::string prepare(const std::string& model_file, std::string output, double contact_radius, bool progress) {
  output = prep::sid_output(model_file, output, "output");
  prep::ModelSpec spec = prep::read_model_file(model_file);
  if (contact_radius > 0) prep::set_contact_radius(spec, contact_radius, "contact_radius");
  py::gil_scoped_release release;
  prep::StderrProgress shown("isosid.prepare");
  return prep::sid_report(prep::prepare(spec, {.build_sid = true, .output = output}, progress ? shown : prep::no_progress()), output).dump();
}

/// The model's `count` lowest modes (rigid-body modes included) as isosid-prep --modes reports
/// them (JSON text).
std::string modes(const std::string& model_file, int count, bool progress) {
  if (count < 1) throw format::InputError(model_file, "count", "must be at least 1");
  const prep::ModelSpec spec = prep::read_model_file(model_file);
  py::gil_scoped_release release;
  prep::StderrProgress shown("isosid.modes");
  return prep::modal_report(prep::analyse_modes(spec, count, progress ? shown : prep::no_progress())).dump();
}

}  // namespace

PYBIND11_MODULE(_isosid_prep, m) {
  m.doc() = "isosid-prep in-process; use isosid.prepare and isosid.modes, not this module";
  // the package's exception classes, kept for the translator for the process's life
  static const auto* errors = new py::module_(py::module_::import("isosid._isosid"));
  py::register_exception_translator([](std::exception_ptr caught) {
    try {
      if (caught) std::rethrow_exception(caught);
    } catch (const py::error_already_set&) {
      throw;
    } catch (const py::builtin_exception&) {
      throw;
    } catch (const format::InputError& e) {
      PyErr_SetString(errors->attr("InputError").ptr(), e.what());
    } catch (const std::bad_alloc&) {
      PyErr_SetString(errors->attr("ComputationError").ptr(), "out of memory");
    } catch (const std::exception& e) {
      PyErr_SetString(errors->attr("ComputationError").ptr(), e.what());
    }
  });
  m.def("prepare", &prepare, py::arg("model_file"), py::arg("output"), py::arg("contact_radius"), py::arg("progress"));
  m.def("modes", &modes, py::arg("model_file"), py::arg("count"), py::arg("progress"));
}
