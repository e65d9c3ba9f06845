// What pfx's OBS filter leaves behind in OBS: no GL objects after it is removed (counted by name
// over a hundred add/remove cycles), none made while no effect would change the frame, and GL
// state a stock OBS filter after it finds as it would after any other source.
#include <catch2/catch.hpp>

#include <EGL/egl.h>
#include <GL/gl.h>

#include "obs_pictures.hpp"
#include "obs_session.hpp"
#include "png_io.hpp"
#include "render_process.hpp"

using namespace pfx::test;

namespace {

// How many GL objects of each kind the context holds, by asking for every name up to a bound far
// above what a few filters use (names are small integers, freed ones reused).
struct GlObjects {
  int textures = 0, buffers = 0, framebuffers = 0, renderbuffers = 0, programs = 0, shaders = 0, vertex_arrays = 0,
      samplers = 0;
  bool operator==(const GlObjects& o) const {
    return textures == o.textures && buffers == o.buffers && framebuffers == o.framebuffers &&
           renderbuffers == o.renderbuffers && programs == o.programs && shaders == o.shaders &&
           vertex_arrays == o.vertex_arrays && samplers == o.samplers;
  }
  int total() const {
    return textures + buffers + framebuffers + renderbuffers + programs + shaders + vertex_arrays + samplers;
  }
};

std::ostream& operator<<(std::ostream& out, const GlObjects& o) {
  return out << "textures " << o.textures << ", buffers " << o.buffers << ", framebuffers " << o.framebuffers
             << ", renderbuffers " << o.renderbuffers << ", programs " << o.programs << ", shaders " << o.shaders
             << ", vertex arrays " << o.vertex_arrays << ", samplers " << o.samplers;
}

using IsObject = GLboolean (*)(GLuint);

GlObjects count_gl_objects(ObsSession& obs) {
  // A released source is destroyed at a tick of OBS's graphics thread, on its destroy task
  // thread: after both.
  obs.wait_for_ticks();
  obs_wait_for_destroy_queue();
  obs_enter_graphics();
  auto is = [](const char* name) { return reinterpret_cast<IsObject>(eglGetProcAddress(name)); };
  const struct {
    IsObject is;
    int GlObjects::*count;
  } kinds[] = {{is("glIsTexture"), &GlObjects::textures},       {is("glIsBuffer"), &GlObjects::buffers},
               {is("glIsFramebuffer"), &GlObjects::framebuffers}, {is("glIsRenderbuffer"), &GlObjects::renderbuffers},
               {is("glIsProgram"), &GlObjects::programs},       {is("glIsShader"), &GlObjects::shaders},
               {is("glIsVertexArray"), &GlObjects::vertex_arrays}, {is("glIsSampler"), &GlObjects::samplers}};
  GlObjects objects;
  for (const auto& kind : kinds)
    for (GLuint name = 1; name < 20000; ++name) objects.*kind.count += kind.is(name) ? 1 : 0;
  obs_leave_graphics();
  return objects;
}

}  // namespace

TEST_CASE("a hundred filters added and removed leave no GL objects behind", "[obs]") {
  ObsSession& obs = ObsSession::get();
  Scratch scratch;
  write_photo_crop(scratch / "in.png", 200, 180, 32, 24);
  obs_source_t* image = obs.image_source(scratch / "in.png");
  const char* const types[] = {"pfx_bloom_filter", "pfx_chain_filter"};
  int cycles = 0;
  auto cycle = [&](bool count_inside) {
    obs_source_t* filter = obs.add_filter(image, count_inside ? "pfx_chain_filter" : types[(cycles++) % 2]);
    obs.render(image);
    const GlObjects inside = count_inside ? count_gl_objects(obs) : GlObjects{};
    obs_source_filter_remove(image, filter);
    obs_source_release(filter);
    return inside;
  };
  cycle(false);  // OBS's own first-use objects
  const GlObjects before = count_gl_objects(obs);
  const long allocations = bnum_allocs();
  const GlObjects inside = cycle(true);
  INFO("before: " << before << "\nwith a filter: " << inside);
  REQUIRE(inside.total() > before.total());  // the count sees the filter's objects
  for (int i = 0; i < 99; ++i) cycle(false);
  const GlObjects after = count_gl_objects(obs);
  INFO("after 100 cycles: " << after);
  CHECK(after == before);
  CHECK(bnum_allocs() == allocations);
  obs_source_release(image);
}

TEST_CASE("with no effect on, or only no-ops, the chain filter draws its source as it is and makes no texture",
          "[obs]") {
  ObsSession& obs = ObsSession::get();
  Scratch scratch;
  write_photo_crop(scratch / "in.png", 200, 180, 48, 40);
  obs_source_t* image = obs.image_source(scratch / "in.png");
  const ObsFrame plain = obs.render(image);
  const int textures = count_gl_objects(obs).textures;
  auto values = [](const char* chain, const char* set) {
    obs_data_t* settings = obs_data_create();
    obs_data_set_string(settings, "chain", chain);
    obs_data_set_string(settings, "set", set);
    return settings;
  };
  obs_data_t* none = values("none", "");
  obs_source_t* filter = obs.add_filter(image, "pfx_chain_filter", none);
  // Nothing drawn into a texture of the filter's, nor copied, decoded or encoded.
  CHECK(obs.render(image).rgba == plain.rgba);
  CHECK(count_gl_objects(obs).textures == textures);
  obs_data_t* no_ops = values("bloom,glare", "bloom.strength=0;glare.strength=0");
  obs_source_update(filter, no_ops);
  CHECK(obs.render(image).rgba == plain.rgba);
  CHECK(count_gl_objects(obs).textures == textures);
  // A chain that runs draws through textures of its own: the count sees them.
  obs_data_t* bloom = values("bloom", "bloom.strength=2");
  obs_source_update(filter, bloom);
  CHECK(obs.render(image).rgba != plain.rgba);
  CHECK(count_gl_objects(obs).textures > textures);
  for (obs_data_t* settings : {none, no_ops, bloom}) obs_data_release(settings);
  obs_source_release(filter);
  obs_source_release(image);
}

TEST_CASE("a stock OBS filter after pfx's gives what it gives after an image of pfx's frame", "[obs]") {
  // OBS's colour correction and sharpen filters, after the pfx filter, and after an image source
  // showing the bytes the pfx filter gave (the image source shows its file's bytes exactly: the
  // harness test). GL state pfx left behind (a framebuffer, a program, a texture unit, blending)
  // would show in the first.
  ObsSession& obs = ObsSession::get();
  Scratch scratch;
  write_photo_crop(scratch / "in.png", 200, 180, 64, 48);
  obs_source_t* image = obs.image_source(scratch / "in.png");
  obs_data_t* bloom_values = obs_data_create();
  obs_data_set_double(bloom_values, "threshold", 0.5);
  obs_source_t* bloom = obs.add_filter(image, "pfx_bloom_filter", bloom_values);
  const ObsFrame pfx_frame = obs.render(image);
  {
    pfx::app::DisplayImage picture{int(pfx_frame.width), int(pfx_frame.height), 4, pfx_frame.rgba};
    std::string error;
    REQUIRE(pfx::app::write_png(scratch / "pfx.png", picture, &error));
  }
  obs_source_t* shown = obs.image_source(scratch / "pfx.png");
  CHECK(worst_difference(obs.render(shown), read_picture(scratch / "pfx.png")) == 0);

  obs_data_t* colour = obs_data_create();
  obs_data_set_double(colour, "gamma", -0.4);
  obs_data_set_double(colour, "contrast", 0.3);
  obs_data_set_double(colour, "saturation", 0.5);
  obs_data_set_double(colour, "hue_shift", 40);
  obs_data_t* sharpen = obs_data_create();
  obs_data_set_double(sharpen, "sharpness", 0.6);
  obs_source_t* stock[] = {obs.add_filter(image, "color_filter_v2", colour), obs.add_filter(image, "sharpness_filter_v2", sharpen),
                           obs.add_filter(shown, "color_filter_v2", colour), obs.add_filter(shown, "sharpness_filter_v2", sharpen)};
  const ObsFrame after_pfx = obs.render(image), after_image = obs.render(shown);
  const ObsFrame unchanged = obs.render(obs.image_source(scratch / "pfx.png"));
  REQUIRE(after_image.rgba != unchanged.rgba);  // the stock filters do something
  CHECK(after_pfx.rgba == after_image.rgba);
  for (obs_source_t* filter : stock) obs_source_release(filter);
  obs_data_release(colour);
  obs_data_release(sharpen);
  obs_data_release(bloom_values);
  obs_source_release(bloom);
  obs_source_release(shown);
  obs_source_release(image);
}
