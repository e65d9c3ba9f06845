#include "frei0r_instance.hpp"

#include <cstdio>
#include <cstring>
#include <exception>

#include "display_frame.hpp"
#include "frame_chain.hpp"

namespace pfx::frei0r {
namespace {

// pfx_chain's parameters, in frei0r order.
std::string* chain_setting(adapters::ChainSettings& settings, int index) {
  switch (index) {
    case 0: return &settings.chain;
    case 1: return &settings.set;
    case 2: return &settings.transfer;
    case 3: return &settings.preset;
    default: return nullptr;
  }
}

}  // namespace

struct Instance::GlSide {
  gl::DisplayFrame frame;
  std::unique_ptr<adapters::FrameChain> chain;
  app::Transfer transfer = app::Transfer::SRGB;
  uint64_t applied = 0;     // the revision of the values the chain has
  std::string chain_error;  // why there is no chain for that revision
};

Instance::Instance(std::shared_ptr<Library> library, unsigned width, unsigned height)
    : library_(std::move(library)), width_(static_cast<int>(width)), height_(static_cast<int>(height)) {
  if (library_->effect) values_.add_effect(library_->effect);
  texts_.resize(library_->params.size());
}

Instance::~Instance() {
  if (gl_) {
    // The textures and effects belong to the worker's context.
    std::string error;
    worker_->run([this] { gl_.reset(); }, &error);
  }
  worker_.reset();
}

void Instance::set_param(int index, const void* param, const char* text) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (index < 0 || static_cast<size_t>(index) >= library_->params.size()) return;
  ++revision_;
  if (library_->kind == Library::Kind::CHAIN) {
    *chain_setting(settings_, index) = text ? text : "";
    return;
  }
  const pfx_param_desc& desc = library_->effect->params[index];
  std::string error, note;
  bool ok = true;
  pfx_value value{};
  switch (frei0r_type(desc)) {
    case F0R_PARAM_DOUBLE:
      value.v[0] = from_unit(desc, *static_cast<const double*>(param));
      ok = values_.set_value(library_->effect_id, desc.id, value, &error, &note);
      break;
    case F0R_PARAM_BOOL:
      value.v[0] = *static_cast<const double*>(param) >= 0.5 ? 1 : 0;
      ok = values_.set_value(library_->effect_id, desc.id, value, &error, &note);
      break;
    case F0R_PARAM_COLOR: {
      const auto* color = static_cast<const f0r_param_color_t*>(param);
      value.v[0] = color->r, value.v[1] = color->g, value.v[2] = color->b;
      ok = values_.set_value(library_->effect_id, desc.id, value, &error, &note);
      break;
    }
    case F0R_PARAM_POSITION: {
      const auto* position = static_cast<const f0r_param_position_t*>(param);
      value.v[0] = from_unit(desc, position->x), value.v[1] = from_unit(desc, position->y);
      ok = values_.set_value(library_->effect_id, desc.id, value, &error, &note);
      break;
    }
    default:
      ok = values_.set(library_->effect_id + "." + desc.id, text ? text : "", &error, &note);
      break;
  }
  if (!ok) say(error + " (the value before it is kept)");
  else if (!note.empty()) say(std::string(desc.id) + ": " + note);
}

void Instance::get_param(int index, void* param) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (index < 0 || static_cast<size_t>(index) >= library_->params.size()) return;
  if (library_->kind == Library::Kind::CHAIN) {
    texts_[index] = *chain_setting(settings_, index);
    *static_cast<const char**>(param) = texts_[index].c_str();
    return;
  }
  const pfx_param_desc& desc = library_->effect->params[index];
  const pfx_value& value = values_.values(library_->effect_id)[index];
  switch (frei0r_type(desc)) {
    case F0R_PARAM_DOUBLE: *static_cast<double*>(param) = to_unit(desc, value.v[0]); break;
    case F0R_PARAM_BOOL: *static_cast<double*>(param) = value.v[0]; break;
    case F0R_PARAM_COLOR:
      *static_cast<f0r_param_color_t*>(param) = {static_cast<float>(value.v[0]), static_cast<float>(value.v[1]),
                                                 static_cast<float>(value.v[2])};
      break;
    case F0R_PARAM_POSITION:
      *static_cast<f0r_param_position_t*>(param) = {to_unit(desc, value.v[0]), to_unit(desc, value.v[1])};
      break;
    default:
      texts_[index] = values_.get_text(library_->effect_id + "." + desc.id);
      *static_cast<const char**>(param) = texts_[index].c_str();
      break;
  }
}

void Instance::update(double time, const uint32_t* in, uint32_t* out) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!library_->problems_said.exchange(true))
    for (const auto& problem : library_->problems) say(problem);
  if (!worker_) worker_ = adapters::GlWorker::acquire();
  std::string error;
  bool rendered = false;
  const bool ran = worker_->run([&] { rendered = render(time, in, out, &error); }, &error);
  ++frames_;
  if (ran && rendered) {
    said_.clear();
    return;
  }
  if (out != in) std::memcpy(out, in, static_cast<size_t>(width_) * height_ * 4);
  say(error + "; frames pass through unchanged");
}

bool Instance::render(double time, const uint32_t* in, uint32_t* out, std::string* error) {
  try {
    if (!gl_) {
      auto side = std::make_unique<GlSide>();
      if (!side->frame.create(error)) return false;
      side->frame.resize(width_, height_);
      gl_ = std::move(side);
    }
    if (!prepare_chain(error)) return false;
    bool passes = false;
    if (!gl_->chain->plans_passes(width_, height_, time, frames_ + 1, &passes, error)) return false;
    if (!passes) {
      // Nothing would change the frame, and decoding and encoding give every code back: one copy
      // on the CPU instead of an upload, two passes and a read back.
      if (out != in) std::memcpy(out, in, static_cast<size_t>(width_) * height_ * 4);
      return true;
    }
    gl_->frame.decode_bytes(reinterpret_cast<const uint8_t*>(in), gl_->transfer);
    GLuint result = 0;
    if (!gl_->chain->render(gl_->frame, time, frames_ + 1, &result, error)) return false;
    gl_->frame.encode_bytes(result, gl_->transfer, reinterpret_cast<uint8_t*>(out));
    return adapters::no_gl_error(error);
  } catch (const std::exception& e) {
    *error = std::string("internal error: ") + e.what();
    return false;
  }
}

bool Instance::prepare_chain(std::string* error) {
  if (gl_->applied == revision_) {
    if (!gl_->chain) *error = gl_->chain_error;
    return gl_->chain != nullptr;
  }
  gl_->applied = revision_;
  std::vector<std::string> notes;
  if (library_->kind == Library::Kind::CHAIN) {
    gl_->chain.reset();
    app::ChainRecipe recipe;
    if (adapters::resolve_chain_settings(settings_, *library_->registry, &gl_->transfer, &recipe, error)) {
      if (!recipe.left_out.empty()) notes.push_back("warning: " + recipe.left_out);
      gl_->chain = adapters::FrameChain::build(*library_->registry, recipe, "set", &notes, error);
    }
  } else if (!library_->effect) {
    *error = library_->problems.empty() ? "the effect is missing" : library_->problems.back();
  } else {
    if (!gl_->chain) {
      app::ChainRecipe recipe;
      recipe.effects.push_back({library_->effect_id, true});
      gl_->chain = adapters::FrameChain::build(*library_->registry, recipe, "set", &notes, error);
    }
    const pfx_value* values = values_.values(library_->effect_id);
    for (uint32_t i = 0; gl_->chain && i < library_->effect->param_count; ++i)
      gl_->chain->params().set_value(library_->effect_id, library_->effect->params[i].id, values[i], error);
  }
  for (const auto& note : notes) say(note);
  if (!gl_->chain) gl_->chain_error = *error;
  return gl_->chain != nullptr;
}

void Instance::say(const std::string& message) {
  if (message == said_) return;
  said_ = message;
  std::fprintf(stderr, "%s: %s\n", library_->name.c_str(), message.c_str());
}

}  // namespace pfx::frei0r
