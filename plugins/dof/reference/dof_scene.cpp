#include "reference/dof_scene.hpp"

#include <algorithm>
#include <cmath>
#include <thread>

namespace pfx_dof {
namespace {

struct Vec {
  double x, y, z;
};
Vec operator+(Vec a, Vec b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec operator-(Vec a, Vec b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec operator*(Vec a, double s) { return {a.x * s, a.y * s, a.z * s}; }

struct Hit {
  double t = HUGE_VAL;
  SceneObject object = OBJECT_NONE;
  Vec point{0, 0, 0};
  double rgb[3] = {0, 0, 0};
};

struct Box {
  Vec lo, hi;
  SceneObject object;
};

struct Sphere {
  Vec center;
  double radius;
  double rgb[3];
};

constexpr double kWallZ = -40.0, kGroundY = -1.6;

const Box kBoxes[] = {
    {{-0.6, -1.6, -kSceneFocusDistance - 0.5}, {0.3, 0.5, -kSceneFocusDistance}, OBJECT_SUBJECT},
    {{-1.55, -1.0, -2.3}, {-0.75, -0.1, -1.6}, OBJECT_NEAR_BOX},
    {{1.6, -1.6, -16.0}, {4.0, 1.4, -14.0}, OBJECT_FAR_BOX},
};

// Bright enough to show bokeh, and a few pixels wide even at 192 px across, so the pinhole frame's
// depth (taken at pixel centres) describes them.
const Sphere kLights[] = {
    {{0.55, 0.3, -2.2}, 0.04, {12, 10, 7}},                    // near, in front of the focus
    {{0.85, -0.6, -kSceneFocusDistance}, 0.06, {16, 16, 16}},  // in focus
    {{-2.5, 1.2, -12.0}, 0.15, {6, 9, 18}},                    // far
    {{-1.2, 2.6, -39.6}, 0.4, {20, 14, 8}},                    // on the wall
    {{4.0, 3.0, -39.6}, 0.4, {16, 16, 16}},
};

void shade(Hit* h) {
  const Vec p = h->point;
  switch (h->object) {
    case OBJECT_WALL: {
      // Smooth behind the subject, so what the subject hides is like what it does not; bold bars far
      // to the sides, where blur shows.
      const double bar = (std::fabs(p.x) > 16.0 && std::fmod(std::fabs(p.x), 2.0) < 0.6) ? 0.35 : 0.0;
      h->rgb[0] = 0.10 + 0.04 * std::sin(0.2 * p.x) + bar;
      h->rgb[1] = 0.12 + 0.03 * std::cos(0.15 * p.y) + bar;
      h->rgb[2] = 0.18 + bar;
      break;
    }
    case OBJECT_GROUND: {
      const bool odd = (static_cast<long>(std::floor(p.x)) + static_cast<long>(std::floor(p.z))) & 1;
      h->rgb[0] = odd ? 0.30 : 0.08;
      h->rgb[1] = odd ? 0.28 : 0.07;
      h->rgb[2] = odd ? 0.22 : 0.05;
      break;
    }
    case OBJECT_SUBJECT: {
      const bool line = std::fmod(p.y + 10.0, 0.25) < 0.03;  // fine detail that must stay sharp
      h->rgb[0] = h->rgb[1] = h->rgb[2] = line ? 0.1 : 1.0;
      break;
    }
    case OBJECT_NEAR_BOX: {
      const bool check = (static_cast<long>(std::floor(p.x * 10)) + static_cast<long>(std::floor(p.y * 10))) & 1;
      h->rgb[0] = check ? 0.9 : 0.5;
      h->rgb[1] = check ? 0.45 : 0.2;
      h->rgb[2] = 0.05;
      break;
    }
    case OBJECT_FAR_BOX: {
      const bool stripe = std::fmod(p.y + 10.0, 0.5) < 0.25;
      h->rgb[0] = 0.05;
      h->rgb[1] = stripe ? 0.25 : 0.12;
      h->rgb[2] = stripe ? 0.6 : 0.3;
      break;
    }
    default: break;
  }
}

// Nearest hit of origin + t * dir for t > 0.
Hit trace(Vec o, Vec d) {
  Hit h;
  auto take = [&](double t, SceneObject object) {
    if (t > 1e-9 && t < h.t) {
      h.t = t;
      h.object = object;
    }
  };
  if (d.z < 0) take((kWallZ - o.z) / d.z, OBJECT_WALL);
  if (d.y < 0) {
    const double t = (kGroundY - o.y) / d.y;
    if (o.z + t * d.z > kWallZ) take(t, OBJECT_GROUND);
  }
  for (const Box& b : kBoxes) {
    double t0 = -HUGE_VAL, t1 = HUGE_VAL;
    const double os[3] = {o.x, o.y, o.z}, ds[3] = {d.x, d.y, d.z};
    const double lo[3] = {b.lo.x, b.lo.y, b.lo.z}, hi[3] = {b.hi.x, b.hi.y, b.hi.z};
    for (int k = 0; k < 3; ++k) {
      if (ds[k] == 0) {
        if (os[k] < lo[k] || os[k] > hi[k]) t0 = HUGE_VAL;
        continue;
      }
      double a = (lo[k] - os[k]) / ds[k], c = (hi[k] - os[k]) / ds[k];
      if (a > c) std::swap(a, c);
      t0 = std::max(t0, a);
      t1 = std::min(t1, c);
    }
    if (t0 <= t1) take(t0, b.object);
  }
  const Sphere* light = nullptr;
  for (const Sphere& s : kLights) {
    const Vec oc = o - s.center;
    const double b = oc.x * d.x + oc.y * d.y + oc.z * d.z;
    const double dd = d.x * d.x + d.y * d.y + d.z * d.z;
    const double c = oc.x * oc.x + oc.y * oc.y + oc.z * oc.z - s.radius * s.radius;
    const double disc = b * b - dd * c;
    if (disc < 0) continue;
    const double t = (-b - std::sqrt(disc)) / dd;
    if (t > 1e-9 && t < h.t) {
      h.t = t;
      h.object = OBJECT_LIGHT;
      light = &s;
    }
  }
  h.point = o + d * h.t;
  if (light) {
    for (int k = 0; k < 3; ++k) h.rgb[k] = light->rgb[k];
  } else {
    shade(&h);
  }
  return h;
}

// Both images integrate over each pixel's square through the same kGrid x kGrid points, so the two
// agree wherever the lens does not matter (the plane in focus) and keep the energy of lights
// smaller than a pixel.
constexpr int kGrid = 4, kPixelSamples = kGrid * kGrid;

// The pinhole ray through point `sample` of pixel (x, y) (rows bottom first), with dir.z = -1.
Vec pixel_direction(const pfx_frame& frame, int x, int y, int sample) {
  const double ty = std::tan(0.5 * double(frame.camera.fovy));
  const double tx = ty * double(frame.camera.aspect);
  const double sx = (sample % kGrid + 0.5) / kGrid, sy = (sample / kGrid + 0.5) / kGrid;
  return {(2.0 * (x + sx) / frame.width - 1.0) * tx, (2.0 * (y + sy) / frame.height - 1.0) * ty, -1.0};
}

uint64_t mix64(uint64_t z) {  // splitmix64's finaliser
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

double unit(uint64_t bits) { return double(bits >> 11) * 0x1.0p-53; }

// Shirley and Chiu's concentric map of the square [-1,1]^2 onto the unit disc: strata stay strata.
void concentric_disc(double a, double b, double* x, double* y) {
  if (a == 0 && b == 0) {
    *x = *y = 0;
    return;
  }
  double r, phi;
  if (std::fabs(a) > std::fabs(b)) {
    r = a;
    phi = M_PI / 4 * (b / a);
  } else {
    r = b;
    phi = M_PI / 2 - M_PI / 4 * (a / b);
  }
  *x = r * std::cos(phi);
  *y = r * std::sin(phi);
}

template <typename RowFunction>
void for_rows(int height, RowFunction f) {
  const int threads = std::max(1u, std::min(16u, std::thread::hardware_concurrency()));
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t)
    pool.emplace_back([&, t] {
      for (int y = t; y < height; y += threads) f(y);
    });
  for (std::thread& th : pool) th.join();
}

}  // namespace

SceneFrame render_pinhole(const pfx_frame& frame) {
  SceneFrame out;
  out.width = static_cast<int>(frame.width);
  out.height = static_cast<int>(frame.height);
  const size_t n = static_cast<size_t>(out.width) * out.height;
  out.rgba.assign(n * 4, 1.0f);
  out.depth.assign(n, HUGE_VALF);
  out.object.assign(n, OBJECT_NONE);
  for_rows(out.height, [&](int y) {
    for (int x = 0; x < out.width; ++x) {
      // Colour: the mean over the pixel's square. Depth and object: the nearest of its points, so a
      // pixel that a small bright object only partly covers still blurs as that object does.
      const size_t i = static_cast<size_t>(y) * out.width + x;
      double sum[3] = {0, 0, 0}, nearest = HUGE_VAL;
      for (int p = 0; p < kPixelSamples; ++p) {
        const Hit sample = trace({0, 0, 0}, pixel_direction(frame, x, y, p));
        for (int k = 0; k < 3; ++k) sum[k] += sample.rgb[k];
        if (-sample.point.z < nearest) {
          nearest = -sample.point.z;
          out.object[i] = sample.object;
        }
      }
      for (int k = 0; k < 3; ++k) out.rgba[i * 4 + k] = static_cast<float>(sum[k] / kPixelSamples);
      out.depth[i] = static_cast<float>(nearest);
    }
  });
  return out;
}

std::vector<float> render_lens_truth(const pfx_frame& frame, double aperture_m, double focus_distance_m,
                                     int lens_samples, uint64_t seed) {
  const int w = static_cast<int>(frame.width), h = static_cast<int>(frame.height);
  std::vector<float> rgba(static_cast<size_t>(w) * h * 4, 1.0f);
  // A multiple of kGrid, so every point of the pixel's square gets the same number of lens samples.
  int side = std::max(1, static_cast<int>(std::ceil(std::sqrt(double(lens_samples)))));
  side = (side + kGrid - 1) / kGrid * kGrid;
  const double lens_radius = 0.5 * aperture_m;
  for_rows(h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      uint64_t state = mix64(seed ^ mix64((static_cast<uint64_t>(y) << 32) | static_cast<uint64_t>(x)));
      const double turn = 2 * M_PI * unit(state);
      const double c = std::cos(turn), s = std::sin(turn);
      double sum[3] = {0, 0, 0};
      for (int j = 0; j < side; ++j)
        for (int i = 0; i < side; ++i) {
          state = mix64(state + 0x9e3779b97f4a7c15ull);
          const double a = 2.0 * (i + unit(state)) / side - 1.0;
          state = mix64(state + 0x9e3779b97f4a7c15ull);
          const double b = 2.0 * (j + unit(state)) / side - 1.0;
          double lx, ly;
          concentric_disc(a, b, &lx, &ly);
          const Vec lens{lens_radius * (c * lx - s * ly), lens_radius * (s * lx + c * ly), 0.0};
          // Each point of the pixel's square meets every fourth stratum of the lens each way, so
          // lens samples from all over the aperture, and all points equally often.
          const int point = (i % kGrid) + kGrid * (j % kGrid);
          const Vec focus = pixel_direction(frame, x, y, point) * focus_distance_m;
          const Hit hit = trace(lens, focus - lens);
          for (int k = 0; k < 3; ++k) sum[k] += hit.rgb[k];
        }
      const size_t i = (static_cast<size_t>(y) * w + x) * 4;
      for (int k = 0; k < 3; ++k) rgba[i + k] = static_cast<float>(sum[k] / (side * side));
    }
  });
  return rgba;
}

}  // namespace pfx_dof
