// Plugin libraries opened so that every registry of the process has its own. dlopen hands whoever
// opens a path again the mapping already there, so two registries loading the same plugin would
// share its globals: what init told it of its host (the thread pool, the log), overwritten by the
// second registry and cleared by the first deinit. A process-wide record of which registry holds
// which mapping tells when a registry must load a private copy of the file instead.
#pragma once

#include <string>

namespace pfx::host {

// Copies the library at `path` to a name no library of this process was loaded from, beside the
// original or, where that folder is read-only, in the temporary folder. False, with *reason, when
// neither takes the copy.
bool make_private_copy(const std::string& path, std::string* copy, std::string* reason);

// Opens `file` for `owner` (RTLD_NOW | RTLD_LOCAL). When another owner holds the mapping dlopen
// hands back, opens a private copy of `file` instead and removes the copy's name at once (the
// mapping keeps the library). Null on failure, with *reason naming the library as `shown_as`,
// never as the copy.
void* open_own_library(const void* owner, const std::string& file, const std::string& shown_as, std::string* reason);

// Undoes open_own_library: call it after the plugin's deinit, never before.
void close_own_library(const void* owner, void* library);

}  // namespace pfx::host
