// What declare hands the host, built in storage that outlives the call as the ABI asks (valid
// until the next declare or destroy): keep one builder in the effect instance and clear it at every
// declare. A pass's optional fields are set by name on the handle pass() returns:
//
//   d.clear();
//   d.target("half", frame->width / 2, frame->height / 2);
//   d.pass("down", "half").input(PFX_INPUT_NAME_COLOR).tag(1);
//   d.pass("up", PFX_OUTPUT_NAME).input(PFX_INPUT_NAME_COLOR, PFX_FILTER_NEAREST).input("half").tag(2);
//   return d.finish(out);
//
// No allocation and no exception: the capacities are the template's arguments, and a declaration
// that outgrows them (or names more inputs in a pass than PFX_MAX_PASS_INPUTS) makes finish return
// PFX_ERROR instead of writing past them.
#pragma once

#include <cstdint>

#include <pfx/effect.h>

namespace pfx::desc {

template <uint32_t MaxTargets, uint32_t MaxPasses>
class DeclarationBuilder {
 public:
  // One declared pass. Left out: no inputs, no blending (PFX_BLEND_NONE), the output's contents
  // undefined before the pass (PFX_LOAD_DONT_CARE), user_tag 0.
  class Pass {
   public:
    // Bound to the next texture unit. Left out: linear filtering, clamped to the edge.
    Pass& input(const char* name, pfx_filter filter = PFX_FILTER_LINEAR, pfx_wrap wrap = PFX_WRAP_CLAMP_TO_EDGE) {
      pfx_pass_desc& pass = builder_->passes_[index_];
      if (pass.input_count == PFX_MAX_PASS_INPUTS) {
        builder_->overflowed_ = true;
        return *this;
      }
      builder_->inputs_[index_][pass.input_count++] = pfx_pass_input{name, filter, wrap};
      return *this;
    }
    // An input made elsewhere (a plugin's own helper for the filtering and wrapping it repeats).
    Pass& input(const pfx_pass_input& made) { return input(made.name, made.filter, made.wrap); }
    // Inputs from a table (count of them), in its order.
    Pass& inputs(const pfx_pass_input* list, uint32_t count) {
      for (uint32_t i = 0; i < count; ++i) input(list[i]);
      return *this;
    }
    Pass& blend(pfx_blend mode) {
      builder_->passes_[index_].blend = mode;
      return *this;
    }
    Pass& load(pfx_load action) {
      builder_->passes_[index_].load = action;
      return *this;
    }
    // The plugin's own number for the pass, handed back in pfx_pass_context.user_tag.
    Pass& tag(uint32_t user_tag) {
      builder_->passes_[index_].user_tag = user_tag;
      return *this;
    }

   private:
    friend class DeclarationBuilder;
    Pass(DeclarationBuilder* builder, uint32_t index) : builder_(builder), index_(index) {}
    DeclarationBuilder* builder_;
    uint32_t index_;
  };

  // Forgets the last declaration (every declare starts here).
  void clear() {
    target_count_ = pass_count_ = 0;
    frame_inputs_ = flags_ = 0;
    overflowed_ = false;
  }

  // A target of a fixed size, computed from the frame's. Left out: RGBA16F. Names are kept as
  // pointers: give them static storage (a literal, or a table that lives as long as the plugin).
  void target(const char* name, uint32_t width, uint32_t height, pfx_format format = PFX_FORMAT_RGBA16F) {
    pfx_target_desc* t = next_target(name, format);
    if (!t) return;
    t->size_mode = PFX_SIZE_FIXED;
    t->width = width;
    t->height = height;
  }
  // A target the host sizes as a scale of the frame (max(1, round(frame * scale)) on each side).
  void scaled_target(const char* name, float scale_x, float scale_y, pfx_format format = PFX_FORMAT_RGBA16F) {
    pfx_target_desc* t = next_target(name, format);
    if (!t) return;
    t->size_mode = PFX_SIZE_FRAME_SCALE;
    t->scale_x = scale_x;
    t->scale_y = scale_y;
  }

  // A full-screen pass writing output (a target's name or PFX_OUTPUT_NAME).
  Pass pass(const char* name, const char* output) { return next_pass(name, PFX_PASS_FULLSCREEN, output); }
  // A pass that issues its own GL work; output may be nullptr (none bound).
  Pass custom_pass(const char* name, const char* output = nullptr) { return next_pass(name, PFX_PASS_CUSTOM, output); }

  // PFX_INPUT_* bits the passes need beyond the textures they name (PFX_INPUT_LIGHTS).
  void frame_inputs(uint32_t bits) { frame_inputs_ |= bits; }

  // Promises PFX_DECLARATION_SAMPLES_AND_DRAWS (pfx/effect.h): the passes only sample "color" and
  // only draw "output", so a display frame's 8-bit texture can be handed in and out as it is.
  void samples_and_draws() { flags_ |= PFX_DECLARATION_SAMPLES_AND_DRAWS; }

  uint32_t pass_count() const { return pass_count_; }

  // Points out at what was declared; PFX_ERROR (and out untouched) when it did not fit.
  pfx_status finish(pfx_declaration* out) const {
    if (overflowed_) return PFX_ERROR;
    out->targets = targets_;
    out->target_count = target_count_;
    out->passes = passes_;
    out->pass_count = pass_count_;
    out->inputs |= frame_inputs_;
    // A host older than 1.5 hands a declaration without the field: the promise is left unsaid.
    if (PFX_STRUCT_HAS(out, pfx_declaration, flags)) out->flags |= flags_;
    return PFX_OK;
  }

 private:
  pfx_target_desc* next_target(const char* name, pfx_format format) {
    if (target_count_ == MaxTargets) {
      overflowed_ = true;
      return nullptr;
    }
    pfx_target_desc& t = targets_[target_count_++];
    t = pfx_target_desc{};
    t.struct_size = sizeof t;
    t.name = name;
    t.format = format;
    return &t;
  }

  Pass next_pass(const char* name, pfx_pass_kind kind, const char* output) {
    uint32_t index = MaxPasses;  // the spare slot: written to, never handed out
    if (pass_count_ < MaxPasses)
      index = pass_count_++;
    else
      overflowed_ = true;
    pfx_pass_desc& pass = passes_[index];
    pass = pfx_pass_desc{};
    pass.struct_size = sizeof pass;
    pass.name = name;
    pass.kind = kind;
    pass.output = output;
    pass.inputs = inputs_[index];
    return Pass(this, index);
  }

  pfx_target_desc targets_[MaxTargets > 0 ? MaxTargets : 1] = {};  // (C++ has no empty arrays)
  pfx_pass_desc passes_[MaxPasses + 1] = {};
  pfx_pass_input inputs_[MaxPasses + 1][PFX_MAX_PASS_INPUTS] = {};
  uint32_t target_count_ = 0, pass_count_ = 0, frame_inputs_ = 0, flags_ = 0;
  bool overflowed_ = false;
};

}  // namespace pfx::desc
