// The GL state a pass must leave as it found it (docs/sdk.md §1.5), read with glGet so a
// snapshot taken before run_pass can be compared with one taken after.
#pragma once

#include <string>
#include <vector>

namespace pfx::validate {

struct GlStateValue {
  std::string name;         // "GL_SCISSOR_TEST", "GL_VIEWPORT"
  std::vector<long> values;  // one for an enable or a binding, four for the viewport or a mask
};

using GlStateSnapshot = std::vector<GlStateValue>;

// Reads every protected value of the current context (this program's GL functions must be
// loaded). Raises no GL error.
GlStateSnapshot snapshot_gl_state();

// One phrase per value that differs: "GL_SCISSOR_TEST enabled (was disabled)".
std::vector<std::string> gl_state_changes(const GlStateSnapshot& before, const GlStateSnapshot& after);

// The names snapshot_gl_state reads, for the documentation and --help.
std::vector<std::string> protected_gl_state_names();

}  // namespace pfx::validate
