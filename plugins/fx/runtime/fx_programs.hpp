#pragma once
// The GL programs of an FX technique's passes, in two sets: live, where every uniform is a GL
// uniform set each frame, and specialised, where the uniforms no frame source fills (the user's
// parameters and plain initial values) are compiled in as constants, so the driver folds the
// branches and loops they decide (ReShade's performance mode, made automatic). Both compute the
// same pictures: a constant holds the bits the uniform would.
//
// Which set runs: the specialised one whenever the values have settled (fx_settled_values.hpp),
// the live one while they move (a slider being dragged), so no frame waits for a compile per
// value. Where the
// driver compiles in the background (KHR_parallel_shader_compile), a specialised set for settled
// values is compiled there while the live one keeps running, and takes over the frame it is
// ready, so no frame waits for it either. A set is built the first time it is needed and kept; specialised programs go through the program cache
// like live ones (their GLSL holds the values, so the cache is keyed by them). PFX_FX_SPECIALISE=0
// keeps every uniform live.
#include <chrono>
#include <string>
#include <vector>

#include <glad/gl.h>

#include "effect_compiler.hpp"
#include "model/full_screen_pass.hpp"
#include "fx_settled_values.hpp"
#include "fx_uniform_values.hpp"

namespace pfx_fx {

struct PassProgram {
  GLuint program = 0;
  GLint target_height_location = -1;
  bool covers_target = true;  // draws every pixel of the back buffer (no copy needed first)
  // While the driver compiles it: the program cache's key to store it under once it has linked;
  // empty once stored, or when it came from the cache.
  std::string cache_key;
};

struct ProgramSet {
  std::vector<pfx::fx::GeneratedPass> generated;  // per pass of the technique
  std::vector<PassProgram> programs;
  pfx::fx::UniformConstants constants;  // what was compiled in; empty for the live set
  int constant_count = 0;               // uniforms compiled in as constants
  bool started = false;                 // programs handed to the driver
  bool built = false;                   // and linked, with their uniforms found: ready to run
};

class FxPrograms {
 public:
  FxPrograms() = default;
  ~FxPrograms() = default;  // release() first, with the context current
  // Deletes every program (a new compile of the source). GL current.
  void release();

  // The set this frame runs, chosen from the uniforms' values and built if it is not yet: false
  // with *error when the GL refuses a program (the generated GLSL is wrong: a compiler bug).
  bool choose(const pfx::fx::CompiledEffect& compiled, int technique, const UniformValues& values, std::string* error);
  const ProgramSet& running() const { return *running_; }
  // The technique pass that draws into the host's output with the frame's alpha (fx_pass_layout),
  // or -1; its programs read that alpha on the unit after its samplers. Set before the next build.
  void set_output_pass(int pass) { output_pass_ = pass; }
  // Of the last build: its time in milliseconds and how many of its programs came from the disk
  // cache.
  double build_ms() const { return build_ms_; }
  int cache_hits() const { return cache_hits_; }

 private:
  // A set is built in two halves: its GLSL generated and handed to the driver (or its programs
  // loaded from the cache), then, once ready() (at once unless the driver compiles on threads of
  // its own), checked, stored in the cache and its uniforms found.
  bool start_build(const pfx::fx::CompiledEffect& compiled, int technique, ProgramSet& set, std::string* error);
  static bool ready(const ProgramSet& set);
  bool finish_build(const pfx::fx::CompiledEffect& compiled, int technique, ProgramSet& set, std::string* error);
  static void release(ProgramSet& set);

  int output_pass_ = -1;
  // pending_: a specialised set the driver compiles while live_ runs (KHR_parallel_shader_compile).
  ProgramSet live_, specialised_, pending_;
  int parallel_compile_ = -1;  // whether the GL offers it; -1 until asked (with the context current)
  const ProgramSet* running_ = &live_;
  SettledValues settle_;
  double build_ms_ = 0;
  int cache_hits_ = 0;
};

}  // namespace pfx_fx
