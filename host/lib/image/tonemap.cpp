#include "tonemap.hpp"

#include <algorithm>
#include <cmath>

namespace pfx::app {
namespace {

struct CurveInfo {
  ToneCurve curve;
  const char* name;
  const char* description;
};

constexpr CurveInfo kCurves[] = {
    {ToneCurve::Linear, "linear", "clamp to [0, 1]; no highlight compression"},
    {ToneCurve::Reinhard, "reinhard", "x / (1 + x); soft highlights, never reaches white"},
    {ToneCurve::Aces, "aces", "ACES filmic fit (Narkowicz 2015); contrasty, saturates highlights"},
};

// Beyond this every curve is at its white point; capping keeps the ACES fit's x^2 terms from
// overflowing to inf/inf = NaN for huge finite inputs.
constexpr float kCurveInputCap = 1.0e9f;

}  // namespace

const std::vector<std::string>& tone_curve_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const CurveInfo& c : kCurves) n.emplace_back(c.name);
    return n;
  }();
  return names;
}

std::string tone_curve_help() {
  std::string text;
  for (const CurveInfo& c : kCurves) {
    text += std::string(c.name) + std::string(10 - std::string(c.name).size(), ' ') +
            c.description + "\n";
  }
  return text;
}

const char* tone_curve_name(ToneCurve curve) {
  for (const CurveInfo& c : kCurves) {
    if (c.curve == curve) return c.name;
  }
  return "unknown";
}

bool parse_tone_curve(const std::string& name, ToneCurve* out, std::string* error) {
  for (const CurveInfo& c : kCurves) {
    if (name == c.name) {
      *out = c.curve;
      return true;
    }
  }
  if (error) {
    std::string list;
    for (const std::string& n : tone_curve_names()) list += (list.empty() ? "" : ", ") + n;
    *error = "unknown tone curve '" + name + "' (choose one of: " + list + ")";
  }
  return false;
}

float apply_tone_curve(ToneCurve curve, float x) {
  if (std::isnan(x)) return x;
  if (!(x > 0.0f)) return 0.0f;  // negative, -inf and zero
  if (std::isinf(x)) return 1.0f;
  x = std::min(x, kCurveInputCap);
  float y = 0.0f;
  switch (curve) {
    case ToneCurve::Linear:
      y = x;
      break;
    case ToneCurve::Reinhard:
      y = x / (1.0f + x);
      break;
    case ToneCurve::Aces:
      y = (x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f);
      break;
  }
  return std::clamp(y, 0.0f, 1.0f);
}

double srgb_oetf(double linear) {
  const double x = std::clamp(linear, 0.0, 1.0);
  return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
}

std::uint8_t encode_srgb8(float display_linear) {
  if (std::isnan(display_linear)) return 0;
  const double code = std::round(srgb_oetf(display_linear) * 255.0);
  return static_cast<std::uint8_t>(std::clamp(code, 0.0, 255.0));
}

void tonemap_pixel(const float rgb[3], const ToneMapSettings& settings, std::uint8_t out[3]) {
  if (std::isnan(rgb[0]) || std::isnan(rgb[1]) || std::isnan(rgb[2])) {
    std::copy(kNanColour, kNanColour + 3, out);
    return;
  }
  const double scale = std::exp2(settings.exposure_ev);
  for (int c = 0; c < 3; ++c) {
    // Zero and infinity are fixed points of any exposure; multiplying them by an absurd scale
    // (0 or inf) would otherwise make NaN.
    const bool fixed = rgb[c] == 0.0f || std::isinf(rgb[c]);
    const float exposed = fixed ? rgb[c] : static_cast<float>(rgb[c] * scale);
    const float display = apply_tone_curve(settings.curve, exposed);
    out[c] = std::isnan(display) ? kNanColour[c] : encode_srgb8(display);
  }
}

DisplayImage tonemap_to_srgb8(const Image& img, const ToneMapSettings& settings) {
  DisplayImage out;
  if (!img.is_consistent()) return out;
  out.width = img.width;
  out.height = img.height;
  out.channels = 3;
  out.pixels.resize(img.pixel_count() * 3);
  for (std::size_t i = 0; i < img.pixel_count(); ++i) {
    tonemap_pixel(&img.rgba[i * 4], settings, &out.pixels[i * 3]);
  }
  return out;
}

}  // namespace pfx::app
