#include "fx_texture_files.hpp"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include <stb/stb_image.h>

#include "fx_catalog.hpp"

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
  std::ifstream file(path, std::ios::binary);
  std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  int w = 0, h = 0, channels = 0;
  unsigned char* pixels = bytes.empty() ? nullptr : stbi_load_from_memory(bytes.data(), static_cast<int>(bytes.size()), &w, &h, &channels, 4);
  if (!pixels) {
    error = "cannot read '" + path + "': " + (bytes.empty() ? std::string("empty or unreadable") : stbi_failure_reason());
    return false;
  }
  // Texels in GL's order (bottom row first), scaled to the declared size. A 3D texture's slices
  // lie side by side in the image, as LUT images do (width = width * depth of the texture).
  int tw = texture.width * (texture.target == GL_TEXTURE_3D ? texture.depth : 1), th = texture.height;
  std::vector<unsigned char> texels(static_cast<std::size_t>(tw) * static_cast<std::size_t>(th) * 4);
  for (int y = 0; y < th; ++y)
    for (int x = 0; x < tw; ++x) {
      int sx = static_cast<int>(static_cast<long long>(x) * w / tw), sy = static_cast<int>(static_cast<long long>(y) * h / th);
      const unsigned char* from = pixels + (static_cast<std::size_t>(sy) * static_cast<std::size_t>(w) + static_cast<std::size_t>(sx)) * 4;
      unsigned char* to = texels.data() + (static_cast<std::size_t>(th - 1 - y) * static_cast<std::size_t>(tw) + static_cast<std::size_t>(x)) * 4;
      for (int c = 0; c < 4; ++c) to[c] = from[c];
    }
  stbi_image_free(pixels);
  // The upload reads client memory with the pixel store the host's contract sets (alignment 4,
  // nothing bound to the unpack buffer), which a row of RGBA8 always satisfies.
  if (texture.target == GL_TEXTURE_3D) {
    // Slice z is the z-th tile of the row of tiles.
    std::vector<unsigned char> volume(texels.size());
    for (int z = 0; z < texture.depth; ++z)
      for (int y = 0; y < th; ++y)
        for (int x = 0; x < texture.width; ++x)
          for (int c = 0; c < 4; ++c)
            volume[((static_cast<std::size_t>(z) * th + y) * texture.width + x) * 4 + c] =
                texels[(static_cast<std::size_t>(y) * tw + static_cast<std::size_t>(z) * texture.width + x) * 4 + c];
    glTextureSubImage3D(texture.texture, 0, 0, 0, 0, texture.width, th, texture.depth, GL_RGBA, GL_UNSIGNED_BYTE, volume.data());
  } else if (texture.target == GL_TEXTURE_1D) {
    glTextureSubImage1D(texture.texture, 0, 0, tw, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  } else {
    glTextureSubImage2D(texture.texture, 0, 0, 0, tw, th, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  }
  if (texture.levels > 1) glGenerateTextureMipmap(texture.texture);
  return true;
}

}  // namespace pfx_fx
