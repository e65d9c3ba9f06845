#include "exr_pixels.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include <ImfFrameBuffer.h>

namespace pfx::app::detail {
namespace {

// Rows are decoded a strip at a time into scratch memory bounded whatever the data window.
// Strips are powers of two up to 256 rows, so they stay multiples of the compression schemes'
// block heights (16, 32, 256 rows) and no block is decoded twice, except for absurdly wide
// images where the memory bound wins.
constexpr std::int64_t kMaxStripRows = 256;
constexpr std::size_t kMaxStripBytes = std::size_t{64} << 20;

// A channel stored at less than full resolution (as the chroma of luminance/chroma images is):
// read whole at its own resolution, then spread over the pixels. Samples sit on the pixels whose
// coordinates are multiples of the sampling; the pixels between them are interpolated linearly,
// and those past the last sample repeat it.
struct Subsampled {
  const ExrChannelPlan::Source* source = nullptr;
  std::int64_t nx = 0, ny = 0;
  std::vector<float> samples;
  // Per data window column: the two sample columns it lies between, and its weight on the second.
  std::vector<std::int64_t> x0, x1;
  std::vector<float> tx;
};

void read_subsampled(Imf::InputPart& file, const ExrWindow& dw, std::vector<Subsampled>* channels) {
  if (channels->empty()) return;
  Imf::FrameBuffer fb;
  for (Subsampled& s : *channels) {
    const int xs = s.source->x_sampling, ys = s.source->y_sampling;
    s.nx = (dw.width() - 1) / xs + 1;
    s.ny = (dw.height() - 1) / ys + 1;
    s.samples.assign(static_cast<std::size_t>(s.nx * s.ny), 0.0f);
    fb.insert(s.source->channel,
              Imf::Slice::Make(Imf::FLOAT, s.samples.data(), Imath::V2i(static_cast<int>(dw.x0), static_cast<int>(dw.y0)),
                               dw.width(), dw.height(), sizeof(float), static_cast<std::size_t>(s.nx) * sizeof(float),
                               xs, ys));
    for (std::int64_t x = 0; x < dw.width(); ++x) {
      const std::int64_t i = x / xs;
      s.x0.push_back(i);
      s.x1.push_back(std::min(i + 1, s.nx - 1));
      s.tx.push_back(static_cast<float>(x - i * xs) / static_cast<float>(xs));
    }
  }
  file.setFrameBuffer(fb);
  file.readPixels(static_cast<int>(dw.y0), static_cast<int>(dw.y1));
}

// Writes rows [y0, y1] of each subsampled channel into its slot of the strip.
void spread_subsampled(const std::vector<Subsampled>& channels, const ExrWindow& dw, std::int64_t y0, std::int64_t y1,
                       std::size_t row_floats, float* strip) {
  for (const Subsampled& s : channels) {
    const int ys = s.source->y_sampling;
    for (std::int64_t y = y0; y <= y1; ++y) {
      const std::int64_t j = (y - dw.y0) / ys, j1 = std::min(j + 1, s.ny - 1);
      const float ty = static_cast<float>((y - dw.y0) - j * ys) / static_cast<float>(ys);
      const float* a = s.samples.data() + j * s.nx;
      const float* b = s.samples.data() + j1 * s.nx;
      float* out = strip + static_cast<std::size_t>(y - y0) * row_floats + s.source->slot;
      for (std::int64_t x = 0; x < dw.width(); ++x) {
        const std::size_t i0 = static_cast<std::size_t>(s.x0[static_cast<std::size_t>(x)]);
        const std::size_t i1 = static_cast<std::size_t>(s.x1[static_cast<std::size_t>(x)]);
        const float t = s.tx[static_cast<std::size_t>(x)];
        const float top = a[i0] + (a[i1] - a[i0]) * t;
        const float bottom = b[i0] + (b[i1] - b[i0]) * t;
        out[static_cast<std::size_t>(x) * kSlotCount] = top + (bottom - top) * ty;
      }
    }
  }
}

// One pixel's slots as RGBA.
void to_rgba(const float* s, ExrColorMode mode, const Imath::V3f& yw, float* rgba) {
  switch (mode) {
    case ExrColorMode::Rgb:
      rgba[0] = s[kSlotR];
      rgba[1] = s[kSlotG];
      rgba[2] = s[kSlotB];
      break;
    case ExrColorMode::Grey:
      rgba[0] = rgba[1] = rgba[2] = s[kSlotR];
      break;
    case ExrColorMode::LuminanceChroma: {
      // RY = (R - Y) / Y and BY = (B - Y) / Y, with Y = yw . (R, G, B) (OpenEXR's ImfRgbaYca.h).
      const float y = s[kSlotR];
      const float r = (s[kSlotG] + 1.0f) * y, b = (s[kSlotB] + 1.0f) * y;
      rgba[0] = r;
      rgba[1] = (y - r * yw.x - b * yw.z) / yw.y;
      rgba[2] = b;
      break;
    }
    case ExrColorMode::None:
      return;
  }
  rgba[3] = s[kSlotA];
}

}  // namespace

void read_planned_pixels(Imf::InputPart& file, const ExrWindow& dw, const ExrWindow& disp, const ExrChannelPlan& plan,
                         const Imath::V3f& yw, Image* img) {
  std::vector<Subsampled> subsampled;
  std::vector<const ExrChannelPlan::Source*> full;
  // A channel can fill two slots (a lone Z is both grey and depth); OpenEXR decodes a channel into
  // one place, so the second slot is a copy of the first.
  std::vector<std::pair<int, int>> copies;  // from slot, to slot
  for (const auto& source : plan.sources) {
    const auto first = std::find_if(plan.sources.data(), &source,
                                    [&](const ExrChannelPlan::Source& s) { return s.channel == source.channel; });
    if (first != &source) {
      copies.emplace_back(first->slot, source.slot);
    } else if (source.x_sampling == 1 && source.y_sampling == 1) {
      full.push_back(&source);
    } else {
      subsampled.emplace_back();
      subsampled.back().source = &source;
    }
  }
  read_subsampled(file, dw, &subsampled);

  const std::size_t row_floats = static_cast<std::size_t>(dw.width()) * kSlotCount;
  std::int64_t strip_rows = kMaxStripRows;
  while (strip_rows > 1 && strip_rows * row_floats * sizeof(float) > kMaxStripBytes) strip_rows /= 2;
  strip_rows = std::min(strip_rows, dw.height());
  // Slots no channel fills keep these: no colour is 0, no alpha is opaque.
  std::vector<float> strip(row_floats * static_cast<std::size_t>(strip_rows), 0.0f);
  for (std::size_t i = kSlotA; i < strip.size(); i += kSlotCount) strip[i] = 1.0f;
  const std::size_t xs = kSlotCount * sizeof(float);
  const std::size_t ys = row_floats * sizeof(float);

  // Only the columns and rows inside the display window are copied out.
  const std::int64_t cx0 = std::max(dw.x0, disp.x0), cx1 = std::min(dw.x1, disp.x1);

  for (std::int64_t y0 = dw.y0; y0 <= dw.y1; y0 += strip_rows) {
    const std::int64_t y1 = std::min(y0 + strip_rows - 1, dw.y1);
    if (!full.empty()) {
      const Imath::V2i origin(static_cast<int>(dw.x0), static_cast<int>(y0));
      Imf::FrameBuffer fb;
      for (const auto* source : full) {
        fb.insert(source->channel, Imf::Slice::Make(Imf::FLOAT, strip.data() + source->slot, origin, dw.width(),
                                                    y1 - y0 + 1, xs, ys));
      }
      file.setFrameBuffer(fb);
      file.readPixels(static_cast<int>(y0), static_cast<int>(y1));
    }
    spread_subsampled(subsampled, dw, y0, y1, row_floats, strip.data());
    const std::size_t strip_floats = static_cast<std::size_t>(y1 - y0 + 1) * row_floats;
    for (const auto& [from, to] : copies) {
      for (std::size_t i = 0; i < strip_floats; i += kSlotCount) strip[i + to] = strip[i + from];
    }

    if (cx0 > cx1) continue;
    for (std::int64_t y = std::max(y0, disp.y0); y <= std::min(y1, disp.y1); ++y) {
      const float* src = strip.data() + static_cast<std::size_t>(y - y0) * row_floats +
                         static_cast<std::size_t>(cx0 - dw.x0) * kSlotCount;
      const std::size_t dst_px = static_cast<std::size_t>(y - disp.y0) * static_cast<std::size_t>(img->width) +
                                 static_cast<std::size_t>(cx0 - disp.x0);
      const std::size_t n = static_cast<std::size_t>(cx1 - cx0 + 1);
      for (std::size_t i = 0; i < n; ++i) {
        const float* s = src + i * kSlotCount;
        if (plan.color != ExrColorMode::None) to_rgba(s, plan.color, yw, img->rgba.data() + (dst_px + i) * 4);
        if (plan.depth) img->depth[dst_px + i] = s[kSlotZ];
      }
    }
  }
}

}  // namespace pfx::app::detail
