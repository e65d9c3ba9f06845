#include "python_chain.hpp"

#include <glad/gl.h>

#include <pfx/host/gl_error.hpp>

#include "chain_builder.hpp"
#include "copy_pass.hpp"
#include "default_chain.hpp"
#include "frame_description.hpp"
#include "frame_report_json.hpp"
#include "half_rounding.hpp"
#include "image_texture.hpp"
#include "plugin_listing.hpp"
#include "python_errors.hpp"
#include "timing_choice.hpp"

namespace pfx::python {
namespace {

// "bloom#2.threshold" -> ("bloom#2", "threshold"): parameter ids have no '.', instance names neither.
bool split_key(const std::string& key, std::string* instance, std::string* param) {
  const size_t dot = key.find('.');
  if (dot == std::string::npos || dot == 0 || dot + 1 == key.size()) return false;
  *instance = key.substr(0, dot);
  *param = key.substr(dot + 1);
  return true;
}

// One name per value: "bloom" and "bloom#1" are the same instance.
std::string canonical_key(const std::string& instance, const std::string& param) {
  return instance + (instance.find('#') == std::string::npos ? "#1." : ".") + param;
}

}  // namespace

PythonChain::PythonChain(std::unique_ptr<host::PluginRegistry> registry, const ChainSettings& settings,
                         std::vector<std::string>* warnings)
    : worker_(adapters::GlWorker::start()), registry_(std::move(registry)) {
  defaults_ = settings.defaults;
  current_defaults_ = settings.defaults == Defaults::DISPLAY ? host::DefaultSet::DISPLAY_REFERRED
                                                             : host::DefaultSet::SCENE_REFERRED;
  params_ = std::make_unique<host::ParamStore>(current_defaults_);
  for (const auto& effect : registry_->effects()) params_->add_effect(effect.desc);
  try {
    const app::ChainRecipe recipe = recipe_for(settings, warnings);
    run_on_gl_thread([&](std::string* error) {
      renderer_ = worker_->renderer();
      host::Timing timing = host::Timing::OFF;
      if (!app::parse_timing(settings.timing, renderer_, &timing)) {
        *error = "timing '" + settings.timing + "' is none of auto, gpu, finish, off";
        return;
      }
      chain_ = std::make_unique<host::Chain>(*registry_, *params_);
      chain_->set_timing(timing);
      for (const auto& effect : recipe.effects) {
        if (!chain_->add(effect.id, error)) return;
        chain_->set_enabled(chain_->size() - 1, effect.enabled);
      }
      chain_->set_source_definitions(recipe.source_definitions, error);
    });
    apply_preset_values(recipe);
  } catch (...) {
    close();
    throw;
  }
}

app::ChainRecipe PythonChain::recipe_for(const ChainSettings& settings, std::vector<std::string>* warnings) const {
  app::ChainRecipe recipe;
  if (settings.preset.empty()) {
    for (const auto& id : settings.effects ? *settings.effects : app::default_chain(*registry_)) recipe.effects.push_back({id, true});
    return recipe;
  }
  // A preset that does not read is an error; in one that does, what is not there is left out,
  // as every host of pfx's leaves it out of a ReShade preset.
  app::Preset preset;
  std::string error;
  if (!app::read_preset(settings.preset, &preset, &error)) throw Error(error);
  std::vector<app::RecipeProblem> problems;
  std::vector<std::string> notes;
  recipe = app::make_chain_recipe(settings.preset, settings.effects, {}, *registry_, app::WithoutChain::DEFAULT_CHAIN,
                                  &problems, &notes);
  for (const auto& problem : problems) {
    if (problem.source == app::RecipeProblem::CHAIN) throw Error(problem.message);
    warnings->push_back(problem.message);
  }
  if (!recipe.left_out.empty()) warnings->push_back(recipe.left_out);
  warnings->insert(warnings->end(), notes.begin(), notes.end());
  return recipe;
}

// The preset's values count as set: a picture's dtype does not move them to other defaults.
void PythonChain::apply_preset_values(const app::ChainRecipe& recipe) {
  std::string error;
  if (!app::apply_recipe_values(recipe, params_.get(), &error, nullptr, "preset")) throw Error(error);
  if (!recipe.parameters_json.empty()) {
    const nlohmann::json parameters = nlohmann::json::parse(recipe.parameters_json);
    for (const auto& instance : parameters.items())
      for (const auto& value : instance.value().items()) set_keys_.insert(canonical_key(instance.key(), value.key()));
  }
  for (const auto& assignment : recipe.sets) {
    std::string instance, param;
    if (split_key(assignment.substr(0, assignment.find('=')), &instance, &param)) set_keys_.insert(canonical_key(instance, param));
  }
}

PythonChain::~PythonChain() { close(); }

void PythonChain::close() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (chain_) {
    std::string unused;
    // The instances' and the pictures' GL objects go with the context that made them.
    worker_->run([this] { release_gl_objects(); }, &unused);
    chain_.reset();
  }
  worker_.reset();  // its context is destroyed on its own thread
  params_.reset();
  registry_.reset();  // the plugins' deinit, once no instance is left
}

void PythonChain::release_gl_objects() {
  chain_.reset();
  float_picture_.release();
  display_picture_.reset();
}

void PythonChain::check_open() const {
  if (!params_) throw Error("this Chain was closed");
}

void PythonChain::run_on_gl_thread(const std::function<void(std::string* error)>& job) {
  std::string error;
  if (!worker_->run([&] {
        try {
          job(&error);
        } catch (const std::exception& e) {
          error = std::string("internal error: ") + e.what();
        }
      }, &error) ||
      !error.empty())
    throw Error(error);
}

void PythonChain::set(const std::string& key, const std::string& text, std::string* note) {
  std::lock_guard<std::mutex> lock(mutex_);
  check_open();
  std::string error;
  if (!params_->set(key, text, &error, note)) throw ParameterError(error);
  std::string instance, param;
  if (split_key(key, &instance, &param)) set_keys_.insert(canonical_key(instance, param));
}

nlohmann::ordered_json PythonChain::get(const std::string& key) const {
  std::lock_guard<std::mutex> lock(mutex_);
  check_open();
  std::string instance, param;
  const pfx_param_desc* desc = split_key(key, &instance, &param) ? params_->descriptor(instance, param) : nullptr;
  if (!desc) throw ParameterError("'" + key + "' names no parameter of this chain: keys are effect.parameter, as in params()");
  // The store's JSON names the first instance "bloom", never "bloom#1".
  const std::string first_suffix = "#1";
  if (instance.size() > first_suffix.size() && instance.compare(instance.size() - 2, 2, first_suffix) == 0)
    instance.resize(instance.size() - 2);
  const nlohmann::ordered_json values = nlohmann::ordered_json::parse(params_->to_json());
  return values.at(instance).at(param);
}

nlohmann::ordered_json PythonChain::params() const {
  std::lock_guard<std::mutex> lock(mutex_);
  check_open();
  const nlohmann::ordered_json values = nlohmann::ordered_json::parse(params_->to_json());
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (size_t i = 0; i < chain_->size(); ++i) {
    const std::string instance = chain_->instance_name(i);
    const pfx_effect_desc* effect = params_->effect_descriptor(chain_->effect_id(i));
    nlohmann::ordered_json params = nlohmann::ordered_json::object();
    for (uint32_t p = 0; p < effect->param_count; ++p) {
      nlohmann::ordered_json entry = {{"value", values.at(instance).at(effect->params[p].id)}};
      entry.update(app::parameter_json(*effect, effect->params[p]));
      entry["key"] = instance + "." + effect->params[p].id;  // what set() and get() take for this instance
      params[effect->params[p].id] = entry;
    }
    out[instance] = params;
  }
  return out;
}

std::vector<std::string> PythonChain::instances() const {
  std::lock_guard<std::mutex> lock(mutex_);
  check_open();
  std::vector<std::string> names;
  for (size_t i = 0; i < chain_->size(); ++i) names.push_back(chain_->instance_name(i));
  return names;
}

nlohmann::ordered_json PythonChain::report() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return report_;
}

double PythonChain::copy_pass_ms(int width, int height) {
  std::lock_guard<std::mutex> lock(mutex_);
  check_open();
  double ms = 0;
  run_on_gl_thread([&](std::string* error) {
    GLint max_size = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
    if (width < 1 || height < 1 || width > max_size || height > max_size) {
      *error = "copy_pass_ms: the size must be 1 to " + std::to_string(max_size) + " pixels a side";
      return;
    }
    ms = gl::median_copy_pass_ms(width, height, 9);
  });
  return ms;
}

bool PythonChain::plans_passes(const RunRequest& request) {
  std::lock_guard<std::mutex> lock(mutex_);
  check_open();
  bool passes = false;
  run_on_gl_thread([&](std::string* error) {
    pfx_frame frame{};
    if (!describe(request, &frame, error) || !chain_->plans_passes(frame, &passes, error)) return;
    if (!passes) report_skipped();
  });
  return passes;
}

RunResult PythonChain::run(const RunRequest& request) {
  std::lock_guard<std::mutex> lock(mutex_);
  check_open();
  RunResult result;
  run_on_gl_thread([&](std::string* error) { render(request, &result, error); });
  return result;
}

void PythonChain::follow_picture_defaults(bool display) {
  const host::DefaultSet wanted = display ? host::DefaultSet::DISPLAY_REFERRED : host::DefaultSet::SCENE_REFERRED;
  if (defaults_ != Defaults::AUTO || wanted == current_defaults_) return;
  for (size_t i = 0; i < chain_->size(); ++i) {
    const std::string instance = chain_->instance_name(i);
    const pfx_effect_desc* effect = params_->effect_descriptor(chain_->effect_id(i));
    for (uint32_t p = 0; p < effect->param_count; ++p) {
      const pfx_param_desc& param = effect->params[p];
      if (set_keys_.count(canonical_key(instance, param.id))) continue;
      std::string unused;  // a descriptor's own default is always valid
      params_->set_value(instance, param.id, host::default_for(param, wanted), &unused);
    }
  }
  current_defaults_ = wanted;
}

// Depth is the one input beside colour a caller can give: say how, before the chain refuses.
bool PythonChain::inputs_given(const pfx_frame& frame, std::string* error) {
  for (size_t i = 0; i < chain_->size(); ++i) {
    uint32_t needed = 0;
    if (!chain_->enabled(i)) continue;
    if (!chain_->inputs_needed(i, frame, &needed, error)) return false;
    if (needed & ~frame.inputs & PFX_INPUT_DEPTH) {
      *error = chain_->instance_name(i) + " needs depth with its current values: pass depth= (an H x W array) to run()";
      return false;
    }
  }
  return true;
}

// A picture no pass would change, with no upload, pass or read back. An 8-bit one comes back as
// it came: decoding and encoding give every code back. A float one comes back at the precision of
// the chain's colour, half float, rounded to the nearest as a float16 array is.
void PythonChain::hand_back(const RunRequest& request, RunResult* result) {
  if (request.display) {
    result->bytes = request.bytes;
  } else {
    const size_t count = request.image.pixel_count() * static_cast<size_t>(request.channels);
    for (size_t i = 0; i < count; ++i) request.result[i] = app::round_to_half(request.colour[i]);
  }
  report_skipped();
}

void PythonChain::report_skipped() {
  host::FrameReport skipped;
  for (size_t i = 0; i < chain_->size(); ++i) skipped.effects_skipped.push_back(chain_->instance_name(i));
  skipped.timing = "off";  // nothing ran to be timed
  report_ = {{"renderer", renderer_}};
  app::add_frame_report(skipped, &report_);
}

// The frame the chain sees for the request's picture, with the values its kind of picture starts
// at; false with *error when the chain needs an input the request does not give.
bool PythonChain::describe(const RunRequest& request, pfx_frame* frame, std::string* error) {
  const app::Image& image = request.image;
  follow_picture_defaults(request.display);
  const uint32_t inputs = PFX_INPUT_COLOR | (image.has_depth() ? uint32_t(PFX_INPUT_DEPTH) : 0u);
  *frame = app::describe_frame(image.width, image.height, inputs, request.depth_encoding,
                               app::make_camera(request.camera, image.width, image.height));
  frame->time_seconds = request.time_seconds;
  frame->frame_index = request.frame_index;
  return inputs_given(*frame, error);
}

void PythonChain::render(const RunRequest& request, RunResult* result, std::string* error) {
  const app::Image& image = request.image;
  pfx_frame frame{};
  if (!describe(request, &frame, error)) return;
  bool passes = false;
  if (!chain_->plans_passes(frame, &passes, error)) return;
  if (!passes) {
    hand_back(request, result);
    return;
  }
  // A picture no pass changes needs no texture: only one that goes through the chain must fit.
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  if (image.width > max_size || image.height > max_size) {
    *error = "the picture is " + std::to_string(image.width) + " x " + std::to_string(image.height) +
             "; this OpenGL takes at most " + std::to_string(max_size) + " pixels a side";
    return;
  }

  float_picture_.upload(image, request.colour, request.channels);  // the colour of a float picture, the depth of either
  host::FrameTextures textures = float_picture_.inputs();
  uint32_t output = float_picture_.output();
  if (request.display) {
    if (!display_picture_) {
      auto made = std::make_unique<gl::DisplayFrame>();
      if (!made->create(error)) return;
      display_picture_ = std::move(made);
    }
    display_picture_->resize(image.width, image.height);
    display_picture_->decode_bytes(request.bytes.data(), request.transfer);
    textures.color = display_picture_->color();
    output = display_picture_->output();
  }
  if (chain_->render(frame, textures, output, error)) {
    chain_->wait_for_timings();  // the pixels are read back next anyway
    if (request.display) {
      result->bytes.resize(image.pixel_count() * 4);
      display_picture_->encode_bytes(output, request.transfer, result->bytes.data());
    } else {
      float_picture_.download(request.result, request.channels);
    }
    report_ = {{"renderer", renderer_}};
    app::add_frame_report(chain_->report(), &report_);
    if (!chain_->report().effect_reports.empty()) report_["effect_reports"] = app::effect_reports_json(chain_->report());
  }
  if (const GLenum gl_error = glGetError(); error->empty() && gl_error != GL_NO_ERROR)
    *error = host::gl_error_text(gl_error) + " while running the chain";
}

}  // namespace pfx::python
