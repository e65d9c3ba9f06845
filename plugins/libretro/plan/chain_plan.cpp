#include "chain_plan.hpp"

#include <algorithm>
#include <cmath>

namespace pfx::libretro {

bool is_integer_format(const std::string& format) {
  return format.size() > 5 && (format.find("_UINT") != std::string::npos || format.find("_SINT") != std::string::npos);
}

ChainPlan plan_chain(const Preset& preset, const std::vector<std::string>& formats,
                     const std::vector<PassInterface>& passes) {
  ChainPlan plan;
  const std::size_t count = preset.passes.size();
  plan.passes.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const PresetPass& pass = preset.passes[i];
    PassPlan& p = plan.passes[i];
    if (i < formats.size() && !formats[i].empty()) p.format = formats[i];
    if (pass.scaled && pass.srgb_framebuffer)
      p.format = "R8G8B8A8_SRGB";
    else if (pass.scaled && pass.float_framebuffer)
      p.format = "R16G16B16A16_SFLOAT";
    if (i + 1 < count) p.mipmapped = preset.passes[i + 1].mipmap_input;
  }
  if (count > 0) plan.original_mipmapped = preset.passes[0].mipmap_input;
  for (const PassInterface& pass : passes)
    for (const ReflectedSampler& sampler : pass.samplers) {
      if (sampler.semantic.kind == SemanticKind::kPassFeedback && sampler.semantic.index >= 0 &&
          static_cast<std::size_t>(sampler.semantic.index) < count)
        plan.passes[static_cast<std::size_t>(sampler.semantic.index)].feedback = true;
      if (sampler.semantic.kind == SemanticKind::kOriginalHistory)
        plan.history = std::max(plan.history, sampler.semantic.index);
    }
  if (count > 0) {
    // A last pass at the viewport's size draws straight into the output: RetroArch's stock blit
    // would copy it texel for texel. Not an sRGB one, which that blit reads back decoded.
    const PresetPass& last = preset.passes.back();
    const bool viewport_sized = last.x.type == ScaleType::kViewport && last.y.type == ScaleType::kViewport &&
                                last.x.factor == 1.0 && last.y.factor == 1.0;
    plan.finish = (last.scaled && !(viewport_sized && plan.passes.back().format != "R8G8B8A8_SRGB")) ||
                  plan.passes.back().feedback;
    // Into the host's 8-bit output as it is: the format is the output's.
    plan.passes.back().to_output = !plan.finish;
    if (!plan.finish) plan.passes.back().format = "R8G8B8A8_UNORM";
  }
  return plan;
}

namespace {

int scaled_axis(const AxisScale& axis, int source, int viewport) {
  double size = 0;
  switch (axis.type) {
    case ScaleType::kSource:
      size = std::round(static_cast<float>(source * axis.factor));
      break;
    case ScaleType::kViewport:
      size = std::round(static_cast<float>(viewport * axis.factor));
      break;
    case ScaleType::kAbsolute:
      size = axis.pixels;
      break;
  }
  if (!(size >= 1)) return 1;  // NaN too
  return static_cast<int>(std::min<double>(size, kMaxTextureSide));
}

}  // namespace

std::vector<PixelSize> pass_sizes(const Preset& preset, const ChainPlan& plan, PixelSize original, PixelSize viewport) {
  std::vector<PixelSize> sizes;
  PixelSize source = original;
  for (std::size_t i = 0; i < preset.passes.size(); ++i) {
    const PresetPass& pass = preset.passes[i];
    const bool last = i + 1 == preset.passes.size();
    PixelSize size = source;
    if (last && (plan.passes.empty() || plan.passes.back().to_output || !pass.scaled))
      size = viewport;
    else if (pass.scaled)
      size = {scaled_axis(pass.x, source.width, viewport.width), scaled_axis(pass.y, source.height, viewport.height)};
    sizes.push_back(size);
    source = size;
  }
  return sizes;
}

}  // namespace pfx::libretro
