// fsi._fsi: the C++ half of the Python module `fsi` (python/fsi/__init__.py is the other half).
// A scene is given as a file or as text (a dict dumped as JSON, which is YAML) plus `--set`
// overrides; check() and run() do what `fsi check` and `fsi run` do, in this process, with the
// GIL released while the models step.
#include "fsi/core/error.hpp"
#include "fsi/core/parallel.hpp"
#include "fsi_app/run.hpp"
#include "fsi_app/scene.hpp"
#include "fsi_app/version.hpp"
#include "fsi_app/wall_motion.hpp"

#include <chrono>
#include <csignal>
#include <filesystem>
#include <iostream>
#include <optional>
#include <pybind11/functional.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>
#include <sstream>
#include <string>
#include <vector>

namespace py = pybind11;
using namespace fsi::app;

namespace {

/// The scene of `file` (or of `text`, named `file` in messages; relative paths resolve against
/// its folder) with the overrides applied. InputError `FILE:LINE: KEY: what` as load_scene.
Scene read(const std::string& file, const std::optional<std::string>& text,
           const std::vector<std::string>& overrides) {
  return text ? parse_scene(*text, file, overrides) : load_scene(file, overrides);
}

/// The models of a validated scene, as `fsi check` builds them: a library's error that names no
/// file gets the scene's.
std::vector<std::unique_ptr<Model>> models_of(const Scene& scene, const std::string& file) {
  check_motion_tables(scene);
  try {
    return build_models(scene);
  } catch (const fsi::InputError& e) {
    if (std::string(e.what()).find(file) != std::string::npos) throw;
    throw fsi::InputError(file + ": " + e.what());
  }
}

/// Validates the scene and builds its models; returns the scene's name.
std::string check(const std::string& file, const std::optional<std::string>& text,
                  const std::vector<std::string>& overrides) {
  const Scene scene = read(file, text, overrides);
  models_of(scene, file);
  return scene.name;
}

/// Runs the scene into `out`. `progress(time, step)` is called with the GIL at most every
/// `interval` wall seconds and after the last step; an exception it raises stops the run as
/// SIGINT does (after the step, with a checkpoint) and is raised again here.
py::dict run(const std::string& file, const std::optional<std::string>& text,
             const std::vector<std::string>& overrides, const std::filesystem::path& out,
             int threads, const std::filesystem::path& restart, bool overwrite,
             const std::optional<std::function<void(double, long)>>& progress, double interval,
             bool quiet) {
  const Scene scene = read(file, text, overrides);
  const int processors = fsi::available_processors();
  if (threads < 0 || threads > processors)
    throw fsi::InputError("fsi: threads = " + std::to_string(threads) + ": give 1 to " +
                          std::to_string(processors) + " (0: all)");
  if (overwrite && !restart.empty())
    throw fsi::InputError("fsi run: overwrite starts afresh, restart continues: give one of them");
  auto models = models_of(scene, file);
  std::ostringstream discard;
  RunOptions options{out, false, quiet ? static_cast<std::ostream*>(&discard) : &std::cerr,
                     restart};
  options.overwrite = overwrite;
  std::optional<py::error_already_set> raised;
  if (progress) {
    options.on_step = [&, end = scene.time.end,
                       last = std::chrono::steady_clock::now()](double time, long step) mutable {
      const auto now = std::chrono::steady_clock::now();
      if (raised || (std::chrono::duration<double>(now - last).count() < interval && time < end))
        return;
      last = now;
      const py::gil_scoped_acquire gil;
      try {
        (*progress)(time, step);
      } catch (py::error_already_set& e) {
        raised.emplace(std::move(e));
        std::raise(SIGINT); // the run's InterruptGuard: stop after this step, with a checkpoint
      }
    };
  }
  const int threads_before = fsi::num_threads();
  if (threads > 0) fsi::set_num_threads(threads);
  RunResult result;
  try {
    const py::gil_scoped_release nogil;
    result = run_scene(scene, models, options);
  } catch (...) {
    fsi::set_num_threads(threads_before);
    throw;
  }
  fsi::set_num_threads(threads_before);
  if (raised) throw std::move(*raised);
  py::dict r;
  r["signal"] = result.signal;
  r["step"] = result.step;
  r["time"] = result.time;
  r["checkpoint"] = result.checkpoint.string();
  return r;
}

} // namespace

PYBIND11_MODULE(_fsi, m) {
  m.doc() = "fsi: scenes, runs and results of the FSI framework (C++ part)";
  py::register_exception<fsi::InputError>(m, "InputError", PyExc_ValueError);
  py::register_exception<fsi::RunError>(m, "RunError", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const std::filesystem::filesystem_error& e) {
      PyErr_SetString(PyExc_OSError, e.what());
    }
  });
  m.def("check", &check, py::arg("file"), py::arg("text"), py::arg("overrides"));
  m.def("run", &run, py::arg("file"), py::arg("text"), py::arg("overrides"), py::arg("out"),
        py::arg("threads"), py::arg("restart"), py::arg("overwrite"), py::arg("progress"),
        py::arg("interval"), py::arg("quiet"));
  m.def("reference", &scene_reference, "the scene-file reference (Markdown)");
  m.def("available_processors", &fsi::available_processors);
  m.attr("__version__") = version();
  m.attr("git_revision") = git_revision();
}
