#pragma once
// Headers that effects of one public shader collection include from another: an effect of one
// collection may include DrawText.fxh, which only reshade-shaders ships. When such a header is not
// found, the error names the collection it comes with.
#include <string>

namespace pfx::fx {

// "crosire/reshade-shaders" for "DrawText.fxh" (the name as #include writes it, any folder before
// it ignored, compared without case); empty for a header pfx does not know.
std::string collection_of_header(const std::string& include_name);

}  // namespace pfx::fx
