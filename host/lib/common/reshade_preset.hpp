// ReShade preset files (.ini) as pfx presets, so a look made in ReShade drives pfx's hosts:
//
//   PreprocessorDefinitions=NAME=VALUE,...
//   Techniques=LumaSharpen@LumaSharpen.fx,Vibrance@Vibrance.fx      (the enabled techniques)
//   TechniqueSorting=Vibrance@Vibrance.fx,LumaSharpen@LumaSharpen.fx (the order they run in)
//   [LumaSharpen.fx]
//   sharp_strength=0.650000
//   VibranceRGBBalance=1.000000,1.000000,1.000000
//
// Each enabled technique becomes the FX plugin's effect fx_<technique> (the id rule both share is
// pfx::identifier_from, pfx/cpp/identifier.hpp), in TechniqueSorting's order (Techniques' when
// there is none); each value of a technique's file becomes an assignment to that effect's
// parameter of the uniform's name. A float4 value sets the parameter of its first three
// components and the "_alpha" or "_w" one of its fourth, whichever the effect has.
// PreprocessorDefinitions become Preset::source_definitions, as written, for the FX effects
// (Chain::set_source_definitions).
#pragma once

#include <string>

#include "preset.hpp"

namespace pfx::app {

// Whether the text is a ReShade preset rather than a pfx JSON preset.
bool looks_like_reshade_preset(const std::string& text);

// Fills out->chain, out->assignments and out->source_definitions. Every text reads, as ReShade
// reads its .ini files: a byte-order mark, CRLF ends, comments (';', '#', '/') and lines that are
// not NAME=VALUE are passed over; a key given twice in a section keeps its first value.
void parse_reshade_preset(const std::string& text, Preset* out);

}  // namespace pfx::app
