#include "inject_options.hpp"

#include "arg_reader.hpp"
#include "cli_text.hpp"

namespace pfx::inject {

std::string inject_usage() {
  return R"(usage: pfx-inject [options] -- APP [ARGS...]

Starts APP with libpfxinject.so preloaded: at every present (glXSwapBuffers, eglSwapBuffers) the
back buffer runs through a pfx chain, on the application's own context, and the result is
presented instead. The application is not changed; a context below OpenGL 4.5, an OpenGL ES
context or any failure leaves its frames untouched, with one line in the log.

  --preset FILE        a preset, pfx-view's .json or ReShade's .ini (chain and values); what it
                       names that is not there is left out with one warning; edits apply while
                       APP runs
  --chain LIST         effects in order, e.g. bloom,dof; "none": no effect, frames presented as drawn
                       (default: the preset's chain, else every effect found)
  --set EFFECT.P=V     a parameter value, after the preset (repeatable; bloom#2.x for a second bloom)
  --plugins DIR        plugin folder (repeatable; default: the one beside pfx-inject)
  --depth-near M       the application's near plane in metres, for its depth buffer (default 0.1)
  --depth-far M        its far plane, or inf (default 1000)
  --transfer T         how the back buffer's 8-bit values relate to light: srgb (default) or linear
  --capture N:PREFIX   for the N-th presented frame write PREFIX.app.exr (the frame as the chain
                       received it), PREFIX.out.exr (the chain's output) and PREFIX.png (what was
                       presented); all:PREFIX with %d in PREFIX for every frame (repeatable)
  --quit-after N       end the application after N presented frames
  --from-frame N       leave the first N-1 presented frames alone: the chain starts at frame N
                       (a splash screen; or, in tests, a frame drawn with no pfx code ever run)
  --panel              open the live control panel beside APP (pfx-view --attach): every effect on
                       or off, every parameter, presets saved and loaded, the chain's pass times
  --panel-option ARG   pass ARG to the panel's pfx-view (repeatable), e.g. --window 500x800
  --dry-run            run the chain every frame but present the application's own frame
  --log FILE           append the injector's messages to FILE (default: stderr)
  --resources-at LIST  after each of these presented frames (e.g. 500,5000) log the application's
                       resident memory and the GL objects of its context: a run that grows shows
  --bench FRAMES       run APP FRAMES frames alone, with an empty chain and with the chain, three
                       times each, and print each one's frame time and the cost in copy passes
  --bench-runs N       runs per configuration for --bench (default 3)
  --bench-json FILE    also write the --bench results as JSON
  -h, --help           this text

The plugins, the chain, the preset, every --set and every capture's folder are checked before
APP starts; a mistake is refused and APP is not started. Every setting reaches the library as an
environment variable (PFX_INJECT_*, docs/inject.md), so LD_PRELOAD=.../libpfxinject.so with those
variables does the same without this program.

Exit code: the application's own (128 + signal when a signal ended it), unchanged; pfx-inject's
own errors use codes applications and shells leave alone: 240 a usage error (bad option, chain,
preset, --set or capture), 241 libpfxinject.so or the effect plugins not found, 242 APP could not
be started, 243 --bench could not measure or write its results.
)";
}

bool parse_inject_options(const std::vector<std::string>& args, InjectOptions* out, std::string* error) {
  InjectOptions options;
  std::vector<std::string> ours;
  size_t dash = args.size();
  for (size_t i = 0; i < args.size(); ++i)
    if (args[i] == "--") {
      dash = i;
      break;
    }
  ours.assign(args.begin(), args.begin() + static_cast<long>(dash));
  if (dash < args.size()) options.command.assign(args.begin() + static_cast<long>(dash) + 1, args.end());

  app::ArgReader reader(ours, error);
  std::string value;
  double near_plane = options.settings.depth_near, far_plane = options.settings.depth_far;
  while (reader.next()) {
    const std::string& arg = reader.arg();
    if (arg == "-h" || arg == "--help") {
      options.help = true;
    } else if (arg == "--preset") {
      if (!reader.value(&options.settings.preset)) return false;
    } else if (arg == "--chain") {
      if (!reader.value(&value)) return false;
      options.settings.chain = value == "none" ? std::vector<std::string>{} : app::split_list(value);
      if (value != "none" && options.settings.chain->empty()) return reader.fail("--chain needs effect ids or none");
    } else if (arg == "--set") {
      if (!reader.value(&options.settings.sets)) return false;
      if (options.settings.sets.back().find('=') == std::string::npos)
        return reader.fail("--set " + options.settings.sets.back() + ": expected EFFECT.PARAM=VALUE");
    } else if (arg == "--plugins") {
      if (!reader.value(&options.settings.plugin_dirs)) return false;
    } else if (arg == "--depth-near" || arg == "--depth-far") {
      if (!reader.value(&value)) return false;
      const bool is_far = arg == "--depth-far";
      if (!parse_depth_plane(value, is_far, is_far ? &far_plane : &near_plane, error)) return reader.fail(arg + ": " + *error);
    } else if (arg == "--transfer") {
      if (!reader.value(&value)) return false;
      if (!app::parse_transfer(value, &options.settings.transfer, error)) return reader.fail("--transfer: " + *error);
    } else if (arg == "--capture") {
      if (!reader.value(&value)) return false;
      Capture capture;
      if (!parse_capture(value, &capture, error)) return reader.fail("--capture: " + *error);
      options.settings.captures.push_back(capture);
    } else if (arg == "--quit-after" || arg == "--from-frame" || arg == "--bench" || arg == "--bench-runs") {
      if (!reader.value(&value)) return false;
      long long count = 0;
      if (!app::parse_count(value, &count) || count < 1 || count > 100000000)
        return reader.fail(arg + " " + value + ": expected a whole number from 1");
      if (arg == "--quit-after") options.settings.quit_after = static_cast<uint64_t>(count);
      else if (arg == "--from-frame") options.settings.from_frame = static_cast<uint64_t>(count);
      else if (arg == "--bench") options.bench_frames = static_cast<int>(count);
      else options.bench_runs = static_cast<int>(count);
    } else if (arg == "--resources-at") {
      if (!reader.value(&value)) return false;
      if (!parse_frame_list(value, &options.settings.resources_at, error)) return reader.fail("--resources-at: " + *error);
    } else if (arg == "--bench-json") {
      if (!reader.value(&options.bench_json)) return false;
    } else if (arg == "--panel") {
      options.panel = true;
    } else if (arg == "--panel-option") {
      if (!reader.value(&options.panel_options)) return false;
    } else if (arg == "--dry-run") {
      options.settings.dry_run = true;
    } else if (arg == "--log") {
      if (!reader.value(&options.settings.log_file)) return false;
    } else {
      return reader.unknown();
    }
  }
  if (!check_depth_planes(near_plane, far_plane, error)) return reader.fail(*error);
  options.settings.depth_near = near_plane;
  options.settings.depth_far = far_plane;
  if (!options.help && options.command.empty()) return reader.fail("no application given: pfx-inject [options] -- APP [ARGS...]");
  if (options.bench_frames && options.bench_frames < 20) return reader.fail("--bench needs at least 20 frames per run");
  if (options.bench_frames && options.panel) return reader.fail("--bench and --panel do not go together");
  if (!options.panel_options.empty() && !options.panel) return reader.fail("--panel-option goes with --panel");
  if (options.bench_frames && options.settings.quit_after)
    return reader.fail("--bench sets the frame count itself: leave out --quit-after");
  *out = std::move(options);
  return true;
}

}  // namespace pfx::inject
