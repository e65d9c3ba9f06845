// Runs an FX conformance file through the Vulkan runtime for FX (plugins/fx/vulkan) on a Vulkan
// device, headless, and judges the picture as run_conformance.py does: `checks`, every pixel
// green, or the checks whose columns are not (check i is the columns [i * CELL, (i + 1) * CELL));
// `input`, the frame's bytes (run_conformance.py's input picture, made here); `invert`, 255 minus
// them in R, G and B. This program is the runtime's owner, as a layer or a host would be: it
// makes the device, hands the runtime its functions, uploads the input picture, records FRAMES frames
// (each submitted and waited for here, never by the runtime) and reads the last picture back.
// Uniforms hold their initial values; the sources framecount, frametime and timer follow the
// frame number (16 ms a frame). Pipelines go through the runtime's pipeline cache file;
// --report-cache says whether it was read from disk.
//
// usage: fx_vulkan_checks [-IFOLDER...] [-DNAME=VALUE...] --size WxH [--cell N] [--frames N]
//          [--technique NAME] [--expect checks|input|invert|gain|none] [--gain G]
//          [--input gradient|alpha|IMAGE] [--raw-out FILE] [--report-cache]
//          [--plugin PFX_FX_SO [--set PARAM=VALUE...]] [--time N] FILE.fx
// `--plugin` runs the technique as a Vulkan host runs an effect of the FX plugin: through its
// "pfx.vulkan_effects/1" factory (pfx/vulkan_effects.h), with the parameters' defaults and the
// `--set` values, the frame's time and number for its sources; `--expect gain` judges the input's
// RGB times G within a code, alpha kept. `--time N` runs N more frames, each submitted and waited
// for alone, and prints their median wall time (by hand: Vulkan's cost of an effect).
// `--input IMAGE` runs on a picture file (PNG, JPEG...) of the size given; `--expect none` judges
// nothing (uniform sources this program does not give hold 0, named in a line) and `--raw-out`
// writes the last picture's RGBA bytes, top row first: how compare_collections.py holds the
// Vulkan runtime to the GL one on collections of effects.
// Exit status: 0 every check holds, 1 some fail or Vulkan fails, 3 the technique needs what the
// Vulkan runtime does not run yet (it says what), 2 usage.
#include <dlfcn.h>
#include <vulkan/vulkan.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <pfx/pfx.h>
#include <pfx/vulkan_effects.h>

#include "effect_compiler.hpp"
#include "vk_pipeline_cache.hpp"
#include "vk_technique.hpp"

namespace {

#define VK_OK(call)                                                                \
  do {                                                                             \
    VkResult result_ = (call);                                                     \
    if (result_ != VK_SUCCESS) {                                                   \
      std::fprintf(stderr, "FAIL: %s returned %d\n", #call, static_cast<int>(result_)); \
      std::exit(1);                                                                \
    }                                                                              \
  } while (0)

// A Vulkan structure of `type`, every other member zero.
template <typename T>
T vk(VkStructureType type) {
  T out{};
  out.sType = type;
  return out;
}

// The device, as the runtime's owner makes it: an instance, the first device, a graphics queue.
struct Owner {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  std::uint32_t family = 0;
  VkPhysicalDeviceMemoryProperties memory{};

  Owner() {
    // lavapipe and the validation layer stay mapped to the end: the loader unloads them at
    // vkDestroyInstance, and a block one keeps in its globals would then read as a leak of an
    // unknown module (or of this program) under LeakSanitizer (docs/reliability.md). Another
    // driver is not touched.
    (void)dlopen("libvulkan_lvp.so", RTLD_NOW | RTLD_NODELETE);
    (void)dlopen("libVkLayer_khronos_validation.so", RTLD_NOW | RTLD_NODELETE);
    auto app = vk<VkApplicationInfo>(VK_STRUCTURE_TYPE_APPLICATION_INFO);
    app.pApplicationName = "fx_vulkan_checks";
    app.apiVersion = VK_API_VERSION_1_1;
    auto info = vk<VkInstanceCreateInfo>(VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO);
    info.pApplicationInfo = &app;
    VK_OK(vkCreateInstance(&info, nullptr, &instance));
    std::uint32_t count = 1;
    VkResult listed = vkEnumeratePhysicalDevices(instance, &count, &physical);
    if ((listed != VK_SUCCESS && listed != VK_INCOMPLETE) || count == 0) {
      std::fprintf(stderr, "FAIL: no Vulkan device (install mesa-vulkan-drivers for lavapipe)\n");
      std::exit(1);
    }
    vkGetPhysicalDeviceMemoryProperties(physical, &memory);
    std::uint32_t families = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &families, nullptr);
    std::vector<VkQueueFamilyProperties> properties(families);
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &families, properties.data());
    while (family < families && !(properties[family].queueFlags & VK_QUEUE_GRAPHICS_BIT)) ++family;
    float priority = 1.0f;
    auto queue_info = vk<VkDeviceQueueCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO);
    queue_info.queueFamilyIndex = family;
    queue_info.queueCount = 1;
    queue_info.pQueuePriorities = &priority;
    auto device_info = vk<VkDeviceCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO);
    device_info.queueCreateInfoCount = 1;
    device_info.pQueueCreateInfos = &queue_info;
    VK_OK(vkCreateDevice(physical, &device_info, nullptr, &device));
    vkGetDeviceQueue(device, family, 0, &queue);
  }
  ~Owner() {
    vkDestroyDevice(device, nullptr);
    vkDestroyInstance(instance, nullptr);
  }

  VkDeviceMemory allocate(VkMemoryRequirements needs, VkMemoryPropertyFlags flags) const {
    auto info = vk<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
    info.allocationSize = needs.size;
    for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i)
      if ((needs.memoryTypeBits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & flags) == flags) {
        info.memoryTypeIndex = i;
        break;
      }
    VkDeviceMemory out;
    VK_OK(vkAllocateMemory(device, &info, nullptr, &out));
    return out;
  }

  // A host-visible buffer holding `size` bytes (`data` copied in when given).
  VkBuffer buffer(VkDeviceSize size, VkBufferUsageFlags usage, VkDeviceMemory& memory_out, const void* data) const {
    auto info = vk<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
    info.size = size;
    info.usage = usage;
    VkBuffer out;
    VK_OK(vkCreateBuffer(device, &info, nullptr, &out));
    VkMemoryRequirements needs;
    vkGetBufferMemoryRequirements(device, out, &needs);
    memory_out = allocate(needs, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    VK_OK(vkBindBufferMemory(device, out, memory_out, 0));
    if (data) {
      void* mapped;
      VK_OK(vkMapMemory(device, memory_out, 0, size, 0, &mapped));
      std::memcpy(mapped, data, static_cast<std::size_t>(size));
      vkUnmapMemory(device, memory_out);
    }
    return out;
  }

};

// The frame: an RGBA8 image the runtime reads and writes, and a host-visible buffer that brings
// the input picture in and the picture out.
struct FrameImage {
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE, staging_memory = VK_NULL_HANDLE;
  VkBuffer staging = VK_NULL_HANDLE;
  int width, height;

  FrameImage(const Owner& d, const std::vector<unsigned char>& rgba, int w, int h) : width(w), height(h) {
    auto info = vk<VkImageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO);
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = VK_FORMAT_R8G8B8A8_UNORM;
    info.extent = {static_cast<std::uint32_t>(w), static_cast<std::uint32_t>(h), 1};
    info.mipLevels = info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.usage = VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    VK_OK(vkCreateImage(d.device, &info, nullptr, &image));
    VkMemoryRequirements needs;
    vkGetImageMemoryRequirements(d.device, image, &needs);
    memory = d.allocate(needs, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    VK_OK(vkBindImageMemory(d.device, image, memory, 0));
    staging = d.buffer(rgba.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, staging_memory, rgba.data());
  }
  VkBufferImageCopy region() const {
    VkBufferImageCopy r{};
    r.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    r.imageExtent = {static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height), 1};
    return r;
  }
  // The input picture into the image, top row first (Vulkan's and FX's order), left for copying from.
  void record_upload(VkCommandBuffer commands) const {
    auto b = vk<VkImageMemoryBarrier>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER);
    b.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    b.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    b.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image;
    b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0, nullptr, 1, &b);
    const VkBufferImageCopy r = region();
    vkCmdCopyBufferToImage(commands, staging, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &r);
  }
  // The picture into the buffer (the runtime left the image ready to copy from).
  void record_readback(VkCommandBuffer commands) const {
    const VkBufferImageCopy r = region();
    vkCmdCopyImageToBuffer(commands, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, staging, 1, &r);
  }
  void destroy(const Owner& d) {
    vkDestroyImage(d.device, image, nullptr);
    vkFreeMemory(d.device, memory, nullptr);
    vkDestroyBuffer(d.device, staging, nullptr);
    vkFreeMemory(d.device, staging_memory, nullptr);
  }
};

// One command buffer, recorded by `body`, submitted and waited for.
template <typename Body>
void submit(const Owner& d, VkCommandPool pool, Body body) {
  auto info = vk<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
  info.commandPool = pool;
  info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  info.commandBufferCount = 1;
  VkCommandBuffer commands;
  VK_OK(vkAllocateCommandBuffers(d.device, &info, &commands));
  auto begin = vk<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VK_OK(vkBeginCommandBuffer(commands, &begin));
  body(commands);
  VK_OK(vkEndCommandBuffer(commands));
  auto s = vk<VkSubmitInfo>(VK_STRUCTURE_TYPE_SUBMIT_INFO);
  s.commandBufferCount = 1;
  s.pCommandBuffers = &commands;
  VK_OK(vkQueueSubmit(d.queue, 1, &s, VK_NULL_HANDLE));
  VK_OK(vkQueueWaitIdle(d.queue));
  vkFreeCommandBuffers(d.device, pool, 1, &commands);
}

// The image file a texture names, looked for as a collection lays them out: beside the effect, or
// anywhere under a Textures folder beside the effect or beside a folder above it
// (reshade-shaders/Textures/SweetFX/AreaTex.png for reshade-shaders/Shaders/SweetFX/SMAA.fx).
bool load_texels(const std::string& effect_file, const pfx::fx::TextureInfo& texture, pfx::fx::TextureTexels& texels, std::string& error) {
  namespace fs = std::filesystem;
  const fs::path name = fs::path(texture.source).filename();
  std::error_code ec;
  fs::path found = fs::path(effect_file).parent_path() / texture.source;
  for (fs::path folder = fs::path(effect_file).parent_path(); !fs::is_regular_file(found, ec) && !folder.empty(); folder = folder.parent_path()) {
    for (fs::recursive_directory_iterator it(folder / "Textures", ec), end; !ec && it != end; it.increment(ec))
      if (it->path().filename() == name && it->is_regular_file(ec)) {
        found = it->path();
        break;
      }
    if (folder == folder.parent_path()) break;
  }
  if (!fs::is_regular_file(found, ec)) {
    error = "'" + texture.source + "' was not found beside the effect or in a Textures folder";
    return false;
  }
  return pfx::fx::decode_texture_image(found.string(), texture.width, texture.height, texture.dimension == 3 ? texture.depth : 1, texels, error);
}

// `any_source`: another source holds 0 (and is named all the same).
std::string uniform_values(const pfx::fx::EffectModel& model, int frame, bool any_source, std::vector<std::vector<double>>& values) {
  values.clear();
  std::string missing;
  for (const pfx::fx::UniformInfo& u : model.uniforms) {
    values.push_back(u.initial);
    if (u.source.empty()) continue;
    double value = u.source == "framecount" ? frame : u.source == "frametime" ? 16.0 : u.source == "timer" ? 16.0 * frame : -1;
    if (value < 0 && any_source) missing += (missing.empty() ? "" : ", ") + u.source, value = 0;
    if (value < 0) return u.source;
    std::fill(values.back().begin(), values.back().end(), value);
  }
  return missing;
}

// The FX plugin as a Vulkan host meets it: its library loaded, its "pfx.vulkan_effects/1" factory,
// and the effect of FILE's technique (PFX_FX_PATH names FILE alone) at its parameters' defaults
// with the --set values.
struct PluginEffect {
  void* library = nullptr;
  const pfx_entry* entry = nullptr;
  const pfx_vulkan_effect_factory* vulkan = nullptr;
  std::string id;
  std::vector<pfx_value> params;
  pfx_host host{};
  void* instance = nullptr;

  static void log(void*, pfx_log_level level, const char* message) {
    if (level >= PFX_LOG_INFO) std::printf("plugin: %s\n", message);
  }
  static pfx_gl_proc no_gl(void*, const char*) { return nullptr; }  // a host without GL

  // "" or what went wrong.
  std::string load(const std::string& path, const std::string& file, const std::string& technique,
                   const std::vector<std::pair<std::string, double>>& sets) {
    setenv("PFX_FX_PATH", file.c_str(), 1);
    library = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!library) return std::string("cannot load the plugin: ") + dlerror();
    auto get_entry = reinterpret_cast<const pfx_entry* (*)()>(dlsym(library, PFX_ENTRY_SYMBOL));
    entry = get_entry ? get_entry() : nullptr;
    host.struct_size = sizeof host;
    host.abi_major = PFX_ABI_MAJOR, host.abi_minor = PFX_ABI_MINOR;
    host.host_name = "fx_vulkan_checks";
    host.log = log;
    host.get_proc_address = no_gl;
    if (!entry || entry->init(&host) != PFX_OK) return "the plugin's init failed";
    vulkan = static_cast<const pfx_vulkan_effect_factory*>(entry->get_factory(PFX_VULKAN_EFFECTS_FACTORY_ID));
    const auto* effects = static_cast<const pfx_effect_factory*>(entry->get_factory(PFX_EFFECTS_FACTORY_ID));
    const auto* sources = static_cast<const pfx_source_factory*>(entry->get_factory(PFX_SOURCES_FACTORY_ID));
    if (!vulkan || vulkan->struct_size < PFX_VULKAN_EFFECT_FACTORY_MIN_SIZE || !effects || !sources)
      return "the plugin offers no pfx.vulkan_effects/1 factory";
    for (uint32_t i = 0; i < effects->effect_count(); ++i) {
      const pfx_effect_desc* desc = effects->get_effect(i);
      const char* name = sources->effect_source_name(desc->id);
      if (!name || technique != name) continue;
      id = desc->id;
      for (uint32_t k = 0; k < desc->param_count; ++k) params.push_back(pfx_at(pfx_param_desc, desc->params, k)->default_value);
      for (const auto& set : sets) {
        bool found = false;
        for (uint32_t k = 0; k < desc->param_count; ++k)
          if (set.first == pfx_at(pfx_param_desc, desc->params, k)->id) params[k].v[0] = set.second, found = true;
        if (!found) return "the effect has no parameter '" + set.first + "'";
      }
    }
    if (id.empty()) return "the plugin lists no effect for technique '" + technique + "'";
    if (!vulkan->supports(id.c_str()) || vulkan->supports("no such effect")) return "supports() answers wrong";
    return "";
  }
  void unload() {
    if (instance) vulkan->destroy(instance);
    if (entry) entry->deinit();
    // The library stays mapped: LeakSanitizer then names its frames.
  }
};

struct Judged {
  std::string expect;  // checks, input, invert, or none (with raw_out: the picture is written)
  int width, height, cell, frames;
  bool varying_alpha;
  bool report_cache;  // say whether the pipeline cache came from its file
  std::string input_file;  // the frame from this image (at the size), not made here
  std::string raw_out;     // the last picture's RGBA bytes, top row first, into this file
  std::string plugin;      // through this FX plugin's "pfx.vulkan_effects/1" factory
  std::vector<std::pair<std::string, double>> sets;  // parameter values for the plugin's effect
  double gain = 1.0;       // expect "gain": the input's RGB times this
  int time_frames = 0;     // --time: frames timed after the judged ones
};

// The checks whose columns hold a pixel that is not pure green.
std::vector<int> failed_checks(const unsigned char* rgba, int width, int height, int cell) {
  std::vector<int> failed;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const unsigned char* p = rgba + (static_cast<std::size_t>(y) * width + x) * 4;
      if (p[0] == 0 && p[1] == 255 && p[2] == 0) continue;
      if (failed.empty() || failed.back() != x / cell) failed.push_back(x / cell);
    }
  std::sort(failed.begin(), failed.end());
  failed.erase(std::unique(failed.begin(), failed.end()), failed.end());
  return failed;
}


// The frame run_conformance.py makes (and include/input_picture.fxh works out in FX): codes that
// differ between neighbours in both directions, so a picture upside down, mirrored or shifted by
// a texel cannot pass for it; alpha 255, or varying for `--input alpha`.
std::vector<unsigned char> input_picture(int width, int height, bool varying_alpha) {
  std::vector<unsigned char> rgba(static_cast<std::size_t>(width) * height * 4);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      unsigned char* p = &rgba[(static_cast<std::size_t>(y) * width + x) * 4];
      p[0] = static_cast<unsigned char>((x * 37 + y * 11) % 256);
      p[1] = static_cast<unsigned char>((x * 5 + y * 67) % 256);
      p[2] = static_cast<unsigned char>((x * 3 + 128) % 256);
      p[3] = static_cast<unsigned char>(varying_alpha ? (x * 7 + y * 13) % 256 : 255);
    }
  return rgba;
}


// What the picture should be, said as the conformance runner says it; "" when it is.
std::string judge(const Judged& judged, const unsigned char* out, const std::vector<unsigned char>& in) {
  if (judged.expect == "checks") {
    const std::vector<int> failed = failed_checks(out, judged.width, judged.height, judged.cell);
    std::string list;
    for (int check : failed) list += (list.empty() ? "" : ", ") + std::to_string(check);
    return failed.empty() ? "" : "checks [" + list + "] of " + std::to_string((judged.width + judged.cell - 1) / judged.cell);
  }
  const bool invert = judged.expect == "invert", gain = judged.expect == "gain";
  for (std::size_t i = 0; i < in.size(); ++i) {
    const bool alpha = i % 4 == 3;
    if (invert && alpha) continue;
    const int wanted = invert ? 255 - in[i] : gain && !alpha ? static_cast<int>(in[i] * judged.gain + 0.5) : in[i];
    if (std::abs(out[i] - wanted) > (gain && !alpha ? 1 : 0)) {
      const std::size_t pixel = i / 4;
      return "pixel (" + std::to_string(pixel % static_cast<std::size_t>(judged.width)) + ", " +
             std::to_string(pixel / static_cast<std::size_t>(judged.width)) + ") channel " + std::to_string(i % 4) + " is " +
             std::to_string(out[i]) + ", not " + std::to_string(wanted) + (invert ? " (255 - the input)" : gain ? " (the input times the gain)" : " (the input)");
    }
  }
  return "";
}


// The technique through the Vulkan runtime itself, its pipelines through the cache file: 0, or the
// exit status to end with.
int make_technique(const pfx::fx::vulkan::Device& device, const std::string& file, const pfx::fx::CompiledEffect& effect, int technique,
                   const Judged& judged, pfx::fx::vulkan::Technique& runtime) {
  pfx::fx::vulkan::PipelineCacheFile cache;
  if (!cache.open(device)) return std::printf("FAIL: vkCreatePipelineCache failed\n"), 1;
  std::string message;
  const auto loader = [&file](const pfx::fx::TextureInfo& texture, pfx::fx::TextureTexels& texels, std::string& error) {
    return load_texels(file, texture, texels, error);
  };
  auto status =
      runtime.create(device, effect, technique, judged.width, judged.height, VK_FORMAT_R8G8B8A8_UNORM, cache.handle(), loader, message);
  // Every frame here runs the live pipelines: built now, while the cache is open.
  std::size_t built = 0;
  if (status == pfx::fx::vulkan::Technique::Status::kOk) message = runtime.prepare(nullptr, &built);
  if (!message.empty()) status = pfx::fx::vulkan::Technique::Status::kFailed;
  cache.save();
  if (judged.report_cache)
    std::printf("pipeline cache: %s (%s)\n", cache.loaded() ? "from the file" : "started empty", cache.path().empty() ? "off" : cache.path().c_str());
  cache.destroy();
  if (status == pfx::fx::vulkan::Technique::Status::kUnsupported) return std::printf("not run: %s\n", message.c_str()), 3;
  if (status != pfx::fx::vulkan::Technique::Status::kOk) return std::printf("FAIL: %s\n", message.c_str()), 1;
  return 0;
}

// The technique through the plugin's factory: 0, or the exit status to end with.
int make_plugin_effect(const Owner& d, const std::string& file, const std::string& technique, const Judged& judged, PluginEffect& plugin) {
  const std::string problem = plugin.load(judged.plugin, std::filesystem::absolute(file).string(), technique, judged.sets);
  if (!problem.empty()) return std::printf("FAIL: %s\n", problem.c_str()), 1;
  pfx_vk_device device{};
  device.struct_size = sizeof device;
  device.instance = d.instance;
  device.physical_device = d.physical;
  device.device = d.device;
  device.get_instance_proc_addr = vkGetInstanceProcAddr;
  device.get_device_proc_addr = vkGetDeviceProcAddr;
  device.queue_family_index = d.family;
  device.api_version = VK_API_VERSION_1_1;
  char error[1024] = "";
  const pfx_status status = plugin.vulkan->create(&plugin.host, plugin.id.c_str(), &device, static_cast<uint32_t>(judged.width),
                                                  static_cast<uint32_t>(judged.height), VK_FORMAT_R8G8B8A8_UNORM, &plugin.instance, error,
                                                  sizeof error);
  if (status == PFX_UNSUPPORTED) return std::printf("not run: %s\n", error), 3;
  if (status != PFX_OK) return std::printf("FAIL: %s\n", error), 1;
  return 0;
}

// Runs `technique` of `effect` for the frames and judges the last picture.
int run(const std::string& file, const pfx::fx::CompiledEffect& effect, int technique, const Judged& judged) {
  const int width = judged.width, height = judged.height;
  std::vector<unsigned char> input = input_picture(width, height, judged.varying_alpha);
  if (!judged.input_file.empty()) {
    pfx::fx::TextureTexels texels;
    std::string error;
    if (!pfx::fx::decode_texture_image(judged.input_file, width, height, 1, texels, error)) return std::printf("FAIL: %s\n", error.c_str()), 1;
    input = texels.rgba;
  }
  const bool any_source = judged.expect == "none";
  std::vector<std::vector<double>> uniforms;
  for (int frame = 0; frame < judged.frames; ++frame) {
    const std::string missing = uniform_values(effect.model, frame, any_source, uniforms);
    if (!missing.empty() && !any_source) return std::printf("not run: this program gives no uniform source '%s'\n", missing.c_str()), 3;
    if (!missing.empty() && frame == 0) std::printf("sources given as 0: %s\n", missing.c_str());
  }
  Owner d;
  pfx::fx::vulkan::Device device;
  const std::string missing = device.load(vkGetInstanceProcAddr, d.instance, d.physical, vkGetDeviceProcAddr, d.device);
  if (!missing.empty()) return std::printf("FAIL: the device gives no %s\n", missing.c_str()), 1;
  pfx::fx::vulkan::Technique runtime;
  PluginEffect plugin;
  const int made = judged.plugin.empty() ? make_technique(device, file, effect, technique, judged, runtime)
                                         : make_plugin_effect(d, file, effect.model.techniques[static_cast<std::size_t>(technique)].name,
                                                              judged, plugin);
  if (made != 0) return made;
  FrameImage frame(d, input, width, height);
  auto pool_info = vk<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
  pool_info.queueFamilyIndex = d.family;
  VkCommandPool pool;
  VK_OK(vkCreateCommandPool(d.device, &pool_info, nullptr, &pool));
  // With --time N, N more frames before the last, each submitted and waited for alone: their
  // median wall time.
  const int total = judged.frames + (judged.time_frames > 0 ? judged.time_frames + 1 : 0);
  std::vector<double> frame_ms;
  for (int n = 0; n < total; ++n) {
    uniform_values(effect.model, n, any_source, uniforms);
    const auto started = std::chrono::steady_clock::now();
    struct Timed {  // the frame's wall time, for the frames --time counts
      std::vector<double>* into;
      std::chrono::steady_clock::time_point started;
      ~Timed() {
        if (into) into->push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count());
      }
    } timed{n >= judged.frames && n + 1 < total ? &frame_ms : nullptr, started};
    submit(d, pool, [&](VkCommandBuffer commands) {
      if (n == 0) frame.record_upload(commands);
      struct ReadBack {  // after the frame's commands, however the body returns
        const FrameImage& frame;
        VkCommandBuffer commands;
        bool last;
        ~ReadBack() {
          if (last) frame.record_readback(commands);
        }
      } read_back{frame, commands, n + 1 == total};
      pfx::fx::vulkan::Frame f;
      f.image = frame.image;
      f.layout = n == 0 ? VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL : VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
      f.final_layout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
      if (judged.plugin.empty()) return runtime.record(commands, f, uniforms);
      pfx_vk_frame_image image{sizeof(pfx_vk_frame_image), f.image, f.layout, f.final_layout, 0};
      pfx_frame info{};
      info.struct_size = sizeof info;
      info.width = static_cast<uint32_t>(width), info.height = static_cast<uint32_t>(height);
      info.time_seconds = n * 0.016;
      info.frame_index = static_cast<uint64_t>(n);
      info.light_struct_size = sizeof(pfx_light);
      if (plugin.vulkan->record(plugin.instance, commands, &image, &info, plugin.params.data()) != PFX_OK)
        std::printf("FAIL: the plugin's record failed\n");
    });
  }
  if (!frame_ms.empty()) {
    std::sort(frame_ms.begin(), frame_ms.end());
    std::printf("frame ms: median %.3f of %zu (min %.3f, max %.3f)\n", frame_ms[frame_ms.size() / 2], frame_ms.size(), frame_ms.front(),
                frame_ms.back());
  }
  const VkDeviceSize pixels_size = static_cast<VkDeviceSize>(width) * height * 4;
  void* mapped;
  VK_OK(vkMapMemory(d.device, frame.staging_memory, 0, pixels_size, 0, &mapped));
  const std::string wrong = judged.expect == "none" ? "" : judge(judged, static_cast<const unsigned char*>(mapped), input);
  if (!judged.raw_out.empty()) {
    std::FILE* out = std::fopen(judged.raw_out.c_str(), "wb");
    const bool written = out && std::fwrite(mapped, 1, static_cast<std::size_t>(pixels_size), out) == pixels_size;
    if (out) std::fclose(out);
    if (!written) std::printf("FAIL: cannot write %s\n", judged.raw_out.c_str());
  }
  vkUnmapMemory(d.device, frame.staging_memory);
  vkDestroyCommandPool(d.device, pool, nullptr);
  runtime.destroy();
  plugin.unload();
  frame.destroy(d);
  if (!wrong.empty()) return std::printf("FAIL: %s\n", wrong.c_str()), 1;
  if (judged.expect == "checks") return std::printf("ok: %d checks\n", (width + judged.cell - 1) / judged.cell), 0;
  if (judged.expect == "none") return std::printf("ok: ran\n"), 0;
  if (judged.expect == "gain") return std::printf("ok: the picture is the input times %g\n", judged.gain), 0;
  return std::printf("ok: the picture is %s\n", judged.expect == "input" ? "the input" : "the input inverted"), 0;
}

}  // namespace

int main(int argc, char** argv) {
  pfx::fx::FrontEndOptions options;
  std::string file, technique_name;
  int width = 0, height = 0, cell = 4, frames = 1;
  bool report_cache = false;
  std::string expect = "checks", input = "gradient", raw_out, plugin;
  std::vector<std::pair<std::string, double>> sets;
  double gain = 1.0;
  int time_frames = 0;
  for (int i = 1; i < argc; ++i) {
    std::string argument = argv[i];
    if (argument.rfind("-I", 0) == 0) options.preprocessor.include_folders.push_back(argument.substr(2));
    else if (argument.rfind("-D", 0) == 0) {
      const std::size_t equals = argument.find('=');
      options.preprocessor.defines.emplace_back(argument.substr(2, equals == std::string::npos ? std::string::npos : equals - 2),
                                                equals == std::string::npos ? "1" : argument.substr(equals + 1));
    }
    else if (argument == "--size" && i + 1 < argc) std::sscanf(argv[++i], "%dx%d", &width, &height);
    else if (argument == "--cell" && i + 1 < argc) cell = std::atoi(argv[++i]);
    else if (argument == "--frames" && i + 1 < argc) frames = std::atoi(argv[++i]);
    else if (argument == "--technique" && i + 1 < argc) technique_name = argv[++i];
    else if (argument == "--expect" && i + 1 < argc) expect = argv[++i];
    else if (argument == "--input" && i + 1 < argc) input = argv[++i];
    else if (argument == "--report-cache") report_cache = true;
    else if (argument == "--raw-out" && i + 1 < argc) raw_out = argv[++i];
    else if (argument == "--plugin" && i + 1 < argc) plugin = argv[++i];
    else if (argument == "--gain" && i + 1 < argc) gain = std::atof(argv[++i]);
    else if (argument == "--time" && i + 1 < argc) time_frames = std::atoi(argv[++i]);
    else if (argument == "--set" && i + 1 < argc) {
      const std::string assignment = argv[++i];
      const std::size_t equals = assignment.find('=');
      if (equals != std::string::npos) sets.emplace_back(assignment.substr(0, equals), std::atof(assignment.c_str() + equals + 1));
    }
    else file = argument;
  }
  if (file.empty() || width <= 0 || height <= 0 || cell <= 0 || frames <= 0 || (expect != "checks" && expect != "input" && expect != "invert" && expect != "none" && expect != "gain") || input.empty()) {
    std::fprintf(stderr, "usage: fx_vulkan_checks [-IFOLDER...] [-DNAME=VALUE...] --size WxH [--cell N] [--frames N] [--technique NAME] "
                         "[--expect checks|input|invert|gain|none] [--gain G] [--input gradient|alpha|IMAGE] [--raw-out FILE] [--report-cache] "
                         "[--plugin PFX_FX_SO [--set PARAM=VALUE...]] [--time N] FILE.fx\n");
    return 2;
  }
  options.preprocessor.buffer_width = width;
  options.preprocessor.buffer_height = height;
  auto effect = pfx::fx::compile_effect(file, options, false);
  if (!effect->ok()) return std::printf("FAIL: %s", effect->errors().c_str()), 1;
  if (technique_name.empty()) technique_name = std::filesystem::path(file).stem().string();
  const auto& techniques = effect->model.techniques;
  int technique = techniques.size() == 1 ? 0 : -1;
  for (std::size_t i = 0; i < techniques.size(); ++i)
    if (techniques[i].name == technique_name) technique = static_cast<int>(i);
  if (technique < 0) return std::printf("FAIL: %s has no technique '%s'\n", file.c_str(), technique_name.c_str()), 1;
  Judged judged{expect, width, height, cell, frames, input == "alpha", report_cache, input == "gradient" || input == "alpha" ? "" : input,
                raw_out, plugin, sets, gain, time_frames};
  return run(file, *effect, technique, judged);
}
