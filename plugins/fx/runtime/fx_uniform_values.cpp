#include "fx_uniform_values.hpp"

#include <cmath>
#include <ctime>

namespace pfx_fx {
namespace {

// A reproducible random number for a frame and uniform (splitmix64): renders of a sequence give
// the same pictures on every run.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

}  // namespace

void UniformValues::reset(const pfx::fx::EffectModel& model, const ParamTable& params) {
  param_uniform_.clear();
  for (const ParamBinding& b : params.bindings) {
    int found = -1;
    for (std::size_t i = 0; i < model.uniforms.size() && found < 0; ++i)
      if (model.uniforms[i].name == b.uniform_name && static_cast<int>(model.uniforms[i].initial.size()) >= b.first + b.count)
        found = static_cast<int>(i);
    param_uniform_.push_back(found);
  }
  values_.clear();
  for (const auto& u : model.uniforms) values_.push_back(u.initial);
  pingpong_.assign(model.uniforms.size() * 2, 0.0);
  for (std::size_t i = 0; i < model.uniforms.size(); ++i) {
    pingpong_[i * 2] = pfx::fx::annotation_number(model.uniforms[i].annotations, "min", 0.0);
    pingpong_[i * 2 + 1] = 1.0;
  }
  last_time_ = -1;
}

void UniformValues::update(const pfx::fx::EffectModel& model, const ParamTable& params, const pfx_value* values, const pfx_frame& frame,
                           bool depth_available) {
  if (values_.size() != model.uniforms.size() || param_uniform_.size() != params.bindings.size()) reset(model, params);
  double frame_seconds = last_time_ < 0 ? 0.0 : std::max(0.0, frame.time_seconds - last_time_);
  last_time_ = frame.time_seconds;
  for (std::size_t p = 0; p < params.bindings.size(); ++p) {
    const ParamBinding& b = params.bindings[p];
    if (param_uniform_[p] < 0) continue;
    auto& target = values_[static_cast<std::size_t>(param_uniform_[p])];
    for (int c = 0; c < b.count; ++c) {
      double v = values[p].v[c];
      target[static_cast<std::size_t>(b.first + c)] = b.whole ? std::round(v) : v;
    }
  }
  for (std::size_t i = 0; i < model.uniforms.size(); ++i) {
    const auto& u = model.uniforms[i];
    if (u.source.empty()) continue;
    auto& v = values_[i];
    const auto& a = u.annotations;
    auto set = [&](std::size_t c, double x) {
      if (c < v.size()) v[c] = x;
    };
    if (u.source == "timer") set(0, frame.time_seconds * 1000.0);
    else if (u.source == "frametime") set(0, frame_seconds * 1000.0);
    else if (u.source == "framecount") set(0, static_cast<double>(frame.frame_index));
    else if (u.source == "random") {
      double low = pfx::fx::annotation_number(a, "min", 0), high = pfx::fx::annotation_number(a, "max", 32767);
      std::uint64_t r = mix(frame.frame_index * 0x100000001B3ull + i);
      set(0, std::floor(low + static_cast<double>(r % 1000003) / 1000003.0 * (high - low + 1)));
    } else if (u.source == "pingpong") {
      // Moves between min and max at `step` units per second, turning at the ends.
      double low = pfx::fx::annotation_number(a, "min", 0), high = pfx::fx::annotation_number(a, "max", 1);
      double speed = pfx::fx::annotation_number(a, "step", 1);
      double& position = pingpong_[i * 2];
      double& direction = pingpong_[i * 2 + 1];
      position += direction * speed * frame_seconds;
      if (position >= high) position = high, direction = -1;
      if (position <= low) position = low, direction = 1;
      set(0, position);
      set(1, direction);
    } else if (u.source == "date") {
      std::time_t now = std::time(nullptr);
      std::tm local{};
      localtime_r(&now, &local);
      set(0, local.tm_year + 1900);
      set(1, local.tm_mon + 1);
      set(2, local.tm_mday);
      set(3, local.tm_hour * 3600 + local.tm_min * 60 + local.tm_sec);
    } else if (u.source == "bufready_depth") {
      set(0, depth_available ? 1 : 0);
    } else if (u.source == "screensize") {
      set(0, frame.width);
      set(1, frame.height);
    }
    // key, mousebutton, mousepoint, mousedelta, mousewheel, overlay_open, overlay_active and
    // unknown sources keep their initial value (zero without one): pfx has no input devices.
  }
}

}  // namespace pfx_fx
