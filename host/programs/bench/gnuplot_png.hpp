// Plots through gnuplot (Debian's gnuplot-nox), written like every output: to a temporary name,
// renamed when complete.
#pragma once

#include <string>

namespace pfx::bench {

// Runs script through gnuplot; the script's "__OUT__" (once, in its `set output`) becomes the
// temporary file. False with *error naming path and why (gnuplot missing or failing).
bool write_gnuplot_png(const std::string& path, const std::string& script, std::string* error);

}  // namespace pfx::bench
