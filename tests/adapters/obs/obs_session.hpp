// libobs driven as OBS Studio drives it, with no window: started once per test process with its
// OpenGL renderer on an X display (xvfb-run gives each test one), the stock modules of Debian's
// obs-studio package and this build's pfx-obs.so loaded; sources made from PNG files or a colour,
// filters added, and a frame rendered into a texture and read back.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <obs.h>

namespace pfx::test {

// An RGBA frame read back from OBS, row 0 at the top.
struct ObsFrame {
  uint32_t width = 0, height = 0;
  std::vector<uint8_t> rgba;
};

class ObsSession {
 public:
  // The session of this process, started on first use; REQUIREs that libobs, its OpenGL renderer
  // and every module start.
  static ObsSession& get();
  ~ObsSession();

  // A new reference the caller releases.
  obs_source_t* image_source(const std::string& png);
  obs_source_t* color_source(uint32_t width, uint32_t height, uint32_t abgr);
  // A filter of `type` added last on `source`; the source holds it, the returned reference too.
  obs_source_t* add_filter(obs_source_t* source, const char* type, obs_data_t* settings = nullptr);

  // Returns once OBS's graphics thread has ticked every source (settings changed before are
  // applied then).
  void wait_for_ticks();
  // One frame of `source` (its filters run) rendered at its size and read back, once changed
  // settings have been applied (wait_for_ticks).
  ObsFrame render(obs_source_t* source);

  // Every line libobs logged since the session started or the last clear.
  std::string log() const;
  void clear_log();

 private:
  ObsSession();
};

}  // namespace pfx::test
