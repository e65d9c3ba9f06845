#pragma once
// Images FX textures name with `source = "file.png"`: found beside the effect as ReShade lays a
// collection out (a Textures folder beside the Shaders folder), in the folders of
// PFX_FX_TEXTURE_PATH, or beside the .fx file; decoded to 8-bit RGBA (images/texture_image.hpp:
// an image of another size than the texture declares is scaled to it, nearest texel) and uploaded
// with GL's row order.
#include <string>

#include "fx_gl_objects.hpp"
#include "model/effect_model.hpp"

namespace pfx_fx {

// The file's path, or "" when no folder has it.
std::string find_texture_file(const std::string& name, const std::string& effect_file);

bool load_texture_file(const pfx::fx::TextureInfo& info, const std::string& effect_file, GlTexture& texture, std::string& error);

}  // namespace pfx_fx
