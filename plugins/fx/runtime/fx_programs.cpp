#include "fx_programs.hpp"

#include <regex>

#include <pfx/cpp/gl_program.hpp>
#include <pfx/cpp/program_cache.hpp>

#include "fx_pass_layout.hpp"

namespace pfx_fx {
namespace {

using pfx::fx::GeneratedPass;
using pfx::fx::PassInfo;
using pfx::gl::ProgramCache;

// Compiled programs of FX passes in $XDG_CACHE_HOME/pfx/fx-programs (program_cache.hpp);
// PFX_FX_CACHE=0 turns the cache off. The GLSL itself is generated at every start: it costs a few
// milliseconds on the CPU. Specialised programs (fx_programs.hpp) add one set per distinct set of
// values an effect settles on, so the folder is bounded: 256 MiB, the programs used longest ago
// deleted first.
ProgramCache fx_program_cache() { return ProgramCache("fx-programs", "PFX_FX_CACHE", "0.1.0", 256ull << 20); }

// The driver's "0:12(5): error" names the source string; the generated code's #line directives
// made that the FX file's index, so the message can name the file.
std::string with_file_names(const std::string& log, const pfx::fx::FileNames& names) {
  std::string out;
  std::regex location(R"((^|\n)(\d+):(\d+)\((\d+)\))");
  std::size_t last = 0;
  for (std::sregex_iterator it(log.begin(), log.end(), location), end; it != end; ++it) {
    const std::smatch& m = *it;
    out += log.substr(last, static_cast<std::size_t>(m.position(0)) - last);
    std::size_t file = std::stoul(m[2].str());
    std::string name = file < names.size() ? names.name(static_cast<std::uint32_t>(file)) : m[2].str();
    out += m[1].str() + name + ":" + m[3].str() + ":" + m[4].str();
    last = static_cast<std::size_t>(m.position(0) + m.length(0));
  }
  return out + log.substr(last);
}

// A program from the cache (its key left empty: nothing to store), else its GLSL handed to the
// driver to compile and link (the key kept, to store it under once it has linked).
GLuint start_cached_program(const ProgramCache& cache, const GeneratedPass& g, std::string* key, int* cache_hits) {
  *key = cache.key({g.vertex, g.fragment, g.compute});
  if (GLuint program = cache.load(*key)) {
    ++*cache_hits;
    key->clear();
    return program;
  }
  if (!g.compute.empty()) {
    const char* source = g.compute.c_str();
    const GLenum stage = GL_COMPUTE_SHADER;
    return pfx::gl::start_program(&stage, &source, 1, cache.usable());
  }
  const char* sources[2] = {g.vertex.c_str(), g.fragment.c_str()};
  const GLenum stages[2] = {GL_VERTEX_SHADER, GL_FRAGMENT_SHADER};
  return pfx::gl::start_program(stages, sources, 2, cache.usable());
}

double ms_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

void FxPrograms::release(ProgramSet& set) {
  for (PassProgram& p : set.programs)
    if (p.program) glDeleteProgram(p.program);
  set = ProgramSet{};
}

void FxPrograms::release() {
  release(live_);
  release(specialised_);
  release(pending_);
  running_ = &live_;
  settle_.reset();
}

bool FxPrograms::choose(const pfx::fx::CompiledEffect& compiled, int technique, const UniformValues& values,
                        std::string* error) {
  const bool enabled = settle_.enabled();
  pfx::fx::UniformConstants held = enabled ? held_values(compiled.model, values) : pfx::fx::UniformConstants{};
  const SettledValues::Frame frame = settle_.observe(held);
  const bool first_frame = frame.first, settled = frame.settled;
  if (parallel_compile_ < 0) parallel_compile_ = pfx::gl::has_parallel_compile() ? 1 : 0;

  // A set compiling in the background for values that have moved on is no use.
  if (pending_.started && pending_.constants != held) release(pending_);
  const bool have_specialised = specialised_.built && specialised_.constants == held;
  bool wants_specialised = enabled && (settled || have_specialised);
  if (wants_specialised && !have_specialised) {
    if (parallel_compile_ && live_.built && !first_frame) {
      // Off the frame path: the driver compiles while the live programs keep running, and the set
      // takes over the frame it is ready (this one, where the driver compiled as it was asked).
      pending_.constants = held;
      if (!pending_.started && !start_build(compiled, technique, pending_, error)) return release(pending_), false;
      wants_specialised = ready(pending_);
      if (wants_specialised) {
        if (!finish_build(compiled, technique, pending_, error)) return release(pending_), false;
        release(specialised_);
        specialised_ = std::move(pending_);
        pending_ = ProgramSet{};
      }
    } else {
      // Nothing else to run yet (the first frame), or a driver that compiles only when asked.
      release(specialised_);
      specialised_.constants = held;
    }
  }
  ProgramSet& set = wants_specialised ? specialised_ : live_;
  if (!set.built && !(start_build(compiled, technique, set, error) && finish_build(compiled, technique, set, error)))
    return release(set), false;
  running_ = &set;
  return true;
}

bool FxPrograms::start_build(const pfx::fx::CompiledEffect& compiled, int technique, ProgramSet& set,
                             std::string* error) {
  const auto start = std::chrono::steady_clock::now();
  cache_hits_ = 0;
  const pfx::fx::EffectModel& model = compiled.model;
  const pfx::fx::TechniqueInfo& info = model.techniques[static_cast<std::size_t>(technique)];
  const auto& live = compiled.passes[static_cast<std::size_t>(technique)];
  set.generated.clear();
  set.programs.clear();
  set.constant_count = 0;
  for (std::size_t i = 0; i < live.size(); ++i) {
    if (set.constants.empty()) {
      set.generated.push_back(live[i]);
      continue;
    }
    // The same checked tree, written again with the values in place of the uniforms: what GLSL
    // could not express there it cannot here, so no diagnostic is new.
    pfx::fx::Diagnostics diagnostics(compiled.front->names);
    set.generated.push_back(
        pfx::fx::generate_pass(compiled.front->unit, model, info.passes[i], diagnostics, &set.constants));
    if (diagnostics.has_errors()) return *error = "the specialised code did not generate:\n" + diagnostics.format_all(), false;
  }
  if (output_pass_ >= 0) {
    GeneratedPass& g = set.generated[static_cast<std::size_t>(output_pass_)];
    g.fragment = with_frame_alpha(g.fragment, g.sampler_units.size(), info.passes[static_cast<std::size_t>(output_pass_)].srgb_write);
  }
  for (std::size_t i = 0; i < set.constants.size(); ++i)
    set.constant_count += pfx::fx::can_be_constant(model.uniforms[i].decl->resolved, set.constants[i]) ? 1 : 0;
  const ProgramCache cache = fx_program_cache();
  for (const GeneratedPass& g : set.generated) {
    PassProgram p;
    p.program = start_cached_program(cache, g, &p.cache_key, &cache_hits_);
    set.programs.push_back(std::move(p));
  }
  set.started = true;
  build_ms_ = ms_since(start);
  return true;
}

bool FxPrograms::ready(const ProgramSet& set) {
  for (const PassProgram& p : set.programs)
    if (!p.cache_key.empty() && !pfx::gl::program_ready(p.program)) return false;
  return true;
}

bool FxPrograms::finish_build(const pfx::fx::CompiledEffect& compiled, int technique, ProgramSet& set,
                              std::string* error) {
  const auto start = std::chrono::steady_clock::now();
  const pfx::fx::EffectModel& model = compiled.model;
  const pfx::fx::TechniqueInfo& info = model.techniques[static_cast<std::size_t>(technique)];
  const ProgramCache cache = fx_program_cache();
  for (std::size_t i = 0; i < set.programs.size(); ++i) {
    PassProgram& p = set.programs[i];
    const GeneratedPass& g = set.generated[i];
    const PassInfo& pass = info.passes[i];
    if (!p.cache_key.empty()) {
      std::string message;
      p.program = pfx::gl::finish_program(p.program, &message);
      if (!p.program) {
        const std::string name = pass.name.empty() ? "pass" + std::to_string(i) : pass.name;
        *error = "pass '" + name + "': the GL refused the generated GLSL (a compiler bug, please report it):\n" +
                 with_file_names(message, compiled.front->names);
        return false;
      }
      cache.store(p.cache_key, p.program);
      p.cache_key.clear();
    }
    p.target_height_location = glGetUniformLocation(p.program, GeneratedPass::kTargetHeightUniform);
    p.covers_target = pfx::fx::covers_back_buffer(pass, g.may_discard);
  }
  set.built = true;
  build_ms_ += ms_since(start);
  return true;
}


}  // namespace pfx_fx
