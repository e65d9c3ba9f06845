// What pfx-inject hands to libpfxinject.so: every setting travels in an environment variable, so
// a user can also preload the library by hand (a game launcher's LD_PRELOAD) and set them there.
// docs/inject.md lists the variables; this file is their one definition.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "display_transfer.hpp"

namespace pfx::inject {

// How the 8-bit values of the application's back buffer relate to light.
using app::Transfer;

struct Capture {
  uint64_t frame = 0;  // the N-th presented frame, from 1; 0 with every_frame
  bool every_frame = false;
  std::string prefix;  // with every_frame it holds one "%d", replaced by the frame number
};

struct InjectSettings {
  // The effects in order; unset: the preset's chain, else every effect found. "none" on the
  // command line gives an empty chain (frames presented as the application drew them).
  std::optional<std::vector<std::string>> chain;
  std::string preset;                // a pfx-view preset file, watched for changes; empty: none
  std::vector<std::string> sets;     // "effect.param=value", applied after the preset
  std::vector<std::string> plugin_dirs;  // empty: the folder beside the library
  double depth_near = 0.1, depth_far = 1000;  // metres; far may be +infinity
  Transfer transfer = Transfer::SRGB;
  std::vector<Capture> captures;
  uint64_t quit_after = 0;           // 0: never
  uint64_t from_frame = 1;           // presents before this one pass through, untouched
  bool dry_run = false;              // run the chain, present the application's own frame
  bool bypass = false;               // hook the present and count frames, touch no GL (bench)
  std::string log_file;              // empty: stderr
  std::string stats_file;            // JSON of frame times written at exit (bench); empty: none
  // After each of these presented frames, log the process's resident memory and the GL objects
  // of the presenting context (to see that a long run does not grow).
  std::vector<uint64_t> resources_at;
  // The live control panel's channel: the chain times its passes and writes them here as JSON
  // a few times a second. Empty: no timing at all.
  std::string timings_file;
};

// The variable names, for the launcher, the library and the docs.
namespace env {
constexpr const char* kChain = "PFX_INJECT_CHAIN";          // "bloom,dof" or "none"
constexpr const char* kPreset = "PFX_INJECT_PRESET";
constexpr const char* kSet = "PFX_INJECT_SET";              // assignments, one per line
constexpr const char* kPlugins = "PFX_INJECT_PLUGINS";      // folders separated by ':'
constexpr const char* kDepthNear = "PFX_INJECT_DEPTH_NEAR";
constexpr const char* kDepthFar = "PFX_INJECT_DEPTH_FAR";   // a number or "inf"
constexpr const char* kTransfer = "PFX_INJECT_TRANSFER";    // "srgb" or "linear"
constexpr const char* kCapture = "PFX_INJECT_CAPTURE";      // "N:PREFIX" items, one per line
constexpr const char* kQuitAfter = "PFX_INJECT_QUIT_AFTER";
constexpr const char* kFromFrame = "PFX_INJECT_FROM_FRAME";
constexpr const char* kDryRun = "PFX_INJECT_DRY_RUN";       // "1"
constexpr const char* kBypass = "PFX_INJECT_BYPASS";        // "1"
constexpr const char* kLog = "PFX_INJECT_LOG";
constexpr const char* kStats = "PFX_INJECT_STATS";
constexpr const char* kResourcesAt = "PFX_INJECT_RESOURCES_AT";  // frame numbers separated by ','
constexpr const char* kTimings = "PFX_INJECT_TIMINGS";
constexpr const char* kAll[] = {kChain,     kPreset,    kSet,    kPlugins, kDepthNear, kDepthFar,    kTransfer, kCapture,
                                kQuitAfter, kFromFrame, kDryRun, kBypass,  kLog,       kStats,       kResourcesAt,
                                kTimings};
}  // namespace env

// The prefixes to write for the `frame`-th presented frame (all:PREFIX gets its %d filled in).
std::vector<std::string> capture_prefixes(const std::vector<Capture>& captures, uint64_t frame);
// What the log says of the captures of the `frame`-th frame that are not written because `why`
// (prefixes with `suffix` added, as a present of a second window names its captures): a line for
// each capture of that frame; for all:PREFIX one line while the reason lasts, which once_key names
// for the log's once-only table (empty for the others).
struct SkippedCapture {
  std::string once_key;
  std::string line;
};
std::vector<SkippedCapture> skipped_captures(const std::vector<Capture>& captures, uint64_t frame,
                                             const std::string& why, const std::string& suffix = "");
// "12:shot" or "all:shot.%d"; false with *error saying what is wrong.
bool parse_capture(const std::string& text, Capture* out, std::string* error);
// "500,5000": presented frame numbers from 1; false with *error naming the item that is not one.
bool parse_frame_list(const std::string& text, std::vector<uint64_t>* out, std::string* error);
// A depth plane: a positive number, or "inf" (far only).
bool parse_depth_plane(const std::string& text, bool allow_infinity, double* out, std::string* error);
// Checks near < far once both are known.
bool check_depth_planes(double near_plane, double far_plane, std::string* error);

// Reads the settings from variables; `lookup` returns the value of one or null (getenv).
// One rule for every variable, since inside somebody else's application a typo must not stop it:
// a value that does not parse, or an item of a list (a capture, an assignment, an effect of the
// chain) that does not, is reported in *problems ("NAME: why") and left out; what is left applies,
// and a variable with nothing usable left keeps its default. Effects and assignments are checked
// against the plugins later (chain_recipe.hpp), by the same rule.
using EnvLookup = const char* (*)(const char* name);
InjectSettings settings_from_environment(EnvLookup lookup, std::vector<std::string>* problems);
// The problems of variables named PFX_INJECT_* that pfx-inject does not know (a misspelt name),
// from the names of the process's variables.
std::vector<std::string> unknown_variables(const std::vector<std::string>& names);
// The variables that give `settings` (those not at their default), as NAME=VALUE strings.
std::vector<std::string> settings_to_environment(const InjectSettings& settings);

}  // namespace pfx::inject
