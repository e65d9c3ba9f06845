// Real images: pfx-render --input X.exr --chain bloom --out Y.exr gives a finite output
// on high-dynamic-range photographs and on frames holding every half-float value, for every bloom
// mode and for glare. The images are made here (no files from outside the repository): a
// photograph-like HDR frame (sky, a sun near the half-float maximum, specular glints, deep
// shadows, sensor-like noise) and every half-float bit pattern.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "exr_io.hpp"

namespace fs = std::filesystem;

namespace {

struct Scratch {
  fs::path dir = fs::temp_directory_path() / ("pfx-bloom-render-" + std::to_string(::getpid()));
  Scratch() { fs::create_directories(dir); }
  ~Scratch() { fs::remove_all(dir); }
  std::string operator/(const std::string& name) const { return (dir / name).string(); }
};

// A deterministic value in [0, 1) per pixel and salt.
double hash01(int x, int y, int salt) {
  uint32_t h = uint32_t(x) * 73856093u ^ uint32_t(y) * 19349663u ^ uint32_t(salt) * 83492791u;
  h ^= h >> 13;
  h *= 0x5bd1e995u;
  h ^= h >> 15;
  return (h & 0xffffff) / double(0x1000000);
}

// Rows top first, as EXR files hold them.
pfx::app::Image hdr_photograph(int w, int h) {
  pfx::app::Image img;
  img.width = w, img.height = h;
  img.rgba.resize(size_t(w) * h * 4);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double v = double(y) / h, u = double(x) / w;
      double r, g, b;
      if (v < 0.55) {  // sky, brighter toward the horizon and the sun
        const double glow = 40.0 / (1.0 + 400.0 * ((u - 0.7) * (u - 0.7) + (v - 0.3) * (v - 0.3)));
        r = 0.8 + 2.0 * v + glow, g = 1.0 + 1.5 * v + 0.8 * glow, b = 2.5 + 0.6 * glow;
      } else {  // ground: textured, with shadows down to 1e-3
        const double texture = 0.05 + 0.3 * hash01(x / 4, y / 4, 1);
        const double shadow = (x / 24 + y / 16) % 3 == 0 ? 0.004 : 1.0;
        r = texture * shadow, g = 0.8 * texture * shadow, b = 0.6 * texture * shadow;
        if (hash01(x, y, 2) > 0.995) r = g = b = 2000.0 + 58000.0 * hash01(x, y, 3);  // glints
      }
      if ((u - 0.7) * (u - 0.7) * w * w + (v - 0.3) * (v - 0.3) * h * h < 25.0) r = g = b = 30000.0;  // the sun
      const double noise = 1.0 + 0.05 * (hash01(x, y, 4) - 0.5);  // sensor noise, multiplicative
      float* c = &img.rgba[(size_t(y) * w + x) * 4];
      c[0] = float(r * noise), c[1] = float(g * noise), c[2] = float(b * noise), c[3] = 1.0f;
    }
  return img;
}

float half_to_float(uint16_t bits) {
  const int sign = (bits >> 15) ? -1 : 1, exponent = (bits >> 10) & 0x1f, mantissa = bits & 0x3ff;
  if (exponent == 0x1f) return mantissa ? std::nanf("") : sign * INFINITY;
  if (exponent == 0) return sign * std::ldexp(float(mantissa), -24);
  return sign * std::ldexp(float(mantissa | 0x400), exponent - 25);
}

// 256x256 RGBA: every bit pattern four times, NaNs, +-Inf, denormals and -0 among them.
pfx::app::Image every_half_value() {
  pfx::app::Image img;
  img.width = img.height = 256;
  img.rgba.resize(size_t(256) * 256 * 4);
  for (size_t i = 0; i < img.rgba.size(); ++i) img.rgba[i] = half_to_float(uint16_t((i * 40503u) & 0xffffu));
  return img;
}

int render(const std::string& args) {
  const std::string command = std::string(PFX_RENDER) + " --plugins " PFX_BLOOM_PLUGIN_DIR " " + args + " > /dev/null 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

const char* const kVariants[][2] = {{"bloom", "bloom.mode=chain"},   {"bloom", "bloom.mode=chain13"},
                                    {"bloom", "bloom.mode=gaussian"}, {"bloom", "bloom.mode=mgf"},
                                    {"glare", "glare.streaks=6"}};

}  // namespace

TEST_CASE("pfx-render blooms an HDR photograph from an EXR into a finite EXR in every mode", "[bloom][render]") {
  Scratch scratch;
  std::string error;
  const pfx::app::Image photo = hdr_photograph(320, 200);
  REQUIRE(pfx::app::write_exr(scratch / "photo.exr", photo, pfx::app::ExrPixelType::Half, &error));
  pfx::app::Image input;
  REQUIRE(pfx::app::read_exr(scratch / "photo.exr", &input, &error));  // as half, what the effect sees
  for (const auto& [effect, setting] : kVariants) {
    INFO(effect << " " << setting);
    REQUIRE(render("--input " + scratch / "photo.exr" + " --chain " + effect + " --set " + setting + " --out " +
                   scratch / "out.exr") == 0);
    pfx::app::Image out;
    REQUIRE(pfx::app::read_exr(scratch / "out.exr", &out, &error));
    REQUIRE((out.width == 320 && out.height == 200));
    double added = 0;
    size_t not_finite = 0, darker = 0;
    for (size_t i = 0; i < out.rgba.size(); ++i) {
      not_finite += !std::isfinite(out.rgba[i]) || std::fabs(out.rgba[i]) > 65504.0f;
      if (i % 4 == 3) continue;
      darker += out.rgba[i] < input.rgba[i] * (1.0f - 1.0f / 1024);  // light is only added (half rounding aside)
      added += double(out.rgba[i]) - input.rgba[i];
    }
    CHECK(not_finite == 0);
    CHECK(darker == 0);
    CHECK(added > 0);
  }
}

TEST_CASE("pfx-render turns an EXR of every half-float value into a finite EXR in every mode", "[bloom][render]") {
  Scratch scratch;
  std::string error;
  REQUIRE(pfx::app::write_exr(scratch / "every_half.exr", every_half_value(), pfx::app::ExrPixelType::Half, &error));
  for (const auto& [effect, setting] : kVariants) {
    INFO(effect << " " << setting);
    REQUIRE(render("--input " + scratch / "every_half.exr" + " --chain " + effect + " --set " + setting + " --out " +
                   scratch / "out.exr") == 0);
    pfx::app::Image out;
    REQUIRE(pfx::app::read_exr(scratch / "out.exr", &out, &error));
    REQUIRE((out.width == 256 && out.height == 256));
    size_t not_finite = 0;
    for (float v : out.rgba) not_finite += !std::isfinite(v);
    CHECK(not_finite == 0);
  }
}
