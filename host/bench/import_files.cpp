#include "import_files.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "atomic_file.hpp"

namespace fs = std::filesystem;

namespace pfx::bench {

namespace {

// Bytes per vertex of the layout below, measured: about 29 (v) + 22 (vt) + 31 (vn) + 2 faces.
double bytes_per_vertex(uint64_t n) {
  const double digits = std::floor(std::log10(double(n) * double(n))) + 1;
  return 29 + 22 + 31 + 2 * (3 * (3 * digits + 2) + 3);
}

bool write_grid(const std::string& path, uint64_t n, std::string* reason) {
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) {
    *reason = "cannot open";
    return false;
  }
  static char buffer[1 << 20];
  std::setvbuf(f, buffer, _IOFBF, sizeof buffer);
  std::fprintf(f, "# pfx-bench import: %llu x %llu height field\no grid\n", static_cast<unsigned long long>(n),
               static_cast<unsigned long long>(n));
  const double step = 1.0 / double(n - 1);
  for (uint64_t j = 0; j < n; ++j)
    for (uint64_t i = 0; i < n; ++i) {
      const double x = i * step, y = j * step;
      const double z = 0.05 * std::sin(12.0 * x) * std::cos(9.0 * y);
      std::fprintf(f, "v %.6f %.6f %.6f\n", x, y, z);
    }
  for (uint64_t j = 0; j < n; ++j)
    for (uint64_t i = 0; i < n; ++i) std::fprintf(f, "vt %.6f %.6f\n", i * step, j * step);
  for (uint64_t j = 0; j < n; ++j)
    for (uint64_t i = 0; i < n; ++i) {
      const double x = i * step, y = j * step;
      double nx = -0.6 * std::cos(12.0 * x) * std::cos(9.0 * y), ny = 0.45 * std::sin(12.0 * x) * std::sin(9.0 * y);
      const double length = std::sqrt(nx * nx + ny * ny + 1.0);
      std::fprintf(f, "vn %.6f %.6f %.6f\n", nx / length, ny / length, 1.0 / length);
    }
  std::fputs("s 1\n", f);
  for (uint64_t j = 0; j + 1 < n; ++j)
    for (uint64_t i = 0; i + 1 < n; ++i) {
      const unsigned long long a = j * n + i + 1, b = a + 1, c = a + n, d = c + 1;
      std::fprintf(f, "f %llu/%llu/%llu %llu/%llu/%llu %llu/%llu/%llu\n", a, a, a, b, b, b, d, d, d);
      std::fprintf(f, "f %llu/%llu/%llu %llu/%llu/%llu %llu/%llu/%llu\n", a, a, a, d, d, d, c, c, c);
    }
  const bool ok = std::ferror(f) == 0;
  if (std::fclose(f) != 0 || !ok) {
    *reason = "write failed (disk full?)";
    return false;
  }
  return true;
}

}  // namespace

bool generate_obj(const std::string& directory, double megabytes, GeneratedObj* out, std::string* error) {
  const double target = megabytes * 1e6;
  uint64_t n = 2;
  while (double(n + 1) * double(n + 1) * bytes_per_vertex(n + 1) <= target) ++n;
  char name[64];
  std::snprintf(name, sizeof name, "grid-%gmb.obj", megabytes);
  out->path = (fs::path(directory) / name).string();
  out->grid = n;
  out->vertices = n * n;
  out->triangles = 2 * (n - 1) * (n - 1);
  std::error_code ec;
  if (!fs::exists(out->path, ec) &&
      !pfx::app::write_atomically(out->path, [&](const std::string& temp, std::string* reason) {
        return write_grid(temp, n, reason);
      }, error))
    return false;
  out->bytes = fs::file_size(out->path, ec);
  return true;
}

}  // namespace pfx::bench
