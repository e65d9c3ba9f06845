#include "import_report.hpp"

#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

namespace pfx::import {

namespace {

std::string vector3(const float v[3]) {
  char text[96];
  std::snprintf(text, sizeof text, "(%g, %g, %g)", v[0], v[1], v[2]);
  return text;
}

}  // namespace

std::string summary_text(const std::string& file, const pfx_import_result& r, double seconds) {
  std::string text = file + "\n";
  char line[256];
  std::snprintf(line, sizeof line,
                "  vertices   %u (unique)\n  triangles  %u\n  sub-meshes %u\n  materials  %u\n", r.vertex_count,
                r.index_count / 3, r.submesh_count, r.material_count);
  text += line;
  text += "  bounds     " + vector3(r.bounds_min) + " to " + vector3(r.bounds_max) + "\n";
  std::snprintf(line, sizeof line, "  skipped    %llu lines, %llu points\n  attributes normals%s%s\n",
                static_cast<unsigned long long>(r.lines_skipped), static_cast<unsigned long long>(r.points_skipped),
                r.texcoords ? ", texture coordinates" : "", r.colors ? ", colours" : "");
  text += line;
  std::snprintf(line, sizeof line, "  warnings   %llu\n", static_cast<unsigned long long>(r.warning_total));
  text += line;
  for (uint32_t i = 0; i < r.warning_count; ++i) text += std::string("    ") + r.warnings[i] + "\n";
  if (r.warning_total > r.warning_count)
    text += "    ... and " + std::to_string(r.warning_total - r.warning_count) + " more\n";
  std::snprintf(line, sizeof line, "  time       %.1f ms\n", seconds * 1000.0);
  text += line;
  return text;
}

std::string summary_json(const std::string& file, const pfx_import_result& r, double seconds) {
  nlohmann::ordered_json j;
  j["file"] = file;
  j["vertices"] = r.vertex_count;
  j["triangles"] = r.index_count / 3;
  j["submeshes"] = r.submesh_count;
  j["materials"] = r.material_count;
  j["bounds"] = {{r.bounds_min[0], r.bounds_min[1], r.bounds_min[2]}, {r.bounds_max[0], r.bounds_max[1], r.bounds_max[2]}};
  j["lines"] = r.lines_skipped;
  j["points"] = r.points_skipped;
  nlohmann::ordered_json warnings = nlohmann::ordered_json::array();
  for (uint32_t i = 0; i < r.warning_count; ++i) warnings.push_back(r.warnings[i]);
  j["warnings"] = warnings;
  j["warnings_total"] = r.warning_total;
  j["ms"] = std::round(seconds * 1e4) / 10.0;
  // Invalid UTF-8 in a file name or warning is replaced, not thrown.
  return j.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

}  // namespace pfx::import
