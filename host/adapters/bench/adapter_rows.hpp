// One row of pfx-adapter-bench: a host program running one filter, and what it measured.
#pragma once

#include <string>

namespace pfx::adapter_bench {

struct Row {
  std::string host, name, what;  // "ffmpeg", "pfx_bloom", the filter as given to the host
  std::string baseline;          // the row whose time this one's extra is measured from ("" for none)
  double ms_per_frame = 0;
  std::string not_run = "";  // why the row was not measured ("" when it was)
  bool fx_file = false;      // vkBasalt runs an FX file: whether it compiled is checked first
};

}  // namespace pfx::adapter_bench
