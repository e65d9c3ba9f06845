#include "glare_params.hpp"

#include <cmath>

#include <pfx/cpp/descriptors.hpp>

#include "bright_pass_params.hpp"

namespace pfx_bloom {
namespace {

constexpr double kPi = 3.14159265358979323846;

const pfx_enum_item kStreakItems[] = {{"4", "4 streaks (a cross)"}, {"6", "6 streaks"}, {"8", "8 streaks"}};
const pfx_enum_item kResolutionItems[] = {
    {"full", "Full resolution (Kawase's)"}, {"half", "Half resolution"}, {"quarter", "Quarter resolution"}};

}  // namespace

const pfx_param_desc kGlareParams[GLARE_PARAM_COUNT] = {
    // On a display-referred frame streaks come only from near-white highlights: 0.85 is linear
    // light of sRGB code 237, eased in from 0.75 (code 225). Bloom's 0.6 there would put a star on
    // every lit surface.
    threshold_param(0.85),
    knee_param(0.1),
    measure_param("How a pixel's brightness is measured against the threshold: the largest of R, G, B or "
                  "Rec. 709 luminance."),
    firefly_clamp_param(),
    pfx::desc::param("strength")
        .label("Strength")
        .group("Glare")
        .tooltip("How much light the streaks add: 1 spreads exactly the light above the threshold over all "
                 "streaks together. 0 turns the effect off (no pass runs).")
        .float_range(0, 100)
        .display_range(0, 4)
        .step(0.05)
        .default_value(1.0),
    pfx::desc::param("tint")
        .label("Tint")
        .group("Glare")
        .tooltip("Colour the added light is multiplied by.")
        .color_range(0, 16)
        .display_range(0, 1)
        .step(0.01)
        .default_value(1.0, 1.0, 1.0),
    pfx::desc::param("streaks")
        .label("Streaks")
        .group("Glare")
        .tooltip("How many streaks leave each bright pixel, evenly spaced (a cross filter's 4, 6 or 8).")
        .items(kStreakItems, 3)
        .default_value(0),
    pfx::desc::param("angle")
        .label("Angle offset")
        .unit("deg")
        .group("Glare")
        .tooltip("Direction of the first streak, counter-clockwise from the x axis (Kawase's 45).")
        .float_range(-360, 360)
        .display_range(0, 90)
        .step(1)
        .default_value(45.0),
    pfx::desc::param("attenuation")
        .label("Attenuation")
        .group("Glare")
        .tooltip("How fast a streak fades: tap weights are a^(b*s), s texels along it (Kawase: 0.9 .. 0.95). "
                 "Closer to 1 is longer.")
        .float_range(0.9, 0.95)
        .step(0.005)
        .default_value(0.925),
    pfx::desc::param("resolution")
        .label("Resolution")
        .group("Glare")
        .tooltip("Resolution the streaks are drawn at: lower is faster and softer across the streak.")
        .items(kResolutionItems, 3)
        .default_value(0),
    nonfinite_param(),
};

void GlareSettings::direction(int j, double* dx, double* dy) const {
  const double theta = 2.0 * kPi * j / streaks + angle;
  *dx = std::cos(theta);
  *dy = std::sin(theta);
}

void GlareSettings::pass_weights(int pass, double* weights) const {
  const double b = std::pow(4.0, pass);
  double sum = 0;
  for (int s = 0; s < kGlareTaps; ++s) sum += weights[s] = std::pow(attenuation, b * s);
  for (int s = 0; s < kGlareTaps; ++s) weights[s] /= sum;
}

GlareSettings glare_settings_from(const pfx_value* v) {
  GlareSettings g;
  g.bright.threshold = v[GLARE_THRESHOLD].v[0];
  g.bright.knee = v[GLARE_KNEE].v[0] < g.bright.threshold ? v[GLARE_KNEE].v[0] : g.bright.threshold;
  g.bright.measure = static_cast<int>(v[GLARE_MEASURE].v[0]);
  g.bright.firefly_clamp = v[GLARE_FIREFLY_CLAMP].v[0];
  g.bright.nonfinite = static_cast<int>(v[GLARE_NONFINITE].v[0]);
  g.strength = v[GLARE_STRENGTH].v[0];
  for (int c = 0; c < 3; ++c) g.tint[c] = v[GLARE_TINT].v[c];
  g.streaks = 4 + 2 * static_cast<int>(v[GLARE_STREAKS].v[0]);
  g.angle = v[GLARE_ANGLE].v[0] * kPi / 180.0;
  g.attenuation = v[GLARE_ATTENUATION].v[0];
  g.downscale = 1 << static_cast<int>(v[GLARE_RESOLUTION].v[0]);
  return g;
}

}  // namespace pfx_bloom
