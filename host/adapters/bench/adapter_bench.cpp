// pfx-adapter-bench: what the video-host adapters cost, measured in the real hosts. For each row
// a host program (ffmpeg, gst-launch-1.0) runs the same clip twice, with a short and a long
// frame count; the difference of the two wall times over the difference of the frame counts is
// the time one more frame takes, without the program's start-up (plugin scan, GL context, shader
// compiles). Each row runs --runs times and its median is kept. A plain full-screen RGBA16F copy
// pass at the same size is timed in this process before and after the rows: the unit the adapters'
// extra time is quoted in, since absolute times on a shared software renderer drift.
//
//   pfx-adapter-bench [--size WxH] [--frames SHORT,LONG] [--runs N] [--json FILE] [--vulkan]
//                     [--vkbasalt-fx FILE.fx]... [--reshade-include DIR] [--reshade-textures DIR]
//
// The adapters are the ones beside this program (BIN/../lib/frei0r-1, BIN/../lib/gstreamer-1.0);
// ffmpeg's glow comes from Debian's frei0r-plugins, gleffects from gstreamer1.0-gl.
// --vulkan measures the Vulkan layer instead (BIN/../share/vulkan/implicit_layer.d), in vkcube
// (vulkan-tools) on a display (xvfb-run), beside vkBasalt's CAS (package vkbasalt) as the peer.
// --vkbasalt-fx measures vkBasalt running ReShade FX files instead: vkcube alone, then one row per
// file, so that an FX effect's cost in pfx (pfx-bench) has the peer's figure beside it.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "adapter_report.hpp"
#include "adapter_rows.hpp"
#include "cli_text.hpp"
#include "copy_pass.hpp"
#include "exit_codes.hpp"
#include "headless_context.hpp"
#include "plugin_directory.hpp"

namespace fs = std::filesystem;
using pfx::adapter_bench::Row;
extern char** environ;

namespace {

struct Options {
  int width = 1920, height = 1080;
  int short_frames = 8, long_frames = 32;
  int runs = 3;
  std::string json;
  bool vulkan = false;
  std::vector<std::string> vkbasalt_fx;  // FX files for vkBasalt; rows of their own when given
  std::string reshade_include;           // vkBasalt's reshadeIncludePath ("" for pfx's headers)
  std::string reshade_textures;          // vkBasalt's reshadeTexturePath ("" for each file's folder)
  std::vector<std::string> pfx_chains;   // chains for pfx's layer beside vkBasalt's rows
};

const char* const kUsage =
    "usage: pfx-adapter-bench [--size WxH] [--frames SHORT,LONG] [--runs N] [--json FILE] [--vulkan]\n"
    "                         [--vkbasalt-fx FILE.fx]... [--reshade-include DIR] [--reshade-textures DIR]\n"
    "                         [--pfx-chain CHAIN]...\n"
    "\n"
    "What the video-host adapters (ffmpeg, GStreamer) or the Vulkan layer cost, in the real hosts: each\n"
    "row runs SHORT and LONG frames (default 8,32), the time of one more frame is the difference of the\n"
    "wall times over LONG-SHORT; median of N runs (default 3). The unit is a full-frame RGBA16F copy\n"
    "pass at the same size (default 1920x1080) timed in this process before and after the rows.\n"
    "\n"
    "  --vulkan               vkcube (vulkan-tools) alone, through pfx's Vulkan layer (chain none natively\n"
    "                         and through the GL, bloom; shared and host memory) and through vkBasalt's\n"
    "                         CAS; needs a display (xvfb-run) and a Vulkan driver (lavapipe:\n"
    "                         VK_ICD_FILENAMES)\n"
    "  --vkbasalt-fx FILE.fx  (repeatable; implies --vulkan) the rows become vkcube alone and vkcube\n"
    "                         through vkBasalt running each ReShade FX file (its first technique); a file\n"
    "                         vkBasalt cannot compile is listed with its first error, not measured\n"
    "  --reshade-include DIR  vkBasalt's reshadeIncludePath: a folder with ReShade.fxh (default: pfx's\n"
    "                         own headers, PLUGINS/fx/include)\n"
    "  --reshade-textures DIR vkBasalt's reshadeTexturePath (default: each FX file's folder)\n"
    "  --pfx-chain CHAIN      (repeatable; with --vkbasalt-fx) also vkcube through pfx's Vulkan layer\n"
    "                         running CHAIN (\"fx_lumasharpen\"), its FX effects found in the FX files'\n"
    "                         folders, natively and through the GL (PFX_VK_NATIVE=0): the same\n"
    "                         application and effect every way in one run\n"
    "  --json FILE            also write the rows as JSON\n";

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values.empty() ? 0 : values[values.size() / 2];
}

// Runs argv with `environment` added, its output (stdout and stderr) to the file `output`; the
// wall time in seconds, or -1 when it failed.
double timed_run(const std::vector<std::string>& argv, const std::vector<std::string>& environment,
                 const std::string& output = "/dev/null") {
  std::vector<std::string> variables;
  for (char** entry = environ; *entry; ++entry) variables.push_back(*entry);
  variables.insert(variables.end(), environment.begin(), environment.end());
  std::vector<char*> args, env;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  for (const auto& v : variables) env.push_back(const_cast<char*>(v.c_str()));
  args.push_back(nullptr);
  env.push_back(nullptr);
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid == 0) {
    std::freopen(output.c_str(), "w", stdout);
    dup2(fileno(stdout), fileno(stderr));
    execvpe(args[0], args.data(), env.data());
    _exit(127);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? seconds : -1;
}

std::vector<std::string> words(const std::string& text) { return pfx::app::split_list(text, ' '); }

bool parse(int argc, char** argv, Options* options) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    std::string error;
    if (arg == "--size" && has_value) {
      if (!pfx::app::parse_frame_size("--size", argv[++i], &options->width, &options->height, &error)) {
        std::fprintf(stderr, "pfx-adapter-bench: %s\n", error.c_str());
        return false;
      }
    } else if (arg == "--frames" && has_value) {
      if (std::sscanf(argv[++i], "%d,%d", &options->short_frames, &options->long_frames) != 2 ||
          options->short_frames < 1 || options->long_frames <= options->short_frames)
        return false;
    } else if (arg == "--runs" && has_value) {
      options->runs = std::atoi(argv[++i]);
      if (options->runs < 1) return false;
    } else if (arg == "--json" && has_value) {
      options->json = argv[++i];
    } else if (arg == "--vulkan") {
      options->vulkan = true;
    } else if (arg == "--vkbasalt-fx" && has_value) {
      options->vkbasalt_fx.push_back(fs::absolute(argv[++i]).string());
      options->vulkan = true;
    } else if (arg == "--reshade-include" && has_value) {
      options->reshade_include = fs::absolute(argv[++i]).string();
    } else if (arg == "--reshade-textures" && has_value) {
      options->reshade_textures = fs::absolute(argv[++i]).string();
    } else if (arg == "--pfx-chain" && has_value) {
      options->pfx_chains.push_back(argv[++i]);
    } else {
      return false;
    }
  }
  return true;
}

// vkcube alone, through pfx's layer on both paths, and through vkBasalt; each row's `what` is the
// variables it runs with. With --vkbasalt-fx: vkcube alone and vkBasalt running each FX file.
std::vector<Row> vulkan_rows(const fs::path& scratch, const Options& options) {
  std::ofstream(scratch / "vkBasalt.conf") << "effects = cas\n";
  const std::string alone = "alone (layers off)";
  if (!options.vkbasalt_fx.empty()) {
    std::vector<Row> rows = {{"vkcube", alone, "DISABLE_PFX_VULKAN=1", ""}};
    const std::string include = !options.reshade_include.empty()
                                    ? options.reshade_include
                                    : (fs::path(pfx::app::default_plugin_directory()) / "fx" / "include").string();
    for (size_t i = 0; i < options.vkbasalt_fx.size(); ++i) {
      const fs::path file = options.vkbasalt_fx[i];
      const std::string textures =
          options.reshade_textures.empty() ? file.parent_path().string() : options.reshade_textures;
      // vkBasalt runs its built-in effect when a name is one of its own (cas, fxaa, smaa, deband,
      // lut, dls), whatever file the config gives that name: each file gets a name it has not.
      const std::string name = "fx" + std::to_string(i);
      const fs::path config = scratch / (name + ".conf");
      std::ofstream(config) << "effects = " << name << "\n"
                            << name << " = " << file.string() << "\n"
                            << "reshadeIncludePath = " << include << "\n"
                            << "reshadeTexturePath = " << textures << "\n";
      rows.push_back({"vkcube", "vkBasalt " + file.filename().string(),
                      "DISABLE_PFX_VULKAN=1 ENABLE_VKBASALT=1 VKBASALT_CONFIG_FILE=" + config.string(), alone});
      rows.back().fx_file = true;
    }
    // pfx's layer finds the effects where vkBasalt found the files.
    std::string folders;
    for (const std::string& file : options.vkbasalt_fx)
      folders += (folders.empty() ? "" : ":") + fs::path(file).parent_path().string();
    // Each chain on both of the layer's paths: native where its effects run on Vulkan, and
    // through the GL.
    for (const std::string& chain : options.pfx_chains) {
      const std::string variables = "ENABLE_PFX_VULKAN=1 PFX_INJECT_CHAIN=" + chain + " PFX_FX_PATH=" + folders;
      rows.push_back({"vkcube", "pfx layer chain=" + chain + ", native", variables, alone});
      rows.push_back({"vkcube", "pfx layer chain=" + chain + ", through GL", variables + " PFX_VK_NATIVE=0", alone});
    }
    return rows;
  }
  return {
      {"vkcube", alone, "DISABLE_PFX_VULKAN=1", ""},
      {"vkcube", "pfx layer chain=none, native", "ENABLE_PFX_VULKAN=1 PFX_INJECT_CHAIN=none", alone},
      {"vkcube", "pfx layer chain=none, GL path, shared memory",
       "ENABLE_PFX_VULKAN=1 PFX_INJECT_CHAIN=none PFX_VK_NATIVE=0", alone},
      {"vkcube", "pfx layer chain=bloom, shared memory", "ENABLE_PFX_VULKAN=1 PFX_INJECT_CHAIN=bloom", alone},
      {"vkcube", "pfx layer chain=none, GL path, host memory",
       "ENABLE_PFX_VULKAN=1 PFX_INJECT_CHAIN=none PFX_VK_NATIVE=0 PFX_VK_HOST_MEMORY=1", alone},
      {"vkcube", "pfx layer chain=bloom, host memory",
       "ENABLE_PFX_VULKAN=1 PFX_INJECT_CHAIN=bloom PFX_VK_HOST_MEMORY=1", alone},
      {"vkcube", "vkBasalt cas", "ENABLE_VKBASALT=1 VKBASALT_CONFIG_FILE=" + (scratch / "vkBasalt.conf").string(), alone},
  };
}

// vkcube for `frames` frames with the row's variables.
std::vector<std::string> vkcube_command(const Row& row, int frames, const Options& options) {
  std::vector<std::string> argv = {"env"};
  for (const auto& word : words(row.what)) argv.push_back(word);
  for (const std::string& arg : {std::string("vkcube"), std::string("--c"), std::to_string(frames),
                                 std::string("--width"), std::to_string(options.width), std::string("--height"),
                                 std::to_string(options.height)})
    argv.push_back(arg);
  return argv;
}

// The variables the hosts run with: where they find the adapters beside this program, and where the
// Vulkan loader finds pfx's layer.
std::vector<std::string> host_environment() {
  const fs::path lib = fs::path(pfx::app::executable_directory()) / ".." / "lib";
  const char* data_dirs = std::getenv("XDG_DATA_DIRS");
  return {"FREI0R_PATH=" + (lib / "frei0r-1").string() + ":/usr/lib/frei0r-1",
          "GST_PLUGIN_PATH=" + (lib / "gstreamer-1.0").string(), "GST_GL_PLATFORM=egl", "GST_GL_WINDOW=egl-device",
          // Where the loader finds pfx's layer manifest in a build tree (pfx-inject does the same).
          "XDG_DATA_DIRS=" + (lib / ".." / "share").string() + ":" +
              (data_dirs ? data_dirs : "/usr/local/share:/usr/share")};
}

// ffmpeg's and GStreamer's rows: each host alone, through pfx's adapters, and through what a user
// would pick instead.
std::vector<Row> video_host_rows() {
  return {
      {"ffmpeg", "no filter (decode, to RGBA)", "format=rgba", ""},
      {"ffmpeg", "pfx_chain chain=none", "format=rgba,frei0r=filter_name=pfx_chain:filter_params=none",
       "no filter (decode, to RGBA)"},
      {"ffmpeg", "pfx_chain bloom at strength 0 (a no-op)",
       "format=rgba,frei0r=filter_name=pfx_chain:filter_params=bloom|bloom.strength=0", "no filter (decode, to RGBA)"},
      {"ffmpeg", "pfx_bloom", "format=rgba,frei0r=filter_name=pfx_bloom", "no filter (decode, to RGBA)"},
      {"ffmpeg", "pfx_chain chain=bloom", "format=rgba,frei0r=filter_name=pfx_chain:filter_params=bloom",
       "no filter (decode, to RGBA)"},
      {"ffmpeg", "pfx_chain chain=bloom,bloom", "format=rgba,frei0r=filter_name=pfx_chain:filter_params=bloom\\,bloom",
       "pfx_chain chain=bloom"},
      {"ffmpeg", "frei0r glow", "format=rgba,frei0r=filter_name=glow", "no filter (decode, to RGBA)"},
      {"ffmpeg", "gblur sigma=8", "format=rgba,gblur=sigma=8", "no filter (decode, to RGBA)"},
      {"gst-launch-1.0", "no filter (upload, download)", "", ""},
      {"gst-launch-1.0", "pfxfilter chain=none", "pfxfilter chain=none !", "no filter (upload, download)"},
      {"gst-launch-1.0", "pfxfilter bloom at strength 0 (a no-op)", "pfxfilter chain=bloom set=bloom.strength=0 !",
       "no filter (upload, download)"},
      {"gst-launch-1.0", "pfxfilter chain=bloom", "pfxfilter chain=bloom !", "no filter (upload, download)"},
      {"gst-launch-1.0", "pfxfilter chain=bloom,bloom", "pfxfilter chain=\"bloom,bloom\" !", "pfxfilter chain=bloom"},
      {"gst-launch-1.0", "gleffects effect=glow", "gleffects effect=glow !", "no filter (upload, download)"},
  };
}

// How the rows' host programs run: with the adapters' environment, ffmpeg on the clip.
struct Hosts {
  const Options& options;
  std::vector<std::string> environment;
  std::string clip;

  // The clip ffmpeg's rows decode: the long run's frames of a test pattern, losslessly.
  bool make_clip() const {
    const std::string size = std::to_string(options.width) + "x" + std::to_string(options.height);
    return timed_run({"ffmpeg", "-hide_banner", "-loglevel", "error", "-f", "lavfi", "-i",
                      "testsrc2=size=" + size + ":rate=25", "-frames:v", std::to_string(options.long_frames), "-c:v",
                      "ffv1", "-y", clip},
                     environment) >= 0;
  }

  // The row's host for `frames` frames.
  std::vector<std::string> command(const Row& row, int frames) const {
    if (row.host == "vkcube") return vkcube_command(row, frames, options);
    if (row.host == "ffmpeg")
      return {"ffmpeg", "-hide_banner", "-loglevel", "error", "-i", clip, "-frames:v",
              std::to_string(frames), "-vf", row.what, "-f", "null", "-"};
    std::vector<std::string> argv = {"gst-launch-1.0", "-q"};
    const std::string pipeline = "videotestsrc num-buffers=" + std::to_string(frames) +
                                 " pattern=smpte ! video/x-raw,format=RGBA,width=" + std::to_string(options.width) +
                                 ",height=" + std::to_string(options.height) + " ! glupload ! " + row.what +
                                 " gldownload ! fakesink sync=false";
    for (const auto& word : words(pipeline)) argv.push_back(word);
    return argv;
  }
};

// vkBasalt goes on without an effect it cannot compile (it logs "vkBasalt err:" and vkcube ends
// with 0), which would time plain vkcube: one frame first, its log read. False, with the row's
// not_run saying why, when vkBasalt could not compile it or vkcube failed.
bool fx_file_compiles(const Hosts& hosts, const fs::path& scratch, Row* row) {
  const fs::path log = scratch / "vkbasalt-check.log";
  const bool ran = timed_run(hosts.command(*row, 1), hosts.environment, log.string()) >= 0;
  std::ifstream in(log);
  std::string last;
  for (std::string line; std::getline(in, line); last = line)
    if (line.rfind("vkBasalt err:", 0) == 0) {
      row->not_run = line.substr(13);
      break;
    }
  if (row->not_run.empty() && !ran) row->not_run = " vkcube failed; its last words: " + last;
  if (row->not_run.empty()) return true;
  std::fprintf(stderr, "%s %s: not measured:%s\n", row->host.c_str(), row->name.c_str(), row->not_run.c_str());
  return false;
}

// The row's time a frame: the difference of a long and a short run's wall times over the
// difference of their frame counts, the median of --runs. False when a run failed.
bool measure_row(const Hosts& hosts, Row* row) {
  const Options& options = hosts.options;
  std::vector<double> per_frame;
  for (int run = 0; run < options.runs; ++run) {
    const double short_run = timed_run(hosts.command(*row, options.short_frames), hosts.environment);
    const double long_run = timed_run(hosts.command(*row, options.long_frames), hosts.environment);
    if (short_run < 0 || long_run < 0) {
      std::fprintf(stderr, "pfx-adapter-bench: %s %s failed\n", row->host.c_str(), row->name.c_str());
      return false;
    }
    per_frame.push_back(1000 * (long_run - short_run) / (options.long_frames - options.short_frames));
  }
  row->ms_per_frame = median(per_frame);
  std::fprintf(stderr, "%s %s: %.1f ms a frame\n", row->host.c_str(), row->name.c_str(), row->ms_per_frame);
  return true;
}

bool asks_for_help(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") return true;
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (asks_for_help(argc, argv)) {
    std::fputs(kUsage, stdout);
    return pfx::exit_code::kOk;
  }
  if (!parse(argc, argv, &options)) {
    std::fputs(kUsage, stderr);
    return pfx::exit_code::kUsage;
  }
  std::string error;
  auto context = pfx::app::HeadlessContext::create(&error);
  if (!context) {
    std::fprintf(stderr, "pfx-adapter-bench: %s\n", error.c_str());
    return pfx::exit_code::kInternal;
  }
  const fs::path scratch = fs::temp_directory_path() / ("pfx-adapter-bench-" + std::to_string(getpid()));
  fs::create_directories(scratch);
  const Hosts hosts{options, host_environment(), (scratch / "clip.mkv").string()};
  if (!hosts.make_clip()) {
    std::fprintf(stderr, "pfx-adapter-bench: ffmpeg could not make the clip\n");
    return pfx::exit_code::kInternal;
  }

  std::vector<Row> rows = options.vulkan ? vulkan_rows(scratch, options) : video_host_rows();
  const double copy_before = pfx::gl::median_copy_pass_ms(options.width, options.height, 15);
  for (auto& row : rows) {
    if (row.fx_file && !fx_file_compiles(hosts, scratch, &row)) continue;
    if (!measure_row(hosts, &row)) return pfx::exit_code::kInternal;
  }
  const double copy_after = pfx::gl::median_copy_pass_ms(options.width, options.height, 15);
  fs::remove_all(scratch);

  pfx::adapter_bench::RunFacts facts;
  facts.renderer = context->renderer();
  facts.size = std::to_string(options.width) + "x" + std::to_string(options.height);
  facts.short_frames = options.short_frames;
  facts.long_frames = options.long_frames;
  facts.runs = options.runs;
  facts.copy_ms = (copy_before + copy_after) / 2;
  facts.copy_before_ms = copy_before;
  facts.copy_after_ms = copy_after;
  pfx::adapter_bench::print_report(rows, facts);
  if (!options.json.empty()) std::ofstream(options.json) << pfx::adapter_bench::report_json(rows, facts);
  return pfx::exit_code::kOk;
}
