#include "fx_catalog.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <set>

#include "effect_compiler.hpp"
#include "fx_effect.hpp"
#include "fx_frame_params.hpp"
#include "vk_technique.hpp"

namespace pfx_fx {
namespace {

namespace fs = std::filesystem;

// Frame size the catalog compiles at: only for listing; instances compile at their frame's size.
// A second compile at another size and shape finds the parameters whose defaults or ranges follow
// the size (fx_frame_params.hpp).
constexpr int kNominalWidth = 1920, kNominalHeight = 1080;
constexpr int kOtherWidth = 800, kOtherHeight = 600;

}  // namespace

std::vector<std::string> folders_in_variable(const char* name) {
  std::vector<std::string> folders;
  const char* value = std::getenv(name);
  std::string list = value ? value : "";
  for (std::size_t start = 0; start < list.size();) {
    std::size_t end = list.find(':', start);
    if (end == std::string::npos) end = list.size();
    if (end > start) folders.push_back(list.substr(start, end - start));
    start = end + 1;
  }
  return folders;
}

std::vector<std::string> search_folders() {
  std::vector<std::string> folders = folders_in_variable("PFX_FX_PATH");
  std::string installed = plugin_folder() + "/fx/shaders";
  std::error_code ec;
  if (fs::is_directory(installed, ec)) folders.push_back(installed);
  return folders;
}

namespace {

// Every .fx file under `folder`, sorted, so the list is the same on every run.
std::vector<std::string> fx_files(const std::string& folder) {
  std::vector<std::string> files;
  std::error_code ec;
  if (fs::is_regular_file(folder, ec)) return {folder};
  for (fs::recursive_directory_iterator it(folder, fs::directory_options::skip_permission_denied, ec), end; !ec && it != end;
       it.increment(ec)) {
    if (it->is_regular_file(ec) && it->path().extension() == ".fx") files.push_back(it->path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string file_stem(const std::string& path) { return fs::path(path).stem().string(); }

void add_file(FxCatalog& c, const std::string& file, std::set<std::string>& ids) {
  auto compiled = pfx::fx::compile_effect(file, compile_options(kNominalWidth, kNominalHeight), false);
  if (!compiled->ok()) {
    // The errors only (warnings are the author's business), without the final newline.
    std::string message;
    for (const pfx::fx::Diagnostic& d : compiled->front->diagnostics.all())
      if (d.severity == pfx::fx::Severity::kError) message += (message.empty() ? "" : "\n") + compiled->front->diagnostics.format(d);
    c.errors.push_back({file, message});
    return;
  }
  const pfx::fx::EffectModel& model = compiled->model;
  // Parameters of the file at another size; none when it does not compile there.
  ParamTable other;
  auto at_other = pfx::fx::compile_effect(file, compile_options(kOtherWidth, kOtherHeight), false);
  std::vector<std::string> unused;
  if (at_other->ok()) build_params(at_other->model, other, unused);
  for (std::size_t t = 0; t < model.techniques.size(); ++t) {
    const pfx::fx::TechniqueInfo& technique = model.techniques[t];
    auto entry = std::make_unique<FxEffectEntry>();
    std::string base = "fx_" + identifier_from(technique.name);
    entry->id = ids.count(base) ? "fx_" + identifier_from(file_stem(file)) + "_" + identifier_from(technique.name) : base;
    for (int k = 2; ids.count(entry->id); ++k) entry->id = base + "_" + std::to_string(k);
    ids.insert(entry->id);
    entry->file = file;
    entry->technique = technique.name;
    entry->technique_index = static_cast<int>(t);
    entry->vulkan_unsupported = pfx::fx::vulkan::Technique::unsupported_reason(model, static_cast<int>(t));
    entry->label = pfx::fx::annotation_string(technique.annotations, "ui_label", technique.name);
    entry->description = pfx::fx::annotation_string(technique.annotations, "ui_tooltip",
                                                    "ReShade FX technique " + technique.name + " from " + fs::path(file).filename().string());
    std::vector<std::string> warnings;
    build_params(model, entry->params, warnings);
    if (at_other->ok()) mark_frame_size_dependence(entry->params, other);
    c.effects.push_back(std::move(entry));
  }
}

}  // namespace

std::string plugin_folder() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<const void*>(&plugin_folder), &info) && info.dli_fname)
    return fs::path(info.dli_fname).parent_path().string();
  return ".";
}

const std::vector<std::string>& include_folders() {
  // The file's own folder is searched first by the preprocessor; then the shader folders (a
  // collection's ReShade.fxh), then pfx's own headers.
  static const std::vector<std::string> folders = [] {
    std::vector<std::string> out;
    for (const std::string& folder : search_folders()) {
      std::error_code ec;
      out.push_back(fs::is_directory(folder, ec) ? folder : fs::path(folder).parent_path().string());
    }
    out.push_back(plugin_folder() + "/fx/include");
    return out;
  }();
  return folders;
}

pfx::fx::FrontEndOptions compile_options(int width, int height) {
  pfx::fx::FrontEndOptions options;
  options.preprocessor.buffer_width = width;
  options.preprocessor.buffer_height = height;
  options.preprocessor.include_folders = include_folders();
  // The depth pfx hands FX effects (fx_instance.hpp) is what these settings of ReShade.fxh read
  // right; defined here, they hold for a collection's own ReShade.fxh too (it only sets them
  // when they are not defined).
  options.preprocessor.defines = {{"RESHADE_DEPTH_INPUT_IS_UPSIDE_DOWN", "0"}, {"RESHADE_DEPTH_INPUT_IS_REVERSED", "0"},
                                  {"RESHADE_DEPTH_INPUT_IS_LOGARITHMIC", "0"}, {"RESHADE_DEPTH_MULTIPLIER", "1"},
                                  {"RESHADE_DEPTH_LINEARIZATION_FAR_PLANE", "1000.0"}};
  return options;
}

const FxCatalog& catalog() {
  static FxCatalog c;
  static std::once_flag once;
  std::call_once(once, [] {
    std::vector<std::string> folders = search_folders();
    std::set<std::string> ids;
    std::set<std::string> seen;
    for (const std::string& folder : folders)
      for (const std::string& file : fx_files(folder))
        if (seen.insert(fs::weakly_canonical(file).string()).second) add_file(c, file, ids);
    if (c.effects.size() > kMaxEffects) {  // each effect needs one of the create functions there are
      c.errors.push_back({"", "PFX_FX_PATH: error: " + std::to_string(c.effects.size()) + " techniques found; only the first " +
                                  std::to_string(kMaxEffects) + " are offered"});
      c.effects.resize(kMaxEffects);
    }
    for (std::size_t i = 0; i < c.effects.size(); ++i) fill_effect_desc(*c.effects[i], i);
  });
  return c;
}

const FxEffectEntry* find_effect(const char* effect_id) {
  if (!effect_id) return nullptr;
  for (const auto& entry : catalog().effects)
    if (entry->id == effect_id) return entry.get();
  return nullptr;
}

const ParamTable* params_at(const FxEffectEntry& entry, int width, int height) {
  if (width < 1 || height < 1 || width > 16384 || height > 16384) return nullptr;
  bool follows = false;
  for (const pfx_param_desc& d : entry.params.descs) follows = follows || (d.flags & PFX_PARAM_FOLLOWS_FRAME_SIZE);
  if (!follows) return nullptr;
  std::lock_guard<std::mutex> lock(entry.sized_mutex);
  auto found = entry.sized.find({width, height});
  if (found != entry.sized.end()) return found->second.get();
  auto compiled = pfx::fx::compile_effect(entry.file, compile_options(width, height), false);
  if (!compiled->ok()) return nullptr;
  auto table = std::make_unique<ParamTable>();
  build_params_at_size(compiled->model, entry.params, *table);
  if (table->descs.size() != entry.params.descs.size()) return nullptr;
  return entry.sized.emplace(std::make_pair(width, height), std::move(table)).first->second.get();
}

}  // namespace pfx_fx
