// pfx-inject --bench: what the injector costs an application, measured in one run on one machine.
// The application runs FRAMES frames three ways (alone, with the library and an empty
// chain, with the chain), each several times in turn; the frame time is the median interval
// between presents, and the cost is quoted in full-frame copy passes timed inside the same
// application at its own size.
#pragma once

#include <string>

#include "inject_options.hpp"

namespace pfx::inject {

// Prints the table (and writes --bench-json); returns 0, or the failing run's exit code.
int run_bench(const InjectOptions& options, const std::string& library);

}  // namespace pfx::inject
