// One frei0r instance: its parameter values (set from any host thread), and on the GL worker its
// frame's textures and chain, made at the first frame (construct stays cheap: hosts construct
// instances only to read defaults). Every failure (an unknown effect, a bad assignment, a missing
// preset, no EGL) turns the frame into a copy of the input and is said once on stderr: frei0r
// has no other way to report.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "frei0r_api.hpp"

#include <pfx/host/param_store.hpp>

#include "chain_settings.hpp"
#include "frei0r_library.hpp"
#include "gl_worker.hpp"

namespace pfx::frei0r {

class Instance {
 public:
  Instance(std::shared_ptr<Library> library, unsigned width, unsigned height);
  ~Instance();
  Instance(const Instance&) = delete;
  Instance& operator=(const Instance&) = delete;

  // `text` is the string of a string parameter, however the host passed it.
  void set_param(int index, const void* param, const char* text);
  void get_param(int index, void* param);
  void update(double time, const uint32_t* in, uint32_t* out);

 private:
  struct GlSide;
  bool render(double time, const uint32_t* in, uint32_t* out, std::string* error);
  bool prepare_chain(std::string* error);
  void say(const std::string& message);

  std::shared_ptr<Library> library_;
  const int width_, height_;
  std::mutex mutex_;  // the values, against a host that sets them from another thread
  // CHAIN: the four settings as text. EFFECT: the effect's values, checked as they are set.
  adapters::ChainSettings settings_;
  host::ParamStore values_{host::DefaultSet::DISPLAY_REFERRED};
  std::vector<std::string> texts_;  // what get_param handed out for string parameters
  uint64_t revision_ = 1;           // changes with every value set
  uint64_t frames_ = 0;
  std::shared_ptr<adapters::GlWorker> worker_;
  std::unique_ptr<GlSide> gl_;      // made, used and destroyed on the worker
  std::string said_;                // the last message said, so each is said once
};

}  // namespace pfx::frei0r
