#pragma once
// A preset's parameters as pfx parameters. Each `#pragma parameter` of the preset's shaders (the
// first pass to declare an id gives its label, range and step, as RetroArch requires every pass
// declaring it to agree) becomes a float parameter with that range and step; its default is the
// value the preset gives it, else the shader's initial value. A parameter whose minimum equals its
// maximum (the collections use them as headings: "[ SCANLINES ]") has nothing to set: it is not
// offered, and the shaders read its one value. Ids are the shader's names made into pfx ids
// (`BEAM_MIN` -> beam_min). Two options of pfx follow them: content_width and content_height
// (content_size.hpp).
#include <memory>
#include <string>
#include <vector>

#include <pfx/params.h>

#include "chain_plan.hpp"
#include "preset.hpp"
#include "slang_source.hpp"

namespace pfx_libretro {

struct LrParameters {
  std::vector<pfx_param_desc> descs;
  std::vector<std::unique_ptr<std::string>> strings;  // what the descriptors point to
  // Per `#pragma parameter` id of the shaders, in the order the slang semantics index them:
  std::vector<std::string> shader_ids;
  std::vector<int> descriptor;                  // its descriptor, or -1 for a heading
  std::vector<double> fixed;                    // a heading's value (and every parameter's default)
  int content_width = -1, content_height = -1;  // the descriptors of the content options

  const char* keep(const std::string& text);
};

// The parameters of a preset whose passes' shaders are `sources`; `warnings` collects ids declared
// twice with different settings (the first declaration is kept).
void build_parameters(const pfx::libretro::Preset& preset,
                      const std::vector<const pfx::libretro::SlangSource*>& sources, LrParameters& out,
                      std::vector<std::string>& warnings);

}  // namespace pfx_libretro
