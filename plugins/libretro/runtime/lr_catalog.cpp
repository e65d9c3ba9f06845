#include "lr_catalog.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <mutex>
#include <set>

#include <pfx/cpp/identifier.hpp>

#include "glsl_source.hpp"
#include "lr_effect.hpp"
#include "slang_source.hpp"

namespace pfx_libretro {
namespace {

namespace fs = std::filesystem;
using namespace pfx::libretro;

std::string plugin_folder() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<const void*>(&plugin_folder), &info) && info.dli_fname)
    return fs::path(info.dli_fname).parent_path().string();
  return ".";
}

// Every .slangp and .glslp under `folder` (or the file itself), sorted, so the list is the same on
// every run.
std::vector<std::string> preset_files(const std::string& folder) {
  std::vector<std::string> files;
  std::error_code ec;
  if (fs::is_regular_file(folder, ec)) return {folder};
  for (fs::recursive_directory_iterator it(folder, fs::directory_options::skip_permission_denied, ec), end;
       !ec && it != end; it.increment(ec))
    if (it->is_regular_file(ec) && (it->path().extension() == ".slangp" || it->path().extension() == ".glslp"))
      files.push_back(it->path().string());
  std::sort(files.begin(), files.end());
  return files;
}

// "file:line: why" as compilers write an error: "file:line: error: why".
std::string as_error(const std::string& message) {
  const std::size_t colon = message.find(": ");
  if (colon == std::string::npos) return "error: " + message;
  return message.substr(0, colon + 2) + "error: " + message.substr(colon + 2);
}

// The shaders' parameters, read once per file: the collections share a shader among many presets.
class ShaderParameters {
 public:
  const SlangSource* read(const std::string& path, std::string* error) {
    auto found = read_.find(path);
    if (found == read_.end()) {
      Entry entry;
      SlangSource full;
      const bool glsl = fs::path(path).extension() != ".slang";  // .glsl, or what a .glslp names
      if (glsl ? read_glsl(path, read_text_file, &full, &entry.error)
               : read_slang(path, read_text_file, &full, &entry.error))
        entry.source.parameters = std::move(full.parameters);
      entry.ok = entry.error.empty();
      found = read_.emplace(path, std::move(entry)).first;
    }
    if (!found->second.ok) *error = found->second.error;
    return found->second.ok ? &found->second.source : nullptr;
  }

 private:
  struct Entry {
    bool ok = false;
    SlangSource source;  // parameters only
    std::string error;
  };
  std::map<std::string, Entry> read_;
};

void add_preset(LrCatalog& c, const std::string& folder, const std::string& file, std::set<std::string>& ids,
                ShaderParameters& shaders) {
  auto entry = std::make_unique<LrEffectEntry>();
  std::string error;
  if (!read_preset(file, read_text_file, &entry->preset, &error)) {
    c.errors.push_back({file, as_error(error)});
    return;
  }
  std::vector<const SlangSource*> sources;
  for (std::size_t i = 0; i < entry->preset.passes.size(); ++i) {
    const SlangSource* source = shaders.read(entry->preset.passes[i].shader, &error);
    if (!source) {
      c.errors.push_back({file, as_error(error) + " (pass " + std::to_string(i) + " of " + file + ")"});
      return;
    }
    sources.push_back(source);
  }
  entry->warnings = entry->preset.warnings;
  build_parameters(entry->preset, sources, entry->params, entry->warnings);
  std::error_code ec;
  fs::path relative = fs::is_directory(folder, ec) ? fs::relative(file, folder, ec) : fs::path(file).filename();
  if (ec || relative.empty()) relative = fs::path(file).filename();
  // The GLSL form of a preset has the slang form's id and "_glsl": collections ship both.
  const bool glsl = entry->preset.format == PresetFormat::kGlsl;
  const std::string base = "libretro_" + pfx::identifier_from(relative.replace_extension().string()) +
                           (glsl ? "_glsl" : "");
  entry->id = base;
  for (int k = 2; ids.count(entry->id); ++k) entry->id = base + "_" + std::to_string(k);
  ids.insert(entry->id);
  entry->file = file;
  entry->label = fs::path(file).stem().string() + (glsl ? " (GLSL)" : "");
  entry->description = std::string(glsl ? "libretro GLSL shader preset " : "libretro shader preset ") +
                       relative.string() + " (" + std::to_string(entry->preset.passes.size()) +
                       (entry->preset.passes.size() == 1 ? " pass)" : " passes)");
  c.effects.push_back(std::move(entry));
}

}  // namespace

std::vector<std::string> search_folders() {
  std::vector<std::string> folders;
  const char* value = std::getenv("PFX_LIBRETRO_PATH");
  const std::string list = value ? value : "";
  for (std::size_t start = 0; start < list.size();) {
    std::size_t end = list.find(':', start);
    if (end == std::string::npos) end = list.size();
    if (end > start) folders.push_back(list.substr(start, end - start));
    start = end + 1;
  }
  const std::string installed = plugin_folder() + "/libretro/shaders";
  std::error_code ec;
  if (fs::is_directory(installed, ec)) folders.push_back(installed);
  return folders;
}

const LrCatalog& catalog() {
  static LrCatalog c;
  static std::once_flag once;
  std::call_once(once, [] {
    std::set<std::string> ids, seen;
    ShaderParameters shaders;
    for (const std::string& folder : search_folders()) {
      std::error_code ec;
      if (!fs::exists(folder, ec)) {
        c.errors.push_back({folder, "PFX_LIBRETRO_PATH: error: " + folder + " does not exist"});
        continue;
      }
      for (const std::string& file : preset_files(folder))
        if (seen.insert(fs::weakly_canonical(file, ec).string()).second) add_preset(c, folder, file, ids, shaders);
    }
    if (c.effects.size() > kMaxEffects) {  // each effect needs one of the create functions there are
      c.errors.push_back({"", "PFX_LIBRETRO_PATH: error: " + std::to_string(c.effects.size()) +
                                  " presets found; only the first " + std::to_string(kMaxEffects) + " are offered"});
      c.effects.resize(kMaxEffects);
    }
    for (std::size_t i = 0; i < c.effects.size(); ++i) fill_effect_desc(*c.effects[i], i);
  });
  return c;
}

const LrEffectEntry* find_effect(const char* effect_id) {
  if (!effect_id) return nullptr;
  for (const auto& entry : catalog().effects)
    if (entry->id == effect_id) return entry.get();
  return nullptr;
}

}  // namespace pfx_libretro
