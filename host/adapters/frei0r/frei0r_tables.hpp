// The parameter tables of the per-effect frei0r plugins, as docs/hosts.md shows them: made from
// the descriptors the plugins themselves use, so the page can be checked against them.
#pragma once

#include <string>

#include <pfx/effect.h>

namespace pfx::frei0r {

// One effect's table in Markdown: a heading naming the plugin in each host, then a row per
// frei0r parameter (index, name, type, what its value means, the default as frei0r and pfx give
// it, and the scene-referred default where it differs).
std::string markdown_table(const pfx_effect_desc& effect);

}  // namespace pfx::frei0r
