#include "preset.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <memory>

namespace pfx::libretro {
namespace {

std::string trimmed(const std::string& text) {
  const std::size_t first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

// Numbers as RetroArch reads them (strtoul with base 0, strtod), a leading part that is a number
// counting, but never in the process's locale: "0x10" is 16, "010" 8, "800.0" as an integer 800.
std::optional<unsigned long long> leading_unsigned(const std::string& value) {
  std::string text = trimmed(value);
  if (!text.empty() && text[0] == '+') text.erase(0, 1);
  int base = 10;
  std::size_t start = 0;
  if (text.size() > 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X'))
    base = 16, start = 2;
  else if (text.size() > 1 && text[0] == '0')
    base = 8, start = 1;
  unsigned long long number = 0;
  const auto [end, status] = std::from_chars(text.data() + start, text.data() + text.size(), number, base);
  if (status != std::errc() || end == text.data() + start)
    return base == 8 ? std::optional<unsigned long long>(0) : std::nullopt;
  return number;
}

std::optional<double> leading_number(const std::string& value) {
  std::string text = trimmed(value);
  if (!text.empty() && text[0] == '+') text.erase(0, 1);
  double number = 0;
  const auto [end, status] = std::from_chars(text.data(), text.data() + text.size(), number);
  if (status != std::errc() || end == text.data()) return std::nullopt;
  return number;
}

std::optional<ScaleType> scale_type_of(const std::string& word) {
  if (word == "source") return ScaleType::kSource;
  if (word == "viewport") return ScaleType::kViewport;
  if (word == "absolute") return ScaleType::kAbsolute;
  return std::nullopt;
}

std::optional<WrapMode> wrap_mode_of(const std::string& word) {
  if (word == "clamp_to_border") return WrapMode::kClampToBorder;
  if (word == "clamp_to_edge") return WrapMode::kClampToEdge;
  if (word == "repeat") return WrapMode::kRepeat;
  if (word == "mirrored_repeat") return WrapMode::kMirroredRepeat;
  return std::nullopt;
}

// The files of one preset, each read once.
class Files {
 public:
  explicit Files(const TextReader& read) : read_(read) {}
  const PresetFile* get(const std::string& path, std::string* error) {
    auto it = files_.find(path);
    if (it != files_.end()) return it->second.get();
    auto file = std::make_unique<PresetFile>();
    if (!read_preset_file(path, read_, file.get(), error)) return nullptr;
    return files_.emplace(path, std::move(file)).first->second.get();
  }

 private:
  const TextReader& read_;
  std::map<std::string, std::unique_ptr<PresetFile>> files_;
};

// The file a reference names. RetroArch first replaces its $WILDCARD$s (the core, the game, the
// video driver...) and keeps the path as written when that file is missing; pfx has no core or
// game, so the path as written is the one.
std::string referenced(const PresetEntry& reference, const std::string& from) {
  return resolve_preset_path(reference.value, from);
}

// The root of `file`: the file its chain of first references ends at.
const PresetFile* root_of(const PresetFile* file, Files& files, std::string* error) {
  for (int hops = 0; file && !file->references.empty(); ++hops) {
    const PresetEntry& first = file->references.front();
    if (hops == kMaxReferenceDepth)
      return *error = first.place.text() + ": references go more than " + std::to_string(kMaxReferenceDepth) +
                      " deep (does a preset reference itself?)",
             nullptr;
    const PresetFile* next = files.get(referenced(first, file->path), error);
    if (!next) return *error = first.place.text() + ": #reference: " + *error, nullptr;
    file = next;
  }
  return file;
}

// Every file whose values apply, in the order they apply: each file after its references, in the
// order it names them (RetroArch's order), at most kMaxReferenceDepth deep.
bool gather_layers(const PresetFile* file, int depth, Files& files, std::vector<const PresetFile*>* layers,
                   std::vector<std::string>* warnings, std::string* error) {
  // Files that reference one another twice over would make the list grow with every level.
  if (layers->size() >= static_cast<std::size_t>(kMaxReferencedFiles))
    return *error = file->path + ": references reach files more than " + std::to_string(kMaxReferencedFiles) + " times",
           false;
  for (const PresetEntry& reference : file->references) {
    if (depth == kMaxReferenceDepth) {
      warnings->push_back(reference.place.text() + ": more than " + std::to_string(kMaxReferenceDepth) +
                          " references deep: its values are left out");
      continue;
    }
    const PresetFile* next = files.get(referenced(reference, file->path), error);
    if (!next) return *error = reference.place.text() + ": #reference: " + *error, false;
    if (!gather_layers(next, depth + 1, files, layers, warnings, error)) return false;
  }
  layers->push_back(file);
  return true;
}

// Reads the root's per-pass and texture keys.
class RootReader {
 public:
  RootReader(const PresetFile& root, Preset& preset, std::string& error)
      : root_(root), preset_(preset), error_(error) {}

  bool passes() {
    const PresetEntry* count = root_.find("shaders");
    const std::optional<unsigned long long> n = count ? leading_unsigned(count->value) : std::nullopt;
    if (!n) return fail(count ? count->place.text() : root_.path, "'shaders' must give the number of passes");
    if (*n == 0 || *n > static_cast<unsigned long long>(kMaxPasses))
      return fail(count->place.text(), "'shaders = " + count->value + "': a preset has 1 to " +
                                           std::to_string(kMaxPasses) + " passes (RetroArch's limit)");
    for (int i = 0; i < static_cast<int>(*n); ++i)
      if (!pass(i, static_cast<int>(*n))) return false;
    return true;
  }

  bool textures(const std::vector<const PresetFile*>& layers) {
    const PresetEntry* list = root_.find("textures");
    if (!list) return true;
    std::size_t start = 0;
    while (start <= list->value.size()) {
      const std::size_t end = std::min(list->value.find(';', start), list->value.size());
      const std::string id = trimmed(list->value.substr(start, end - start));
      start = end + 1;
      if (id.empty()) continue;
      if (preset_.textures.size() == static_cast<std::size_t>(kMaxLookupTextures))
        return fail(list->place.text(),
                    "more than " + std::to_string(kMaxLookupTextures) + " textures (RetroArch's limit)");
      LookupTexture texture;
      texture.id = id;
      // The file: from the last file that names it, relative to that file.
      for (auto layer = layers.rbegin(); texture.path.empty() && layer != layers.rend(); ++layer)
        if (const PresetEntry* path = (*layer)->find(id))
          texture.path = resolve_preset_path(path->value, (*layer)->path);
      if (texture.path.empty())
        return fail(list->place.text(), "texture '" + id + "' is listed, but no '" + id + " = FILE' gives its file");
      texture.linear = boolean(id + "_linear");
      texture.wrap = wrap(id + "_wrap_mode");
      texture.mipmap = boolean(id + "_mipmap").value_or(false);
      preset_.textures.push_back(texture);
    }
    return true;
  }

 private:
  bool fail(const std::string& where, const std::string& why) { return error_ = where + ": " + why, false; }

  void warn(const PresetEntry& entry, const std::string& why) {
    preset_.warnings.push_back(entry.place.text() + ": " + why);
  }

  // RetroArch's booleans: 1, 0, true, false; anything else counts as unset.
  std::optional<bool> boolean(const std::string& key) {
    const PresetEntry* entry = root_.find(key);
    if (!entry) return std::nullopt;
    if (entry->value == "1" || entry->value == "true") return true;
    if (entry->value == "0" || entry->value == "false") return false;
    warn(*entry, "'" + key + " = " + entry->value + "' is not a boolean (true, false, 1, 0): the default applies");
    return std::nullopt;
  }

  WrapMode wrap(const std::string& key) {
    const PresetEntry* entry = root_.find(key);
    if (!entry) return WrapMode::kClampToBorder;
    if (const auto mode = wrap_mode_of(entry->value)) return *mode;
    warn(*entry,
         "'" + key + " = " + entry->value +
             "' is not a wrap mode (clamp_to_border, clamp_to_edge, repeat, mirrored_repeat): clamp_to_border applies");
    return WrapMode::kClampToBorder;
  }

  // One axis: its type (`scale_typeN` over `scale_type_xN`), its amount (`scaleN` over `scale_xN`).
  bool axis(int i, const char* suffix, AxisScale* out) {
    const std::string n = std::to_string(i);
    const PresetEntry* type = root_.find("scale_type" + n);
    if (!type) type = root_.find(std::string("scale_type_") + suffix + n);
    if (type) {
      const auto parsed = scale_type_of(type->value);
      if (!parsed)
        return fail(type->place.text(), "'" + type->value + "' is not a scale type (source, viewport, absolute)");
      out->type = *parsed;
    }
    const PresetEntry* amount = root_.find("scale" + n);
    if (!amount) amount = root_.find(std::string("scale_") + suffix + n);
    if (out->type == ScaleType::kAbsolute) {
      // RetroArch reads an absolute size as an integer ("800.0" is 800).
      const auto pixels = amount ? leading_unsigned(amount->value) : std::nullopt;
      if (!pixels || *pixels < 1 || *pixels > 16384)
        return fail(amount ? amount->place.text() : type->place.text(),
                    std::string("an absolute scale needs a size of 1 to 16384 pixels in 'scale") + n + "' or 'scale_" +
                        suffix + n + "'");
      out->pixels = static_cast<int>(*pixels);
      return true;
    }
    if (!amount) return true;
    const auto factor = leading_number(amount->value);
    if (!factor || !std::isfinite(*factor) || *factor <= 0)
      return fail(amount->place.text(), "'" + amount->value + "' is not a positive scale factor");
    out->factor = *factor;
    return true;
  }

  bool pass(int i, int count) {
    const std::string n = std::to_string(i);
    PresetPass pass;
    const PresetEntry* shader = root_.find("shader" + n);
    if (!shader || shader->value.empty())
      return fail(root_.path, "pass " + n + " of " + std::to_string(count) + " has no 'shader" + n + " = FILE'");
    pass.shader = resolve_preset_path(shader->value, root_.path);
    pass.place = shader->place;
    pass.filter_linear = boolean("filter_linear" + n);
    pass.wrap = wrap("wrap_mode" + n);
    pass.mipmap_input = boolean("mipmap_input" + n).value_or(false);
    if (const PresetEntry* alias = root_.find("alias" + n)) pass.alias = alias->value;
    pass.float_framebuffer = boolean("float_framebuffer" + n).value_or(false);
    pass.srgb_framebuffer = boolean("srgb_framebuffer" + n).value_or(false);
    pass.scaled = root_.find("scale_type" + n) || root_.find("scale_type_x" + n) || root_.find("scale_type_y" + n);
    if (pass.scaled && (!axis(i, "x", &pass.x) || !axis(i, "y", &pass.y))) return false;
    if (const PresetEntry* mod = root_.find("frame_count_mod" + n)) {
      const auto value = leading_unsigned(mod->value);
      if (value && *value <= 0xFFFFFFFFull)
        pass.frame_count_mod = static_cast<unsigned>(*value);
      else
        warn(*mod, "'" + mod->value + "' is not a frame count modulus: FrameCount is not wrapped");
    }
    preset_.passes.push_back(pass);
    return true;
  }

  const PresetFile& root_;
  Preset& preset_;
  std::string& error_;
};

bool ends_with(const std::string& text, const std::string& end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

}  // namespace

std::optional<double> Preset::parameter_value(const std::string& id) const {
  for (auto layer = layers.rbegin(); layer != layers.rend(); ++layer)
    if (const PresetEntry* entry = layer->find(id))
      if (const auto value = leading_number(entry->value); value && std::isfinite(*value)) return value;
  return std::nullopt;
}

bool read_preset(const std::string& path, const TextReader& read, Preset* out, std::string* error) {
  *out = Preset{};
  out->path = path;
  Files files(read);
  const PresetFile* loaded = files.get(path, error);
  if (!loaded) return false;
  const PresetFile* root = root_of(loaded, files, error);
  if (!root) return false;
  if (!root->find("shaders"))
    return *error = root->path + ": has no 'shaders' key" +
                    (root == loaded ? std::string()
                                    : ", and the chain of first references from " + path + " ends there"),
           false;
  // Further references give values only: RetroArch refuses one that leads to passes.
  for (std::size_t i = 1; i < loaded->references.size(); ++i) {
    const PresetEntry& reference = loaded->references[i];
    const PresetFile* file = files.get(referenced(reference, path), error);
    const PresetFile* its_root = file ? root_of(file, files, error) : nullptr;
    if (!its_root) return *error = reference.place.text() + ": #reference: " + *error, false;
    if (its_root->find("shaders"))
      return *error = reference.place.text() +
                      ": only the first #reference may lead to a preset with passes ('shaders'); this one leads to " +
                      its_root->path,
             false;
  }
  std::vector<const PresetFile*> layers;
  if (!gather_layers(loaded, 0, files, &layers, &out->warnings, error)) return false;
  out->root = root->path;
  out->format = ends_with(root->path, ".glslp") ? PresetFormat::kGlsl : PresetFormat::kSlang;
  RootReader reader(*root, *out, *error);
  if (!reader.passes() || !reader.textures(layers)) return false;
  if (const PresetEntry* feedback = root->find("feedback_pass")) {
    const auto pass = leading_unsigned(feedback->value);
    if (pass && *pass < out->passes.size())
      out->feedback_pass = static_cast<int>(*pass);
    else
      out->warnings.push_back(feedback->place.text() + ": '" + feedback->value +
                              "' is not a pass of this preset: no pass is fed back");
  }
  std::vector<const PresetFile*> warned;  // a file reached by two references warns once
  for (const PresetFile* layer : layers) {
    out->layers.push_back(*layer);
    if (std::find(warned.begin(), warned.end(), layer) != warned.end()) continue;
    warned.push_back(layer);
    out->warnings.insert(out->warnings.end(), layer->warnings.begin(), layer->warnings.end());
  }
  return true;
}

const char* scale_type_name(ScaleType type) {
  switch (type) {
    case ScaleType::kSource:
      return "source";
    case ScaleType::kViewport:
      return "viewport";
    case ScaleType::kAbsolute:
      return "absolute";
  }
  return "?";
}

const char* wrap_mode_name(WrapMode mode) {
  switch (mode) {
    case WrapMode::kClampToBorder:
      return "clamp_to_border";
    case WrapMode::kClampToEdge:
      return "clamp_to_edge";
    case WrapMode::kRepeat:
      return "repeat";
    case WrapMode::kMirroredRepeat:
      return "mirrored_repeat";
  }
  return "?";
}

}  // namespace pfx::libretro
