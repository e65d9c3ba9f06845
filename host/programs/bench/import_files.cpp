#include "import_files.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "atomic_file.hpp"

namespace fs = std::filesystem;

namespace pfx::bench {

namespace {

struct LayoutInfo {
  ObjLayout layout;
  const char* name;
};
const LayoutInfo kLayouts[] = {{ObjLayout::kPositionTriangles, "positions"}, {ObjLayout::kTriangles, "triangles"},
                               {ObjLayout::kQuads, "quads"},                 {ObjLayout::kRelativeQuads, "relative-quads"},
                               {ObjLayout::kObjects, "objects"},             {ObjLayout::kLongNumbers, "long-numbers"},
                               {ObjLayout::kShortNumbers, "short-numbers"}};
constexpr int kObjects = 8, kMaterials = 3;

// Writes the layout for an N x N grid to f (which may be /dev/null, to measure); returns the bytes.
uint64_t write_grid(FILE* f, ObjLayout layout, uint64_t n) {
  uint64_t bytes = 0;
  auto put = [&](int written) { bytes += written > 0 ? static_cast<uint64_t>(written) : 0; };
  const bool attributes = layout != ObjLayout::kPositionTriangles;
  const bool quads = layout == ObjLayout::kQuads || layout == ObjLayout::kRelativeQuads || layout == ObjLayout::kObjects;
  const char* number = layout == ObjLayout::kLongNumbers ? "%.9e" : layout == ObjLayout::kShortNumbers ? "%.2f" : "%.6f";
  char v_format[64], vt_format[64], vn_format[64];
  std::snprintf(v_format, sizeof v_format, "v %s %s %s\n", number, number, number);
  std::snprintf(vt_format, sizeof vt_format, "vt %s %s\n", number, number);
  std::snprintf(vn_format, sizeof vn_format, "vn %s %s %s\n", number, number, number);
  put(std::fprintf(f, "# pfx-bench import: %llu x %llu height field, layout %s\n", static_cast<unsigned long long>(n),
                   static_cast<unsigned long long>(n), layout_name(layout)));
  if (layout == ObjLayout::kObjects) put(std::fprintf(f, "mtllib materials.mtl\n"));
  const double step = 1.0 / double(n - 1);
  // Rows of the grid in bands, one object each (one band but for the objects layout); each band
  // writes its own rows of vertices, then its cells (a band shares its first row with the last).
  const uint64_t bands = layout == ObjLayout::kObjects ? kObjects : 1;
  uint64_t written = 0;  // vertices written before this band
  for (uint64_t band = 0; band < bands; ++band) {
    const uint64_t first_row = (n - 1) * band / bands, last_row = (n - 1) * (band + 1) / bands;
    if (layout == ObjLayout::kObjects)
      put(std::fprintf(f, "o part%llu\ng part%llu\nusemtl material%llu\n", static_cast<unsigned long long>(band),
                       static_cast<unsigned long long>(band), static_cast<unsigned long long>(band % kMaterials)));
    for (uint64_t j = first_row; j <= last_row; ++j)
      for (uint64_t i = 0; i < n; ++i) {
        const double x = i * step, y = j * step;
        put(std::fprintf(f, v_format, x, y, 0.05 * std::sin(12.0 * x) * std::cos(9.0 * y)));
        if (!attributes) continue;
        put(std::fprintf(f, vt_format, x, y));
        const double nx = -0.6 * std::cos(12.0 * x) * std::cos(9.0 * y), ny = 0.45 * std::sin(12.0 * x) * std::sin(9.0 * y);
        const double length = std::sqrt(nx * nx + ny * ny + 1.0);
        put(std::fprintf(f, vn_format, nx / length, ny / length, 1.0 / length));
      }
    const uint64_t rows = last_row - first_row + 1, total = written + rows * n;
    for (uint64_t j = 0; j + 1 < rows; ++j)
      for (uint64_t i = 0; i + 1 < n; ++i) {
        // Corners a b (this row), c d (the next), 1-based; relative: counted back from the last.
        long long a = static_cast<long long>(written + j * n + i + 1), b = a + 1, c = a + static_cast<long long>(n), d = c + 1;
        if (layout == ObjLayout::kRelativeQuads) {
          const long long after = static_cast<long long>(total) + 1;
          a -= after, b -= after, c -= after, d -= after;
        }
        if (!attributes)
          put(std::fprintf(f, "f %lld %lld %lld\nf %lld %lld %lld\n", a, b, d, a, d, c));
        else if (quads)
          put(std::fprintf(f, "f %lld/%lld/%lld %lld/%lld/%lld %lld/%lld/%lld %lld/%lld/%lld\n", a, a, a, b, b, b, d, d, d, c, c, c));
        else
          put(std::fprintf(f, "f %lld/%lld/%lld %lld/%lld/%lld %lld/%lld/%lld\nf %lld/%lld/%lld %lld/%lld/%lld %lld/%lld/%lld\n",
                           a, a, a, b, b, b, d, d, d, a, a, a, d, d, d, c, c, c));
      }
    written = total;
  }
  return bytes;
}

bool write_file(const std::string& path, ObjLayout layout, uint64_t n, std::string* reason) {
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) {
    *reason = "cannot open";
    return false;
  }
  static char buffer[1 << 20];
  std::setvbuf(f, buffer, _IOFBF, sizeof buffer);
  write_grid(f, layout, n);
  const bool ok = std::ferror(f) == 0;
  if (std::fclose(f) != 0 || !ok) {
    *reason = "write failed (disk full?)";
    return false;
  }
  return true;
}

bool write_materials(const std::string& path, std::string* error) {
  return pfx::app::write_atomically(path, [&](const std::string& temp, std::string* reason) {
    FILE* f = std::fopen(temp.c_str(), "wb");
    if (!f) {
      *reason = "cannot open";
      return false;
    }
    for (int m = 0; m < kMaterials; ++m)
      std::fprintf(f, "newmtl material%d\nKd %.2f 0.5 0.5\nKs 0.1 0.1 0.1\nNs 32\n\n", m, 0.25 * (m + 1));
    return std::fclose(f) == 0;
  }, error);
}

}  // namespace

const std::vector<ObjLayout>& all_layouts() {
  static const std::vector<ObjLayout> layouts = [] {
    std::vector<ObjLayout> list;
    for (const LayoutInfo& info : kLayouts) list.push_back(info.layout);
    return list;
  }();
  return layouts;
}

const char* layout_name(ObjLayout layout) {
  for (const LayoutInfo& info : kLayouts)
    if (info.layout == layout) return info.name;
  return "?";
}

bool layout_from_name(const std::string& name, ObjLayout* out) {
  for (const LayoutInfo& info : kLayouts)
    if (name == info.name) {
      *out = info.layout;
      return true;
    }
  return false;
}

bool generate_obj(const std::string& directory, ObjLayout layout, double megabytes, GeneratedObj* out,
                  std::string* error) {
  // The size per vertex, measured on a small grid, sets N; the numbers' digits grow with N a little.
  FILE* null = std::fopen("/dev/null", "wb");
  if (!null) {
    *error = "cannot open /dev/null";
    return false;
  }
  const uint64_t probe = 200;
  const double per_vertex = double(write_grid(null, layout, probe)) / double(probe * probe);
  std::fclose(null);
  const uint64_t n = std::max<uint64_t>(2, static_cast<uint64_t>(std::sqrt(megabytes * 1e6 / per_vertex)));
  char name[96];
  std::snprintf(name, sizeof name, "%s-%gmb.obj", layout_name(layout), megabytes);
  out->path = (fs::path(directory) / name).string();
  out->grid = n;
  out->triangles = 2 * (n - 1) * (n - 1);
  std::error_code ec;
  if (layout == ObjLayout::kObjects && !write_materials((fs::path(directory) / "materials.mtl").string(), error))
    return false;
  if (!fs::exists(out->path, ec) &&
      !pfx::app::write_atomically(out->path, [&](const std::string& temp, std::string* reason) {
        return write_file(temp, layout, n, reason);
      }, error))
    return false;
  out->bytes = fs::file_size(out->path, ec);
  return true;
}

}  // namespace pfx::bench
