// Material libraries (.mtl): the statements pfx uses (newmtl, Kd, Ks, Ke, Ns, d, Tr, map_Kd,
// map_Ke, map_d, bump / map_Bump, norm); every other statement is skipped. A bad material library never fails an import: its
// problems are warnings, and the model loads with default materials.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace pfx_obj {

struct Material {
  explicit Material(std::string material_name = "") : name(std::move(material_name)) {}
  std::string name;
  float diffuse[3] = {0.8f, 0.8f, 0.8f};
  float specular[3] = {0.0f, 0.0f, 0.0f};
  float emissive[3] = {0.0f, 0.0f, 0.0f};
  float shininess = 0.0f;
  float opacity = 1.0f;
  std::string diffuse_map;   // resolved against the .mtl file's folder; empty when absent
  std::string emissive_map;
  std::string alpha_map;     // map_d
  std::string bump_map;      // bump, map_Bump
  std::string normal_map;    // norm
};

// Appends the materials of `text`. Warnings are "FILE:LINE: text" with `file_name`; map paths
// are resolved against `directory` (backslashes read as '/').
void parse_mtl(std::string_view text, const std::string& file_name, const std::string& directory,
               std::vector<Material>* materials, std::vector<std::string>* warnings);

// `path` as written in a material library or OBJ file, resolved against `directory`.
std::string resolve_path(const std::string& directory, std::string path);

}  // namespace pfx_obj
