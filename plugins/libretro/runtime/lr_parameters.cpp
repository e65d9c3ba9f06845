#include "lr_parameters.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <unordered_map>

#include <pfx/cpp/descriptors.hpp>
#include <pfx/cpp/identifier.hpp>

namespace pfx_libretro {

using pfx::libretro::Preset;
using pfx::libretro::SlangParameter;
using pfx::libretro::SlangSource;

const char* LrParameters::keep(const std::string& text) {
  strings.push_back(std::make_unique<std::string>(text));
  return strings.back()->c_str();
}

namespace {

bool same_settings(const SlangParameter& a, const SlangParameter& b) {
  return a.label == b.label && a.initial == b.initial && a.minimum == b.minimum && a.maximum == b.maximum &&
         a.step == b.step;
}

}  // namespace

void build_parameters(const Preset& preset, const std::vector<const SlangSource*>& sources, LrParameters& out,
                      std::vector<std::string>& warnings) {
  std::vector<const SlangParameter*> declared;
  std::unordered_map<std::string, const SlangParameter*> first;  // some presets declare hundreds in every pass
  for (const SlangSource* source : sources)
    for (const SlangParameter& parameter : source->parameters) {
      auto [found, added] = first.emplace(parameter.id, &parameter);
      if (added) {
        declared.push_back(&parameter);
      } else if (!same_settings(*found->second, parameter)) {
        warnings.push_back(parameter.place.text() + ": warning: parameter '" + parameter.id + "' is declared at " +
                           found->second->place.text() + " with other settings; those apply");
      }
    }
  std::set<std::string> ids = {"content_width", "content_height"};
  for (const SlangParameter* parameter : declared) {
    double value = preset.parameter_value(parameter->id).value_or(parameter->initial);
    if (!std::isfinite(value)) value = parameter->initial;
    out.shader_ids.push_back(parameter->id);
    out.fixed.push_back(value);
    if (!(parameter->maximum > parameter->minimum)) {
      out.descriptor.push_back(-1);
      continue;
    }
    std::string id = pfx::identifier_from(parameter->id);
    for (int k = 2; ids.count(id); ++k) id = pfx::identifier_from(parameter->id) + "_" + std::to_string(k);
    ids.insert(id);
    // A preset may set a value outside the shader's range (RetroArch takes it): the range grows.
    const double low = std::min(parameter->minimum, value), high = std::max(parameter->maximum, value);
    const std::string label = parameter->label.empty() ? parameter->id : parameter->label;
    out.descriptor.push_back(static_cast<int>(out.descs.size()));
    out.descs.push_back(pfx::desc::param(out.keep(id))
                            .label(out.keep(label))
                            .tooltip(out.keep("The shader parameter " + parameter->id + "."))
                            .float_range(low, high)
                            .display_range(low, high)
                            .step(parameter->step > 0 ? parameter->step : (high - low) / 100)
                            .default_value(value));
  }
  out.content_width = static_cast<int>(out.descs.size());
  out.descs.push_back(pfx::desc::param("content_width")
                          .label("Content width")
                          .tooltip("The width of the picture the shaders see (OriginalSize), in pixels: the frame is "
                                   "averaged down to it. 0: from content_height and the frame's aspect, or the frame's "
                                   "own width when both are 0.")
                          .unit("px")
                          .group("Content")
                          .int_range(0, pfx::libretro::kMaxTextureSide)
                          .display_range(0, 1920)
                          .default_value(0));
  out.content_height = static_cast<int>(out.descs.size());
  out.descs.push_back(pfx::desc::param("content_height")
                          .label("Content lines")
                          .tooltip("The height of the picture the shaders see, in lines (240 for a console's picture): "
                                   "a CRT preset then draws that many scanlines over the frame. 0: from content_width "
                                   "and the frame's aspect, or the frame's own height when both are 0.")
                          .unit("px")
                          .group("Content")
                          .int_range(0, pfx::libretro::kMaxTextureSide)
                          .display_range(0, 1080)
                          .default_value(0));
}

}  // namespace pfx_libretro
