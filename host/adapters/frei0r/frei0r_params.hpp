// frei0r parameters made from a pfx effect's parameter descriptors, and values carried between
// the two. frei0r has five types and hosts show a double as a 0-1 slider, so:
//   float, int   F0R_PARAM_DOUBLE 0-1 over the descriptor's display range (logarithmic when the
//                descriptor asks for a logarithmic slider; ints rounded); a value past 0 or 1 goes
//                past the range the same way, up to the hard range
//   bool         F0R_PARAM_BOOL
//   enum         F0R_PARAM_STRING, the item's id (its index is taken too)
//   colour       F0R_PARAM_COLOR, linear RGB as it is
//   vec2         F0R_PARAM_POSITION, each component 0-1 over the display range
//   vec3         F0R_PARAM_STRING "x,y,z"
// The name is the parameter's id ("threshold"); the explanation its label, tooltip and mapping.
#pragma once

#include <string>
#include <vector>

#include <pfx/effect.h>

namespace pfx::frei0r {

struct ParamSlot {
  std::string name;
  int type = 0;  // F0R_PARAM_*
  std::string explanation;
};

int frei0r_type(const pfx_param_desc& desc);
std::vector<ParamSlot> effect_slots(const pfx_effect_desc& effect);

// A component of a float, int or vec2 parameter: its value as frei0r's 0-1 and back.
double to_unit(const pfx_param_desc& desc, double value);
double from_unit(const pfx_param_desc& desc, double unit);

// "0-1 is 0-8", "0-1 is 1-64 px (logarithmic)": the mapping in words, for explanations and docs.
std::string unit_mapping_text(const pfx_param_desc& desc);

}  // namespace pfx::frei0r
