#include "lights_bench_report.hpp"

#include <algorithm>
#include <cstdio>
#include <map>

#include <nlohmann/json.hpp>

#include "atomic_file.hpp"
#include "gnuplot_png.hpp"

namespace pfx::bench {
namespace {

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

std::string size_of(const LightsCell& c) { return std::to_string(c.width) + "x" + std::to_string(c.height); }

// The fastest mode other than brute force at a size and count.
const LightsCell* best(const LightsResults& r, int width, int height, int lights) {
  const LightsCell* found = nullptr;
  for (const auto& c : r.cells)
    if (c.width == width && c.height == height && c.lights == lights && c.mode != "brute" && c.ran &&
        (!found || c.total_ms < found->total_ms))
      found = &c;
  return found;
}

const char* kTableHeader =
    "| size | lights | mode | frames | in view | cull ms | shade ms | total ms | x copy | speed-up | lists | "
    "list mean | list max | list entries | SSBO bytes |\n"
    "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";

std::string table_row(const LightsCell& c, const std::string& lights) {
  std::string md = "| " + size_of(c) + " | " + lights + " | " + c.mode + " | ";
  if (!c.ran)
    return md + "0 | | | | *" + format("%.0f", c.total_ms) + " estimated* | *" + format("%.1f", c.ratio_to_copy) +
           "* | 1 | | | | | |\n";
  return md + std::to_string(c.frames) + (c.warmup ? "+" + std::to_string(c.warmup) : "") + " | " +
         std::to_string(c.lights_in_view) + " | " + format("%.2f", c.cull_ms) + " | " + format("%.2f", c.shade_ms) +
         " | " + format("%.2f", c.total_ms) + " | " + format("%.1f", c.ratio_to_copy) + " | " +
         (c.speedup > 0 ? format("%.1f", c.speedup) + (c.speedup_estimated ? " *est*" : "") : "") + " | " +
         std::to_string(c.lists) + " | " + format("%.1f", c.list_mean) + " | " + std::to_string(c.list_max) + " | " +
         std::to_string(c.list_entries) + " | " + std::to_string(c.ssbo_bytes) + " |\n";
}

nlohmann::ordered_json cell_json(const LightsCell& c) {
  return {{"width", c.width}, {"height", c.height}, {"lights", c.lights}, {"mode", c.mode}, {"ran", c.ran},
          {"frames", c.frames}, {"warmup", c.warmup}, {"cull_ms", c.cull_ms}, {"shade_ms", c.shade_ms},
          {"total_ms", c.total_ms}, {"ratio_to_copy", c.ratio_to_copy}, {"speedup", c.speedup},
          {"speedup_estimated", c.speedup_estimated}, {"lights_in_view", c.lights_in_view}, {"lists", c.lists},
          {"list_mean", c.list_mean}, {"list_max", c.list_max}, {"list_entries", c.list_entries},
          {"ssbo_bytes", c.ssbo_bytes}, {"reach_mean", c.reach_mean}, {"lit_mean", c.lit_mean},
          {"tile_reach_mean", c.tile_reach_mean}};
}

}  // namespace

std::string lights_markdown(const LightsResults& r) {
  std::string md = "## tiledlights against the light count (pfx-bench --lights)\n\n";
  md += "Renderer: " + r.renderer + " (timing: " + r.timing + "). Medians of " + std::to_string(r.frames) +
        " frames after " + std::to_string(r.warmup) +
        " warm-up (frames column: timed+warm-up); light-field scene (one light per 4 m^2, the floor grows "
        "with the count). Brute force ran only where one frame was predicted to finish in " +
        format("%.0f", r.brute_limit_s) +
        " s, timing as many frames as fit; *estimated* cells are its linear prediction from the last count that "
        "ran, and speed-ups against them are marked *est*.\n\n";
  for (const auto& [size, ms] : r.copy_ms) md += "- copy pass at " + size + ": " + format("%.3f", ms) + " ms\n";
  md += "\n" + std::string(kTableHeader);
  for (const auto& c : r.cells) md += table_row(c, std::to_string(c.lights));
  // The two targets, read off the table.
  md += "\n### Targets\n\n";
  std::map<std::string, std::pair<int, int>> sizes;
  for (const auto& c : r.cells) sizes[size_of(c)] = {c.width, c.height};
  for (const auto& [name, wh] : sizes) {
    if (const LightsCell* b = best(r, wh.first, wh.second, 10000))
      md += "- " + name + ", 10,000 lights: best mode " + b->mode + ", " + format("%.1f", b->speedup) + "x brute force" +
            (b->speedup_estimated ? " (brute estimated)" : "") + " (target >= 50x): " +
            (b->speedup >= 50 ? "met" : "not met") + "\n";
    const LightsCell* few = best(r, wh.first, wh.second, 1000);
    const LightsCell* many = best(r, wh.first, wh.second, 100000);
    if (few && many) {
      // The same mode at both counts: the one best at 100,000.
      for (const auto& c : r.cells)
        if (c.width == wh.first && c.height == wh.second && c.lights == 1000 && c.mode == many->mode) few = &c;
      const double growth = few->shade_ms > 0 ? many->shade_ms / few->shade_ms : 0;
      md += "- " + name + ", shading of " + many->mode + " from 1,000 to 100,000 lights: x" + format("%.2f", growth) +
            " (target <= 2): " + (growth <= 2 ? "met" : "not met") + "\n";
    }
  }
  if (!r.dense_cells.empty()) {
    md += "\n### Dense: the demo scene with more lights in the same room\n\n";
    md += "pfx-render --demo --lights N --seed " + std::to_string(r.dense_seed) +
          ": the demo's 400 lights plus N more inside the floor's box, from 0.2 to 4 m up; brute force measured "
          "in this run (frames column), every speed-up against it.\n\n" + kTableHeader;
    for (const auto& c : r.dense_cells) md += table_row(c, "400 + " + std::to_string(c.lights));
    md += "\n";
    std::map<int, const LightsCell*> best_dense;
    for (const auto& c : r.dense_cells)
      if (c.mode != "brute" && c.speedup > 0 && (!best_dense[c.lights] || c.speedup > best_dense[c.lights]->speedup))
        best_dense[c.lights] = &c;
    for (const auto& c : r.dense_cells)
      if (c.mode == "brute" && c.reach_mean > 0)
        md += "- 400 + " + std::to_string(c.lights) + " lights: brute force sums " + std::to_string(c.lights_in_view) +
              " lights at each pixel with geometry; on average " + format("%.1f", c.reach_mean) +
              " reach its point and " + format("%.1f", c.lit_mean) +
              " of those light it (a term that is not zero). A method summing only the lights that reach is at "
              "most " + format("%.1f", double(c.lights_in_view) / c.reach_mean) +
              "x faster than brute force here; any exact method at most " +
              (c.lit_mean > 0 ? format("%.1f", double(c.lights_in_view) / c.lit_mean) + "x" : std::string("unbounded")) +
              ". Lists of 16-pixel tiles culled perfectly would sum " + format("%.1f", c.tile_reach_mean) +
              " (at most " + format("%.1f", double(c.lights_in_view) / c.tile_reach_mean) + "x)\n";
    for (const auto& [lights, b] : best_dense)
      md += "- dense, 400 + " + std::to_string(lights) + " lights: best mode " + b->mode + ", " +
            format("%.1f", b->speedup) + "x brute force measured in this run (target >= 20x): " +
            (b->speedup >= 20 ? "met" : "not met") + "\n";
  }
  if (!r.cutoffs.empty()) {
    md += "\n### Error against the un-windowed sum as the cutoff varies\n\n";
    md += std::to_string(r.error_width) + "x" + std::to_string(r.error_height) + ", " + std::to_string(r.error_lights) +
          " lights, mode " + r.error_mode +
          ". Error: RMSE against the plugin's ideal reference (every light at every pixel, no window) divided "
          "by the RMS of the light that reference adds; max: the largest absolute difference.\n\n";
    md += "| range rule | cutoff | total ms | x copy | list mean | RMSE / change | max abs |\n";
    md += "|---|---:|---:|---:|---:|---:|---:|\n";
    for (const auto& p : r.cutoffs)
      md += "| " + p.rule + " | " + (p.rule == "seed" ? std::string("-") : format("%g", p.cutoff)) + " | " +
            format("%.2f", p.total_ms) + " | " + format("%.1f", p.ratio_to_copy) + " | " + format("%.1f", p.list_mean) +
            " | " + format("%.4g", p.error.change_relative_rmse) + " | " + format("%.4g", p.error.max_abs) + " |\n";
  }
  if (!r.notes.empty()) {
    md += "\n### Notes\n\n";
    for (const auto& note : r.notes) md += "- " + note + "\n";
  }
  return md;
}

bool write_lights_reports(LightsResults& r, const std::string& dir, std::string* error) {
  nlohmann::ordered_json root;
  root["renderer"] = r.renderer;
  root["timing"] = r.timing;
  root["frames"] = r.frames;
  root["warmup"] = r.warmup;
  root["brute_limit_s"] = r.brute_limit_s;
  for (const auto& [size, ms] : r.copy_ms) root["copy_ms"][size] = ms;
  root["cells"] = nlohmann::ordered_json::array();
  for (const auto& c : r.cells) root["cells"].push_back(cell_json(c));
  root["dense"] = {{"seed", r.dense_seed}, {"cells", nlohmann::ordered_json::array()}};
  for (const auto& c : r.dense_cells) root["dense"]["cells"].push_back(cell_json(c));
  root["error"] = {{"width", r.error_width}, {"height", r.error_height}, {"lights", r.error_lights},
                   {"mode", r.error_mode}, {"points", nlohmann::ordered_json::array()}};
  for (const auto& p : r.cutoffs)
    root["error"]["points"].push_back({{"range_rule", p.rule}, {"cutoff", p.cutoff}, {"total_ms", p.total_ms},
                                       {"ratio_to_copy", p.ratio_to_copy}, {"list_mean", p.list_mean},
                                       {"rmse_over_change", p.error.change_relative_rmse},
                                       {"relative_rmse", p.error.relative_rmse}, {"max_abs", p.error.max_abs}});
  root["notes"] = r.notes;

  // Plots first, so a missing gnuplot becomes a note in the written reports.
  std::string time_script = "set terminal pngcairo size 900,600\nset output '__OUT__'\nset logscale xy\nset grid\n"
                            "set xlabel 'lights'\nset ylabel 'total ms per frame'\nset key outside right\n"
                            "set title '" + r.renderer + "'\nplot ";
  std::string data;
  std::map<std::string, std::vector<const LightsCell*>> curves;
  for (const auto& c : r.cells)
    if (c.lights > 0) curves[c.mode + " " + size_of(c) + (c.ran ? "" : " (estimated)")].push_back(&c);
  bool first = true;
  for (const auto& [name, cells] : curves) {
    time_script += std::string(first ? "" : ", ") + "'-' using 1:2 with linespoints title '" + name + "'";
    first = false;
    for (const LightsCell* c : cells) data += std::to_string(c->lights) + " " + format("%.6f", c->total_ms) + "\n";
    data += "e\n";
  }
  std::string plot_error;
  if (!curves.empty() && !write_gnuplot_png(dir + "/lights_time.png", time_script + "\n" + data, &plot_error))
    r.notes.push_back("no lights_time.png: " + plot_error);
  if (!r.cutoffs.empty()) {
    std::string script = "set terminal pngcairo size 900,600\nset output '__OUT__'\nset logscale xy\nset grid\n"
                         "set xlabel 'time (x plain copy pass)'\nset ylabel 'RMSE vs un-windowed sum / RMS of its light'\n"
                         "set title 'tiledlights " + r.error_mode + ", cutoff labelled'\n"
                         "plot '-' using 1:2 with linespoints title 'cutoff rule', '-' using 1:2:3 with labels offset 1,1 "
                         "notitle, '-' using 1:2 with points pointsize 2 title 'range 3 sqrt(max colour)'\n";
    std::string points, labels, seed;
    for (const auto& p : r.cutoffs) {
      const double y = p.error.change_relative_rmse > 0 ? p.error.change_relative_rmse : 1e-12;
      const std::string xy = format("%.6f", p.ratio_to_copy) + " " + format("%.9f", y);
      if (p.rule == "seed") seed += xy + "\n";
      else {
        points += xy + "\n";
        labels += xy + " " + format("%g", p.cutoff) + "\n";
      }
    }
    if (!write_gnuplot_png(dir + "/lights_error.png", script + points + "e\n" + labels + "e\n" + seed + "e\n", &plot_error))
      r.notes.push_back("no lights_error.png: " + plot_error);
  }
  root["notes"] = r.notes;
  return pfx::app::write_text_atomically(dir + "/lights.json", root.dump(2) + "\n", error) &&
         pfx::app::write_text_atomically(dir + "/lights.md", lights_markdown(r), error);
}

}  // namespace pfx::bench
