#include "gnuplot_png.hpp"

#include <cstdio>

#include "atomic_file.hpp"

namespace pfx::bench {

bool write_gnuplot_png(const std::string& path, const std::string& script, std::string* error) {
  return pfx::app::write_atomically(
      path,
      [&](const std::string& temp, std::string* reason) {
        std::string text = script;
        text.replace(text.find("__OUT__"), 7, temp);
        FILE* gnuplot = popen("gnuplot", "w");
        if (!gnuplot) {
          *reason = "cannot run gnuplot (install gnuplot-nox)";
          return false;
        }
        std::fwrite(text.data(), 1, text.size(), gnuplot);
        const int status = pclose(gnuplot);
        if (status != 0) *reason = "gnuplot failed (status " + std::to_string(status) + ")";
        return status == 0;
      },
      error);
}

}  // namespace pfx::bench
