#pragma once
// One technique of an FX effect, run natively on a Vulkan device it is given: the passes compiled
// to SPIR-V (the generator's Vulkan dialect through glslang), the effect's textures as images with
// their formats and mip levels (kept from frame to frame, as FX effects expect), a sampler per FX
// sampler, the uniforms in one block updated inside the command buffer, two back buffers that
// the passes draw between as ReShade's runtime does (beside a copy of the frame, which the first
// passes sample until one writes the back buffer), and a pipeline per pass (built when a frame first
// runs it: prepare()). record() writes a
// frame's work into the caller's command buffer: the frame's image is copied in, each pass drawn
// or dispatched with the barriers it needs, the picture copied back, the image left in the layout
// asked for. Nothing is submitted and nothing waits: the owner submits on its queue, frames in
// the order they were recorded.
//
// The stencil buffer is ReShade's: 8 bits of the frame's size, cleared to 0 when the technique
// starts (every frame), kept from pass to pass, tested by a pass whose first target has the
// frame's size. Textures with `source =` start from the texels the owner's loader gives (it finds
// and decodes the file: images/texture_image.hpp). What the GL runtime does that this does not
// yet: the frame's depth (the depth texture is one texel at the far plane), render targets that
// are not 2D. create() says kUnsupported with the reason for a technique that needs one of them.
#include <vulkan/vulkan.h>

#include <functional>
#include <string>
#include <vector>

#include "effect_compiler.hpp"
#include "texture_image.hpp"
#include "vk_device.hpp"
#include "vk_frame_alpha.hpp"
#include "vk_images.hpp"
#include "vk_pipelines.hpp"
#include "vk_texture_uploads.hpp"
#include "codegen/uniform_block.hpp"

namespace pfx::fx::vulkan {

// The caller's frame: an image of `format` at the size the effect was compiled for, usable as a
// copy source and destination, in `layout` when the commands start; left in `final_layout`. Its
// earlier writes are waited for (all commands, memory writes), and later commands wait for ours.
struct Frame {
  VkImage image = VK_NULL_HANDLE;
  VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
  VkImageLayout layout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  VkImageLayout final_layout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  // The frame's alpha comes back as it went in (FX passes use the back buffer's alpha as
  // scratch); false where it means nothing (a swapchain composited opaque) saves a draw.
  bool keep_alpha = true;
};

// Finds and decodes the image file a texture names (`source`), at the texture's size; false with
// the reason.
using TexelLoader = std::function<bool(const TextureInfo& texture, TextureTexels& texels, std::string& error)>;

class Technique {
 public:
  enum class Status { kOk, kUnsupported, kFailed };

  Technique() = default;
  Technique(const Technique&) = delete;
  Technique& operator=(const Technique&) = delete;
  ~Technique() { destroy(); }

  // Builds technique `technique` of `effect` (its model and tree, compiled for frames of `width` x
  // `height`) for frames of `frame_format`. `cache` may be VK_NULL_HANDLE. On anything but kOk,
  // `message` says why and nothing is left behind. `device` and `effect` outlive the technique.
  Status create(const Device& device, const CompiledEffect& effect, int technique, int width, int height, VkFormat frame_format,
                VkPipelineCache cache, const TexelLoader& load_texels, std::string& message);
  // Why this runtime cannot run technique `technique` of `model`, "" when it can: a pass that
  // renders to a texture that is not 2D (the GL runtime draws into its first layer). The plugin
  // asks at listing, so that a host sends such an effect to GL.
  static std::string unsupported_reason(const EffectModel& model, int technique);
  // Pipelines with `constants` compiled in (GLSL generated with them: the uniforms whose values
  // have settled, fx_settled_values.hpp), so the driver folds what they decide. A pass whose
  // specialised code samples or stores other textures than its live code keeps its live pipeline.
  // Every set built is kept until destroy(), as frames still in flight may use it; at most
  // kSpecialisedSets, after which values not seen before run the live pipelines. *built says a
  // set was made now; false with `message` when it could not be (the live pipelines run on).
  static constexpr std::size_t kSpecialisedSets = 8;
  bool specialise(const CompiledEffect& effect, const UniformConstants& constants, VkPipelineCache cache, bool* built,
                  std::string& message);
  bool has_specialised(const UniformConstants& constants) const { return specialised_for(constants) != nullptr; }
  // Builds the live pipelines that a frame with `constants` (null: every uniform live) runs: those
  // of passes without a specialised pipeline for them. Live pipelines are built when a frame
  // first needs one, not at create(), so an effect whose values settle at once (a renderer, a
  // video host) compiles each pass once. *built: how many were built now. "" or why not.
  std::string prepare(const UniformConstants* constants, std::size_t* built);
  // The frame's work, after prepare() with the same `constants`. `uniforms`: per model uniform,
  // its components as the runtimes hold them. `constants`: the pipelines specialised for them
  // (specialise()) where a set was built, else (and when null) the live ones. Both compute the
  // same picture.
  void record(VkCommandBuffer commands, const Frame& frame, const std::vector<std::vector<double>>& uniforms,
              const UniformConstants* constants = nullptr);
  void destroy();

 private:
  struct Pass {
    const PassInfo* info = nullptr;
    bool compute = false;
    bool writes_back_buffer = false, copy_first = false;
    bool stencil = false;  // tests the stencil buffer
    int back_buffer = 0;  // which back buffer holds the picture when the pass starts (0: the frame's copy)
    std::vector<int> targets, sampled, stored;  // image indices
    std::vector<VkImageView> owned_views;       // storages' level views
    std::string live_code[2];  // the live code's GLSL (compute, or vertex and fragment), compiled when first run
    VkShaderModule modules[2] = {VK_NULL_HANDLE, VK_NULL_HANDLE};
    VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
    VkDescriptorSet set = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkRenderPass render_pass = VK_NULL_HANDLE;
    VkFramebuffer framebuffer = VK_NULL_HANDLE;
    VkPipeline pipeline = VK_NULL_HANDLE;
    int area_width = 1, area_height = 1;
    // What a specialised pipeline must match: the live code's texture bindings and whether it may
    // discard, and for a graphics pass what its pipeline is made from.
    std::vector<int> sampler_units, image_units;
    bool may_discard = false;
    GraphicsPlan plan;
  };
  // Pipelines for one set of settled values, per pass (null: the pass runs its live pipeline).
  struct Specialised {
    UniformConstants constants;
    std::vector<VkPipeline> pipelines;
    std::vector<VkShaderModule> modules;
  };
  const Specialised* specialised_for(const UniformConstants& constants) const;
  void destroy(Specialised& set);

  std::string create_images(VkFormat frame_format, const TexelLoader& load_texels);
  std::string create_pass(std::size_t index, const GeneratedPass& generated);
  std::string create_bindings(Pass& pass, const GeneratedPass& generated);
  std::string create_draw(Pass& pass);
  std::string build_live(std::size_t index);
  std::string create_pool();            // a descriptor set per pass
  std::string create_uniform_buffer();  // the block, updated in each frame's commands
  int image_of_texture(int texture, int back_buffer) const;
  VkImageView sampled_view(const SamplerInfo& sampler, int back_buffer) const;
  void record_uniforms(VkCommandBuffer commands, const std::vector<std::vector<double>>& uniforms);
  void record_pass(VkCommandBuffer commands, Pass& pass, VkPipeline pipeline);

  const Device* d_ = nullptr;
  VkPipelineCache cache_ = VK_NULL_HANDLE;  // the owner's, for the live pipelines built later
  const EffectModel* model_ = nullptr;
  const TechniqueInfo* technique_ = nullptr;
  int width_ = 0, height_ = 0;
  // Per model texture, then the back buffers (the frame's copy and the two the passes draw
  // between), the depth texture and the stencil buffer (when a pass tests it).
  std::vector<Image> images_;
  int back_buffer_image_ = 0, depth_image_ = 0, stencil_image_ = 0;
  int last_back_buffer_ = 0;  // which back buffer holds the picture after the last pass
  FrameAlpha frame_alpha_;    // when a pass writes the back buffer
  TextureUploads uploads_;    // textures from image files
  std::vector<VkSampler> samplers_;  // per model sampler
  UniformBlockLayout block_;
  VkBuffer uniform_buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory uniform_memory_ = VK_NULL_HANDLE;
  VkAccessFlags uniform_access_ = 0;
  std::vector<unsigned char> block_bytes_;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  std::vector<Pass> passes_;
  std::vector<Specialised> specialised_;
  bool started_ = false;  // the images were cleared: ReShade's textures start as zeros
};

}  // namespace pfx::fx::vulkan
