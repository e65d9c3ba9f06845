#include "shift_probe.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "image_texture.hpp"

namespace pfx::bench {
namespace {

constexpr int kPositions = 16;
// Bright enough to clear any sensible threshold, far from the half-float maximum.
constexpr float kProbeValue = 1000.0f;

}  // namespace

bool measure_shift(pfx::host::Chain& chain, pfx_frame frame, uint32_t depth, ShiftFigures* out, std::string* error) {
  const int w = static_cast<int>(frame.width), h = static_cast<int>(frame.height);
  // The window the responses are compared in: an eighth of the shorter side around the pixel.
  const int reach = std::max(1, std::min(w, h) / 8);
  const int y0 = h / 2, x0 = std::max(0, w / 2 - kPositions / 2);
  std::vector<double> energy;
  std::vector<std::vector<double>> windows;
  pfx::app::Image probe;
  probe.width = w;
  probe.height = h;
  probe.rgba.assign(static_cast<size_t>(w) * h * 4, 0.0f);
  for (size_t i = 3; i < probe.rgba.size(); i += 4) probe.rgba[i] = 1.0f;
  const uint32_t output = pfx::app::create_color_texture(w, h);
  bool ok = true;
  for (int i = 0; i < kPositions && ok; ++i) {
    const int px = std::min(x0 + i, w - 1);
    const size_t at = (static_cast<size_t>(y0) * w + px) * 4;
    for (int c = 0; c < 3; ++c) probe.rgba[at + c] = kProbeValue;
    pfx::host::FrameTextures textures;
    textures.color = pfx::app::upload_color_texture(probe);
    textures.depth = depth;
    ok = chain.render(frame, textures, output, error);
    pfx::app::delete_texture(textures.color);
    for (int c = 0; c < 3; ++c) probe.rgba[at + c] = 0.0f;
    if (!ok) break;
    const pfx::app::Image result = pfx::app::download_color_texture(output, w, h);  // rows top first, as probe
    double total = 0;
    std::vector<double> window;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const size_t k = (static_cast<size_t>(y) * w + x) * 4;
        double added = 0;
        for (int c = 0; c < 3; ++c) added += result.rgba[k + c] - ((x == px && y == y0) ? kProbeValue : 0.0f);
        if (!std::isfinite(added)) added = 0;
        total += added;
        if (std::abs(x - px) <= reach && std::abs(y - y0) <= reach) window.push_back(added);
      }
    energy.push_back(total);
    windows.push_back(window);
  }
  pfx::app::delete_texture(output);
  if (!ok) return false;
  double mean = 0, variance = 0;
  for (double e : energy) mean += e / kPositions;
  for (double e : energy) variance += (e - mean) * (e - mean) / kPositions;
  out->energy_cv = mean != 0 ? std::sqrt(variance) / std::fabs(mean) : 0.0;
  // Windows near a frame edge are cut short; compare only the cells every window has.
  size_t cells = windows.front().size();
  for (const auto& win : windows) cells = std::min(cells, win.size());
  double deviation = 0, norm = 0;
  for (size_t k = 0; k < cells; ++k) {
    double m = 0;
    for (const auto& win : windows) m += win[k] / kPositions;
    for (const auto& win : windows) deviation += (win[k] - m) * (win[k] - m) / kPositions;
    norm += m * m;
  }
  out->shape_rms = norm > 0 ? std::sqrt(deviation / norm) : 0.0;
  return true;
}

}  // namespace pfx::bench
