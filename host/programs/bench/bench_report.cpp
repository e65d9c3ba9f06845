#include "bench_report.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>

#include <nlohmann/json.hpp>

#include "atomic_file.hpp"
#include "gnuplot_png.hpp"

namespace pfx::bench {
namespace {

bool write_text(const std::string& path, const std::string& text, std::string* error) {
  return pfx::app::write_atomically(
      path,
      [&](const std::string& temp, std::string* reason) {
        std::ofstream out(temp, std::ios::binary);
        out << text;
        out.close();
        if (!out) *reason = "write failed";
        return static_cast<bool>(out);
      },
      error);
}

nlohmann::ordered_json metrics_json(const std::optional<ErrorMetrics>& m) {
  if (!m) return nullptr;
  nlohmann::ordered_json j = {{"relative_rmse", m->relative_rmse}};
  if (m->change_relative_rmse >= 0) j["change_relative_rmse"] = m->change_relative_rmse;
  j["max_abs"] = m->max_abs;
  j["nonfinite"] = m->nonfinite;
  return j;
}

std::string fixed(double value, int digits) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", digits, value);
  return buffer;
}

std::string error_cell(const std::optional<ErrorMetrics>& m) {
  if (!m) return "—";
  char buffer[96];
  if (m->change_relative_rmse >= 0)
    std::snprintf(buffer, sizeof buffer, "%.3g / %.3g / %.3g", m->relative_rmse, m->change_relative_rmse, m->max_abs);
  else
    std::snprintf(buffer, sizeof buffer, "%.3g / — / %.3g", m->relative_rmse, m->max_abs);
  return buffer;
}

std::string shift_cell(const std::optional<ShiftFigures>& f) {
  if (!f) return "—";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.2g / %.3g", f->energy_cv, f->shape_rms);
  return buffer;
}

// The error a plot shows: relative to the change the reference makes, where there is one.
double plotted_error(const ErrorMetrics& m) {
  return m.change_relative_rmse > 0 ? m.change_relative_rmse : m.relative_rmse;
}

}  // namespace

bool write_bench_json(const BenchResults& results, const std::string& path, std::string* error) {
  nlohmann::ordered_json root;
  root["renderer"] = results.renderer;
  root["timing"] = results.timing;
  root["frames"] = results.frames;
  root["warmup"] = results.warmup;
  root["units"] = nlohmann::ordered_json::array();
  for (const auto& unit : results.units)
    root["units"].push_back({{"width", unit.width}, {"height", unit.height}, {"source", unit.source}, {"copy_ms", unit.copy_ms}});
  root["rows"] = nlohmann::ordered_json::array();
  for (const auto& row : results.rows) {
    nlohmann::ordered_json r;
    r["effect"] = row.effect;
    r["settings"] = row.settings;
    r["width"] = row.width;
    r["height"] = row.height;
    r["median_ms"] = row.median_ms;
    r["copy_ms"] = row.copy_ms;
    r["ratio_to_copy"] = row.ratio_to_copy;
    r["peak_target_bytes"] = row.peak_target_bytes;
    r["pass_count"] = row.pass_count;
    r["passes"] = nlohmann::ordered_json::array();
    for (const auto& pass : row.passes) r["passes"].push_back({{"pass", pass.pass}, {"median_ms", pass.median_ms}});
    r["error_model"] = metrics_json(row.error_model);
    r["error_ideal"] = metrics_json(row.error_ideal);
    if (row.error_truth) r["error_truth"] = metrics_json(row.error_truth);
    if (row.halo_px) r["halo_px"] = *row.halo_px;
    if (row.shift) r["shift"] = {{"energy_cv", row.shift->energy_cv}, {"shape_rms", row.shift->shape_rms}};
    if (!row.note.empty()) r["note"] = row.note;
    root["rows"].push_back(r);
  }
  root["notes"] = results.notes;
  return write_text(path, root.dump(2) + "\n", error);
}

std::string bench_markdown(const BenchResults& results) {
  std::string md = "# pfx-bench\n\nRenderer: " + results.renderer + "  \nTiming: " + results.timing + ", median of " +
                   std::to_string(results.frames) + " frames after " + std::to_string(results.warmup) +
                   " warm-up frames. Ratios are to a plain full-screen copy pass at the same size, timed before each of the row's frames (its median is the row's 'copy ms').\n\n";
  for (const auto& unit : results.units) {
    md += "## " + std::to_string(unit.width) + "x" + std::to_string(unit.height) +
          (unit.source.empty() ? std::string() : ", " + unit.source) + " — copy pass " + fixed(unit.copy_ms, 3) +
          " ms\n\n";
    bool truth = false, halo = false;
    for (const auto& row : results.rows)
      if (row.width == unit.width && row.height == unit.height) truth |= bool(row.error_truth), halo |= bool(row.halo_px);
    md += "| effect | settings | passes | median ms | copy ms | x copy | peak target bytes | error vs model (rel RMSE / of change / max) | "
          "error vs ideal (rel RMSE / of change / max) |" +
          std::string(truth ? " error vs truth (rel RMSE / of change / max) |" : "") + (halo ? " halo px |" : "") +
          " shift (energy CV / shape RMS) |\n";
    md += "|---|---|---:|---:|---:|---:|---:|---|---|" + std::string(truth ? "---|" : "") + (halo ? "---:|" : "") + "---|\n";
    for (const auto& row : results.rows) {
      if (row.width != unit.width || row.height != unit.height) continue;
      md += "| " + row.effect + " | " + row.settings + (row.note.empty() ? "" : " (" + row.note + ")") + " | " +
            std::to_string(row.pass_count) + " | " + fixed(row.median_ms, 3) + " | " + fixed(row.copy_ms, 3) + " | " +
            fixed(row.ratio_to_copy, 2) +
            " | " + std::to_string(row.peak_target_bytes) + " | " + error_cell(row.error_model) + " | " +
            error_cell(row.error_ideal) + " |" + (truth ? " " + error_cell(row.error_truth) + " |" : "") +
            (halo ? " " + (row.halo_px ? std::to_string(*row.halo_px) : std::string("—")) + " |" : "") + " " +
            shift_cell(row.shift) + " |\n";
    }
    md += "\n";
  }
  if (!results.notes.empty()) {
    md += "## Notes\n\n";
    for (const auto& note : results.notes) md += "- " + note + "\n";
  }
  return md;
}

bool write_bench_markdown(const BenchResults& results, const std::string& path, std::string* error) {
  return write_text(path, bench_markdown(results), error);
}

bool write_error_plot(const BenchResults& results, const std::string& path, std::string* error, std::string* skipped) {
  // One curve per effect, size and all settings but the last (the suite varies the last along a
  // curve: "mode=gather resolution=half samples=16, 32, ..."): (ratio to copy, error against the
  // ground truth where one was given, else against the ideal reference; relative to the change
  // the reference makes where that is known).
  bool truth = false;
  for (const auto& row : results.rows) truth |= bool(row.error_truth);
  std::map<std::string, std::vector<std::pair<double, double>>> curves;
  for (const auto& row : results.rows) {
    const std::optional<ErrorMetrics>& error = truth ? row.error_truth : row.error_ideal;
    if (!error) continue;
    const size_t last = row.settings.rfind(' ');
    const std::string fixed_settings = last == std::string::npos ? "" : " " + row.settings.substr(0, last);
    curves[row.effect + fixed_settings + " " + std::to_string(row.width) + "x" + std::to_string(row.height)].push_back(
        {row.ratio_to_copy, plotted_error(*error)});
  }
  for (auto& [name, points] : curves) std::sort(points.begin(), points.end());
  if (curves.empty()) {
    *skipped = "no effect has an ideal CPU reference yet: no error-against-time plot";
    return true;
  }
  std::string script = "set terminal pngcairo size 900,600\nset output '__OUT__'\n"
                       "set xlabel 'time (x plain copy pass)'\nset ylabel 'RMSE vs " +
                       std::string(truth ? "ground truth" : "ideal") + ": RMSE / RMS of the change (or of the reference)'\n"
                       "set logscale xy\nset grid\nset key outside right\nset title '" + results.renderer + "'\nplot ";
  std::string data;
  bool first = true;
  for (const auto& [name, points] : curves) {
    script += std::string(first ? "" : ", ") + "'-' using 1:2 with linespoints title '" + name + "'";
    first = false;
    for (const auto& [x, y] : points) data += fixed(x, 6) + " " + fixed(y > 0 ? y : 1e-12, 12) + "\n";
    data += "e\n";
  }
  script += "\n" + data;
  return write_gnuplot_png(path, script, error);
}

}  // namespace pfx::bench
