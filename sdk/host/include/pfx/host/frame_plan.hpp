// Planning a frame, without any GL: which passes run, which targets they touch, when each target
// is first and last used, and which targets can share one pooled texture because their lifetimes
// do not overlap (a small render graph, docs/architecture.md). The Chain executes what this
// produces.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <pfx/effect.h>

#include "pfx/host/api.hpp"

namespace pfx::host {

// A declaration copied out of the plugin's storage (valid only until its next declare).
struct DeclaredTarget {
  std::string name;
  pfx_format format = PFX_FORMAT_RGBA16F;
  uint32_t width = 1, height = 1;  // resolved against the frame size
};
struct DeclaredInput {
  std::string name;
  pfx_filter filter = PFX_FILTER_LINEAR;
  pfx_wrap wrap = PFX_WRAP_CLAMP_TO_EDGE;
  bool operator==(const DeclaredInput& o) const { return name == o.name && filter == o.filter && wrap == o.wrap; }
};
struct DeclaredPass {
  std::string name;
  pfx_pass_kind kind = PFX_PASS_FULLSCREEN;
  std::string output;  // empty: no output (custom pass only)
  std::vector<DeclaredInput> inputs;
  pfx_blend blend = PFX_BLEND_NONE;
  pfx_load load = PFX_LOAD_DONT_CARE;
  uint32_t user_tag = 0;
};
struct Declaration {
  std::vector<DeclaredTarget> targets;
  std::vector<DeclaredPass> passes;
  uint32_t inputs = 0;
  uint32_t flags = 0;  // PFX_DECLARATION_* promises
  // The passes read and write sRGB codes (PFX_DECLARATION_DISPLAY_REFERRED).
  bool display_referred() const { return (flags & PFX_DECLARATION_DISPLAY_REFERRED) != 0; }
  // "color" and "output" may be 8-bit textures: promised, or implied by display_referred().
  bool samples_and_draws() const {
    return (flags & (PFX_DECLARATION_SAMPLES_AND_DRAWS | PFX_DECLARATION_DISPLAY_REFERRED)) != 0;
  }
};

// Copies and resolves a plugin's declaration; false with *error naming the problem (bad sizes,
// formats, duplicate or reserved target names, NULL names).
PFX_HOST_API bool copy_declaration(const pfx_declaration& in, uint32_t frame_width, uint32_t frame_height,
                                   Declaration* out, std::string* error);
PFX_HOST_API bool operator==(const Declaration& a, const Declaration& b);
// The PFX_INPUT_* bits a declaration needs: its `inputs` and each frame input a pass reads.
PFX_HOST_API uint32_t declared_frame_inputs(const Declaration& declaration);
// "normal, albedo, lights": the names of PFX_INPUT_* bits, for messages.
PFX_HOST_API std::string frame_input_names(uint32_t bits);
PFX_HOST_API uint64_t format_bytes_per_pixel(pfx_format format);

// What a pass reads or writes, after planning.
struct ResourceRef {
  enum Kind { NONE, FRAME_INPUT, POOLED, CHAIN_OUTPUT } kind = NONE;
  std::string frame_input;  // FRAME_INPUT: "color", "depth", ...
  int resource = -1;        // POOLED: index into FramePlan::resources
};

// Where two neighbouring effects want the frame in different encodings (one display-referred,
// PFX_DECLARATION_DISPLAY_REFERRED, the other linear light) and the linear one did not promise
// PFX_DECLARATION_SAMPLES_AND_DRAWS, the chain converts with a pass of its own: its one input is
// the earlier effect's "output", its output the later effect's "color".
enum class Conversion { NONE, TO_DISPLAY, TO_LINEAR };

struct PlannedPass {
  int effect = 0;  // index into the effects given to plan_frame; for a conversion, the effect it feeds
  int pass = 0;    // index into that effect's declared passes; -1 for a conversion
  Conversion conversion = Conversion::NONE;
  bool display_referred = false;  // the effect's passes read and write sRGB codes
  ResourceRef output;
  std::vector<ResourceRef> inputs;
};

// A target of one effect (or an intermediate "output"), mapped to a pooled texture.
struct PlannedResource {
  int effect = 0;
  std::string name;
  pfx_format format = PFX_FORMAT_RGBA16F;
  uint32_t width = 0, height = 0;
  // An "output" between effects that holds sRGB codes (PFX_FORMAT_RGBA8): display-referred
  // passes read and write it raw, linear ones through its sRGB view (sampling decodes, drawing
  // encodes).
  bool display_codes = false;
  int first_pass = 0, last_pass = 0;  // global pass indices, inclusive
  int slot = -1;                      // index into FramePlan::slots
};

struct PoolSlot {
  pfx_format format = PFX_FORMAT_RGBA16F;
  uint32_t width = 0, height = 0;
  uint64_t bytes() const { return uint64_t(width) * height * format_bytes_per_pixel(format); }
};

struct FramePlan {
  std::vector<PlannedPass> passes;
  std::vector<PlannedResource> resources;
  std::vector<PoolSlot> slots;
  uint64_t peak_target_bytes = 0;      // all slots: they live together for the whole frame
  uint64_t unpooled_target_bytes = 0;  // what one texture per resource would have cost
};

struct PlanInput {
  std::string effect_id;
  const Declaration* declaration = nullptr;  // an effect with no passes must not be given
};

// Plans a chain of effects over a frame of the given size with the given PFX_INPUT_* bits.
// Effect k reads "color" from effect k-1's "output" (the frame's colour for k = 0); the last
// effect's "output" is the chain's output texture. Between two effects the "output" is RGBA16F
// linear light, or 8-bit sRGB codes where either neighbour is display-referred, with a conversion
// pass where the other cannot sample or draw those itself. False with *error naming effect, pass
// and input when something is missing or inconsistent.
PFX_HOST_API bool plan_frame(const std::vector<PlanInput>& effects, uint32_t frame_width, uint32_t frame_height,
                             uint32_t available_inputs, FramePlan* plan, std::string* error);

}  // namespace pfx::host
