#include "pfx_filter.hpp"

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "adapter_plugins.hpp"
#include "chain_settings.hpp"
#include "filter_gl.hpp"

namespace {

enum Property { PROP_0, PROP_CHAIN, PROP_SET, PROP_TRANSFER, PROP_PRESET };

// Both pads: GL textures of 8-bit RGBA or 10-bit RGB with 2-bit alpha, rows as GStreamer keeps
// them (top first).
#define PFX_FILTER_CAPS                                                                                   \
  "video/x-raw(" GST_CAPS_FEATURE_MEMORY_GL_MEMORY "), format = (string) { RGBA, RGB10A2_LE }, "          \
  "width = " GST_VIDEO_SIZE_RANGE ", height = " GST_VIDEO_SIZE_RANGE ", framerate = " GST_VIDEO_FPS_RANGE \
  ", texture-target = (string) 2D"

GstStaticPadTemplate sink_template =
    GST_STATIC_PAD_TEMPLATE("sink", GST_PAD_SINK, GST_PAD_ALWAYS, GST_STATIC_CAPS(PFX_FILTER_CAPS));
GstStaticPadTemplate src_template =
    GST_STATIC_PAD_TEMPLATE("src", GST_PAD_SRC, GST_PAD_ALWAYS, GST_STATIC_CAPS(PFX_FILTER_CAPS));

// The element's C++ side: the settings (set from any thread, under the object lock) and, on the
// GL thread, FilterGl.
struct State {
  pfx::adapters::ChainSettings settings;
  uint64_t revision = 1;
  double time_seconds = 0;  // of the buffer being filtered
  std::unique_ptr<pfx::gst::FilterGl> gl;
  std::string said;  // the last warning posted, so each is posted once
};

}  // namespace

struct _GstPfxFilter {
  GstGLFilter parent;
  State* state;
};

G_DEFINE_TYPE(GstPfxFilter, gst_pfx_filter, GST_TYPE_GL_FILTER)

namespace {

std::string* setting(State* state, guint property) {
  switch (property) {
    case PROP_CHAIN: return &state->settings.chain;
    case PROP_SET: return &state->settings.set;
    case PROP_TRANSFER: return &state->settings.transfer;
    case PROP_PRESET: return &state->settings.preset;
    default: return nullptr;
  }
}

void set_property(GObject* object, guint property, const GValue* value, GParamSpec* spec) {
  auto* self = GST_PFX_FILTER(object);
  std::string* target = setting(self->state, property);
  if (!target) {
    G_OBJECT_WARN_INVALID_PROPERTY_ID(object, property, spec);
    return;
  }
  const char* text = g_value_get_string(value);
  GST_OBJECT_LOCK(self);
  *target = text ? text : "";
  ++self->state->revision;
  GST_OBJECT_UNLOCK(self);
}

void get_property(GObject* object, guint property, GValue* value, GParamSpec* spec) {
  auto* self = GST_PFX_FILTER(object);
  std::string* source = setting(self->state, property);
  if (!source) {
    G_OBJECT_WARN_INVALID_PROPERTY_ID(object, property, spec);
    return;
  }
  GST_OBJECT_LOCK(self);
  g_value_set_string(value, source->c_str());
  GST_OBJECT_UNLOCK(self);
}

void finalize(GObject* object) {
  delete GST_PFX_FILTER(object)->state;
  G_OBJECT_CLASS(gst_pfx_filter_parent_class)->finalize(object);
}

// The reason GStreamer's context cannot run pfx, or "" when it can (desktop OpenGL 4.5).
std::string context_problem(GstGLContext* context) {
  const GstGLAPI api = gst_gl_context_get_gl_api(context);
  gint major = 0, minor = 0;
  gst_gl_context_get_gl_version(context, &major, &minor);
  const std::string version = std::to_string(major) + "." + std::to_string(minor);
  if (!(api & (GST_GL_API_OPENGL | GST_GL_API_OPENGL3)))
    return "GStreamer's GL context is OpenGL ES " + version + ": pfx needs desktop OpenGL 4.5 (GST_GL_API picks the API)";
  if (major * 10 + minor < 45) return "GStreamer's GL context is OpenGL " + version + ": pfx needs OpenGL 4.5";
  return "";
}

gboolean gl_start(GstGLBaseFilter* base) {
  auto* self = GST_PFX_FILTER(base);
  const std::string problem = context_problem(base->context);
  if (!problem.empty()) {
    GST_ELEMENT_ERROR(self, RESOURCE, SETTINGS, ("pfxfilter: %s", problem.c_str()),
                      ("the element refuses contexts it cannot run effects on"));
    return FALSE;
  }
  GstGLContext* context = base->context;
  std::vector<std::string> messages;
  std::string error;
  self->state->gl = pfx::gst::FilterGl::start(
      [context](const char* name) {
        return reinterpret_cast<pfx_gl_proc>(gst_gl_context_get_proc_address(context, name));
      },
      pfx::adapters::library_path_of(reinterpret_cast<const void*>(&gl_start)), &messages, &error);
  for (const auto& message : messages) GST_ELEMENT_WARNING(self, RESOURCE, NOT_FOUND, ("pfxfilter: %s", message.c_str()), (nullptr));
  if (!self->state->gl) {
    GST_ELEMENT_ERROR(self, RESOURCE, SETTINGS, ("pfxfilter: %s", error.c_str()), (nullptr));
    return FALSE;
  }
  return GST_GL_BASE_FILTER_CLASS(gst_pfx_filter_parent_class)->gl_start(base);
}

void gl_stop(GstGLBaseFilter* base) {
  auto* self = GST_PFX_FILTER(base);
  self->state->gl.reset();
  GST_GL_BASE_FILTER_CLASS(gst_pfx_filter_parent_class)->gl_stop(base);
}

struct FrameJob {
  GstPfxFilter* self;
  pfx::adapters::ChainSettings settings;
  uint64_t revision;
  double time_seconds;
  GstGLMemory *in, *out;
  std::string warning, error;
  bool ok = false;
};

// The settings and the time of the buffer being filtered, as the streaming thread last set them.
FrameJob frame_job(GstPfxFilter* self) {
  FrameJob job{self, {}, 0, 0, nullptr, nullptr, {}, {}, false};
  GST_OBJECT_LOCK(self);
  job.settings = self->state->settings;
  job.revision = self->state->revision;
  job.time_seconds = self->state->time_seconds;
  GST_OBJECT_UNLOCK(self);
  return job;
}

void say_warning(GstPfxFilter* self, const std::string& warning) {
  if (warning.empty() || warning == self->state->said) return;
  self->state->said = warning;
  GST_ELEMENT_WARNING(self, STREAM, FAILED, ("pfxfilter: %s", warning.c_str()), (nullptr));
}

void plan_on_gl_thread(GstGLContext*, gpointer data) {
  auto* job = static_cast<FrameJob*>(data);
  auto* filter = GST_GL_FILTER(job->self);
  job->ok = job->self->state->gl &&
            job->self->state->gl->runs_passes(job->settings, job->revision, GST_VIDEO_INFO_WIDTH(&filter->out_info),
                                              GST_VIDEO_INFO_HEIGHT(&filter->out_info), job->time_seconds,
                                              &job->warning);
}

void run_on_gl_thread(GstGLContext*, gpointer data) {
  auto* job = static_cast<FrameJob*>(data);
  auto* filter = GST_GL_FILTER(job->self);
  job->ok = job->self->state->gl &&
            job->self->state->gl->process(job->settings, job->revision, gst_gl_memory_get_texture_id(job->in),
                                          gst_gl_memory_get_texture_id(job->out),
                                          GST_VIDEO_INFO_WIDTH(&filter->out_info),
                                          GST_VIDEO_INFO_HEIGHT(&filter->out_info), job->time_seconds,
                                          &job->warning, &job->error);
}

// A frame that no pass would change (no effect on, every effect a no-op with its values, settings
// that do not build) leaves as the very buffer that came in, as a passthrough element's does:
// nothing is allocated, decoded, copied or encoded. Otherwise an output buffer as usual.
GstFlowReturn prepare_output_buffer(GstBaseTransform* transform, GstBuffer* inbuf, GstBuffer** outbuf) {
  auto* self = GST_PFX_FILTER(transform);
  // The buffer's time reaches the chain as the frame time (seconds of stream time).
  const GstClockTime pts = GST_BUFFER_PTS(inbuf);
  GST_OBJECT_LOCK(self);
  self->state->time_seconds = GST_CLOCK_TIME_IS_VALID(pts) ? static_cast<double>(pts) / GST_SECOND : 0.0;
  GST_OBJECT_UNLOCK(self);
  FrameJob job = frame_job(self);
  gst_gl_context_thread_add(GST_GL_BASE_FILTER(transform)->context, plan_on_gl_thread, &job);
  say_warning(self, job.warning);
  if (!job.ok) {
    // The base class neither unrefs an input it is handed back as the output nor copies it.
    *outbuf = inbuf;
    return GST_FLOW_OK;
  }
  return GST_BASE_TRANSFORM_CLASS(gst_pfx_filter_parent_class)->prepare_output_buffer(transform, inbuf, outbuf);
}

GstFlowReturn transform(GstBaseTransform* transform, GstBuffer* inbuf, GstBuffer* outbuf) {
  // The buffer handed on as it came: nothing to draw, and no fence to set on a buffer others may
  // share.
  if (inbuf == outbuf) return GST_FLOW_OK;
  return GST_BASE_TRANSFORM_CLASS(gst_pfx_filter_parent_class)->transform(transform, inbuf, outbuf);
}

gboolean filter_texture(GstGLFilter* filter, GstGLMemory* in, GstGLMemory* out) {
  auto* self = GST_PFX_FILTER(filter);
  FrameJob job = frame_job(self);
  job.in = in;
  job.out = out;
  gst_gl_context_thread_add(GST_GL_BASE_FILTER(filter)->context, run_on_gl_thread, &job);
  say_warning(self, job.warning);
  if (!job.ok) {
    GST_ELEMENT_ERROR(self, STREAM, FAILED, ("pfxfilter: %s", job.error.c_str()), (nullptr));
    return FALSE;
  }
  return TRUE;
}

void install_string(GObjectClass* klass, guint id, const char* name, const char* nick, const char* blurb,
                    const char* value) {
  g_object_class_install_property(
      klass, id,
      g_param_spec_string(name, nick, blurb, value,
                          static_cast<GParamFlags>(G_PARAM_READWRITE | G_PARAM_STATIC_STRINGS | GST_PARAM_MUTABLE_PLAYING)));
}

}  // namespace

static void gst_pfx_filter_class_init(GstPfxFilterClass* klass) {
  auto* object_class = G_OBJECT_CLASS(klass);
  object_class->set_property = set_property;
  object_class->get_property = get_property;
  object_class->finalize = finalize;
  const pfx::adapters::ChainSettings defaults;
  install_string(object_class, PROP_CHAIN, "chain", "Chain",
                 "pfx effects to run, in order, separated by ',' (e.g. bloom,glare); none: no effect, the frame is "
                 "handed on as it came; empty (the default): the preset's chain, else bloom. Effects see colour alone (no depth)",
                 defaults.chain.c_str());
  install_string(object_class, PROP_SET, "set", "Set",
                 "Parameter values, effect.param=value items separated by ';' (bloom.threshold=0.5;bloom.strength=2; "
                 "bloom#2.x for a second bloom). Effects start from their display-referred defaults (docs/hosts.md)",
                 defaults.set.c_str());
  install_string(object_class, PROP_TRANSFER, "transfer", "Transfer",
                 "How the frame's values relate to light: srgb (the exact sRGB curve, what almost all video holds) or "
                 "linear",
                 defaults.transfer.c_str());
  install_string(object_class, PROP_PRESET, "preset", "Preset",
                 "A preset file, pfx-view's .json or ReShade's .ini: its chain (unless chain names one), effects on or "
                 "off, values (set overrides them); what it names that is not there is left out with one warning",
                 defaults.preset.c_str());

  auto* element_class = GST_ELEMENT_CLASS(klass);
  gst_element_class_set_static_metadata(element_class, "pfx effects", "Filter/Effect/Video",
                                        "Runs a chain of pfx post effects (bloom, glare, ...) on GStreamer's OpenGL "
                                        "context (desktop OpenGL 4.5)",
                                        "pfx");
  gst_element_class_add_static_pad_template(element_class, &sink_template);
  gst_element_class_add_static_pad_template(element_class, &src_template);

  auto* base_class = GST_GL_BASE_FILTER_CLASS(klass);
  // Any API is accepted here so that a GLES context is refused by gl_start with the reason.
  base_class->supported_gl_api = static_cast<GstGLAPI>(GST_GL_API_OPENGL | GST_GL_API_OPENGL3 | GST_GL_API_GLES2);
  base_class->gl_start = gl_start;
  base_class->gl_stop = gl_stop;
  auto* transform_class = GST_BASE_TRANSFORM_CLASS(klass);
  transform_class->prepare_output_buffer = prepare_output_buffer;
  transform_class->transform = transform;
  auto* filter_class = GST_GL_FILTER_CLASS(klass);
  filter_class->filter_texture = filter_texture;
}

static void gst_pfx_filter_init(GstPfxFilter* self) { self->state = new State; }
