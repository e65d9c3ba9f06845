// The "tiledlights" effect on the GPU. Passes by mode:
//
//   brute      shade (uploads every light that reaches anything; every light at every pixel)
//   cpu8x4     cull  (CPU: lights in view, Olsson and Assarsson's grid of sub-frustums, lists into the
//                     upload ring)
//              shade (each pixel reads its tile's list)
//   tiled      cull  (CPU: lights in view; GPU compute: per-tile lists with the tile's depth bounds,
//                     counted, placed by a prefix sum, filled: gpu_lists.hpp)
//              shade
//   clustered  cull  (CPU: lights in view; GPU compute: per-cluster lists, tiles x depth slices, the same way)
//              shade
//
// Every list is in increasing light order and holds every light whose (slightly widened) sphere
// reaches its tile or cluster, however many, and the window is exactly 0 past a light's range, so
// every mode sums the same non-zero terms in the same order as brute force.
#include "tiledlights_effect.hpp"

#include <pfx/cpp/declaration.hpp>
#include <pfx/cpp/gl_program.hpp>
#include <pfx/cpp/descriptors.hpp>
#include <pfx/cpp/plugin_entry.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <new>
#include <string>

#include "cpu_culling.hpp"
#include "gpu_lists.hpp"
#include "light_set.hpp"
#include "list_bound.hpp"
#include "tiledlights_params.hpp"
#include "tiledlights_shaders.hpp"
#include "upload_ring.hpp"
#include "view_frustum.hpp"

namespace pfx_tiledlights {
namespace {

namespace sh = shaders;

enum PassTag : uint32_t { TAG_PREPARE = 1u, TAG_CULL = 2u, TAG_SHADE = 4u };

struct Instance {
  const pfx_host* host = nullptr;
  GLuint shade = 0;
  UploadRing ring;
  // GPU-built lists, in buffers per ring slot: llvmpipe runs a compute dispatch at once but defers
  // the draws before it, so the next frame's culling would overwrite lists a queued draw has yet
  // to read; the ring's fence keeps the slot's buffers until then.
  GpuLists gpu_lists;
  GLint ssbo_alignment = 256;
  GLint64 max_block_bytes = 1 << 24;
  // Mesa's llvmpipe ends a shader invocation's loops after 65535 turns in all. The shaders sum 16
  // lights a turn, so a pixel can take about a million lights there (clustered culling, which
  // also walks each chunk's candidates per slice, about 400,000); past that the frame is refused
  // instead of silently missing lights.
  uint64_t loop_guard_lights = 0;  // 0: no such guard

  pfx::desc::DeclarationBuilder<0, 2> declaration;  // the cull and the shading pass

  // This frame, from the first pass to the shading pass.
  Settings settings;
  LightSet set;
  std::vector<uint32_t> visible;  // indices into set.lights that were uploaded
  GridLists grid;
  int list_mode = sh::LIST_ALL;
  int tiles_x = 0, tiles_y = 0, tile_size = 1;
  size_t lights_offset = 0, lights_bytes = 0, heads_offset = 0, heads_bytes = 0, indices_offset = 0,
         indices_bytes = 0;
  ListStats list_stats;
  uint64_t list_bound = 0, index_capacity = 0;
  bool gpu_stats = false;
  char report[768] = "";
};

void log_error(const Instance* inst, const std::string& message) {
  inst->host->log(inst->host->host_data, PFX_LOG_ERROR, ("tiledlights: " + message).c_str());
}

void destroy(void* self) {
  Instance* inst = static_cast<Instance*>(self);
  if (!inst) return;
  glDeleteProgram(inst->shade);
  delete inst;
}

pfx_status create(const pfx_host* host, void** out) {
  if (!pfx::plugin::usable_host(host) || !out) return PFX_INVALID_ARGUMENT;
  if (!pfx::gl::load_gl_or_log(host, "tiledlights")) return PFX_GL_ERROR;
  Instance* inst = new (std::nothrow) Instance;
  if (!inst) return PFX_OUT_OF_MEMORY;
  inst->host = host;
  const pfx_status built = pfx::plugin::without_exceptions([&] {  // std::bad_alloc from a string
    std::string error;
    inst->shade = pfx::gl::build_fullscreen_program(sh::shade_fragment().c_str(), &error);
    if (!inst->shade) error = "shader 'shade': " + error;
    if (!inst->shade || !inst->gpu_lists.create(&error)) {
      log_error(inst, error);
      return PFX_GL_ERROR;
    }
    return PFX_OK;
  });
  if (built != PFX_OK) {
    destroy(inst);
    return built;
  }
  glGetIntegerv(GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT, &inst->ssbo_alignment);
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (renderer && std::strstr(renderer, "llvmpipe")) inst->loop_guard_lights = 900000;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &inst->max_block_bytes);
  *out = inst;
  return PFX_OK;
}

// What declare and the first pass both check: lights and camera. Logs and returns false.
bool check_frame(Instance* inst, const pfx_frame& frame, const Settings& settings, Perspective* perspective) {
  std::string error;
  try {
    if (!prepare_lights(frame, settings, &inst->set, &error) || !perspective_of(frame.camera, perspective, &error)) {
      log_error(inst, error);
      return false;
    }
  } catch (const std::bad_alloc&) {
    log_error(inst, "out of memory preparing " + std::to_string(frame.light_count) + " lights");
    return false;
  }
  return true;
}

pfx_status declare(void* self, const pfx_frame* frame, const pfx_value* params, pfx_declaration* out) {
  Instance* inst = static_cast<Instance*>(self);
  if (!inst || !pfx::plugin::usable_declare_arguments(frame, params, out)) return PFX_INVALID_ARGUMENT;
  const Settings settings = settings_from(params);
  Perspective perspective;
  if (!check_frame(inst, *frame, settings, &perspective)) return PFX_INVALID_ARGUMENT;
  out->inputs = PFX_INPUT_LIGHTS;
  // No light reaches anything and the base is the incoming colour: the output is the input.
  if (inst->set.lights.empty() && settings.base == BASE_COLOR && settings.show == SHOW_LIGHT) return PFX_OK;
  auto& d = inst->declaration;
  d.clear();
  if (settings.mode != MODE_BRUTE) {
    // The GPU modes read the depth to bound their tiles; the CPU grid reads nothing.
    auto cull = d.custom_pass("cull").tag(TAG_PREPARE | TAG_CULL);
    if (settings.mode == MODE_TILED || settings.mode == MODE_CLUSTERED)
      cull.input(PFX_INPUT_NAME_DEPTH, PFX_FILTER_NEAREST);
  }
  auto shade = d.pass("shade", PFX_OUTPUT_NAME)
                   .input(PFX_INPUT_NAME_COLOR, PFX_FILTER_NEAREST)
                   .input(PFX_INPUT_NAME_DEPTH, PFX_FILTER_NEAREST)
                   .input(PFX_INPUT_NAME_NORMAL, PFX_FILTER_NEAREST)
                   .input(PFX_INPUT_NAME_ALBEDO, PFX_FILTER_NEAREST)
                   .tag(settings.mode == MODE_BRUTE ? (TAG_PREPARE | TAG_SHADE) : TAG_SHADE);
  if (settings.base == BASE_EMISSIVE) shade.input(PFX_INPUT_NAME_EMISSIVE, PFX_FILTER_NEAREST);
  // The cull touches neither colour nor output; the shading samples one and draws the other.
  d.samples_and_draws();
  return d.finish(out);
}

void set_frame_uniforms(GLuint program, const pfx_frame& frame, const Perspective& perspective, uint32_t light_count,
                        const Instance& inst) {
  glProgramUniform1ui(program, sh::U_LIGHT_COUNT, light_count);
  glProgramUniform1i(program, sh::U_DEPTH_ENCODING, static_cast<GLint>(frame.depth_encoding));
  glProgramUniform2f(program, sh::U_NEAR_FAR, frame.camera.near_plane, frame.camera.far_plane);
  glProgramUniform4f(program, sh::U_PERSPECTIVE, static_cast<float>(perspective.scale_x),
                     static_cast<float>(perspective.scale_y), static_cast<float>(perspective.offset_x),
                     static_cast<float>(perspective.offset_y));
  glProgramUniform2i(program, sh::U_FRAME_SIZE, static_cast<GLint>(frame.width), static_cast<GLint>(frame.height));
  glProgramUniform2i(program, sh::U_TILE_SIZE, inst.tile_size, inst.tile_size);
  glProgramUniform2i(program, sh::U_TILES, inst.tiles_x, inst.tiles_y);
  // Exponential slices from the near plane to the far plane (1000 x near for an infinite one).
  const double near_depth = frame.camera.near_plane;
  const double far_depth = std::isfinite(frame.camera.far_plane) ? double(frame.camera.far_plane) : 1000.0 * near_depth;
  glProgramUniform1i(program, sh::U_SLICES, inst.settings.slices);
  glProgramUniform2f(program, sh::U_SLICE_RANGE, static_cast<float>(near_depth),
                     static_cast<float>(std::log(far_depth / near_depth)));
}

// The lights this frame uploads (every one for brute force, else those in view) and the CPU
// grid's lists; what the last frame's lists left is cleared.
pfx_status cull_on_cpu(Instance* inst, const pfx_frame& frame, const Perspective& perspective) {
  const Settings& s = inst->settings;
  const int w = static_cast<int>(frame.width), h = static_cast<int>(frame.height);
  try {
    if (s.mode == MODE_BRUTE) {
      inst->visible.resize(inst->set.lights.size());
      for (uint32_t i = 0; i < inst->visible.size(); ++i) inst->visible[i] = i;
    } else {
      inst->visible = lights_in_view(inst->set, perspective, w, h, frame.camera.near_plane, frame.camera.far_plane);
    }
    inst->list_mode = sh::LIST_ALL;
    inst->list_stats = ListStats{};
    inst->list_bound = inst->index_capacity = 0;
    inst->gpu_stats = false;
    inst->heads_bytes = inst->indices_bytes = 0;
    if (s.mode == MODE_CPU8X4) {
      inst->list_mode = sh::LIST_TILES_BY_GRID;
      inst->tiles_x = s.cpu_tiles_x;
      inst->tiles_y = s.cpu_tiles_y;
      if (!cull_grid(inst->set, inst->visible, perspective, w, h, s.cpu_tiles_x, s.cpu_tiles_y, &inst->grid)) {
        log_error(inst, "the light lists would hold more than 2^32 indices");
        return PFX_OUT_OF_MEMORY;
      }
      inst->list_stats = inst->grid.stats;
      inst->list_bound = inst->index_capacity = inst->grid.stats.entries;
      inst->heads_bytes = inst->grid.heads.size() * 4;
      inst->indices_bytes = std::max<size_t>(4, inst->grid.indices.size() * 4);
    }
  } catch (const std::bad_alloc&) {
    log_error(inst, "out of memory culling " + std::to_string(inst->set.lights.size()) + " lights");
    return PFX_OUT_OF_MEMORY;
  }
  return PFX_OK;
}

// Whether every light in view fits under llvmpipe's loop guard (always, elsewhere); logs when not.
bool within_loop_guard(Instance* inst) {
  const Settings& s = inst->settings;
  const uint64_t guard = s.mode == MODE_CLUSTERED ? inst->loop_guard_lights * 4 / 9 : inst->loop_guard_lights;
  if (!guard || inst->visible.size() <= guard) return true;
  log_error(inst, std::to_string(inst->visible.size()) + " lights in view: more than llvmpipe's loop guard lets a " +
                      kModeNames[s.mode] + " frame sum (" + std::to_string(guard) + ")");
  return false;
}

// One slot of the upload ring holds the lights, then the CPU grid's list heads and indices, each
// at the shader storage alignment; the lights are bound for the passes that read them.
pfx_status upload_lights(Instance* inst) {
  const size_t alignment = static_cast<size_t>(std::max(inst->ssbo_alignment, 4));
  inst->lights_offset = 0;
  inst->lights_bytes = std::max<size_t>(1, inst->visible.size()) * sizeof(GpuLight);
  if (static_cast<GLint64>(inst->lights_bytes) > inst->max_block_bytes) {
    log_error(inst, std::to_string(inst->visible.size()) + " lights need " + std::to_string(inst->lights_bytes) +
                        " bytes, past this GL's shader storage block limit of " +
                        std::to_string(inst->max_block_bytes) + " bytes");
    return PFX_OUT_OF_MEMORY;
  }
  inst->heads_offset = align_up(inst->lights_bytes, alignment);
  inst->indices_offset = align_up(inst->heads_offset + inst->heads_bytes, alignment);
  unsigned char* mapping = inst->ring.begin(inst->indices_offset + inst->indices_bytes);
  if (!mapping) {
    log_error(inst, "could not map the upload buffer");
    return PFX_GL_ERROR;
  }
  auto* lights = reinterpret_cast<GpuLight*>(mapping + inst->lights_offset);
  for (size_t k = 0; k < inst->visible.size(); ++k) lights[k] = inst->set.lights[inst->visible[k]];
  if (inst->heads_bytes) std::memcpy(mapping + inst->heads_offset, inst->grid.heads.data(), inst->heads_bytes);
  if (!inst->grid.indices.empty() && inst->settings.mode == MODE_CPU8X4)
    std::memcpy(mapping + inst->indices_offset, inst->grid.indices.data(), inst->grid.indices.size() * 4);
  glBindBufferRange(GL_SHADER_STORAGE_BUFFER, sh::SSBO_LIGHTS, inst->ring.buffer(),
                    static_cast<GLintptr>(inst->lights_offset), static_cast<GLsizeiptr>(inst->lights_bytes));
  return PFX_OK;
}

// The tiled and clustered modes: per-tile or per-cluster lists built on the GPU into the ring
// slot's buffers, within the storage block limit and the user's index budget.
pfx_status build_gpu_lists(Instance* inst, const pfx_frame& frame, const Perspective& perspective) {
  const Settings& s = inst->settings;
  const int w = static_cast<int>(frame.width), h = static_cast<int>(frame.height);
  const bool clustered = s.mode == MODE_CLUSTERED;
  inst->tile_size = clustered ? s.cluster_tile_size : s.tile_size;
  inst->tiles_x = (w + inst->tile_size - 1) / inst->tile_size;
  inst->tiles_y = (h + inst->tile_size - 1) / inst->tile_size;
  inst->list_mode = clustered ? sh::LIST_CLUSTERS : sh::LIST_TILES_BY_SIZE;
  ListShape shape;
  shape.clustered = clustered;
  shape.tiles_x = inst->tiles_x;
  shape.tiles_y = inst->tiles_y;
  shape.slices = s.slices;
  const uint64_t lists = shape.lists();
  if (static_cast<GLint64>(lists * 8) > inst->max_block_bytes) {
    log_error(inst, std::to_string(lists) + " lists need more than this GL's shader storage block limit of " +
                        std::to_string(inst->max_block_bytes) + " bytes: use larger tiles or fewer slices");
    return PFX_OUT_OF_MEMORY;
  }
  ListGrid grid;
  grid.width = w;
  grid.height = h;
  grid.tile_size = inst->tile_size;
  grid.slices = clustered ? s.slices : 0;
  grid.slice_near = frame.camera.near_plane;
  grid.slice_far = std::isfinite(frame.camera.far_plane) ? double(frame.camera.far_plane)
                                                         : 1000.0 * frame.camera.near_plane;
  inst->list_bound = list_entries_bound(inst->set, inst->visible, perspective, grid);
  // The index buffer is one shader storage block: its size limit, and the user's budget.
  uint64_t budget = std::min<uint64_t>(uint64_t(inst->max_block_bytes) / 4, 0xffffffffull);
  if (s.max_list_indices >= 1) budget = std::min<uint64_t>(budget, uint64_t(s.max_list_indices));
  const GLuint program = inst->gpu_lists.program(clustered);
  set_frame_uniforms(program, frame, perspective, static_cast<uint32_t>(inst->visible.size()), *inst);
  std::string error;
  if (!inst->gpu_lists.build(inst->ring.slot(), shape, inst->list_bound, budget, &error)) {
    log_error(inst, error);
    return PFX_OUT_OF_MEMORY;
  }
  inst->index_capacity = inst->gpu_lists.index_capacity(inst->ring.slot());
  inst->list_stats.lists = lists;
  inst->gpu_stats = true;
  return PFX_OK;
}

// The first pass of a frame: prepare the lights, cull what the mode culls on the CPU, upload, and
// in the GPU modes build the lists.
pfx_status prepare(Instance* inst, const pfx_pass_context* context) {
  const pfx_frame& frame = *context->frame;
  const Settings s = settings_from(context->params);
  inst->settings = s;
  Perspective perspective;
  if (!check_frame(inst, frame, s, &perspective)) return PFX_INVALID_ARGUMENT;
  if (const pfx_status culled = cull_on_cpu(inst, frame, perspective); culled != PFX_OK) return culled;
  if (!within_loop_guard(inst)) return PFX_UNSUPPORTED;
  if (const pfx_status uploaded = upload_lights(inst); uploaded != PFX_OK) return uploaded;
  if (s.mode == MODE_TILED || s.mode == MODE_CLUSTERED) return build_gpu_lists(inst, frame, perspective);
  return PFX_OK;
}

pfx_status shade(Instance* inst, const pfx_pass_context* context) {
  const pfx_frame& frame = *context->frame;
  Perspective perspective;
  std::string error;
  if (!perspective_of(frame.camera, &perspective, &error)) return PFX_INVALID_ARGUMENT;
  double view[16];
  view_matrix(frame.camera, view);
  double inverse[16];
  if (!invert_matrix(view, inverse)) {
    log_error(inst, "the camera's view matrix is not invertible");
    return PFX_INVALID_ARGUMENT;
  }
  float inverse_f[16];
  for (int i = 0; i < 16; ++i) inverse_f[i] = static_cast<float>(inverse[i]);

  const GLuint program = inst->shade;
  set_frame_uniforms(program, frame, perspective, static_cast<uint32_t>(inst->visible.size()), *inst);
  glProgramUniform1i(program, sh::U_LIST_MODE, inst->list_mode);
  glProgramUniformMatrix4fv(program, sh::U_INVERSE_VIEW, 1, GL_FALSE, inverse_f);
  glProgramUniform1i(program, sh::U_BASE, inst->settings.base);
  glProgramUniform1i(program, sh::U_SHOW, inst->settings.show);
  glProgramUniform1i(program, sh::U_NONFINITE, inst->settings.nonfinite);
  glBindBufferRange(GL_SHADER_STORAGE_BUFFER, sh::SSBO_LIGHTS, inst->ring.buffer(),
                    static_cast<GLintptr>(inst->lights_offset), static_cast<GLsizeiptr>(inst->lights_bytes));
  if (inst->list_mode == sh::LIST_TILES_BY_GRID) {
    glBindBufferRange(GL_SHADER_STORAGE_BUFFER, sh::SSBO_HEADS, inst->ring.buffer(),
                      static_cast<GLintptr>(inst->heads_offset), static_cast<GLsizeiptr>(inst->heads_bytes));
    glBindBufferRange(GL_SHADER_STORAGE_BUFFER, sh::SSBO_INDICES, inst->ring.buffer(),
                      static_cast<GLintptr>(inst->indices_offset), static_cast<GLsizeiptr>(inst->indices_bytes));
  } else if (inst->list_mode != sh::LIST_ALL) {
    inst->gpu_lists.bind_for_shading(inst->ring.slot());
  }
  glUseProgram(program);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glUseProgram(0);
  inst->ring.end();
  return PFX_OK;
}

pfx_status run_pass(void* self, const pfx_pass_context* context) {
  Instance* inst = static_cast<Instance*>(self);
  if (!inst || !context || context->struct_size < PFX_PASS_CONTEXT_MIN_SIZE || !context->frame ||
      !context->params)
    return PFX_INVALID_ARGUMENT;
  if (context->user_tag & TAG_PREPARE) {
    const pfx_status status = prepare(inst, context);
    if (status != PFX_OK) return status;
  }
  if (context->user_tag & TAG_SHADE) return shade(inst, context);
  return PFX_OK;
}

const char* report_json(void* self) {
  Instance* inst = static_cast<Instance*>(self);
  ListStats& stats = inst->list_stats;
  if (inst->gpu_stats) {
    // Waits for the list building: the counts are only known once it ran.
    const GpuLists::Stats gpu = inst->gpu_lists.read_stats();
    stats.entries = gpu.entries;
    stats.max_length = gpu.longest;
    stats.inconsistent = gpu.inconsistent;
    // Cannot happen while the count and fill phases agree; if it did, a list would be wrong.
    if (gpu.inconsistent)
      log_error(inst, std::to_string(gpu.inconsistent) + " light lists came out a different length than counted");
    inst->gpu_stats = false;
  }
  const uint64_t ssbo_bytes = inst->ring.bytes() + inst->gpu_lists.bytes();
  std::snprintf(inst->report, sizeof inst->report,
                "\"mode\": \"%s\", \"lights\": %u, \"lights_reaching\": %zu, \"lights_uploaded\": %zu, "
                "\"lists\": %llu, \"list_entries\": %llu, \"list_mean\": %.3f, \"list_max\": %u, "
                "\"list_bound\": %llu, \"index_capacity\": %llu, \"inconsistent_lists\": %u, "
                "\"list_readbacks\": %llu, \"ssbo_bytes\": %llu, \"ring_waits\": %llu",
                kModeNames[std::min(std::max(inst->settings.mode, 0), MODE_COUNT - 1)], inst->set.frame_lights,
                inst->set.lights.size(), inst->visible.size(), static_cast<unsigned long long>(stats.lists),
                static_cast<unsigned long long>(stats.entries), stats.mean_length(), stats.max_length,
                static_cast<unsigned long long>(inst->list_bound),
                static_cast<unsigned long long>(inst->index_capacity), stats.inconsistent,
                static_cast<unsigned long long>(inst->gpu_lists.readbacks()),
                static_cast<unsigned long long>(ssbo_bytes), static_cast<unsigned long long>(inst->ring.waits()));
  return inst->report;
}

}  // namespace

const pfx_effect_desc kTiledLightsEffect =
    pfx::desc::effect("tiledlights")
        .label("Tiled lights")
        .description(
            "Lights the G-buffer with many point lights (a 1 / (1 + d^2) falloff) and adds them to the "
            "colour; culled by brute force, sub-frustums culled on the CPU, GPU tiles or GPU clusters, all "
            "giving the same image.")
        .params(kParams, PARAM_COUNT)
        .create(create)
        .destroy(destroy)
        .declare(declare)
        .run_pass(run_pass)
        .report_json(report_json);

}  // namespace pfx_tiledlights
