#include "depth_judge.hpp"

#include <cmath>
#include <cstdio>

namespace pfx::inject {
namespace {

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

}  // namespace

DepthFinding judge_depth(const float* samples, size_t count) {
  DepthFinding finding;
  double low = INFINITY, high = -INFINITY;
  size_t at_far = 0, at_zero = 0, finite = 0;
  for (size_t i = 0; i < count; ++i) {
    const float value = samples[i];
    if (!std::isfinite(value)) continue;
    ++finite;
    low = std::fmin(low, value);
    high = std::fmax(high, value);
    if (value >= 1.0f) ++at_far;
    if (value <= 0.0f) ++at_zero;
  }
  if (finite == 0) {
    finding.what = "no finite value in it";
    return finding;
  }
  if (low == high) {
    finding.kind = DepthFinding::ONE_VALUE;
    // Nothing a depth of field could tell apart. A cleared buffer reads the clear value: 1 for
    // the usual projection, 0 for reversed-Z.
    finding.what = "one value everywhere (" + number(low) +
                   (low >= 1 ? ": the far plane, nothing drawn into it" : low <= 0 ? ": nothing drawn into it" : "") + ")";
    return finding;
  }
  if (at_zero > 0 && at_far == 0) {
    finding.kind = DepthFinding::REVERSED;
    // Where nothing is drawn the usual projection leaves the far plane (1); reversed-Z leaves 0.
    finding.what = "reversed-Z (" + number(100.0 * double(at_zero) / double(count)) +
                   " % of it at 0, where nothing is drawn, none at 1)";
    return finding;
  }
  finding.kind = DepthFinding::USABLE;
  finding.what = number(100.0 * double(finite - at_far) / double(count)) + " % of the frame drawn, from " +
                 number(low) + " to " + number(high);
  return finding;
}

}  // namespace pfx::inject
