#include "obs_filter.hpp"

#include <mutex>
#include <string>

#include <glad/gl.h>
#include <graphics/vec4.h>
#include <util/platform.h>

#include "texture_filter.hpp"

namespace pfx::obs {
namespace {

std::shared_ptr<const host::PluginRegistry> g_registry;

struct Filter {
  obs_source_t* source = nullptr;
  const FilterKind* kind = nullptr;
  std::mutex mutex;  // settings change on OBS's UI thread, frames run on its graphics thread
  adapters::ChainSettings settings;
  uint64_t revision = 1;
  // On the graphics thread:
  std::unique_ptr<adapters::TextureFilter> gl;
  gs_texrender_t* input = nullptr;
  gs_texture_t* output = nullptr;
  uint32_t width = 0, height = 0;
  adapters::ChainSettings frame_settings;  // the graphics thread's copy of settings at frame_revision
  uint64_t frame_revision = 0;
  std::string said;     // the last warning logged, so each is logged once
  bool broken = false;  // GL failed: frames pass through from then on
  // A warning about settings waits until they have held for a while (settled_warning).
  std::string pending;
  uint64_t pending_revision = 0, pending_since_ns = 0;
};

// OBS applies a text field at every keystroke: typing "bloom" into the chain field passes through
// "b", "bl", "blo"..., each bad for a moment. A warning about settings is logged once they have
// stayed the same this long, so a user sees the value they stopped at, not every one on the way.
constexpr uint64_t kSettleNs = 1'000'000'000;

uint32_t gl_name(gs_texture_t* texture) {
  // OBS's OpenGL device hands out a pointer to the texture's GL name.
  return *static_cast<const uint32_t*>(gs_texture_get_obj(texture));
}

const char* get_name(void* type_data) { return static_cast<const FilterKind*>(type_data)->name.c_str(); }

void update(void* data, obs_data_t* settings) {
  auto* filter = static_cast<Filter*>(data);
  adapters::ChainSettings chain = kind_chain_settings(*filter->kind, settings);
  std::lock_guard<std::mutex> lock(filter->mutex);
  filter->settings = std::move(chain);
  ++filter->revision;
}

void release_graphics(Filter* filter) {
  obs_enter_graphics();
  filter->gl.reset();
  gs_texrender_destroy(filter->input);
  gs_texture_destroy(filter->output);
  obs_leave_graphics();
}

void* create(obs_data_t* settings, obs_source_t* source) {
  auto* filter = new Filter;
  filter->source = source;
  filter->kind = static_cast<const FilterKind*>(obs_source_get_type_data(source));
  std::string error;
  obs_enter_graphics();
  if (g_registry) filter->gl = adapters::TextureFilter::create(g_registry, &error);
  else error = "the module has no pfx plugins loaded";
  filter->input = gs_texrender_create(GS_RGBA, GS_ZS_NONE);
  obs_leave_graphics();
  if (!filter->gl)
    blog(LOG_WARNING, "[pfx-obs] '%s': %s; the source passes through unchanged", obs_source_get_name(source),
         error.c_str());
  update(filter, settings);
  return filter;
}

void destroy(void* data) {
  auto* filter = static_cast<Filter*>(data);
  release_graphics(filter);
  delete filter;
}

obs_properties_t* get_properties(void* data, void* type_data) {
  // The filter's source, when OBS asks for a filter's properties: its size sets the ranges of
  // parameters that follow the frame size.
  auto* filter = static_cast<Filter*>(data);
  obs_source_t* target = filter ? obs_filter_get_target(filter->source) : nullptr;
  const uint32_t width = target ? obs_source_get_base_width(target) : 0;
  const uint32_t height = target ? obs_source_get_base_height(target) : 0;
  return kind_properties(*static_cast<const FilterKind*>(type_data), width, height);
}

void get_defaults(void* type_data, obs_data_t* settings) {
  kind_defaults(*static_cast<const FilterKind*>(type_data), settings);
}

void say_once(Filter* filter, int level, const std::string& message) {
  if (message.empty() || message == filter->said) return;
  filter->said = message;
  blog(level, "[pfx-obs] '%s': %s", obs_source_get_name(filter->source), message.c_str());
}

// `warning` is what this frame's settings (at `revision`) gave, empty when they gave nothing new:
// the texture filter says each revision's warning once. Logged when the settings held kSettleNs.
void settled_warning(Filter* filter, const std::string& warning, uint64_t revision) {
  const uint64_t now = os_gettime_ns();
  if (revision != filter->pending_revision) {
    filter->pending.clear();
    filter->pending_revision = revision;
  }
  if (!warning.empty()) {
    filter->pending = warning;
    filter->pending_since_ns = now;
  }
  if (!filter->pending.empty() && now - filter->pending_since_ns >= kSettleNs) {
    say_once(filter, LOG_WARNING, filter->pending);
    filter->pending.clear();
  }
}

// The source below the filter, as it would be drawn onto a scene, into filter->input.
bool draw_input(Filter* filter, uint32_t width, uint32_t height) {
  gs_texrender_reset(filter->input);
  gs_blend_state_push();
  gs_blend_function(GS_BLEND_ONE, GS_BLEND_ZERO);
  const bool drawn = gs_texrender_begin(filter->input, width, height);
  if (drawn) {
    vec4 clear;
    vec4_zero(&clear);
    gs_clear(GS_CLEAR_COLOR, &clear, 0.0f, 0);
    gs_ortho(0.0f, static_cast<float>(width), 0.0f, static_cast<float>(height), -100.0f, 100.0f);
    obs_source_skip_video_filter(filter->source);
    gs_texrender_end(filter->input);
  }
  gs_blend_state_pop();
  return drawn;
}

void video_render(void* data, gs_effect_t*) {
  auto* filter = static_cast<Filter*>(data);
  obs_source_t* target = obs_filter_get_target(filter->source);
  const uint32_t width = target ? obs_source_get_base_width(target) : 0;
  const uint32_t height = target ? obs_source_get_base_height(target) : 0;
  if (!filter->gl || filter->broken || width == 0 || height == 0) {
    obs_source_skip_video_filter(filter->source);
    return;
  }
  {
    // Copied only when they changed: most frames find the same settings.
    std::lock_guard<std::mutex> lock(filter->mutex);
    if (filter->frame_revision != filter->revision) {
      filter->frame_settings = filter->settings;
      filter->frame_revision = filter->revision;
    }
  }
  const adapters::ChainSettings& settings = filter->frame_settings;
  const uint64_t revision = filter->frame_revision;
  const double time_seconds = static_cast<double>(obs_get_video_frame_time()) * 1e-9;
  std::string warning, error;
  // A frame no pass would change (no effect on, only no-ops, settings that do not build) is the
  // source drawn as if the filter were not there: no texture drawn into, copied, decoded or encoded.
  if (!filter->gl->runs_passes(settings, revision, static_cast<int>(width), static_cast<int>(height), time_seconds,
                               &warning)) {
    settled_warning(filter, warning, revision);
    obs_source_skip_video_filter(filter->source);
    return;
  }
  // The filter works on the frame's 8-bit codes (sRGB-encoded video) and draws its result's codes
  // as they are: OBS's linear blending is off while it draws, and put back after.
  const bool linear_srgb = gs_get_linear_srgb();
  const bool framebuffer_srgb = gs_framebuffer_srgb_enabled();
  gs_set_linear_srgb(false);
  if (!draw_input(filter, width, height)) {
    gs_set_linear_srgb(linear_srgb);
    obs_source_skip_video_filter(filter->source);
    return;
  }
  if (!filter->output || filter->width != width || filter->height != height) {
    gs_texture_destroy(filter->output);
    filter->output = gs_texture_create(width, height, GS_RGBA, 1, nullptr, GS_RENDER_TARGET);
    filter->width = width;
    filter->height = height;
  }
  gs_texture_t* input = gs_texrender_get_texture(filter->input);
  // OBS's 8-bit textures have sRGB formats that sources draw into with sRGB writes: the stored
  // bytes are the frame's codes. pfx takes them, and gives its result, as bytes (a blit with sRGB
  // writes off moves bits), into an sRGB texture too, which OBS draws without decoding.
  const bool ok = filter->gl->process(settings, revision, gl_name(input), gl_name(filter->output),
                                      static_cast<int>(width), static_cast<int>(height), time_seconds, &warning,
                                      &error);
  settled_warning(filter, warning, revision);
  gs_texture_t* shown = filter->output;
  if (!ok) {
    say_once(filter, LOG_ERROR, error + "; the source passes through unchanged from now on");
    filter->broken = true;
    shown = input;
  }
  gs_enable_framebuffer_srgb(false);
  gs_effect_t* effect = obs_get_base_effect(OBS_EFFECT_DEFAULT);
  gs_effect_set_texture(gs_effect_get_param_by_name(effect, "image"), shown);
  while (gs_effect_loop(effect, "Draw")) gs_draw_sprite(shown, 0, width, height);
  gs_set_linear_srgb(linear_srgb);
  gs_enable_framebuffer_srgb(framebuffer_srgb);
}

}  // namespace

void set_filter_registry(std::shared_ptr<const host::PluginRegistry> registry) { g_registry = std::move(registry); }

obs_source_info filter_info(const FilterKind& kind) {
  obs_source_info info{};
  info.id = kind.type_id.c_str();
  info.type = OBS_SOURCE_TYPE_FILTER;
  info.output_flags = OBS_SOURCE_VIDEO;
  info.type_data = const_cast<FilterKind*>(&kind);
  info.get_name = get_name;
  info.create = create;
  info.destroy = destroy;
  info.update = update;
  info.get_properties2 = get_properties;
  info.get_defaults2 = get_defaults;
  info.video_render = video_render;
  return info;
}

}  // namespace pfx::obs
