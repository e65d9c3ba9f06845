// Keeps the shared objects that one call loads (a GL driver) in memory for the rest of the process.
//
// Mesa's EGL loads its driver (swrast_dri.so and LLVM with it) in eglInitialize and unloads it in
// eglTerminate. The driver allocates process-wide state once and never frees it: harmless while
// it is loaded, but after the unload nothing points at those blocks any more, so LeakSanitizer
// reports them as leaks in every program that terminates a display, from an unknown module it
// cannot name or suppress. Kept loaded, the blocks stay reachable from the driver's own globals,
// and a second eglInitialize in the same process does not load the driver again.
#pragma once

#include <string>
#include <vector>

namespace pfx::app {

// The file names of the shared objects mapped into the process now (dl_iterate_phdr order).
std::vector<std::string> loaded_shared_objects();

// Marks every shared object loaded now but not in `before` as never to be unloaded
// (dlopen RTLD_NOLOAD | RTLD_NODELETE); returns how many it marked.
int keep_loaded_since(const std::vector<std::string>& before);

}  // namespace pfx::app
