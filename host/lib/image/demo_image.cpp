#include "demo_image.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace pfx::app {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kFarDepth = 50.0;
constexpr double kNearDepth = 1.0;
constexpr double kHorizon = 0.45;  // fraction of the height from the top

struct Rgb {
  double r, g, b;
};

Rgb mix(const Rgb& a, const Rgb& b, double t) {
  return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t};
}

struct Disc {
  double u, v, radius;  // centre as fractions of width and height; radius as a fraction of min side
  Rgb colour;
  double depth;
};

struct Spot {
  double u, v, peak;
  Rgb tint;
};

constexpr Disc kDiscs[] = {
    {0.18, 0.28, 0.09, {0.90, 0.35, 0.10}, 25.0},
    {0.48, 0.22, 0.06, {0.20, 0.60, 0.30}, 8.0},
    {0.62, 0.35, 0.05, {0.60, 0.60, 0.65}, 2.5},
};

struct Writer {
  Image* img;
  void set(int x, int y, const Rgb& c, double depth) const {
    const std::size_t i = static_cast<std::size_t>(y) * img->width + x;
    img->rgba[i * 4 + 0] = static_cast<float>(c.r);
    img->rgba[i * 4 + 1] = static_cast<float>(c.g);
    img->rgba[i * 4 + 2] = static_cast<float>(c.b);
    img->depth[i] = static_cast<float>(depth);
  }
  void add(int x, int y, const Rgb& c) const {
    const std::size_t i = static_cast<std::size_t>(y) * img->width + x;
    img->rgba[i * 4 + 0] += static_cast<float>(c.r);
    img->rgba[i * 4 + 1] += static_cast<float>(c.g);
    img->rgba[i * 4 + 2] += static_cast<float>(c.b);
  }
};

Rgb background(double v) {
  if (v < kHorizon) {
    return mix({0.10, 0.22, 0.65}, {0.85, 0.75, 0.60}, v / kHorizon);
  }
  const double t = (v - kHorizon) / (1.0 - kHorizon);
  return mix({0.30, 0.26, 0.20}, {0.12, 0.10, 0.08}, t);
}

bool inside(double u, double v, double u0, double v0, double u1, double v1) {
  return u >= u0 && u < u1 && v >= v0 && v < v1;
}

// Gaussian spots are added on top of whatever is there, centred on a pixel centre so the peak
// value really occurs in the image at any size.
void add_spots(const Writer& out, int w, int h, double side) {
  std::vector<Spot> spots = {
      {0.88, 0.12, 1000.0, {1.00, 0.95, 0.85}},
      {0.18, 0.28, 10.0, {1.00, 0.70, 0.40}},
      {0.48, 0.22, 100.0, {0.60, 0.90, 1.00}},
      {0.62, 0.35, 300.0, {1.00, 1.00, 1.00}},
  };
  for (int i = 0; i < 7; ++i) {
    spots.push_back({0.1 + 0.8 * i / 6.0, 0.5, 10.0 * std::exp2(i), {1.0, 0.85, 0.6}});
  }
  const double sigma = std::max(0.75, 0.004 * side);
  const int reach = static_cast<int>(std::ceil(5.0 * sigma));
  for (const Spot& s : spots) {
    const int cx = std::min(w - 1, static_cast<int>(s.u * w));
    const int cy = std::min(h - 1, static_cast<int>(s.v * h));
    for (int y = std::max(0, cy - reach); y <= std::min(h - 1, cy + reach); ++y) {
      for (int x = std::max(0, cx - reach); x <= std::min(w - 1, cx + reach); ++x) {
        const double d2 = double(x - cx) * (x - cx) + double(y - cy) * (y - cy);
        const double k = s.peak * std::exp(-d2 / (2.0 * sigma * sigma));
        out.add(x, y, {k * s.tint.r, k * s.tint.g, k * s.tint.b});
      }
    }
  }
}

}  // namespace

Image make_demo_image(int width, int height) {
  Image img;
  if (width <= 0 || height <= 0) return img;
  img.width = width;
  img.height = height;
  img.rgba.assign(img.pixel_count() * 4, 1.0f);
  img.depth.assign(img.pixel_count(), 0.0f);
  const Writer out{&img};
  const double side = std::min(width, height);
  const double zone_cx = 0.75 * width, zone_cy = 0.62 * height, zone_r = 0.15 * side;

  for (int y = 0; y < height; ++y) {
    const double v = (y + 0.5) / height;
    for (int x = 0; x < width; ++x) {
      const double u = (x + 0.5) / width;
      Rgb c = background(v);
      // Sky at the far depth; the ground recedes geometrically from the bottom row to the
      // horizon, as a plane seen in perspective. Every object below is nearer than the
      // background it covers, so the depth buffer stays physically plausible.
      const double ground = std::max(0.0, (v - kHorizon) / (1.0 - kHorizon));
      double depth = kNearDepth * std::pow(kFarDepth / kNearDepth, 1.0 - ground);

      if (inside(u, v, 0.05, 0.62, 0.30, 0.92)) {
        const bool on = ((x + y) & 1) != 0;
        c = on ? Rgb{0.75, 0.75, 0.75} : Rgb{0.05, 0.05, 0.05};
        depth = 1.5;
      } else if (inside(u, v, 0.36, 0.58, 0.56, 0.80)) {
        const bool line = x % 3 == 0 || y % 7 == 0;
        c = line ? Rgb{0.90, 0.90, 0.90} : Rgb{0.03, 0.03, 0.03};
        depth = 4.0;
      } else {
        // Phase pi r^2 / (2R) has a local frequency of r / (2R) cycles per pixel: 0.5 at the rim.
        const double dx = x + 0.5 - zone_cx, dy = y + 0.5 - zone_cy;
        const double r2 = dx * dx + dy * dy;
        if (r2 < zone_r * zone_r) {
          const double k = 0.5 + 0.5 * std::cos(kPi * r2 / (2.0 * zone_r));
          c = {0.05 + 0.8 * k, 0.05 + 0.8 * k, 0.05 + 0.8 * k};
          depth = 5.0;
        }
      }

      for (const Disc& d : kDiscs) {
        const double dx = (x + 0.5 - d.u * width) / (d.radius * side);
        const double dy = (y + 0.5 - d.v * height) / (d.radius * side);
        const double q = dx * dx + dy * dy;
        if (q < 1.0) {
          // Lit like a sphere from the front, so the discs read as objects, not stickers.
          const double shade = 0.3 + 0.7 * std::sqrt(1.0 - q);
          c = {d.colour.r * shade, d.colour.g * shade, d.colour.b * shade};
          depth = d.depth;
        }
      }
      out.set(x, y, c, depth);
    }
  }
  add_spots(out, width, height, side);
  return img;
}

}  // namespace pfx::app
