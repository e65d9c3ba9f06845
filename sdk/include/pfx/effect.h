/* pfx C ABI v1 — effects: frame inputs, declared targets and passes, the effect factory.
 *
 * Lifetime of an instance (every call on the GL thread with the host's context current, except
 * where noted):
 *   create -> { declare -> run_pass x N -> [report] }* -> destroy
 * The host calls declare whenever the frame size, the available inputs or a parameter changed
 * (cheap: resizing is never a reload), then runs the declared passes in order. */
#ifndef PFX_EFFECT_H
#define PFX_EFFECT_H

#include "pfx/core.h"
#include "pfx/params.h"

#ifdef __cplusplus
extern "C" {
#endif

#define PFX_EFFECTS_FACTORY_ID "pfx.effects/1"

/* ---- Frame inputs, provided by the host by name ------------------------------------------------ */

/* Texture names a pass may read, besides the effect's own targets. */
#define PFX_INPUT_NAME_COLOR "color"       /* HDR linear scene colour, RGBA16F (see the promises below) */
#define PFX_INPUT_NAME_DEPTH "depth"       /* R32F or a depth texture; see pfx_depth_encoding */
#define PFX_INPUT_NAME_NORMAL "normal"     /* world-space unit normal in RGB */
#define PFX_INPUT_NAME_ALBEDO "albedo"     /* linear base colour in RGB */
#define PFX_INPUT_NAME_EMISSIVE "emissive" /* linear emitted radiance in RGB */
/* The target every effect writes its result to; it becomes the next effect's "color". */
#define PFX_OUTPUT_NAME "output"

enum {
  PFX_INPUT_COLOR = 1u << 0,
  PFX_INPUT_DEPTH = 1u << 1,
  PFX_INPUT_NORMAL = 1u << 2,
  PFX_INPUT_ALBEDO = 1u << 3,
  PFX_INPUT_EMISSIVE = 1u << 4,
  PFX_INPUT_LIGHTS = 1u << 5
};

typedef uint32_t pfx_depth_encoding;
enum {
  PFX_DEPTH_NONE = 0,
  /* Window-space depth of a standard OpenGL projection: 0 at near, 1 at far (far may be infinite). */
  PFX_DEPTH_HARDWARE = 1,
  /* Reversed Z with glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE): 1 at near, 0 at far (or infinity). */
  PFX_DEPTH_HARDWARE_REVERSED = 2,
  /* Linear view depth in metres: distance along the view axis, positive in front of the camera. */
  PFX_DEPTH_LINEAR = 3
};

/* Matrices are column-major, OpenGL convention: the camera looks down -Z in view space. */
typedef struct pfx_camera {
  float view[16];        /* world -> view */
  float projection[16];  /* view -> clip */
  float near_plane;      /* metres, > 0 */
  float far_plane;       /* metres, > near; +INFINITY for an infinite projection */
  float fovy;            /* vertical field of view, radians */
  float aspect;          /* width / height of the frame */
} pfx_camera;

typedef struct pfx_light {
  float position[3];  /* world space, metres */
  float range;        /* metres; <= 0 lets the effect derive it from colour and intensity */
  float color[3];     /* linear RGB */
  float intensity;    /* multiplies color */
} pfx_light;
#define PFX_LIGHT_MIN_SIZE PFX_STRUCT_SIZE_THROUGH(pfx_light, intensity)

typedef struct pfx_frame {
  uint32_t struct_size;
  uint32_t width, height;          /* the output resolution in pixels, >= 1 */
  uint32_t inputs;                 /* PFX_INPUT_* bits available this frame */
  pfx_depth_encoding depth_encoding;
  pfx_camera camera;
  double time_seconds;
  uint64_t frame_index;
  const pfx_light* lights;         /* light_count lights, each light_struct_size bytes apart */
  uint32_t light_count;
  uint32_t light_struct_size;      /* sizeof(pfx_light) of the host; later versions may grow it */
} pfx_frame;
#define PFX_FRAME_MIN_SIZE PFX_STRUCT_SIZE_THROUGH(pfx_frame, light_struct_size)

/* ---- Declared targets and passes ------------------------------------------------------------- */

typedef uint32_t pfx_format;
enum {
  PFX_FORMAT_RGBA16F = 0,
  PFX_FORMAT_RGBA32F = 1,
  PFX_FORMAT_R16F = 2,
  PFX_FORMAT_R32F = 3,
  PFX_FORMAT_RG16F = 4,
  PFX_FORMAT_RG32F = 5,
  PFX_FORMAT_RGBA8 = 6
};

typedef uint32_t pfx_size_mode;
enum {
  /* width = max(1, round(frame.width * scale_x)), likewise height. */
  PFX_SIZE_FRAME_SCALE = 0,
  /* width and height as given (>= 1). The effect sees the frame size in declare, so it can
   * compute exact pyramid sizes itself. */
  PFX_SIZE_FIXED = 1
};

typedef struct pfx_target_desc {
  uint32_t struct_size;
  const char* name;      /* unique within the effect; not a frame input name nor "output" */
  pfx_format format;
  pfx_size_mode size_mode;
  float scale_x, scale_y;
  uint32_t width, height;
} pfx_target_desc;
#define PFX_TARGET_DESC_MIN_SIZE PFX_STRUCT_SIZE_THROUGH(pfx_target_desc, height)

typedef uint32_t pfx_filter;
enum { PFX_FILTER_LINEAR = 0, PFX_FILTER_NEAREST = 1 };

typedef uint32_t pfx_wrap;
enum {
  PFX_WRAP_CLAMP_TO_EDGE = 0,
  PFX_WRAP_CLAMP_TO_BORDER = 1, /* border colour transparent black */
  PFX_WRAP_REPEAT = 2,
  PFX_WRAP_MIRRORED_REPEAT = 3
};

/* The most inputs one pass may name (texture units 0..15): every OpenGL 4.5 context has at least
 * 16 fragment and 16 compute texture units. A host refuses a pass naming more. */
#define PFX_MAX_PASS_INPUTS 16u

/* How a pass samples one texture. Sampling is per pass, not per target: a pyramid level may be
 * read clamped-to-border going down and clamped-to-edge going up. */
typedef struct pfx_pass_input {
  const char* name;  /* a frame input name or one of the effect's target names */
  pfx_filter filter;
  pfx_wrap wrap;
} pfx_pass_input;

typedef uint32_t pfx_pass_kind;
enum {
  /* The host binds the output framebuffer, viewport, blend state, an empty vertex array and the
   * inputs; the plugin binds its program and draws (a single triangle covering the viewport). */
  PFX_PASS_FULLSCREEN = 0,
  /* The host binds the inputs and (if any) the output framebuffer and viewport; the plugin issues
   * its own GL work, e.g. a compute dispatch writing the output texture as an image. */
  PFX_PASS_CUSTOM = 1
};

typedef uint32_t pfx_blend;
enum {
  PFX_BLEND_NONE = 0,
  PFX_BLEND_ADD = 1  /* glBlendFunc(GL_ONE, GL_ONE): the pass adds into what the target holds */
};

typedef uint32_t pfx_load;
enum {
  PFX_LOAD_DONT_CARE = 0, /* the pass overwrites every pixel it reads back: contents undefined */
  PFX_LOAD_CLEAR = 1,     /* the output is cleared to transparent black first */
  PFX_LOAD_KEEP = 2       /* the output keeps what an earlier pass of this frame wrote */
};

typedef struct pfx_pass_desc {
  uint32_t struct_size;
  const char* name;               /* for timings and messages: "down1" */
  pfx_pass_kind kind;
  const char* output;             /* a target name, PFX_OUTPUT_NAME, or NULL (custom pass only) */
  const pfx_pass_input* inputs;   /* bound to texture units 0 .. input_count-1, in order */
  uint32_t input_count;
  pfx_blend blend;
  pfx_load load;
  uint32_t user_tag;              /* the plugin's own number for the pass; passed back on run */
} pfx_pass_desc;
#define PFX_PASS_DESC_MIN_SIZE PFX_STRUCT_SIZE_THROUGH(pfx_pass_desc, user_tag)

/* Filled by declare. The host zeroes it and sets struct_size; the plugin points the arrays at its
 * own storage, which must stay valid until the next declare or destroy. No passes means the effect
 * is a no-op with these settings: the host runs nothing for it and allocates nothing. */
typedef struct pfx_declaration {
  uint32_t struct_size;
  const pfx_target_desc* targets;
  uint32_t target_count;
  const pfx_pass_desc* passes;
  uint32_t pass_count;
  uint32_t inputs;  /* PFX_INPUT_* bits these passes need beyond the textures they name (e.g. LIGHTS) */
  uint32_t flags;   /* PFX_DECLARATION_* promises about these passes; 0: none */ /* since 1.5 */
} pfx_declaration;
#define PFX_DECLARATION_MIN_SIZE PFX_STRUCT_SIZE_THROUGH(pfx_declaration, inputs)

/* Promises a declaration may make (pfx_declaration.flags, since 1.5).
 * SAMPLES_AND_DRAWS: every pass reads "color" only through the texture unit the host bound it to
 * (texture(), texelFetch(): never as an image, never by copying it), and writes "output" only by
 * drawing into the framebuffer the host bound (blending and clears included: never as an image,
 * never by copying into output_texture). The host may then hand "color" and "output" as 8-bit
 * textures of a display frame instead of RGBA16F: an sRGB one decodes to linear values when
 * sampled and encodes them when drawn into (the host enables GL_FRAMEBUFFER_SRGB for such a pass),
 * a plain RGBA8 one holds linear values; either way the pass computes in linear light as before,
 * and values outside [0, 1] written to "output" are clamped. The host may also bind a framebuffer
 * of its own as "output" (a window's back buffer): output_texture is then 0 and output_framebuffer
 * may be 0, the default framebuffer, which the pass draws into as bound. Without the promise the
 * host converts such a frame to RGBA16F before the effect and back after it. */
enum { PFX_DECLARATION_SAMPLES_AND_DRAWS = 1u << 0 };

/* DISPLAY_REFERRED (since 1.6; makes the promise of SAMPLES_AND_DRAWS too, and the host reads it so
 * whether or not that bit is set): the passes want "color" and write "output" display-referred, as
 * sRGB codes in [0, 1], the values an 8-bit display frame holds (a ReShade FX effect's back buffer),
 * not linear light. The host binds both as 8-bit textures read and written raw: "color" samples as
 * code / 255, and what a pass draws into "output" is stored as it is (no GL_FRAMEBUFFER_SRGB;
 * context->output_format PFX_FORMAT_RGBA8; output_texture 0 where the host bound a framebuffer of
 * its own). The pass may also sample "color" on units it binds itself, as long as it only samples
 * it; "color" and a texture "output" have immutable storage, so it may make views of them (an
 * sRGB view samples decoded). The chain converts only where a neighbour (or the host's frame)
 * holds linear light, and folds that into sampling an sRGB view or drawing into one where the
 * neighbour promised SAMPLES_AND_DRAWS; a run of display-referred effects over an 8-bit frame
 * converts nothing. A host older than 1.6 ignores the bit and hands linear light: check
 * pfx_host.abi_minor >= 6 first. */
enum { PFX_DECLARATION_DISPLAY_REFERRED = 1u << 1 };

/* One texture a pass reads, as bound by the host. */
typedef struct pfx_bound_texture {
  uint32_t texture;   /* GL texture name */
  uint32_t unit;      /* texture unit it is bound to (its index in the pass's inputs) */
  uint32_t width, height;
} pfx_bound_texture;

typedef struct pfx_pass_context {
  uint32_t struct_size;
  uint32_t pass_index;               /* index into the declared passes */
  uint32_t user_tag;
  const pfx_frame* frame;
  const pfx_value* params;           /* one per parameter descriptor */
  uint32_t output_texture;           /* 0 when the pass has no output */
  uint32_t output_framebuffer;
  uint32_t output_width, output_height;
  pfx_format output_format;
  const pfx_bound_texture* inputs;   /* input_count entries, in declared order */
  uint32_t input_count;
} pfx_pass_context;
#define PFX_PASS_CONTEXT_MIN_SIZE PFX_STRUCT_SIZE_THROUGH(pfx_pass_context, input_count)

/* ---- The effect ------------------------------------------------------------------------------ */

typedef struct pfx_effect_desc {
  uint32_t struct_size;
  const char* id;           /* unique across all loaded plugins: "bloom" */
  const char* label;
  const char* description;
  const pfx_param_desc* params;
  uint32_t param_count;
  /* Creates an instance: compile programs, make buffers. The host passed to init is given again
   * so the plugin can load GL through get_proc_address. */
  pfx_status (*create)(const pfx_host* host, void** out_instance);
  void (*destroy)(void* instance);
  /* Says which targets and passes this frame needs with these parameter values. No GL calls
   * required; must be cheap: it runs on every resize and parameter change. */
  pfx_status (*declare)(void* instance, const pfx_frame* frame, const pfx_value* params,
                        pfx_declaration* out);
  /* Runs one declared pass. On return the GL state the contract protects must be as on entry
   * (docs/sdk.md, "GL state"). */
  pfx_status (*run_pass)(void* instance, const pfx_pass_context* context);
  /* Optional (may be NULL): figures of the last frame as the members of a JSON object, without
   * braces, e.g. "\"lights_visible\": 120". Owned by the instance, valid until the next call. */
  const char* (*report_json)(void* instance);
  uint32_t flags;  /* PFX_EFFECT_* promises about every instance; 0: none */ /* since 1.9 */
} pfx_effect_desc;
#define PFX_EFFECT_DESC_MIN_SIZE PFX_STRUCT_SIZE_THROUGH(pfx_effect_desc, report_json)

/* Promises an effect may make (pfx_effect_desc.flags, since 1.9).
 * COLOR_ONLY: offered a frame of colour alone (pfx_frame.inputs PFX_INPUT_COLOR, no depth), every
 * declaration of this effect, whatever its parameter values, names no input but "color" and its
 * own targets and sets no PFX_INPUT_* bit. A host that would make an instance only to learn this
 * (an adapter choosing which effects run on video frames and applications' pictures) may trust the
 * bit and make none: for a plugin that compiles programs in create, over a collection of many
 * effects, that is the difference between starting at once and compiling them all. pfx-validate
 * checks the promise. An effect that reads more where a frame offers it (depth) may still make it. */
enum { PFX_EFFECT_COLOR_ONLY = 1u << 0 };

/* What get_factory(PFX_EFFECTS_FACTORY_ID) returns. */
typedef struct pfx_effect_factory {
  uint32_t struct_size;
  uint32_t (*effect_count)(void);
  const pfx_effect_desc* (*get_effect)(uint32_t index);
} pfx_effect_factory;
#define PFX_EFFECT_FACTORY_MIN_SIZE PFX_STRUCT_SIZE_THROUGH(pfx_effect_factory, get_effect)

#ifdef __cplusplus
}
#endif
#endif /* PFX_EFFECT_H */
