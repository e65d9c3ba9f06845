#include "bloom_rig.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>

#include "bloom_levels.hpp"
#include "bloom_params.hpp"
#include "reference/glare_model.hpp"
#include "gl_test_support.hpp"
#include "image_texture.hpp"

namespace bloom_test {

Picture::Picture(int w, int h, float r, float g, float b, float a) : width(w), height(h) {
  rgba.resize(static_cast<size_t>(w) * h * 4);
  for (size_t i = 0; i < rgba.size(); i += 4) rgba[i] = r, rgba[i + 1] = g, rgba[i + 2] = b, rgba[i + 3] = a;
}

Picture scene(int width, int height) {
  Picture p(width, height, 0, 0, 0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      float* c = p.at(x, y);
      // Multiples of 1/64 below 1: exact in half.
      c[0] = float((x * 5 + y * 3) % 48) / 64.0f;
      c[1] = float((x * 2 + y * 7) % 40) / 64.0f;
      c[2] = float((x + y) % 56) / 64.0f;
    }
  struct Spot {
    double fx, fy;
    int radius;
    float r, g, b;
  };
  const Spot spots[] = {{0.3, 0.6, 0, 40.0f, 30.0f, 20.0f},
                        {0.7, 0.3, 1, 3.0f, 6.0f, 1.5f},
                        {0.55, 0.75, 2, 0.5f, 1.25f, 9.0f},
                        {0.0, 0.0, 1, 12.0f, 12.0f, 12.0f}};  // on the corner: the border matters
  for (const Spot& s : spots) {
    const int cx = int(s.fx * (width - 1)), cy = int(s.fy * (height - 1));
    for (int y = cy - s.radius; y <= cy + s.radius; ++y)
      for (int x = cx - s.radius; x <= cx + s.radius; ++x)
        if (x >= 0 && y >= 0 && x < width && y < height) {
          float* c = p.at(x, y);
          c[0] = s.r, c[1] = s.g, c[2] = s.b;
        }
  }
  return p;
}

Rig::Rig(const std::string& effect) : effect_(effect), registry_(pfx::test::make_registry()) {
  std::string error;
  INFO(error);
  REQUIRE(registry_->load(PFX_BLOOM_PLUGIN, &error));
  const pfx::host::EffectInfo* info = registry_->find_effect(effect_);
  REQUIRE(info);
  references_ = info->plugin->references;
  REQUIRE(references_);
  chain_ = std::make_unique<pfx::host::Chain>(*registry_, *params_);
  const bool added = chain_->add(effect_, &error);
  INFO(error);
  REQUIRE(added);
}

void Rig::set(const std::string& assignment) {
  const size_t dot = assignment.find('.'), equals = assignment.find('=');
  const std::string full = dot < equals ? assignment : effect_ + "." + assignment;
  std::string error;
  INFO(full << ": " << error);
  REQUIRE(params_->set_assignment(full, &error));
}

Rig rig_for(const char* variant) {
  if (std::string(variant) == "glare") return Rig("glare");
  Rig rig("bloom");
  rig.set(std::string("mode=") + variant);
  return rig;
}

namespace {

Picture from_image(const pfx::app::Image& img) {
  Picture p;
  p.width = img.width;
  p.height = img.height;
  p.rgba = pfx::app::flip_rows(img.rgba, img.width, img.height, 4);
  return p;
}

}  // namespace

Rendered Rig::render(const Picture& picture) {
  const int w = picture.width, h = picture.height;
  pfx::app::Image img;
  img.width = w;
  img.height = h;
  img.rgba = pfx::app::flip_rows(picture.rgba, w, h, 4);
  pfx::host::FrameTextures textures;
  textures.color = pfx::app::upload_color_texture(img);
  const uint32_t output = pfx::app::create_color_texture(w, h);
  const pfx_frame frame = pfx::test::make_frame(w, h);
  std::string error;
  const bool ok = chain_->render(frame, textures, output, &error);
  INFO(error);
  REQUIRE(ok);

  Rendered r;
  r.input = from_image(pfx::app::download_color_texture(textures.color, w, h));
  r.output = from_image(pfx::app::download_color_texture(output, w, h));
  pfx::app::delete_texture(textures.color);
  pfx::app::delete_texture(output);
  r.passes = chain_->report().passes.size();

  const pfx_value* values = params_->values(effect_);
  r.model = Picture(w, h, 0, 0, 0, 0);
  if (effect_ == "glare") {
    r.mode = "glare";
    r.nonfinite = pfx_bloom::glare_settings_from(values).bright.nonfinite;
    evaluate_glare_model(pfx_bloom::glare_settings_from(values), w, h, r.input.rgba.data(), r.model.rgba.data(), &r.trace);
  } else {
    const pfx_bloom::Settings settings = pfx_bloom::settings_from(values);
    r.levels = r.passes ? pfx_bloom::plan_for(settings, w, h).count : 0;
    r.mode = pfx_bloom::mode_name(settings.mode);
    r.frame_scale = settings.mode == pfx_bloom::MODE_GAUSSIAN ? settings.tone_scale : 1.0;
    r.nonfinite = settings.nonfinite;
    // exactly what the GPU read
    pfx_bloom::evaluate_model(settings, w, h, r.input.rgba.data(), r.model.rgba.data(), &r.trace);
  }
  if (w * h <= 64 * 64) {  // small frames: the reference factory hosts see gives the very same model
    Picture through_abi(w, h, 0, 0, 0, 0);
    pfx_reference_request request{};
    request.struct_size = sizeof request;
    request.effect_id = effect_.c_str();
    request.kind = PFX_REFERENCE_MODEL;
    request.frame = &frame;
    request.params = values;
    request.color = r.input.rgba.data();
    request.output = through_abi.rgba.data();
    REQUIRE(references_->evaluate(&request) == PFX_OK);
    REQUIRE(std::memcmp(through_abi.rgba.data(), r.model.rgba.data(), r.model.rgba.size() * sizeof(float)) == 0);
    // A host built against ABI 1.0 sends the request without the G-buffer fields of 1.1: the
    // same answer (minor versions only append).
    request.struct_size = offsetof(pfx_reference_request, normal);
    std::fill(through_abi.rgba.begin(), through_abi.rgba.end(), -1.0f);
    REQUIRE(references_->evaluate(&request) == PFX_OK);
    REQUIRE(std::memcmp(through_abi.rgba.data(), r.model.rgba.data(), r.model.rgba.size() * sizeof(float)) == 0);
  }
  return r;
}

Picture Rig::render_output(const Picture& picture) {
  const int w = picture.width, h = picture.height;
  pfx::app::Image img;
  img.width = w;
  img.height = h;
  img.rgba = pfx::app::flip_rows(picture.rgba, w, h, 4);
  pfx::host::FrameTextures textures;
  textures.color = pfx::app::upload_color_texture(img);
  const uint32_t output = pfx::app::create_color_texture(w, h);
  std::string error;
  const bool ok = chain_->render(pfx::test::make_frame(w, h), textures, output, &error);
  INFO(error);
  REQUIRE(ok);
  Picture out = from_image(pfx::app::download_color_texture(output, w, h));
  pfx::app::delete_texture(textures.color);
  pfx::app::delete_texture(output);
  return out;
}

// The tolerance, per pixel and channel:
//
//   |gpu - model| <= V * (S * 2^-10 + 2^-7) + |model| * 2^-10
//
// V is the largest value any target holds (the model traces it), S the most half-float stores a
// value passes through on its way to the output (2 per level for the chains, 4 for gaussian, 2 per
// buffer + 2 for mgf). Why:
// - Half-float storage: a half has an 11-bit significand, so one store is off by at most 2^-11
//   relative rounding to nearest, 2^-10 rounding toward zero (which Mesa does on some paths): at
//   most V * 2^-10 per store. Every stage after a store averages with weights summing to at most 1,
//   so an error is never magnified; S stores add up to V * S * 2^-10. The output store of colour +
//   bloom adds |model| * 2^-10.
// - Bilinear weights: GPUs compute filter weights in fixed point with (typically) 8 fractional
//   bits, so a tap's weight along one axis is off by up to 2^-8 (truncated), and a tap's value by
//   2^-8 of the spread of the texels it mixes per axis, 2^-7 for both, with every texel <= V.
//   Taps are averaged with weights summing to 1 at every stage, so this does not grow along the
//   chain beyond the level values, all bounded by V.
// A wrong tap offset, weight, wrap mode or level size moves the bloom by far more (the tests check
// that a 10% change of strength fails).
double worst_error_ratio(const Picture& output, const Picture& model, const pfx_bloom::ModelTrace& trace) {
  double worst = 0;
  for (size_t i = 0; i < model.rgba.size(); ++i) {
    if (i % 4 == 3) continue;
    const double m = model.rgba[i], o = output.rgba[i];
    const double tolerance = trace.largest_stored * (trace.stores * std::ldexp(1.0, -10) + std::ldexp(1.0, -7)) +
                             std::fabs(m) * std::ldexp(1.0, -10) + 1e-7;
    const double ratio = std::isfinite(o) ? std::fabs(o - m) / tolerance : HUGE_VAL;
    worst = std::fmax(worst, ratio);
  }
  return worst;
}

// The same over the whole image, in the RMS sense and against the bloom itself rather than the
// largest stored value:
//
//   rms(gpu - model) <= (S * 2^-10 + 2^-7) * rms(bloom) + 2^-10 * rms(model),
//   bloom = model - frame * frame_scale
//
// Every pass is linear in what it reads (the caps only lower values), so a store's rounding, at most
// 2^-10 of the value stored, reaches the output through the rest of the passes as at most 2^-10 of
// the light that flows on from that store, which is part of the bloom at that pixel: S stores give
// S * 2^-10 * bloom per pixel. The bilinear-weight term is taken to scale with the bloom the same
// way. This is what makes a 10% error of the bloom fail even where a few bright texels make the
// largest stored value V much larger than the bloom (mgf, gaussian). The last term is the output's
// own store of colour + bloom, as per pixel.
double rms_error_ratio(const Picture& output, const Picture& model, const Picture& input,
                       const pfx_bloom::ModelTrace& trace, double frame_scale, int nonfinite) {
  double error = 0, bloom = 0, total = 0;
  for (size_t i = 0; i < model.rgba.size(); ++i) {
    if (i % 4 == 3) continue;
    const float in = input.rgba[i];
    const float* pixel = &input.rgba[i / 4 * 4];
    const bool dropped = nonfinite == pfx_bloom::NONFINITE_ZERO &&
                         !(std::isfinite(pixel[0]) && std::isfinite(pixel[1]) && std::isfinite(pixel[2]));
    const double finite_in = dropped || std::isnan(in) ? 0.0 : std::fmax(-65504.0, std::fmin(65504.0, double(in)));
    const double m = model.rgba[i], o = output.rgba[i];
    if (!std::isfinite(o)) return HUGE_VAL;
    error += (o - m) * (o - m);
    total += m * m;
    bloom += (m - finite_in * frame_scale) * (m - finite_in * frame_scale);
  }
  const double allowed = (trace.stores * std::ldexp(1.0, -10) + std::ldexp(1.0, -7)) * std::sqrt(bloom) +
                         std::ldexp(1.0, -10) * std::sqrt(total) + 1e-6;
  return std::sqrt(error) / allowed;
}

void require_matches_model(const Rendered& r) {
  const double worst = worst_error_ratio(r.output, r.model, r.trace);
  INFO(r.mode << " " << r.input.width << "x" << r.input.height << ", " << r.levels
              << " levels: worst error / tolerance = " << worst);
  // BLOOM_TEST_VERBOSE=1 prints the margin of every comparison.
  if (std::getenv("BLOOM_TEST_VERBOSE"))
    std::fprintf(stderr, "%s %dx%d L%d worst %.4f\n", r.mode.c_str(), r.input.width, r.input.height, r.levels, worst);
  REQUIRE(worst <= 1.0);
  const double rms = rms_error_ratio(r.output, r.model, r.input, r.trace, r.frame_scale, r.nonfinite);
  INFO("RMS error / RMS tolerance = " << rms);
  if (std::getenv("BLOOM_TEST_VERBOSE")) std::fprintf(stderr, "%s rms %.4f\n", r.mode.c_str(), rms);
  REQUIRE(rms <= 1.0);
}

bool all_finite(const Picture& p) {
  for (float v : p.rgba)
    if (!std::isfinite(v)) return false;
  return true;
}

}  // namespace bloom_test
