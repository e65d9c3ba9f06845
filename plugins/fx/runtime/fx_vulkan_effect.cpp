#include "fx_vulkan_effect.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <vector>

#include <pfx/cpp/plugin_entry.hpp>

#include "fx_catalog.hpp"
#include "fx_definitions.hpp"
#include "fx_frame_params.hpp"
#include "fx_settled_values.hpp"
#include "fx_source_watch.hpp"
#include "fx_texture_files.hpp"
#include "fx_uniform_values.hpp"
#include "texture_image.hpp"
#include "vk_pipeline_cache.hpp"
#include "vk_retired_techniques.hpp"
#include "vk_technique.hpp"

namespace pfx_fx {
namespace {

class FxVulkanInstance {
 public:
  FxVulkanInstance(const FxEffectEntry& entry, const pfx_host* host) : entry_(entry), host_(host) {}
  ~FxVulkanInstance() {
    technique_.reset();
    retired_.destroy_all();  // the host destroys an instance once its command buffers completed
    cache_.destroy();
  }
  // `definitions`: the host's preprocessor definitions, without those pfx defines itself.
  pfx_status create(const pfx_vk_device& device, int width, int height, VkFormat format, const Definitions& definitions,
                    std::string& error);
  // The host's list read as set_definitions reads it (fx_definitions.hpp); false with `error`.
  bool read_definitions(const char* list, Definitions* out, std::string& error) const;
  pfx_status record(VkCommandBuffer commands, const pfx_vk_frame_image& image, const pfx_frame& frame, const pfx_value* params);

 private:
  // The file compiled at the instance's size with its definitions (never null: its included files
  // are watched even when it failed); `error` says why it cannot run.
  std::unique_ptr<pfx::fx::CompiledEffect> compile(std::string& error) const;
  // A technique built from `compiled` on the device; null with `error`, and *unsupported set when
  // it needs what the Vulkan runtime lacks.
  std::unique_ptr<pfx::fx::vulkan::Technique> build(const pfx::fx::CompiledEffect& compiled, bool* unsupported,
                                                    std::string& error);
  // The file or an include was edited: a version that compiles and builds runs from this frame
  // on (the old one retired until the frames using it complete); one that does not is logged and
  // the running one stays, as on GL.
  void reload();

  void log(pfx_log_level level, const std::string& message) const {
    host_->log(host_->host_data, level, ("fx: " + entry_.id + " (Vulkan): " + message).c_str());
  }
  // After pipelines were built: the cache file keeps them, and the log says what took how long
  // ("<what> in N ms").
  void report_build(const std::string& what, std::chrono::steady_clock::time_point start) {
    cache_.save();
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    log(PFX_LOG_INFO, what + " in " + std::to_string(static_cast<long>(ms)) + " ms");
  }

  const FxEffectEntry& entry_;
  const pfx_host* host_;
  pfx::fx::vulkan::Device device_;
  int width_ = 0, height_ = 0;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  Definitions definitions_;
  std::unique_ptr<pfx::fx::CompiledEffect> compiled_;
  pfx::fx::vulkan::PipelineCacheFile cache_;
  std::unique_ptr<pfx::fx::vulkan::Technique> technique_;
  pfx::fx::vulkan::RetiredTechniques retired_;  // versions before an edit, while frames may use them
  SourceWatch watch_;
  UniformValues uniforms_;
  FrameParams frame_params_;
  // When the values have settled, the technique runs pipelines with them compiled in.
  SettledValues settle_;
  bool told_live_ = false;  // why values run live, said once
};

bool FxVulkanInstance::read_definitions(const char* list, Definitions* out, std::string& error) const {
  if (!parse_definitions(list ? list : "", out, &error)) return error = "preprocessor definitions refused: " + error, false;
  // As on GL: pfx hands FX effects its own depth and defines the depth settings itself.
  const std::vector<std::string> ignored = remove_own_definitions(compile_options(1, 1).preprocessor.defines, out);
  std::string names;
  for (const std::string& name : ignored) names += (names.empty() ? "" : ", ") + name;
  if (!names.empty())
    log(PFX_LOG_WARNING, "preprocessor definitions ignored: " + names + " (pfx hands FX effects its own depth and sets these)");
  return true;
}

std::unique_ptr<pfx::fx::CompiledEffect> FxVulkanInstance::compile(std::string& error) const {
  pfx::fx::FrontEndOptions options = compile_options(width_, height_);
  // After the file's defaults and pfx's own, as the GL instance compiles with them.
  options.preprocessor.defines.insert(options.preprocessor.defines.end(), definitions_.begin(), definitions_.end());
  auto compiled = pfx::fx::compile_effect(entry_.file, options, false);
  if (!compiled->ok()) {
    error = compiled->errors();
    return compiled;
  }
  const auto& techniques = compiled->model.techniques;
  if (static_cast<std::size_t>(entry_.technique_index) >= techniques.size() ||
      techniques[static_cast<std::size_t>(entry_.technique_index)].name != entry_.technique)
    error = "technique '" + entry_.technique + "' is no longer in " + entry_.file;
  return compiled;
}

std::unique_ptr<pfx::fx::vulkan::Technique> FxVulkanInstance::build(const pfx::fx::CompiledEffect& compiled, bool* unsupported,
                                                                     std::string& error) {
  const std::string effect_file = entry_.file;
  const auto load = [effect_file](const pfx::fx::TextureInfo& texture, pfx::fx::TextureTexels& texels, std::string& message) {
    const std::string path = find_texture_file(texture.source, effect_file);
    if (path.empty()) {
      message = "source image '" + texture.source + "' was not found (looked in a Textures folder beside the effect and in PFX_FX_TEXTURE_PATH)";
      return false;
    }
    return pfx::fx::decode_texture_image(path, texture.width, texture.height, texture.dimension == 3 ? texture.depth : 1, texels, message);
  };
  auto technique = std::make_unique<pfx::fx::vulkan::Technique>();
  const auto status = technique->create(device_, compiled, entry_.technique_index, width_, height_, format_, cache_.handle(), load, error);
  cache_.save();
  *unsupported = status == pfx::fx::vulkan::Technique::Status::kUnsupported;
  if (status != pfx::fx::vulkan::Technique::Status::kOk) return nullptr;
  return technique;
}

pfx_status FxVulkanInstance::create(const pfx_vk_device& device, int width, int height, VkFormat format,
                                    const Definitions& definitions, std::string& error) {
  error = device_.load(device.get_instance_proc_addr, device.instance, device.physical_device, device.get_device_proc_addr, device.device);
  if (!error.empty()) return error = "the device gives no " + error, PFX_ERROR;
  width_ = width, height_ = height, format_ = format, definitions_ = definitions;
  compiled_ = compile(error);
  watch_.watch(*compiled_, entry_.file);
  if (!error.empty()) return PFX_ERROR;
  if (!cache_.open(device_)) return error = "vkCreatePipelineCache failed", PFX_ERROR;
  bool unsupported = false;
  technique_ = build(*compiled_, &unsupported, error);
  if (!technique_) return unsupported ? PFX_UNSUPPORTED : PFX_ERROR;
  uniforms_.reset(compiled_->model, entry_.params);
  frame_params_.reset(compiled_->model, entry_.params, width, height);
  return PFX_OK;
}

void FxVulkanInstance::reload() {
  std::string error;
  auto compiled = compile(error);
  std::unique_ptr<pfx::fx::vulkan::Technique> technique;
  bool unsupported = false;
  if (error.empty()) technique = build(*compiled, &unsupported, error);
  watch_.watch(*compiled, entry_.file);  // an edit that fixes it is picked up too
  if (!technique) {
    log(PFX_LOG_ERROR, "edited, and " + std::string(unsupported ? "needs what the Vulkan runtime lacks: " : "does not build:\n") + error +
                           "\nThe last version that compiled keeps running.");
    return;
  }
  retired_.retire(device_, std::move(technique_), std::move(compiled_));
  technique_ = std::move(technique);
  compiled_ = std::move(compiled);
  uniforms_.reset(compiled_->model, entry_.params);
  frame_params_.reset(compiled_->model, entry_.params, width_, height_);
  settle_.reset();
  told_live_ = false;
  log(PFX_LOG_INFO, "reloaded " + entry_.file);
}

pfx_status FxVulkanInstance::record(VkCommandBuffer commands, const pfx_vk_frame_image& image, const pfx_frame& frame, const pfx_value* params) {
  if (!params && !entry_.params.descs.empty()) return PFX_INVALID_ARGUMENT;  // an effect without parameters may get none
  retired_.release_finished();
  if (watch_.edited()) reload();
  std::vector<std::string> notes;
  const pfx_value* values = frame_params_.resolve(entry_.params, params, notes);
  for (const std::string& note : notes) log(PFX_LOG_WARNING, note);
  uniforms_.update(compiled_->model, entry_.params, values, frame, false);
  const pfx::fx::UniformConstants held =
      settle_.enabled() ? held_values(compiled_->model, uniforms_) : pfx::fx::UniformConstants{};
  const bool settled = settle_.observe(held).settled;
  std::size_t held_count = 0;  // an effect with none has nothing to compile in
  for (const auto& value : held) held_count += value.empty() ? 0 : 1;
  bool specialised = false;
  if (held_count && (settled || technique_->has_specialised(held))) {
    // On the frame path, as the GL runtime builds where the driver cannot compile in the
    // background: once per set of values that held still.
    bool built = false;
    std::string message;
    const auto start = std::chrono::steady_clock::now();
    specialised = technique_->specialise(*compiled_, held, cache_.handle(), &built, message);
    if (built)
      report_build("values compiled in: " + std::to_string(held_count) + " uniforms as constants, pipelines built", start);
    if (!specialised && !told_live_) {
      told_live_ = true;
      log(PFX_LOG_INFO, "uniforms stay live: " + message);
    }
  }
  // The live pipelines this frame runs, built the first time one is needed.
  std::size_t live_built = 0;
  const auto start = std::chrono::steady_clock::now();
  const std::string error = technique_->prepare(specialised ? &held : nullptr, &live_built);
  if (!error.empty()) return log(PFX_LOG_ERROR, error), PFX_ERROR;
  if (live_built)
    report_build("live pipelines built for " + std::to_string(live_built) + (live_built == 1 ? " pass" : " passes"), start);
  pfx::fx::vulkan::Frame f;
  f.image = image.image;
  f.layout = image.layout;
  f.final_layout = image.final_layout;
  f.keep_alpha = !(image.flags & PFX_VK_FRAME_ALPHA_UNUSED);
  technique_->record(commands, f, uniforms_.all(), specialised ? &held : nullptr);
  retired_.mark(commands);
  return PFX_OK;
}

// Instances this factory made and has not destroyed: a pointer of anybody else's is refused.
std::mutex live_mutex;
std::set<const FxVulkanInstance*> live;

FxVulkanInstance* live_vulkan_instance(void* instance) {
  std::lock_guard<std::mutex> lock(live_mutex);
  auto* fx = static_cast<FxVulkanInstance*>(instance);
  return live.count(fx) ? fx : nullptr;
}

void copy_error(const std::string& message, char* error, uint32_t error_size) {
  if (!error || error_size == 0) return;
  const std::size_t n = std::min<std::size_t>(message.size(), error_size - 1);
  std::memcpy(error, message.data(), n);
  error[n] = '\0';
}

int32_t supports(const char* effect_id) {
  try {
    const FxEffectEntry* entry = find_effect(effect_id);
    return entry && entry->vulkan_unsupported.empty() ? 1 : 0;
  } catch (...) {
    return 0;
  }
}

pfx_status create_with_definitions(const pfx_host* host, const char* effect_id, const pfx_vk_device* device, uint32_t width,
                                   uint32_t height, VkFormat format, const char* definitions, void** out_instance, char* error,
                                   uint32_t error_size) {
  if (out_instance) *out_instance = nullptr;
  if (!host || !device || !out_instance || device->struct_size < PFX_VK_DEVICE_MIN_SIZE || width == 0 || height == 0 || width > 16384 ||
      height > 16384)
    return copy_error("invalid arguments", error, error_size), PFX_INVALID_ARGUMENT;
  std::string message;
  const pfx_status status = pfx::plugin::without_exceptions([&]() -> pfx_status {
    const FxEffectEntry* entry = find_effect(effect_id);
    if (!entry) return message = std::string("no FX effect '") + (effect_id ? effect_id : "") + "'", PFX_INVALID_ARGUMENT;
    auto fx = std::make_unique<FxVulkanInstance>(*entry, host);
    Definitions defined;
    if (!fx->read_definitions(definitions, &defined, message)) return PFX_INVALID_ARGUMENT;
    const pfx_status made = fx->create(*device, static_cast<int>(width), static_cast<int>(height), format, defined, message);
    if (made != PFX_OK) return made;
    std::lock_guard<std::mutex> lock(live_mutex);
    live.insert(fx.get());
    *out_instance = fx.release();
    return PFX_OK;
  });
  if (status != PFX_OK) copy_error(message.empty() ? "the instance could not be made" : message, error, error_size);
  return status;
}

pfx_status create(const pfx_host* host, const char* effect_id, const pfx_vk_device* device, uint32_t width, uint32_t height, VkFormat format,
                  void** out_instance, char* error, uint32_t error_size) {
  return create_with_definitions(host, effect_id, device, width, height, format, nullptr, out_instance, error, error_size);
}

pfx_status record(void* instance, VkCommandBuffer commands, const pfx_vk_frame_image* image, const pfx_frame* frame, const pfx_value* params) {
  FxVulkanInstance* fx = live_vulkan_instance(instance);
  if (!fx || !commands || !image || image->struct_size < PFX_VK_FRAME_IMAGE_MIN_SIZE || !frame || frame->struct_size < PFX_FRAME_MIN_SIZE)
    return PFX_INVALID_ARGUMENT;
  return pfx::plugin::without_exceptions([&]() -> pfx_status { return fx->record(commands, *image, *frame, params); });
}

void destroy(void* instance) {
  FxVulkanInstance* fx = live_vulkan_instance(instance);
  if (!fx) return;
  {
    std::lock_guard<std::mutex> lock(live_mutex);
    live.erase(fx);
  }
  delete fx;
}

}  // namespace

const pfx_vulkan_effect_factory kVulkanEffects = {sizeof(pfx_vulkan_effect_factory), supports, create, record, destroy,
                                                   create_with_definitions};

}  // namespace pfx_fx
