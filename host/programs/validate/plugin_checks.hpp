// The checks that need the plugin library but no GL: loading, the entry struct, init/deinit,
// factories, descriptors. Each runs in its own child process (see checks.hpp) and reports through
// a CheckReporter.
#pragma once

#include <string>

#include "child_process.hpp"

namespace pfx::validate {

// dlopen(RTLD_NOW | RTLD_LOCAL) and the entry symbol.
void check_load(const std::string& path, CheckReporter& report);
// The entry struct: size, ABI major, a well-formed plugin id, name, version, functions. Reports
// the facts plugin_id, name and version.
void check_entry(const std::string& path, CheckReporter& report);
// init twice (idempotent), deinit, init again (after a deinit), deinit; no GL asked for.
void check_init_deinit(const std::string& path, CheckReporter& report);
// The effect factory is complete, effect ids are well-formed and unique, and unknown factory ids
// give NULL. Reports a fact "effect" per effect, in order.
void check_factories(const std::string& path, CheckReporter& report);
// The descriptor of one effect (descriptor_checks.hpp).
void check_descriptors(const std::string& path, const std::string& effect_id, CheckReporter& report);

}  // namespace pfx::validate
