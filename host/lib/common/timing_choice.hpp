// Which timing scheme a program runs its chain with. libpfxhost takes the scheme it is given and
// never looks at the renderer; our programs pick their default from it here.
#pragma once

#include <string>

#include <pfx/host/chain.hpp>

namespace pfx::app {

// FINISH_AND_CLOCK on Mesa's software renderers (llvmpipe, softpipe), whose timestamp queries are
// taken when commands are queued rather than when the deferred rasteriser runs them;
// GPU_QUERIES elsewhere. `gl_renderer` is GL_RENDERER's text.
pfx::host::Timing default_timing(const std::string& gl_renderer);

// "gpu", "finish", "off", or "auto" (default_timing). False for any other name.
bool parse_timing(const std::string& name, const std::string& gl_renderer, pfx::host::Timing* timing);

}  // namespace pfx::app
