#include "glare_params.hpp"

#include <cmath>

#include <pfx/cpp/descriptors.hpp>

#include "bright_pass_params.hpp"

namespace pfx_bloom {
namespace {

constexpr double kPi = 3.14159265358979323846;

const pfx_enum_item kStreakItems[] = {{"4", "4 streaks (a cross)"}, {"6", "6 streaks"}, {"8", "8 streaks"}};
const pfx_enum_item kResolutionItems[] = {
    {"full", "Full resolution (the seed's)"}, {"half", "Half resolution"}, {"quarter", "Quarter resolution"}};

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
    pfx::desc::param("strength", "Strength",
         "How much light the streaks add: 1 spreads exactly the light above the threshold over all "
         "streaks together. 0 turns the effect off (no pass runs).",
         "", "Glare", PFX_PARAM_FLOAT, 0, 100, 0, 4, 0.05, {{1.0}}),
    pfx::desc::param("tint", "Tint", "Colour the added light is multiplied by.", "", "Glare", PFX_PARAM_COLOR, 0, 16, 0, 1,
         0.01, {{1.0, 1.0, 1.0}}),
    pfx::desc::with_items(pfx::desc::param("streaks", "Streaks",
                    "How many streaks leave each bright pixel, evenly spaced (a cross filter's 4, 6 or 8).",
                    "", "Glare", PFX_PARAM_ENUM, 0, 2, 0, 2, 1, {{0}}),
               kStreakItems, 3),
    pfx::desc::param("angle", "Angle offset",
         "Direction of the first streak, counter-clockwise from the x axis (the seed's 45).",
         "deg", "Glare", PFX_PARAM_FLOAT, -360, 360, 0, 90, 1, {{45.0}}),
    pfx::desc::param("attenuation", "Attenuation",
         "How fast a streak fades: tap weights are a^(b*s), s texels along it (Kawase: 0.9 .. 0.95). "
         "Closer to 1 is longer.",
         "", "Glare", PFX_PARAM_FLOAT, 0.9, 0.95, 0.9, 0.95, 0.005, {{0.925}}),
    pfx::desc::with_items(pfx::desc::param("resolution", "Resolution",
                    "Resolution the streaks are drawn at: lower is faster and softer across the streak.",
                    "", "Glare", PFX_PARAM_ENUM, 0, 2, 0, 2, 1, {{0}}),
               kResolutionItems, 3),
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
