#include "reference/dof_gather_model.hpp"

#include <algorithm>
#include <cmath>

#include "dof_gather_plan.hpp"
#include "dof_rings.hpp"
#include "reference/dof_inputs.hpp"

namespace pfx_dof {
namespace {

double density(double r) { return 1.0 / (M_PI * (r * r + 1.0 / 12.0)); }

Texture prepare(const GatherPlan& plan, const Texture& sharp, const std::vector<double>& coc, double max_coc) {
  Texture work(plan.work_width, plan.work_height);
  const int w = sharp.width, h = sharp.height;
  for (int y = 0; y < work.height; ++y)
    for (int x = 0; x < work.width; ++x) {
      Texel& t = work.at(x, y);
      if (!plan.half) {
        t = sharp.fetch(x, y);
        t[3] = coc[static_cast<size_t>(y) * w + x];
        continue;
      }
      t = {0, 0, 0, max_coc};
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
          const int qx = std::min(2 * x + i, w - 1), qy = std::min(2 * y + j, h - 1);
          for (int k = 0; k < 3; ++k) t[k] += 0.25 * sharp.fetch(qx, qy)[k];
          t[3] = std::min(t[3], coc[static_cast<size_t>(qy) * w + qx]);
        }
    }
  store_half(&work);
  return work;
}

Texture dilated_tiles(const GatherPlan& plan, const Texture& work) {
  Texture tiles(plan.tiles_width, plan.tiles_height);
  for (int ty = 0; ty < tiles.height; ++ty)
    for (int tx = 0; tx < tiles.width; ++tx) {
      double near = 0, reach = 0;
      for (int y = ty * plan.tile; y < std::min((ty + 1) * plan.tile, work.height); ++y)
        for (int x = tx * plan.tile; x < std::min((tx + 1) * plan.tile, work.width); ++x) {
          const double c = work.fetch(x, y)[3];
          near = std::max(near, -c);
          reach = std::max(reach, std::fabs(c));
        }
      tiles.at(tx, ty) = {near, reach, 0, 0};
    }
  store_half(&tiles);
  Texture dilated(tiles.width, tiles.height);
  for (int ty = 0; ty < tiles.height; ++ty)
    for (int tx = 0; tx < tiles.width; ++tx) {
      double near = 0;
      for (int y = -plan.dilation; y <= plan.dilation; ++y)
        for (int x = -plan.dilation; x <= plan.dilation; ++x) near = std::max(near, tiles.fetch(tx + x, ty + y)[0]);
      dilated.at(tx, ty) = {near, tiles.fetch(tx, ty)[1], 0, 0};
    }
  store_half(&dilated);
  return dilated;
}

double tile_reach(const Texture& dilated, int x, int y, int tile) {
  const Texel& t = dilated.fetch(x / tile, y / tile);
  return std::max(t[0], t[1]);
}

double tile_near(const Texture& dilated, int x, int y, int tile) { return dilated.fetch(x / tile, y / tile)[0]; }

// The gather of one work pixel: rgb and what the near field leaves visible.
Texel gather(const GatherPlan& plan, const Texture& work, const std::vector<RingSample>& rings, double near_reach,
             int px, int py) {
  const double scale = plan.half ? 0.5 : 1.0;
  const Texel& center = work.fetch(px, py);
  const double r_p = std::max(0.5 * std::fabs(center[3]) * scale, 0.5);
  const double radius = std::max(r_p, 0.5 * near_reach * scale);
  double far_weight = density(r_p), near_weight = 0;
  double far_sum[3], near_sum[3] = {0, 0, 0};
  for (int k = 0; k < 3; ++k) far_sum[k] = center[k] * far_weight;
  const std::vector<DiscOffset>& disc = disc_offsets();
  const int count = static_cast<int>(rings.size());
  const bool whole_disc = count >= kDiscOffsetCount || disc[count].length >= radius + 0.5;
  for (int i = 0; i < count; ++i) {
    int ox, oy;
    double area;
    if (whole_disc) {
      if (disc[i].length >= radius + 0.5) break;
      ox = disc[i].x;
      oy = disc[i].y;
      area = 1.0;
    } else {
      ox = static_cast<int>(std::floor(double(rings[i].x) * radius + 0.5));
      oy = static_cast<int>(std::floor(double(rings[i].y) * radius + 0.5));
      if (ox == 0 && oy == 0) continue;
      area = double(rings[i].area) * radius * radius;
    }
    const double d = std::hypot(double(ox), double(oy));
    const Texel& q = work.fetch(px + ox, py + oy);
    if (q[3] < center[3]) {
      const double r_q = std::max(0.5 * std::fabs(q[3]) * scale, 0.5);
      const double w = area * disc_coverage(d, r_q) * density(r_q);
      for (int k = 0; k < 3; ++k) near_sum[k] += w * q[k];
      near_weight += w;
    } else {
      const double w = area * disc_coverage(d, r_p) * density(r_p);
      for (int k = 0; k < 3; ++k) far_sum[k] += w * q[k];
      far_weight += w;
    }
  }
  const double alpha = std::min(near_weight, 1.0);
  Texel out{0, 0, 0, 1.0 - alpha};
  for (int k = 0; k < 3; ++k) {
    const double near = near_weight > 0 ? near_sum[k] / near_weight : 0.0;
    out[k] = far_sum[k] / far_weight * (1.0 - alpha) + near * alpha;
  }
  return out;
}

}  // namespace

void evaluate_gather_model(const Settings& settings, const pfx_frame& frame, const float* color, const float* depth,
                           float* output) {
  const int w = static_cast<int>(frame.width), h = static_cast<int>(frame.height);
  const GatherPlan plan = plan_gather(frame.width, frame.height, settings);
  const Texture sharp = safe_color(frame, color, settings.nonfinite);
  const std::vector<double> coc = coc_image(frame, frame_lens(frame, settings, depth), depth);
  const Texture work = prepare(plan, sharp, coc, settings.max_coc);
  const Texture dilated = dilated_tiles(plan, work);
  const std::vector<RingSample> rings = ring_samples(settings.samples);

  auto write = [&](int x, int y, const Texel& t) {
    for (int k = 0; k < 4; ++k) output[(static_cast<size_t>(y) * w + x) * 4 + k] = static_cast<float>(t[k]);
  };
  if (!plan.half) {
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const double reach = tile_reach(dilated, x, y, plan.tile);
        Texel out = sharp.fetch(x, y);
        if (reach >= 1.0) {
          const Texel g = gather(plan, work, rings, tile_near(dilated, x, y, plan.tile), x, y);
          for (int k = 0; k < 3; ++k) out[k] = g[k];
        }
        write(x, y, out);
      }
    return;
  }
  Texture blur(plan.work_width, plan.work_height);
  for (int y = 0; y < blur.height; ++y)
    for (int x = 0; x < blur.width; ++x) {
      const double reach = tile_reach(dilated, x, y, plan.tile);
      const Texel& c = work.fetch(x, y);
      blur.at(x, y) = reach < 1.0 ? Texel{c[0], c[1], c[2], 1.0}
                                  : gather(plan, work, rings, tile_near(dilated, x, y, plan.tile), x, y);
    }
  store_half(&blur);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Texel& sharp_texel = sharp.fetch(x, y);
      if (tile_reach(dilated, x, y, kTileFramePixels) < 1.0) {
        write(x, y, sharp_texel);
        continue;
      }
      const double hx = x * 0.5 - 0.25, hy = y * 0.5 - 0.25;
      const double bx = std::floor(hx), by = std::floor(hy), fx = hx - bx, fy = hy - by;
      const int ix = static_cast<int>(bx), iy = static_cast<int>(by);
      auto bilinear = [&](int i, int j) { return (i == 1 ? fx : 1.0 - fx) * (j == 1 ? fy : 1.0 - fy); };
      double lo = HUGE_VAL, hi = -HUGE_VAL, interpolated = 0;
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
          const double a = work.fetch(ix + i, iy + j)[3];
          lo = std::min(lo, a);
          hi = std::max(hi, a);
          interpolated += bilinear(i, j) * a;
        }
      // One smooth surface under the four texels: plain bilinear, and the interpolated CoC (the
      // GPU's fast path); else CoC-weighted taps and the pixel's own CoC.
      const bool even = hi - lo <= 0.25 * (1.0 + 0.25 * std::fabs(interpolated));
      const double c = even ? interpolated : coc[static_cast<size_t>(y) * w + x];
      const double t = std::clamp(std::fabs(c) - 1.0, 0.0, 1.0);
      Texel b{0, 0, 0, 0};
      double half_color[3] = {0, 0, 0}, total = 0;
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
          const Texel& wk = work.fetch(ix + i, iy + j);
          const double weight =
              even ? bilinear(i, j)
                   : bilinear(i, j) * std::max(1e-3, 1.0 - std::fabs(wk[3] - c) / (1.0 + 0.25 * std::fabs(c)));
          const Texel& bl = blur.fetch(ix + i, iy + j);
          for (int k = 0; k < 4; ++k) b[k] += weight * bl[k];
          for (int k = 0; k < 3; ++k) half_color[k] += weight * wk[k];
          total += weight;
        }
      Texel out = sharp_texel;
      for (int k = 0; k < 3; ++k)
        out[k] = b[k] / total + b[3] / total * (1.0 - t) * (sharp_texel[k] - half_color[k] / total);
      write(x, y, out);
    }
}

}  // namespace pfx_dof
