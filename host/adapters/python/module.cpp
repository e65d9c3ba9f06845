// The Python module `pfx` (docs/python.md): the effects found, a Chain that runs them over numpy
// pictures on a headless OpenGL 4.5 context, and the model importers. The work is in
// python_chain.cpp, numpy_image.cpp and model_import.cpp; this file says what Python sees.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "model_import.hpp"
#include "numpy_image.hpp"
#include "plugin_listing.hpp"
#include "plugin_set.hpp"
#include "python_chain.hpp"
#include "python_errors.hpp"
#include "python_values.hpp"

namespace py = pybind11;
using namespace py::literals;
using pfx::python::PythonChain;

namespace {

using PluginList = std::optional<std::vector<std::string>>;

void warn(const std::string& message) {
  if (PyErr_WarnEx(PyExc_RuntimeWarning, message.c_str(), 1) != 0) throw py::error_already_set();
}

py::list effects(const PluginList& plugins) {
  const auto registry = pfx::python::load_plugin_set(plugins, warn);
  py::list list;
  for (const auto& plugin : registry->plugins())
    for (const pfx_effect_desc* effect : plugin->effects) {
      nlohmann::ordered_json json = pfx::app::effect_json(*effect);
      json["plugin"] = plugin->id;
      json["plugin_path"] = plugin->path;
      list.append(pfx::python::to_python(json));
    }
  return list;
}

std::unique_ptr<PythonChain> make_chain(const PluginList& effects, const PluginList& plugins,
                                        const std::string& defaults, const std::string& timing,
                                        const std::optional<std::string>& preset) {
  pfx::python::ChainSettings settings;
  if (defaults == "scene")
    settings.defaults = pfx::python::Defaults::SCENE;
  else if (defaults == "display")
    settings.defaults = pfx::python::Defaults::DISPLAY;
  else if (defaults != "auto")
    throw py::value_error("defaults must be 'auto' (as each picture's dtype says), 'scene' (linear HDR pictures) or "
                          "'display' (8-bit pictures), not '" + defaults + "'");
  auto registry = pfx::python::load_plugin_set(plugins, warn);
  settings.effects = effects;
  settings.timing = timing;
  settings.preset = preset.value_or("");
  std::vector<std::string> warnings;
  std::unique_ptr<PythonChain> chain;
  {
    py::gil_scoped_release release;  // the effects' programs compile now
    chain = std::make_unique<PythonChain>(std::move(registry), settings, &warnings);
  }
  for (const auto& message : warnings) warn(message);
  return chain;
}

pfx_depth_encoding depth_encoding(const std::string& name) {
  if (name == "linear") return PFX_DEPTH_LINEAR;
  if (name == "hardware") return PFX_DEPTH_HARDWARE;
  if (name == "hardware_reversed") return PFX_DEPTH_HARDWARE_REVERSED;
  throw py::value_error("depth_encoding must be 'linear', 'hardware' or 'hardware_reversed', not '" + name + "'");
}

// Anything numpy can make an array of, so that a list is told what dtype it would need.
py::array as_array(const py::object& value, const char* name) {
  py::array array = py::array::ensure(value);
  if (!array) throw py::type_error(std::string(name) + " must be a numpy array");
  return array;
}

py::array run(PythonChain& chain, const py::object& rgba, const std::optional<py::object>& depth,
              const std::optional<pfx::app::CameraOptions>& camera, const std::string& encoding, double time,
              uint64_t frame_index, const std::string& transfer) {
  pfx::python::RunRequest request;
  pfx::python::PictureForm form;
  std::optional<py::array> depth_array;
  if (depth && !depth->is_none()) depth_array = as_array(*depth, "depth");
  if (std::string problem; !pfx::app::parse_transfer(transfer, &request.transfer, &problem))
    throw py::value_error("transfer: " + problem);
  const py::array picture = as_array(rgba, "rgba");
  request.image = pfx::python::picture_frame(picture, depth_array, &form);
  request.display = form.bytes;
  request.depth_encoding = depth_encoding(encoding);
  if (camera) request.camera = *camera;
  request.time_seconds = time;
  request.frame_index = frame_index;
  // A picture no pass would change comes back without a trip through the GL: one pass over it.
  bool passes = false;
  {
    py::gil_scoped_release release;
    passes = chain.plans_passes(request);
  }
  if (!passes) return pfx::python::unchanged_picture(picture, form);
  pfx::python::FloatPicture floats;
  if (form.bytes) {
    pfx::python::read_picture_bytes(picture, form, &request.bytes);
  } else {
    floats = pfx::python::float_picture(picture);
    request.colour = floats.colour.data();
    request.result = floats.result.mutable_data();
    request.channels = form.channels;
  }
  pfx::python::RunResult result;
  {
    py::gil_scoped_release release;
    result = chain.run(request);
  }
  if (form.bytes) return pfx::python::numpy_from_bytes(result.bytes, request.image.width, request.image.height, form);
  return pfx::python::float_result(floats, form);
}

pfx::app::CameraOptions make_camera(double fovy, double near_plane, double far_plane) {
  pfx::app::CameraOptions camera;
  camera.fovy_degrees = fovy;
  camera.near_plane = near_plane;
  camera.far_plane = far_plane;
  if (const std::string problem = pfx::app::camera_problem(camera); !problem.empty())
    throw py::value_error("Camera: " + problem);
  return camera;
}

// pfx.Error and its subclass pfx.ParameterError, which the chain's C++ exceptions become.
void bind_errors(py::module_& m) {
  static py::exception<pfx::python::Error> error(m, "Error", PyExc_RuntimeError);
  static py::exception<pfx::python::ParameterError> parameter_error(m, "ParameterError", error.ptr());
  // Registered last, tried first: the subclass before its base.
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const pfx::python::ParameterError& e) {
      parameter_error(e.what());
    } catch (const pfx::python::Error& e) {
      error(e.what());
    }
  });
}

// What the plugins offer and the lens a picture was seen through: pfx.effects() and pfx.Camera.
void bind_descriptions(py::module_& m) {
  m.def("effects", &effects, "plugins"_a = py::none(),
        "The effects of the plugins found: a list of dicts with id, label, description, parameters (each with "
        "key, type, range, default...), plugin and plugin_path, as pfx-render --list --json describes them.");

  py::class_<pfx::app::CameraOptions>(m, "Camera", "The lens a picture was seen through, as pfx-render's --camera.")
      .def(py::init(&make_camera), "fovy"_a = 45.0, "near"_a = 0.1, "far"_a = 1000.0,
           "fovy: vertical field of view in degrees; near, far: the clip planes in metres (far may be inf).")
      .def_readonly("fovy", &pfx::app::CameraOptions::fovy_degrees)
      .def_readonly("near", &pfx::app::CameraOptions::near_plane)
      .def_readonly("far", &pfx::app::CameraOptions::far_plane)
      .def("__repr__", [](const pfx::app::CameraOptions& c) {
        return "pfx.Camera(fovy=" + py::repr(py::float_(c.fovy_degrees)).cast<std::string>() +
               ", near=" + py::repr(py::float_(c.near_plane)).cast<std::string>() +
               ", far=" + py::repr(py::float_(c.far_plane)).cast<std::string>() + ")";
      });
}

void bind_chain(py::module_& m) {
  py::class_<PythonChain>(m, "Chain",
                          "Effects run in order over pictures, on an OpenGL 4.5 context of the chain's own. "
                          "Use one Chain from one thread at a time; several may run at once on different threads.")
      .def(py::init(&make_chain), "effects"_a = py::none(), "plugins"_a = py::none(), "defaults"_a = "auto",
           "timing"_a = "auto", "preset"_a = py::none(),
           "effects: effect ids in order (an id twice makes a second instance, 'bloom#2'); None: the preset's "
           "chain, else every effect found, in the default order. plugins: plugin files or folders; None: the folder beside the module "
           "and PFX_PLUGIN_PATH. defaults: where a parameter starts until set() gives it a value: 'auto' follows "
           "each picture's dtype (the display-referred defaults for uint8, the scene-referred ones for floats), "
           "'scene' or 'display' fixes them. timing: "
           "'auto', 'gpu', 'finish' or 'off'. preset: a pfx preset (JSON, as pfx-view saves) or a ReShade "
           "preset (.ini): its chain with each effect on or off, its values (fixed, as set() fixes them) and its "
           "preprocessor definitions; what it names that is not loaded is left out with a warning.")
      .def("set", [](PythonChain& chain, const std::string& key, const py::handle& value) {
            std::string note;
            chain.set(key, pfx::python::value_text(value), &note);
            if (!note.empty()) warn(key + ": " + note);
          }, "key"_a, "value"_a,
          "Sets 'effect.parameter' ('bloom#2.threshold' for a second instance) as pfx-render's --set does. "
          "Raises pfx.ParameterError for an unknown key or a value the parameter refuses; warns when it clamps.")
      .def("get", [](const PythonChain& chain, const std::string& key) { return pfx::python::to_python(chain.get(key)); },
           "key"_a, "The current value of 'effect.parameter'.")
      .def("params", [](const PythonChain& chain) { return pfx::python::to_python(chain.params()); },
           "{instance: {parameter: {'value': ..., and its description}}} in chain order.")
      .def_property_readonly("effects", &PythonChain::instances, "The instances in chain order: 'bloom', 'bloom#2'...")
      .def("run", &run, "rgba"_a, "depth"_a = py::none(), "camera"_a = py::none(), "depth_encoding"_a = "linear",
           "time"_a = 0.0, "frame_index"_a = 0, "transfer"_a = "srgb",
           "Runs the chain over rgba (H x W x 4 or H x W x 3, top row first) and returns the result in the same "
           "dtype and shape. float16 and float32 hold linear light; uint8 is a display-referred picture, decoded "
           "to linear light with transfer ('srgb', or 'linear' for values that are linear already) and the result "
           "encoded back, as pfx-render does an 8-bit PNG. depth: H x W, linear metres along the view axis, or window depth "
           "with depth_encoding 'hardware' or 'hardware_reversed'. camera: pfx.Camera (default fovy 45, near 0.1, "
           "far 1000).")
      .def_property_readonly("report", [](const PythonChain& chain) { return pfx::python::to_python(chain.report()); },
                             "The last run's report as pfx-render --json gives it: passes with their times in ms, "
                             "total_ms, timing, peak_target_bytes...; None before the first run.")
      .def_property_readonly("renderer", &PythonChain::renderer, "GL_RENDERER and GL_VERSION of the chain's context.")
      .def("copy_pass_ms", [](PythonChain& chain, int width, int height) {
            py::gil_scoped_release release;
            return chain.copy_pass_ms(width, height);
          }, "width"_a, "height"_a,
          "The median time in ms of a full-frame copy pass between two RGBA16F textures of that size on the "
          "chain's GL context (glFinish and a clock around each of 9): the unit pfx's benchmarks give costs in, "
          "to judge a run's time against.")
      .def("close", [](PythonChain& chain) {
            py::gil_scoped_release release;
            chain.close();
          }, "Frees the effects, their GL objects and the context now; the Chain cannot run afterwards.")
      .def("__enter__", [](py::object self) { return self; })
      .def("__exit__", [](PythonChain& chain, const py::args&) {
        py::gil_scoped_release release;
        chain.close();
      });
}

void bind_import(py::module_& m) {
  m.def("import_model", &pfx::python::import_model, "path"_a, "plugins"_a = py::none(), "threads"_a = 0,
        "Imports a model file (OBJ...) through the importer plugins: positions, normals, uvs, colors, indices, "
        "submeshes as numpy arrays, with materials, bounds and warnings.");
}

}  // namespace

PYBIND11_MODULE(pfx, m) {
  m.doc() = "pfx post effects on numpy pictures, headless (docs/python.md)";
  m.attr("__version__") = PFX_VERSION;
  m.attr("__license__") = PFX_LICENSE;
  bind_errors(m);
  // Camera before Chain, so that the signature of Chain.run names pfx.Camera.
  bind_descriptions(m);
  bind_chain(m);
  bind_import(m);
}
