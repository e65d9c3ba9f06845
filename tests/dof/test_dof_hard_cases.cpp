// The named hard cases of the issue, in every mode on the GPU: each gives a finite documented
// result (checked against the mode's CPU model where one applies) or a clear error.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "dof_params.hpp"
#include "dof_rig.hpp"

using namespace dof_test;

namespace {

// Every mode and working resolution: "mode" or "mode/resolution".
const char* const kModes[] = {"seed", "gather/half", "gather/full"};

Rig& rig_for(const std::string& mode) {
  const size_t slash = mode.find('/');
  Rig& rig = shared_rig(mode.substr(0, slash));
  if (slash != std::string::npos) rig.set("dof.resolution=" + mode.substr(slash + 1));
  return rig;
}

// Finite everywhere, and equal to the model where the model's output is finite and moderate.
void require_finite_and_close(const Rendered& r) {
  REQUIRE(all_finite(r.output));
  REQUIRE(all_finite(r.model));
  for (size_t i = 0; i < r.output.size(); ++i) {
    if (i % 4 == 3) continue;
    const double m = r.model[i], o = r.output[i];
    INFO("value " << i / 4 << "." << i % 4);
    REQUIRE(std::fabs(o - m) <= 0.02 * std::fabs(m) + 0.05 + 0.02 * std::fabs(o));
  }
}

}  // namespace

TEST_CASE("NaN, infinite, too-bright and negative colours give a finite image", "[dof][hard]") {
  // With either policy for non-finite pixels: zero (the default: such a pixel is black) and clamp
  // (the behaviour before the parameter: NaN -> 0, +-Inf -> +-65504 per channel).
  for (const char* policy : {"dof.nonfinite=zero", "dof.nonfinite=clamp"})
    for (const char* mode : kModes) {
      Rig& rig = rig_for(mode);
      rig.set(policy);
      Frame f = scene(48, 32);
      const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
      const float bad[] = {nan, inf, -inf, 70000.0f, -3.0f};
      for (int i = 0; i < 5; ++i) {
        float* c = f.at(6 + 8 * i, 16);  // in the near square and the backdrop, where the blur spreads them
        c[0] = c[1] = c[2] = bad[i];
        c = f.at(6 + 8 * i, 5);
        c[0] = bad[i];
      }
      INFO("mode " << mode << ", " << policy);
      const Rendered r = rig.render(f);
      require_finite_and_close(r);
    }
}

namespace {

// Pixels whose RGB differs by more than the half-float rounding of a value of that size.
int changed_pixels(const std::vector<float>& a, const std::vector<float>& b) {
  int changed = 0;
  for (size_t i = 0; i < a.size(); i += 4)
    for (int c = 0; c < 3; ++c)
      if (std::fabs(a[i + c] - b[i + c]) > std::ldexp(std::fmax(std::fabs(a[i + c]), 1.0), -9)) {
        ++changed;
        break;
      }
  return changed;
}

}  // namespace

// With nonfinite=zero the documented neighbourhood of a bad pixel is nothing: the output is that of
// the frame with those pixels black (to the half-float rounding of the values, since the half-size
// pass averages a block holding a bad pixel texel by texel and a clean one with one filtered tap).
// With clamp, four +Inf pixels in the blurred backdrop spread 65504 over their circles of confusion.
TEST_CASE("4 +Inf, NaN or -Inf pixels change nothing but themselves with nonfinite=zero", "[dof][hard][nonfinite]") {
  const int bad_at[4][2] = {{5, 5}, {40, 8}, {20, 25}, {60, 40}};
  Frame base = scene(72, 48), black = base;
  for (const auto& p : bad_at)
    for (int c = 0; c < 3; ++c) black.at(p[0], p[1])[c] = 0.0f;
  for (const char* mode : kModes) {
    Rig& rig = rig_for(mode);
    const Rendered reference = rig.render(black);
    for (float bad : {std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN(),
                      -std::numeric_limits<float>::infinity()}) {
      Frame f = base;
      for (const auto& p : bad_at)
        for (int c = 0; c < 3; ++c) f.at(p[0], p[1])[c] = bad;
      INFO("mode " << mode << " with " << bad);
      const Rendered r = rig.render(f);
      require_finite_and_close(r);
      CHECK(changed_pixels(r.output, reference.output) == 0);
    }
    rig.set("dof.nonfinite=clamp");
    Frame f = base;
    for (const auto& p : bad_at)
      for (int c = 0; c < 3; ++c) f.at(p[0], p[1])[c] = std::numeric_limits<float>::infinity();
    INFO("mode " << mode << " with +Inf, nonfinite=clamp");
    const Rendered r = rig.render(f);
    REQUIRE(all_finite(r.output));
    CHECK(changed_pixels(r.output, reference.output) > 4);  // the +Inf spreads
  }
}

TEST_CASE("NaN, infinite, zero and negative depths give a finite image", "[dof][hard]") {
  for (const char* mode : kModes) {
    Rig& rig = rig_for(mode);
    Frame f = scene(48, 32);
    const float values[] = {std::numeric_limits<float>::quiet_NaN(), HUGE_VALF, -HUGE_VALF, 0.0f, -2.0f};
    for (int i = 0; i < 5; ++i)
      for (int y = 10; y < 14; ++y) f.z(4 + 9 * i, y) = values[i];
    INFO("mode " << mode);
    const Rendered r = rig.render(f);
    require_finite_and_close(r);
  }
}

TEST_CASE("hardware depth exactly 0 and 1, with finite and infinite far planes", "[dof][hard]") {
  for (const char* mode : kModes)
    for (double far_plane : {100.0, HUGE_VAL}) {
      Rig& rig = rig_for(mode);
      Frame f = scene(40, 30);
      f.encoding = PFX_DEPTH_HARDWARE;
      f.far_plane = far_plane;
      for (int y = 0; y < f.height; ++y)
        for (int x = 0; x < f.width; ++x) f.z(x, y) = (x < f.width / 2) ? 0.0f : 1.0f;
      INFO("mode " << mode << " far " << far_plane);
      const Rendered r = rig.render(f);
      require_finite_and_close(r);
    }
}

TEST_CASE("near == far gives one CoC for the whole frame, finite", "[dof][hard]") {
  for (const char* mode : kModes) {
    Rig& rig = rig_for(mode);
    Frame f = scene(40, 30);
    f.encoding = PFX_DEPTH_HARDWARE;
    f.near_plane = f.far_plane = 2.0;
    for (float& z : f.depth) z = 0.37f;
    INFO("mode " << mode);
    const Rendered r = rig.render(f);
    require_finite_and_close(r);
  }
}

TEST_CASE("1x1, 2x1, 1x3 and odd sizes render and match the model", "[dof][hard]") {
  for (const char* mode : kModes)
    for (const auto& size : {std::pair{1, 1}, std::pair{2, 1}, std::pair{1, 3}, std::pair{17, 9}, std::pair{33, 31}}) {
      Rig& rig = rig_for(mode);
      Frame f = scene(size.first, size.second);
      for (float& z : f.depth) z = 1.0f;  // everything blurred
      INFO("mode " << mode << " " << size.first << "x" << size.second);
      const Rendered r = rig.render(f);
      require_finite_and_close(r);
    }
}

TEST_CASE("focus at the focal length, at 0 and at infinity, the f-number at its hard minimum", "[dof][hard]") {
  for (const char* mode : kModes) {
    Rig& rig = rig_for(mode);
    const Frame f = scene(48, 32);
    // 0.0244 m is the focal length the 45-degree, 36 mm camera gets when focused far away.
    for (const char* focus : {"dof.focus_distance=0.0244", "dof.focus_distance=0.001", "dof.focus_distance=1e9"}) {
      rig.set(focus);
      INFO("mode " << mode << " " << focus);
      require_finite_and_close(rig.render(f));
    }
    rig.set("dof.focus_distance=5");
    rig.set("dof.f_number=0.05");
    require_finite_and_close(rig.render(f));
  }
}

TEST_CASE("out-of-range camera parameters are clamped with a note, NaN is refused", "[dof][hard]") {
  pfx::host::ParamStore store;
  {
    auto registry = pfx::test::make_registry();
    std::string error;
    REQUIRE(registry->load(PFX_DOF_PLUGIN, &error));
    store.add_effect(registry->find_effect("dof")->desc);
    std::string note;
    REQUIRE(store.set_assignment("dof.focus_distance=0", &error, &note));
    CHECK(note == "clamped to 0.001");
    REQUIRE(store.set_assignment("dof.focus_distance=inf", &error, &note));
    CHECK(note == "clamped to 1e+09");
    REQUIRE(store.set_assignment("dof.f_number=0", &error, &note));
    CHECK(note == "clamped to 0.05");
    CHECK_FALSE(store.set_assignment("dof.f_number=nan", &error, &note));
    CHECK_THAT(error, Catch::Contains("NaN"));
  }
}

TEST_CASE("a frame without depth is refused naming the input", "[dof][hard]") {
  Rig& rig = rig_for("seed");
  std::string error;
  CHECK_FALSE(rig.try_render(scene(8, 8), &error, false));
  CHECK_THAT(error, Catch::Contains("'dof'") && Catch::Contains("depth"));
}

TEST_CASE("degenerate cameras are refused with the reason in the log", "[dof][hard]") {
  Rig& rig = rig_for("seed");
  Frame f = scene(8, 8);
  f.fovy_degrees = 180;
  std::string error;
  CHECK_FALSE(rig.try_render(f, &error));
  CHECK_THAT(error, Catch::Contains("dof"));
  bool logged = false;
  for (const std::string& line : rig.log().lines) logged |= line.find("field of view") != std::string::npos;
  CHECK(logged);
}
