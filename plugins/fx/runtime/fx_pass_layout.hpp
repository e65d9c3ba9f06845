#pragma once
// How an FX technique's passes become the passes the effect declares to pfx. Around the
// technique's own passes stands a first pass of pfx's (it converts the depth and, where needed,
// brings the frame into the back buffer) and, unless a technique pass can draw the result itself,
// a last one that moves the picture out. A host of ABI 1.6 or later hands the effect sRGB codes
// (PFX_DECLARATION_DISPLAY_REFERRED), so nothing needs converting, and where the technique allows
// it nothing is copied either: its passes sample the host's colour as the back buffer (through an
// sRGB view of it for an sRGB sampler) until one writes the back buffer, and its last back-buffer
// pass draws straight into the host's output (encoding in the shader what an sRGB write would).
#include <cstddef>

#include "effect_compiler.hpp"

namespace pfx_fx {

struct FxPassLayout {
  bool display_referred = false;  // the host hands and takes sRGB codes
  bool samples_frame = false;     // the technique starts on the host's colour as it is
  bool srgb_frame_view = false;   // ...and samples it through an sRGB sampler too: a view decodes
  // The technique pass that draws into "output" itself, with the frame's alpha; -1: the last
  // declared pass moves the picture out.
  int output_pass = -1;

  // Passes declared for a technique of `technique_passes` passes.
  std::size_t declared_passes(std::size_t technique_passes) const {
    return technique_passes + (output_pass < 0 ? 2 : 1);
  }
  bool operator==(const FxPassLayout& o) const {
    return display_referred == o.display_referred && samples_frame == o.samples_frame &&
           srgb_frame_view == o.srgb_frame_view && output_pass == o.output_pass;
  }
  bool operator!=(const FxPassLayout& o) const { return !(*this == o); }
};

// The layout for `technique` of `compiled` in a host that hands sRGB codes or not.
FxPassLayout plan_pass_layout(const pfx::fx::CompiledEffect& compiled, int technique, bool display_referred);

// The fragment shader of the output pass: the technique's pixel shader, then the frame's alpha
// (sampled on texture unit `unit`) in place of the alpha it wrote, as the last pass would keep it;
// `encode_srgb`: its colour encoded as an sRGB write would (the host's output takes codes as
// they are), clamped to [0, 1] with NaN as 0 as the hosts' encodings do.
std::string with_frame_alpha(const std::string& fragment, std::size_t unit, bool encode_srgb);

}  // namespace pfx_fx
