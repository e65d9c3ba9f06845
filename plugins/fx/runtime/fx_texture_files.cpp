#include "fx_texture_files.hpp"

#include <algorithm>
#include <filesystem>
#include <vector>

#include "fx_catalog.hpp"
#include "texture_image.hpp"

namespace pfx_fx {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> candidate_folders(const std::string& effect_file) {
  std::vector<std::string> folders = folders_in_variable("PFX_FX_TEXTURE_PATH");
  // ReShade's layout: reshade-shaders/Shaders/[...]/Effect.fx beside reshade-shaders/Textures.
  for (fs::path folder = fs::path(effect_file).parent_path(); !folder.empty(); folder = folder.parent_path()) {
    folders.push_back((folder / "Textures").string());
    folders.push_back((folder.parent_path() / "Textures").string());
    if (folder == folder.parent_path()) break;
  }
  for (const std::string& root : search_folders()) folders.push_back((fs::path(root).parent_path() / "Textures").string());
  folders.push_back(fs::path(effect_file).parent_path().string());
  return folders;
}

}  // namespace

std::string find_texture_file(const std::string& name, const std::string& effect_file) {
  std::error_code ec;
  std::vector<std::string> folders = candidate_folders(effect_file);
  for (const std::string& folder : folders) {
    fs::path candidate = fs::path(folder) / name;
    if (fs::is_regular_file(candidate, ec)) return candidate.string();
  }
  // Collections keep their textures in sub-folders (Textures/SweetFX/AreaTex.png), as ReShade's
  // default texture search path (Textures\**) allows.
  fs::path wanted = fs::path(name).filename();
  for (const std::string& folder : folders) {
    if (fs::path(folder).filename() != "Textures" || !fs::is_directory(folder, ec)) continue;
    for (fs::recursive_directory_iterator it(folder, fs::directory_options::skip_permission_denied, ec), end; !ec && it != end; it.increment(ec))
      if (it->path().filename() == wanted && it->is_regular_file(ec)) return it->path().string();
  }
  return "";
}

bool load_texture_file(const pfx::fx::TextureInfo& info, const std::string& effect_file, GlTexture& texture, std::string& error) {
  std::string path = find_texture_file(info.source, effect_file);
  if (path.empty()) {
    error = "source image '" + info.source + "' was not found (looked in a Textures folder beside the effect and in PFX_FX_TEXTURE_PATH)";
    return false;
  }
  pfx::fx::TextureTexels decoded;
  const int depth = texture.target == GL_TEXTURE_3D ? texture.depth : 1;
  if (!pfx::fx::decode_texture_image(path, texture.width, texture.height, depth, decoded, error)) return false;
  // GL's row order: each slice's bottom row first.
  const std::size_t row = static_cast<std::size_t>(texture.width) * 4;
  std::vector<unsigned char> texels(decoded.rgba.size());
  for (int z = 0; z < depth; ++z)
    for (int y = 0; y < texture.height; ++y) {
      const std::size_t slice = static_cast<std::size_t>(z) * static_cast<std::size_t>(texture.height);
      std::copy_n(decoded.rgba.data() + (slice + static_cast<std::size_t>(y)) * row, row,
                  texels.data() + (slice + static_cast<std::size_t>(texture.height - 1 - y)) * row);
    }
  // The upload reads client memory with the pixel store the host's contract sets (alignment 4,
  // nothing bound to the unpack buffer), which a row of RGBA8 always satisfies.
  if (texture.target == GL_TEXTURE_3D)
    glTextureSubImage3D(texture.texture, 0, 0, 0, 0, texture.width, texture.height, texture.depth, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  else if (texture.target == GL_TEXTURE_1D)
    glTextureSubImage1D(texture.texture, 0, 0, texture.width, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  else
    glTextureSubImage2D(texture.texture, 0, 0, 0, texture.width, texture.height, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  if (texture.levels > 1) glGenerateTextureMipmap(texture.texture);
  return true;
}

}  // namespace pfx_fx
