// The checks that run an effect on a headless GL context (render_rig.hpp), each in its own child
// process.
#pragma once

#include <cstdint>
#include <string>

#include "child_process.hpp"

namespace pfx::validate {

// create, destroy, create again: no GL error, no GL state changed, then one small frame.
void check_create_destroy(const std::string& path, const std::string& effect_id, CheckReporter& report);
// The defaults over every synthetic input (synthetic_inputs.hpp).
void check_defaults(const std::string& path, const std::string& effect_id, CheckReporter& report);
// `runs` random parameter sets from `seed` (random_params.hpp), each over a gradient and a
// NaN/Inf frame. A failure names the set as --set assignments, to reproduce it with pfx-render.
void check_random(const std::string& path, const std::string& effect_id, uint64_t seed, int runs,
                  CheckReporter& report);
// One instance through 64x48, 1917x1079, 1x1, 33x17 and back to 64x48: every size renders, and
// the last frame matches the first (nothing left over from the larger sizes).
void check_resize(const std::string& path, const std::string& effect_id, CheckReporter& report);

// An effect that promises PFX_DECLARATION_SAMPLES_AND_DRAWS, at its display-referred defaults,
// over an 8-bit frame handed as 8-bit textures, against the same frame in RGBA16F encoded back on
// the CPU: within kDisplayFrameCodes codes, and with no conversion pass of the chain's. Skipped for
// an effect that does not promise it or runs no pass over such a frame.
constexpr int kDisplayFrameCodes = 3;
void check_display_frame(const std::string& path, const std::string& effect_id, CheckReporter& report);

}  // namespace pfx::validate
