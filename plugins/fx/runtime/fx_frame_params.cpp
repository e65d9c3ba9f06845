#include "fx_frame_params.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>

namespace pfx_fx {
namespace {

int components(pfx_param_type type) {
  return type == PFX_PARAM_COLOR || type == PFX_PARAM_VEC3 ? 3 : type == PFX_PARAM_VEC2 ? 2 : 1;
}

bool same_parameters(const ParamTable& a, const ParamTable& b) {
  if (a.descs.size() != b.descs.size()) return false;
  for (std::size_t i = 0; i < a.descs.size(); ++i)
    if (std::strcmp(a.descs[i].id, b.descs[i].id) != 0 || a.descs[i].type != b.descs[i].type) return false;
  return true;
}

bool same_value(const pfx_value& a, const pfx_value& b, int n) {
  for (int c = 0; c < n; ++c)
    if (a.v[c] != b.v[c]) return false;
  return true;
}

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

}  // namespace

void mark_frame_size_dependence(ParamTable& listed, const ParamTable& other) {
  if (!same_parameters(listed, other)) return;
  for (std::size_t i = 0; i < listed.descs.size(); ++i) {
    pfx_param_desc& d = listed.descs[i];
    const pfx_param_desc& o = other.descs[i];
    if (!same_value(d.default_value, o.default_value, components(d.type)) || d.display_min != o.display_min ||
        d.display_max != o.display_max)
      d.flags |= PFX_PARAM_FOLLOWS_FRAME_SIZE;
  }
}

void build_params_at_size(const pfx::fx::EffectModel& model, const ParamTable& listed, ParamTable& out) {
  std::vector<std::string> warnings;  // said when the file was listed
  build_params(model, out, warnings);
  if (!same_parameters(listed, out)) return;
  for (std::size_t i = 0; i < out.descs.size(); ++i) out.descs[i].flags = listed.descs[i].flags;
}

void FrameParams::reset(const pfx::fx::EffectModel& model, const ParamTable& listed, int width, int height) {
  at_size_ = ParamTable{};
  any_follows_ = false;
  for (const pfx_param_desc& d : listed.descs) any_follows_ = any_follows_ || (d.flags & PFX_PARAM_FOLLOWS_FRAME_SIZE);
  if (any_follows_) build_params_at_size(model, listed, at_size_);
  any_follows_ = any_follows_ && same_parameters(listed, at_size_);
  size_ = std::to_string(width) + "x" + std::to_string(height);
}

const pfx_value* FrameParams::resolve(const ParamTable& listed, const pfx_value* host, std::vector<std::string>& notes) {
  if (!any_follows_) return host;
  values_.assign(host, host + listed.descs.size());
  for (std::size_t i = 0; i < listed.descs.size(); ++i) {
    const pfx_param_desc& d = listed.descs[i];
    if (!(d.flags & PFX_PARAM_FOLLOWS_FRAME_SIZE)) continue;
    const pfx_param_desc& here = at_size_.descs[i];
    const int n = components(d.type);
    if (same_value(host[i], d.default_value, n)) {
      values_[i] = here.default_value;
      continue;
    }
    bool clamped = false;
    for (int c = 0; c < n; ++c) {
      double v = std::min(std::max(host[i].v[c], here.display_min), here.display_max);
      clamped = clamped || v != host[i].v[c];
      values_[i].v[c] = v;
    }
    if (clamped && told_.insert(std::string(d.id) + "@" + size_).second)
      notes.push_back(std::string("parameter '") + d.id + "' = " + number(host[i].v[0]) + " is outside its range at " + size_ +
                      " [" + number(here.display_min) + ", " + number(here.display_max) + "]: runs clamped to it");
  }
  return values_.data();
}

}  // namespace pfx_fx
