/* c_host.c: a foreign host in plain C99 that runs the fixture plugins without libpfxhost.
 *
 * It proves that the ABI in sdk/include/pfx/ and docs/sdk.md are enough on their own: this file
 * makes its own EGL context, implements pfx_host, loads the plugin with dlopen, allocates the
 * declared targets and runs the declared passes as docs/sdk.md §1.4-1.7 say (arrays stepped by
 * struct_size, samplers with compare mode NONE, pending GL errors cleared first, at most
 * PFX_MAX_PASS_INPUTS inputs), then checks the pixels. With the minimal plugin it checks gain and
 * boxblur; with --probe, the probe fixture's effects, which show the host's side of the contract.
 *
 * usage: pfx_c_host MINIMAL.so | --probe PROBE.so   (exit 0 when every check passes, 1 otherwise)
 */
#define _POSIX_C_SOURCE 200809L

#include <dlfcn.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <glad/gl.h>
#include <pfx/pfx.h>

/* Odd sizes on purpose: half-size targets must round, not truncate to a wrong size. */
enum { WIDTH = 7, HEIGHT = 5, MAX_TARGETS = 8, MAX_INPUTS = PFX_MAX_PASS_INPUTS };

static int g_failures;

static void fail(const char* format, ...) {
  va_list args;
  va_start(args, format);
  fputs("c_host: FAIL: ", stderr);
  vfprintf(stderr, format, args);
  fputc('\n', stderr);
  va_end(args);
  ++g_failures;
}

static void die(const char* format, ...) {
  va_list args;
  va_start(args, format);
  fputs("c_host: FATAL: ", stderr);
  vfprintf(stderr, format, args);
  fputc('\n', stderr);
  va_end(args);
  exit(1);
}

/* ---- pfx_host ------------------------------------------------------------------------------- */

typedef struct host_state {
  int errors_logged; /* a plugin error message is a failure unless a check expects it */
} host_state;

static void host_log(void* host_data, pfx_log_level level, const char* message) {
  static const char* const names[] = {"debug", "info", "warning", "error"};
  host_state* state = (host_state*)host_data;
  if (level >= PFX_LOG_ERROR) ++state->errors_logged;
  fprintf(stderr, "plugin %s: %s\n", level >= 0 && level <= 3 ? names[level] : "?", message);
}

static pfx_gl_proc host_get_proc_address(void* host_data, const char* name) {
  (void)host_data;
  return (pfx_gl_proc)eglGetProcAddress(name);
}

static GLADapiproc glad_loader(void* userptr, const char* name) {
  (void)userptr;
  return (GLADapiproc)eglGetProcAddress(name);
}

static void create_context(void) {
  const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                               4,
                               EGL_CONTEXT_MINOR_VERSION,
                               5,
                               EGL_CONTEXT_OPENGL_PROFILE_MASK,
                               EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                               EGL_NONE};
  const char* extensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display =
      (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
  EGLDisplay display;
  EGLContext context;
  if (!extensions || !strstr(extensions, "EGL_MESA_platform_surfaceless") || !get_platform_display)
    die("EGL has no surfaceless platform (EGL_MESA_platform_surfaceless)");
  display = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
  if (display == EGL_NO_DISPLAY || !eglInitialize(display, NULL, NULL))
    die("cannot open the EGL surfaceless display (EGL error 0x%04x)", eglGetError());
  if (!eglBindAPI(EGL_OPENGL_API)) die("eglBindAPI(EGL_OPENGL_API) failed");
  context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
  if (context == EGL_NO_CONTEXT)
    die("no OpenGL 4.5 core context (EGL error 0x%04x)", eglGetError());
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context))
    die("eglMakeCurrent failed");
  if (!gladLoadGLUserPtr(glad_loader, NULL)) die("cannot load the GL 4.5 entry points");
}

/* ---- A small pass runner: what a host does with a declaration ------------------------------- */

typedef struct texture {
  GLuint texture, framebuffer;
  uint32_t width, height;
  pfx_format format;
} texture;

static GLenum gl_internal_format(pfx_format format) {
  static const GLenum formats[] = {GL_RGBA16F, GL_RGBA32F, GL_R16F, GL_R32F,
                                   GL_RG16F,   GL_RG32F,   GL_RGBA8};
  if (format >= sizeof formats / sizeof formats[0]) die("unknown pfx_format %u", (unsigned)format);
  return formats[format];
}

static texture make_texture(pfx_format format, uint32_t width, uint32_t height, const float* rgba) {
  texture t;
  t.width = width;
  t.height = height;
  t.format = format;
  glCreateTextures(GL_TEXTURE_2D, 1, &t.texture);
  glTextureStorage2D(t.texture, 1, gl_internal_format(format), (GLsizei)width, (GLsizei)height);
  if (rgba)
    glTextureSubImage2D(t.texture, 0, 0, 0, (GLsizei)width, (GLsizei)height, GL_RGBA, GL_FLOAT,
                        rgba);
  glCreateFramebuffers(1, &t.framebuffer);
  glNamedFramebufferTexture(t.framebuffer, GL_COLOR_ATTACHMENT0, t.texture, 0);
  if (glCheckNamedFramebufferStatus(t.framebuffer, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    die("framebuffer of a %ux%u target is incomplete", (unsigned)width, (unsigned)height);
  return t;
}

static void free_texture(texture* t) {
  glDeleteFramebuffers(1, &t->framebuffer);
  glDeleteTextures(1, &t->texture);
}

static uint32_t scaled_size(uint32_t frame_size, float scale) {
  long size = lroundf((float)frame_size * scale);
  return size < 1 ? 1u : (uint32_t)size;
}

/* The state a plugin must leave as it found it (the GL state contract). */
typedef struct protected_state {
  GLint framebuffer, vertex_array, viewport[4];
  GLboolean blend, depth_test, scissor_test, cull_face, stencil_test;
} protected_state;

static protected_state read_protected_state(void) {
  protected_state s;
  memset(&s, 0, sizeof s); /* compared with memcmp: the padding must be zero too */
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &s.framebuffer);
  glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &s.vertex_array);
  glGetIntegerv(GL_VIEWPORT, s.viewport);
  s.blend = glIsEnabled(GL_BLEND);
  s.depth_test = glIsEnabled(GL_DEPTH_TEST);
  s.scissor_test = glIsEnabled(GL_SCISSOR_TEST);
  s.cull_face = glIsEnabled(GL_CULL_FACE);
  s.stencil_test = glIsEnabled(GL_STENCIL_TEST);
  return s;
}

/* The frame's textures: colour in, depth (NULL when the frame has none), the effect's output. */
typedef struct frame_textures {
  const texture *color, *depth, *output;
} frame_textures;

/* Declares, then runs every declared pass from the colour into the output. Returns the pass count. */
static uint32_t run_effect(const pfx_effect_desc* effect, void* instance, const pfx_frame* frame,
                           const pfx_value* params, const frame_textures* io) {
  const texture* output = io->output;
  pfx_declaration declaration;
  texture targets[MAX_TARGETS];
  GLuint samplers[MAX_INPUTS], vertex_array;
  uint32_t i, p;
  pfx_status status;

  memset(&declaration, 0, sizeof declaration);
  declaration.struct_size = sizeof declaration;
  status = effect->declare(instance, frame, params, &declaration);
  if (status != PFX_OK) die("%s: declare returned %d", effect->id, (int)status);
  if (declaration.target_count > MAX_TARGETS) die("%s: too many targets", effect->id);
  for (i = 0; i < declaration.target_count; ++i) {
    const pfx_target_desc* d = pfx_at(pfx_target_desc, declaration.targets, i);
    uint32_t w = d->size_mode == PFX_SIZE_FIXED ? d->width : scaled_size(frame->width, d->scale_x);
    uint32_t h =
        d->size_mode == PFX_SIZE_FIXED ? d->height : scaled_size(frame->height, d->scale_y);
    targets[i] = make_texture(d->format, w, h, NULL);
  }
  glCreateVertexArrays(1, &vertex_array);
  /* Sampler objects start with compare mode NONE: a depth input then reads as depth, whatever the
   * compare mode of the texture itself (an engine's shadow-map setup). */
  glCreateSamplers(MAX_INPUTS, samplers);
  /* Errors the host (or its engine) made before are not the plugin's: clear them, so the check
   * after each pass blames only that pass. */
  while (glGetError() != GL_NO_ERROR) {
  }
  /* The once-per-frame state of docs/sdk.md §1.5: this context holds GL's initial values, so only
   * dithering (on in a fresh context) differs. */
  glDisable(GL_DITHER);

  for (p = 0; p < declaration.pass_count; ++p) {
    const pfx_pass_desc* pass = pfx_at(pfx_pass_desc, declaration.passes, p);
    const texture* out = NULL;
    pfx_bound_texture bound[MAX_INPUTS];
    pfx_pass_context context;
    protected_state before, after;
    GLenum error;

    if (pass->output && strcmp(pass->output, PFX_OUTPUT_NAME) == 0) out = output;
    for (i = 0; pass->output && !out && i < declaration.target_count; ++i)
      if (strcmp(pass->output, pfx_at(pfx_target_desc, declaration.targets, i)->name) == 0) out = &targets[i];
    if (pass->output && !out)
      die("%s/%s: unknown output \"%s\"", effect->id, pass->name, pass->output);
    if (pass->input_count > PFX_MAX_PASS_INPUTS) die("%s/%s: more inputs than a pass may name", effect->id, pass->name);

    for (i = 0; i < pass->input_count; ++i) {
      static const GLenum wraps[] = {GL_CLAMP_TO_EDGE, GL_CLAMP_TO_BORDER, GL_REPEAT,
                                     GL_MIRRORED_REPEAT};
      const pfx_pass_input* in = &pass->inputs[i];
      const texture* source = NULL;
      uint32_t t;
      GLenum filter = in->filter == PFX_FILTER_NEAREST ? GL_NEAREST : GL_LINEAR;
      if (strcmp(in->name, PFX_INPUT_NAME_COLOR) == 0) source = io->color;
      if (strcmp(in->name, PFX_INPUT_NAME_DEPTH) == 0) source = io->depth;
      if (strcmp(in->name, PFX_OUTPUT_NAME) == 0) source = output;
      for (t = 0; !source && t < declaration.target_count; ++t)
        if (strcmp(in->name, pfx_at(pfx_target_desc, declaration.targets, t)->name) == 0) source = &targets[t];
      if (!source) die("%s/%s: unknown input \"%s\"", effect->id, pass->name, in->name);
      if (in->wrap > PFX_WRAP_MIRRORED_REPEAT) die("%s/%s: unknown wrap", effect->id, pass->name);
      glSamplerParameteri(samplers[i], GL_TEXTURE_MIN_FILTER, (GLint)filter);
      glSamplerParameteri(samplers[i], GL_TEXTURE_MAG_FILTER, (GLint)filter);
      glSamplerParameteri(samplers[i], GL_TEXTURE_WRAP_S, (GLint)wraps[in->wrap]);
      glSamplerParameteri(samplers[i], GL_TEXTURE_WRAP_T, (GLint)wraps[in->wrap]);
      glBindTextureUnit(i, source->texture);
      glBindSampler(i, samplers[i]);
      bound[i].texture = source->texture;
      bound[i].unit = i;
      bound[i].width = source->width;
      bound[i].height = source->height;
    }

    glBindVertexArray(vertex_array);
    glActiveTexture(GL_TEXTURE0);
    glBindFramebuffer(GL_FRAMEBUFFER, out ? out->framebuffer : 0); /* draw and read */
    if (out) glViewport(0, 0, (GLsizei)out->width, (GLsizei)out->height);
    if (pass->blend == PFX_BLEND_ADD) {
      glEnable(GL_BLEND);
      glBlendFunc(GL_ONE, GL_ONE);
    }
    if (out && pass->load == PFX_LOAD_CLEAR) {
      static const float zero[4] = {0, 0, 0, 0};
      glClearBufferfv(GL_COLOR, 0, zero);
    }

    memset(&context, 0, sizeof context);
    context.struct_size = sizeof context;
    context.pass_index = p;
    context.user_tag = pass->user_tag;
    context.frame = frame;
    context.params = params;
    context.output_texture = out ? out->texture : 0;
    context.output_framebuffer = out ? out->framebuffer : 0;
    context.output_width = out ? out->width : 0;
    context.output_height = out ? out->height : 0;
    context.output_format = out ? out->format : PFX_FORMAT_RGBA16F;
    context.inputs = bound;
    context.input_count = pass->input_count;

    before = read_protected_state();
    status = effect->run_pass(instance, &context);
    after = read_protected_state();
    if (status != PFX_OK) fail("%s/%s: run_pass returned %d", effect->id, pass->name, (int)status);
    if (memcmp(&before, &after, sizeof before) != 0)
      fail("%s/%s: the pass changed protected GL state", effect->id, pass->name);
    while ((error = glGetError()) != GL_NO_ERROR)
      fail("%s/%s: GL error 0x%04x", effect->id, pass->name, (unsigned)error);

    glDisable(GL_BLEND);
    for (i = 0; i < pass->input_count; ++i) glBindSampler(i, 0);
  }

  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glBindVertexArray(0);
  glDeleteVertexArrays(1, &vertex_array);
  glDeleteSamplers(MAX_INPUTS, samplers);
  for (i = 0; i < declaration.target_count; ++i) free_texture(&targets[i]);
  return declaration.pass_count;
}

/* ---- The checks ----------------------------------------------------------------------------- */

static const pfx_effect_desc* find_effect(const pfx_effect_factory* factory, const char* id) {
  uint32_t i;
  for (i = 0; i < factory->effect_count(); ++i) {
    const pfx_effect_desc* effect = factory->get_effect(i);
    if (effect && strcmp(effect->id, id) == 0) return effect;
  }
  die("the plugin has no effect \"%s\"", id);
  return NULL;
}

static uint32_t find_param(const pfx_effect_desc* effect, const char* id) {
  uint32_t i;
  for (i = 0; i < effect->param_count; ++i)
    if (strcmp(pfx_at(pfx_param_desc, effect->params, i)->id, id) == 0) return i;
  die("effect \"%s\" has no parameter \"%s\"", effect->id, id);
  return 0;
}

/* Every parameter at its default, as a host starts an instance. */
static pfx_value* default_params(const pfx_effect_desc* effect) {
  pfx_value* params = (pfx_value*)calloc(effect->param_count + 1u, sizeof *params);
  uint32_t i;
  if (!params) die("out of memory");
  for (i = 0; i < effect->param_count; ++i) params[i] = pfx_at(pfx_param_desc, effect->params, i)->default_value;
  return params;
}

/* The output is RGBA16F: allow half precision's rounding (2^-11 relative) with some margin. */
static void check_pixels(const char* what, const texture* output, const float* expected) {
  float actual[WIDTH * HEIGHT * 4];
  int i, reported = 0;
  glGetTextureImage(output->texture, 0, GL_RGBA, GL_FLOAT, (GLsizei)sizeof actual, actual);
  for (i = 0; i < WIDTH * HEIGHT * 4; ++i) {
    double tolerance = fabs(expected[i]) / 1024.0 + 1e-4;
    if (!(fabs(actual[i] - expected[i]) <= tolerance) && reported++ < 5)
      fail("%s: pixel (%d,%d) channel %d is %.6f, expected %.6f", what, (i / 4) % WIDTH,
           i / 4 / WIDTH, i % 4, actual[i], expected[i]);
  }
}

/* ---- Loading: what every host does with a library ------------------------------------------- */

typedef struct loaded_plugin {
  void* library;
  const pfx_entry* entry;
  const pfx_effect_factory* factory;
} loaded_plugin;

static host_state g_state;
static pfx_host g_host;

static loaded_plugin load_plugin(const char* path, const char* expected_id) {
  loaded_plugin plugin;
  pfx_get_entry_fn get_entry;
  void* symbol;
  plugin.library = dlopen(path, RTLD_NOW | RTLD_LOCAL);
  if (!plugin.library) die("dlopen: %s", dlerror());
  symbol = dlsym(plugin.library, PFX_ENTRY_SYMBOL);
  if (!symbol) die("%s has no %s", path, PFX_ENTRY_SYMBOL);
  /* ISO C has no cast from an object pointer to a function pointer; POSIX guarantees the bits. */
  memcpy(&get_entry, &symbol, sizeof get_entry);
  plugin.entry = get_entry();
  /* The growth rule (pfx/core.h): accept any struct from its first published size on. */
  if (!plugin.entry || plugin.entry->struct_size < PFX_ENTRY_MIN_SIZE || plugin.entry->abi_major != PFX_ABI_MAJOR)
    die("bad entry struct (abi_major %u)", plugin.entry ? (unsigned)plugin.entry->abi_major : 0u);
  if (strcmp(plugin.entry->id, expected_id) != 0) fail("plugin id is \"%s\"", plugin.entry->id);

  memset(&g_host, 0, sizeof g_host);
  g_host.struct_size = sizeof g_host;
  g_host.abi_major = PFX_ABI_MAJOR;
  g_host.abi_minor = PFX_ABI_MINOR;
  g_host.host_name = "pfx c_host test";
  g_host.host_data = &g_state;
  g_host.log = host_log;
  g_host.get_proc_address = host_get_proc_address;
#if PFX_ABI_MINOR == 99
  g_host.future_count = 0xdeadbeefu;
  g_host.future_name = "a field of ABI 1.99";
#endif
  if (plugin.entry->init(&g_host) != PFX_OK || plugin.entry->init(&g_host) != PFX_OK)
    die("init failed (twice is allowed)");
  if (plugin.entry->get_factory("nope") != NULL) fail("get_factory(\"nope\") is not NULL");
  if (plugin.entry->get_factory(PFX_IMPORTERS_FACTORY_ID) != NULL) fail("get_factory(importers) is not NULL");
  plugin.factory = (const pfx_effect_factory*)plugin.entry->get_factory(PFX_EFFECTS_FACTORY_ID);
  if (!plugin.factory || plugin.factory->struct_size < PFX_EFFECT_FACTORY_MIN_SIZE) die("no effects factory");
  if (plugin.factory->get_effect(plugin.factory->effect_count()) != NULL) fail("get_effect(past the end) is not NULL");
  return plugin;
}

static void unload_plugin(loaded_plugin* plugin) {
  plugin->entry->deinit();
  if (g_state.errors_logged) fail("the plugin logged %d error(s)", g_state.errors_logged);
  dlclose(plugin->library);
}

static pfx_frame make_frame(uint32_t inputs) {
  pfx_frame frame;
  memset(&frame, 0, sizeof frame);
  frame.struct_size = sizeof frame;
#if PFX_ABI_MINOR == 99
  /* Built against the future fixture headers: fill what a later host would, which no plugin of
   * an earlier version may read. */
  frame.future_count = 0xdeadbeefu;
  frame.future_name = "a field of ABI 1.99";
#endif
  frame.width = WIDTH;
  frame.height = HEIGHT;
  frame.inputs = inputs;
  frame.light_struct_size = sizeof(pfx_light);
  return frame;
}

/* get_proc_address of a context that has nothing: a plugin must refuse to create (not crash). */
static pfx_gl_proc no_gl_proc(void* host_data, const char* name) {
  (void)host_data, (void)name;
  return NULL;
}

/* ---- The minimal plugin: gain and boxblur --------------------------------------------------- */

static void check_minimal(const char* path) {
  loaded_plugin plugin = load_plugin(path, "org.pfx.test.minimal");
  pfx_frame frame = make_frame(PFX_INPUT_COLOR);
  const pfx_effect_desc *gain, *blur;
  pfx_value *gain_params, *blur_params;
  uint32_t gain_index, channels_index, radius_index;
  void* instance = NULL;
  float input[WIDTH * HEIGHT * 4], expected[WIDTH * HEIGHT * 4];
  texture color, output;
  frame_textures io;
  pfx_host empty_gl;
  int x, y, i;

  gain = find_effect(plugin.factory, "gain");
  gain_index = find_param(gain, "gain");
  channels_index = find_param(gain, "channels");
  if (pfx_at(pfx_param_desc, gain->params, channels_index)->type != PFX_PARAM_ENUM ||
      pfx_at(pfx_param_desc, gain->params, channels_index)->item_count < 2)
    fail("gain.channels is not an enum with two items");
  gain_params = default_params(gain);

  /* Values exact in half precision, negative ones included: a gain must not clamp. */
  for (y = 0; y < HEIGHT; ++y)
    for (x = 0; x < WIDTH; ++x) {
      float* px = &input[(y * WIDTH + x) * 4];
      px[0] = 0.125f * (float)(x + 1);
      px[1] = 0.25f * (float)(y + 1);
      px[2] = -0.5f + 0.0625f * (float)(x * y);
      px[3] = 0.25f + 0.125f * (float)(x % 3);
    }
  color = make_texture(PFX_FORMAT_RGBA32F, WIDTH, HEIGHT, input);
  output = make_texture(PFX_FORMAT_RGBA16F, WIDTH, HEIGHT, NULL);
  io.color = &color, io.depth = NULL, io.output = &output;

  /* get_proc_address may return stubs for names a context lacks (Mesa does), or NULL: a plugin
   * checks the version it got. With nothing at all it must refuse, with PFX_GL_ERROR. */
  empty_gl = g_host;
  empty_gl.get_proc_address = no_gl_proc;
  if (gain->create(&empty_gl, &instance) != PFX_GL_ERROR) fail("gain: create without GL is not PFX_GL_ERROR");
  g_state.errors_logged = 0; /* that refusal was logged as an error, as it should */
  instance = NULL;

  if (gain->create(&g_host, &instance) != PFX_OK || !instance) die("gain: create failed");
  gain_params[gain_index].v[0] = 2.5;
  if (run_effect(gain, instance, &frame, gain_params, &io) != 1) fail("gain 2.5: not one pass");
  for (i = 0; i < WIDTH * HEIGHT * 4; ++i) expected[i] = i % 4 == 3 ? input[i] : input[i] * 2.5f;
  check_pixels("gain 2.5", &output, expected);

  gain_params[gain_index].v[0] = 2.0;
  gain_params[channels_index].v[0] = 1.0; /* "luma" */
  if (run_effect(gain, instance, &frame, gain_params, &io) != 1) fail("gain luma: not one pass");
  for (i = 0; i < WIDTH * HEIGHT * 4; i += 4) {
    float luma = 0.2126f * input[i] + 0.7152f * input[i + 1] + 0.0722f * input[i + 2];
    expected[i] = expected[i + 1] = expected[i + 2] = 2.0f * luma;
    expected[i + 3] = input[i + 3];
  }
  check_pixels("gain 2 luma", &output, expected);

  gain_params[gain_index].v[0] = 1.0;
  gain_params[channels_index].v[0] = 0.0;
  if (run_effect(gain, instance, &frame, gain_params, &io) != 0) fail("gain 1: the no-op must declare zero passes");
  gain->destroy(instance);

  /* boxblur: three passes through two half-size targets. A constant image stays constant. */
  blur = find_effect(plugin.factory, "boxblur");
  radius_index = find_param(blur, "radius");
  blur_params = default_params(blur);
  for (i = 0; i < WIDTH * HEIGHT * 4; ++i) input[i] = expected[i] = (float)(i % 4 + 1) * 0.25f;
  glTextureSubImage2D(color.texture, 0, 0, 0, WIDTH, HEIGHT, GL_RGBA, GL_FLOAT, input);
  if (blur->create(&g_host, &instance) != PFX_OK || !instance) die("boxblur: create failed");
  blur_params[radius_index].v[0] = 1.5;
  if (run_effect(blur, instance, &frame, blur_params, &io) != 3) fail("boxblur: not three passes");
  check_pixels("boxblur of a constant image", &output, expected);
  blur_params[radius_index].v[0] = 0.0;
  if (run_effect(blur, instance, &frame, blur_params, &io) != 0)
    fail("boxblur radius 0: the no-op must declare zero passes");
  blur->destroy(instance);

  unload_plugin(&plugin);
  free_texture(&color);
  free_texture(&output);
  free(gain_params);
  free(blur_params);
  if (!g_failures) printf("c_host: minimal plugin OK (gain, gain luma, no-op, boxblur, no GL refused)\n");
}

/* ---- The probe plugin: the host's side of the contract, in pixels ---------------------------- */

/* Runs one probe effect over `io` with its default parameters (and `count` for "inputs"). */
static void run_probe(const loaded_plugin* plugin, const char* id, const pfx_frame* frame, const frame_textures* io,
                      double count) {
  const pfx_effect_desc* effect = find_effect(plugin->factory, id);
  pfx_value* params = default_params(effect);
  void* instance = NULL;
  if (effect->param_count) params[0].v[0] = count;
  if (effect->create(&g_host, &instance) != PFX_OK || !instance) die("%s: create failed", id);
  if (run_effect(effect, instance, frame, params, io) == 0) fail("%s: no pass ran", id);
  effect->destroy(instance);
  free(params);
}

static void check_probe(const char* path) {
  loaded_plugin plugin = load_plugin(path, "org.pfx.test.probe");
  pfx_frame frame = make_frame(PFX_INPUT_COLOR | PFX_INPUT_DEPTH);
  float input[WIDTH * HEIGHT * 4], expected[WIDTH * HEIGHT * 4], depth_values[WIDTH * HEIGHT];
  texture color = make_texture(PFX_FORMAT_RGBA32F, WIDTH, HEIGHT, NULL);
  texture output = make_texture(PFX_FORMAT_RGBA16F, WIDTH, HEIGHT, NULL);
  texture depth;
  frame_textures io;
  int x, y, i;

  for (i = 0; i < WIDTH * HEIGHT * 4; ++i) input[i] = (float)(i % 13) * 0.125f - 0.5f;
  glTextureSubImage2D(color.texture, 0, 0, 0, WIDTH, HEIGHT, GL_RGBA, GL_FLOAT, input);
  /* An engine's depth buffer, its texture set up for shadow lookups: the host's sampler object
   * (compare mode NONE, as every pfx host binds) must win, or texture() returns comparisons. */
  for (y = 0; y < HEIGHT; ++y)
    for (x = 0; x < WIDTH; ++x) depth_values[y * WIDTH + x] = (float)(y * WIDTH + x) / (WIDTH * HEIGHT);
  glCreateTextures(GL_TEXTURE_2D, 1, &depth.texture);
  glTextureStorage2D(depth.texture, 1, GL_DEPTH_COMPONENT32F, WIDTH, HEIGHT);
  glTextureSubImage2D(depth.texture, 0, 0, 0, WIDTH, HEIGHT, GL_DEPTH_COMPONENT, GL_FLOAT, depth_values);
  glTextureParameteri(depth.texture, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  depth.framebuffer = 0, depth.width = WIDTH, depth.height = HEIGHT, depth.format = PFX_FORMAT_R32F;
  io.color = &color, io.depth = &depth, io.output = &output;

  /* Orientation: row 0 of every texture is the bottom row; gl_FragCoord and a full-screen
   * triangle's v_uv both start at the bottom-left. */
  run_probe(&plugin, "coords", &frame, &io, 0);
  for (y = 0; y < HEIGHT; ++y)
    for (x = 0; x < WIDTH; ++x) {
      float* e = &expected[(y * WIDTH + x) * 4];
      e[0] = (float)x + 0.5f, e[1] = (float)y + 0.5f;
      e[2] = ((float)x + 0.5f) / WIDTH, e[3] = ((float)y + 0.5f) / HEIGHT;
    }
  check_pixels("coords (row 0 is the bottom row)", &output, expected);

  /* PFX_SIZE_FRAME_SCALE: max(1, round(frame * scale)), halves away from zero: 7/3 -> 2, 5/2 -> 3. */
  run_probe(&plugin, "sizes", &frame, &io, 0);
  for (i = 0; i < WIDTH * HEIGHT * 4; i += 4)
    expected[i] = 2, expected[i + 1] = 3, expected[i + 2] = WIDTH, expected[i + 3] = HEIGHT;
  check_pixels("sizes (a target of scale 1/3 x 1/2 of 7x5)", &output, expected);

  run_probe(&plugin, "depth", &frame, &io, 0);
  for (i = 0; i < WIDTH * HEIGHT; ++i)
    expected[4 * i] = depth_values[i], expected[4 * i + 1] = 0, expected[4 * i + 2] = 0, expected[4 * i + 3] = 1;
  check_pixels("depth sampled through the host's sampler", &output, expected);

  /* A custom pass: image store, barrier, then two full-screen passes reading it back. */
  run_probe(&plugin, "custom", &frame, &io, 0);
  for (i = 0; i < WIDTH * HEIGHT * 4; ++i) expected[i] = 2.0f * input[i] + 1.0f;
  check_pixels("custom pass (2 * colour stored as an image, + 1 by full-screen passes)", &output, expected);

  run_probe(&plugin, "inputs", &frame, &io, PFX_MAX_PASS_INPUTS);
  for (i = 0; i < WIDTH * HEIGHT * 4; ++i) expected[i] = (float)PFX_MAX_PASS_INPUTS * input[i];
  check_pixels("a pass naming PFX_MAX_PASS_INPUTS inputs", &output, expected);

  unload_plugin(&plugin);
  free_texture(&color);
  free_texture(&output);
  glDeleteTextures(1, &depth.texture);
  if (!g_failures) printf("c_host: probe plugin OK (orientation, target sizes, depth sampler, custom pass, 16 inputs)\n");
}

int main(int argc, char** argv) {
  const int probe = argc == 3 && strcmp(argv[1], "--probe") == 0;
  if (argc != 2 && !probe) die("usage: %s MINIMAL.so | --probe PROBE.so", argv[0]);
  create_context();
  if (probe) check_probe(argv[2]);
  else check_minimal(argv[1]);
  if (g_failures) {
    fprintf(stderr, "c_host: %d check(s) failed\n", g_failures);
    return 1;
  }
  return 0;
}
