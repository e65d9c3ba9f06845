// Timing schemes (docs/sdk.md §2.2, "Timing"): GPU timestamps are read frames later and never
// waited for inside render(); wait_for_timings() is the one call that waits; timing OFF issues no
// query at all. libpfxhost's query calls are watched through the GL loader the registry hands out.
#include <catch2/catch.hpp>

#include <glad/gl.h>

#include "gl_test_support.hpp"
#include "image_texture.hpp"

namespace {

// What libpfxhost (and the plugins) asked of the query API since the last reset.
struct QueryCalls {
  int made = 0;            // glGenQueries, glCreateQueries
  int started = 0;         // glQueryCounter, glBeginQuery, glBeginQueryIndexed
  int blocking_reads = 0;  // a result read with GL_QUERY_RESULT: waits for the GPU
  int other_reads = 0;     // GL_QUERY_RESULT_AVAILABLE, GL_QUERY_RESULT_NO_WAIT
};
QueryCalls g_calls;

PFNGLGENQUERIESPROC real_gen_queries;
PFNGLCREATEQUERIESPROC real_create_queries;
PFNGLQUERYCOUNTERPROC real_query_counter;
PFNGLBEGINQUERYPROC real_begin_query;
PFNGLBEGINQUERYINDEXEDPROC real_begin_query_indexed;
PFNGLGETQUERYOBJECTIVPROC real_get_iv;
PFNGLGETQUERYOBJECTUIVPROC real_get_uiv;
PFNGLGETQUERYOBJECTI64VPROC real_get_i64v;
PFNGLGETQUERYOBJECTUI64VPROC real_get_ui64v;

void count_read(GLenum pname) {
  if (pname == GL_QUERY_RESULT) ++g_calls.blocking_reads;
  else ++g_calls.other_reads;
}

void GLAD_API_PTR gen_queries(GLsizei n, GLuint* ids) {
  ++g_calls.made;
  real_gen_queries(n, ids);
}
void GLAD_API_PTR create_queries(GLenum target, GLsizei n, GLuint* ids) {
  ++g_calls.made;
  real_create_queries(target, n, ids);
}
void GLAD_API_PTR query_counter(GLuint id, GLenum target) {
  ++g_calls.started;
  real_query_counter(id, target);
}
void GLAD_API_PTR begin_query(GLenum target, GLuint id) {
  ++g_calls.started;
  real_begin_query(target, id);
}
void GLAD_API_PTR begin_query_indexed(GLenum target, GLuint index, GLuint id) {
  ++g_calls.started;
  real_begin_query_indexed(target, index, id);
}
void GLAD_API_PTR get_iv(GLuint id, GLenum pname, GLint* v) {
  count_read(pname);
  real_get_iv(id, pname, v);
}
void GLAD_API_PTR get_uiv(GLuint id, GLenum pname, GLuint* v) {
  count_read(pname);
  real_get_uiv(id, pname, v);
}
void GLAD_API_PTR get_i64v(GLuint id, GLenum pname, GLint64* v) {
  count_read(pname);
  real_get_i64v(id, pname, v);
}
void GLAD_API_PTR get_ui64v(GLuint id, GLenum pname, GLuint64* v) {
  count_read(pname);
  real_get_ui64v(id, pname, v);
}

template <typename Fn>
pfx_gl_proc watch(pfx_gl_proc real, Fn** keep, Fn* wrapper) {
  *keep = reinterpret_cast<Fn*>(real);
  return reinterpret_cast<pfx_gl_proc>(wrapper);
}

// The context's entry points, with the query API's replaced by the counting ones above.
pfx_gl_proc watching_loader(const char* name) {
  const pfx_gl_proc real = pfx::app::HeadlessContext::get_proc_address(nullptr, name);
  const std::string n = name;
  if (n == "glGenQueries") return watch(real, &real_gen_queries, gen_queries);
  if (n == "glCreateQueries") return watch(real, &real_create_queries, create_queries);
  if (n == "glQueryCounter") return watch(real, &real_query_counter, query_counter);
  if (n == "glBeginQuery") return watch(real, &real_begin_query, begin_query);
  if (n == "glBeginQueryIndexed") return watch(real, &real_begin_query_indexed, begin_query_indexed);
  if (n == "glGetQueryObjectiv") return watch(real, &real_get_iv, get_iv);
  if (n == "glGetQueryObjectuiv") return watch(real, &real_get_uiv, get_uiv);
  if (n == "glGetQueryObjecti64v") return watch(real, &real_get_i64v, get_i64v);
  if (n == "glGetQueryObjectui64v") return watch(real, &real_get_ui64v, get_ui64v);
  return real;
}

// The minimal plugin's boxblur (three passes) over a small frame, loaded through the watching loader.
struct TimedRig {
  std::unique_ptr<pfx::host::PluginRegistry> registry;
  pfx::host::ParamStore params;
  std::unique_ptr<pfx::host::Chain> chain;
  pfx::host::FrameTextures textures;
  uint32_t output = 0;

  explicit TimedRig(pfx::host::Timing timing) {
    pfx::test::gl_context();
    registry = std::make_unique<pfx::host::PluginRegistry>(
        watching_loader, [](pfx_log_level, const std::string&, const std::string&) {}, "pfx-tests");
    std::string error;
    REQUIRE(registry->load(PFX_TEST_MINIMAL_PLUGIN, &error));
    chain = std::make_unique<pfx::host::Chain>(*registry, params);
    REQUIRE(chain->add("boxblur", &error));
    REQUIRE(params.set_assignment("boxblur.radius=1", &error));
    chain->set_timing(timing);
    textures.color = pfx::app::upload_color_texture(pfx::test::test_image(32, 32));
    output = pfx::app::create_color_texture(32, 32);
  }
  ~TimedRig() {
    pfx::app::delete_texture(textures.color);
    pfx::app::delete_texture(output);
  }
  void render() {
    std::string error;
    INFO(error);
    REQUIRE(chain->render(pfx::test::make_frame(32, 32), textures, output, &error));
  }
};

}  // namespace

TEST_CASE("GPU timestamps: render() never waits for a query, and reports only earlier frames", "[timing]") {
  TimedRig rig(pfx::host::Timing::GPU_QUERIES);
  g_calls = {};
  const int frames = 8;
  for (int i = 1; i <= frames; ++i) {
    rig.render();
    const pfx::host::FrameReport& report = rig.chain->report();
    INFO("frame " << i);
    CHECK(report.frame == uint64_t(i));
    CHECK(report.timing == "gpu-timestamps");
    CHECK(report.times.frame < report.frame);  // an earlier frame's times, or none (0)
    if (report.times.frame != 0) {
      REQUIRE(report.times.passes.size() == 3);
      CHECK(report.times.passes[0].pass == "down");
    }
    for (const auto& pass : report.passes) CHECK(pass.ms == 0);  // this frame's are not in yet
  }
  CHECK(g_calls.started == frames * 4);  // a start stamp and one per pass
  CHECK(g_calls.blocking_reads == 0);

  // The one call that waits gives the last frame's complete times.
  REQUIRE(rig.chain->wait_for_timings());
  const pfx::host::FrameReport& report = rig.chain->report();
  CHECK(g_calls.blocking_reads == 4);
  CHECK(report.times.frame == uint64_t(frames));
  REQUIRE(report.times.passes.size() == 3);
  double sum = 0;
  for (size_t p = 0; p < 3; ++p) {
    CHECK(report.times.passes[p].ms >= 0);
    CHECK(report.passes[p].ms == report.times.passes[p].ms);  // the report's own frame, now timed
    sum += report.times.passes[p].ms;
  }
  CHECK(report.times.total_ms == Approx(sum));
  CHECK(report.times.passes[2].pass == "up");
  // Nothing left in flight: waiting again reads nothing more.
  REQUIRE(rig.chain->wait_for_timings());
  CHECK(g_calls.blocking_reads == 4);
}

TEST_CASE("GPU timestamps: a frame's times arrive in a later frame's report once the GPU is done", "[timing]") {
  TimedRig rig(pfx::host::Timing::GPU_QUERIES);
  rig.render();
  glFinish();  // frame 1 is done on the GPU, so its queries have landed by frame 2's end
  rig.render();
  CHECK(rig.chain->report().times.frame == 1);
  CHECK(rig.chain->report().times.passes.size() == 3);
}

TEST_CASE("timing OFF makes, starts and reads no query", "[timing]") {
  TimedRig rig(pfx::host::Timing::OFF);
  g_calls = {};
  for (int i = 0; i < 3; ++i) rig.render();
  CHECK(g_calls.made == 0);
  CHECK(g_calls.started == 0);
  CHECK(g_calls.blocking_reads + g_calls.other_reads == 0);
  CHECK_FALSE(rig.chain->wait_for_timings());
  CHECK(rig.chain->report().times.frame == 0);
  CHECK(rig.chain->report().timing == "off");
}

TEST_CASE("finish+clock times the frame itself, with no query", "[timing]") {
  TimedRig rig(pfx::host::Timing::FINISH_AND_CLOCK);
  g_calls = {};
  rig.render();
  rig.render();
  const pfx::host::FrameReport& report = rig.chain->report();
  CHECK(report.times.frame == 2);
  REQUIRE(report.passes.size() == 3);
  for (const auto& pass : report.passes) CHECK(pass.ms > 0);
  CHECK(g_calls.made + g_calls.started == 0);
  CHECK(rig.chain->wait_for_timings());  // nothing to wait for: the times are the last frame's already
}
