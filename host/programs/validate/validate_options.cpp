#include "validate_options.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <filesystem>

#include "arg_reader.hpp"

namespace fs = std::filesystem;

namespace pfx::validate {

std::string validate_usage() {
  return
      "usage: pfx-validate PLUGIN.so|FOLDER... [--json] [--seed S] [--runs N] [--timeout SECONDS]\n"
      "\n"
      "Checks pfx plugins the way a host relies on them, before they ship. Every check runs in its\n"
      "own child process, so a plugin that crashes or hangs is reported, not fatal. A FOLDER means\n"
      "every *.so in it.\n"
      "\n"
      "checks of the plugin\n"
      "  load            dlopen(RTLD_NOW | RTLD_LOCAL) and the entry symbol pfx_get_entry\n"
      "  entry           struct size, ABI major, a reverse-DNS plugin id, name, version, functions\n"
      "  init/deinit     init twice, deinit, init again, deinit; no GL asked for there\n"
      "  factories       the effect factory is complete; effect ids are [a-z0-9_]+ and unique;\n"
      "                  unknown factory ids give NULL\n"
      "  process state   loading, init, each effect's create, render (declare and passes) and destroy,\n"
      "                  each importer's import and release of a small OBJ, deinit and unloading:\n"
      "                  each leaves the calling thread's CPU affinity, scheduling, signal mask and\n"
      "                  locale, the signal handlers, the C and C++ locales, the working directory,\n"
      "                  the environment, the floating-point environment (rounding, traps, FTZ/DAZ),\n"
      "                  the umask and the number of threads as they were\n"
      "  unique ids      no plugin or effect id repeats across the plugins given\n"
      "checks of each effect\n"
      "  descriptors     labels, description, tooltips; hard_min <= default <= hard_max; the display\n"
      "                  range inside the hard range; enum items non-empty with valid ids\n"
      "  create/destroy  create, destroy, create: no GL error and the GL bindings left alone\n"
      "  defaults        renders gradient, checkerboard and NaN/Inf/70000 frames at 64x48, 1x1\n"
      "                  and 1917x1079 with the default parameters\n"
      "  random params   renders N seeded random parameter sets inside the hard ranges\n"
      "  resize          64x48, 1917x1079, 1x1, 33x17, then 64x48 again matches the first frame\n"
      "  8-bit frames    an effect that promises to only sample colour and draw output\n"
      "                  (PFX_DECLARATION_SAMPLES_AND_DRAWS), at its display-referred defaults,\n"
      "                  given an 8-bit frame as 8-bit textures is within 3 codes of the same frame\n"
      "                  in RGBA16F; skipped, saying why, for one that does not promise it\n"
      "  dirty state     create, a frame and destroy under an engine's leftover GL state (polygon\n"
      "                  mode, discard, logic op, clip control, sRGB, pixel store, bound buffers,\n"
      "                  textures, images...): the same bits as in a clean context, and the\n"
      "                  engine reads its state back as it left it; a difference names the items\n"
      "  heap growth     create, a 16x9 frame and destroy, over and over: the heap in use (glibc's\n"
      "                  mallinfo2) must not grow; skipped, saying why, where malloc is not glibc's\n"
      "                  (AddressSanitizer)\n"
      "Every render must succeed (no GL error), give an output that is finite wherever the input\n"
      "colour was, and leave the GL state of docs/sdk.md §1.5 unchanged by each pass (compared with\n"
      "glGet before and after). Every frame input is provided: colour, linear depth (with +inf and\n"
      "0 in the NaN/Inf frame), normal, albedo, emissive and four lights. A plugin must print\n"
      "nothing to stdout.\n"
      "\n"
      "options\n"
      "  --json           print one JSON object instead of the tables\n"
      "  --seed S         seed of the random parameter sets (default 1); a failure names the set\n"
      "  --runs N         random parameter sets per effect (default 8; 0 to 10000)\n"
      "  --timeout SECONDS  the longest one check may take before it is killed (default 120)\n"
      "  -h, --help       this text\n"
      "\n"
      "exit codes: 0 every check passed, 1 a check failed, 2 usage error (or no plugin found)\n";
}

bool parse_validate_options(const std::vector<std::string>& list, ValidateOptions* out, std::string* error) {
  ValidateOptions options;
  pfx::app::ArgReader args(list, error);
  while (args.next()) {
    const std::string& arg = args.arg();
    std::string text;
    if (arg == "-h" || arg == "--help") {
      options.help = true;
    } else if (arg == "--json") {
      options.json = true;
    } else if (arg == "--seed") {
      if (!args.value(&text)) return false;
      char* end = nullptr;
      errno = 0;
      options.seed = std::strtoull(text.c_str(), &end, 10);
      if (text.empty() || *end || errno == ERANGE || text[0] == '-')
        return args.fail("--seed " + text + ": expected a whole number from 0 to 2^64-1");
    } else if (arg == "--runs") {
      if (!args.value(&text)) return false;
      char* end = nullptr;
      const long runs = std::strtol(text.c_str(), &end, 10);
      if (text.empty() || *end || runs < 0 || runs > 10000) return args.fail("--runs " + text + ": expected 0 to 10000");
      options.runs = static_cast<int>(runs);
    } else if (arg == "--timeout") {
      if (!args.value(&text)) return false;
      char* end = nullptr;
      const double seconds = std::strtod(text.c_str(), &end);
      if (text.empty() || *end || !(seconds > 0) || seconds > 86400)
        return args.fail("--timeout " + text + ": expected seconds, more than 0 and at most 86400");
      options.timeout_s = seconds;
    } else if (!arg.empty() && arg[0] == '-') {
      return args.unknown();
    } else {
      options.paths.push_back(arg);
    }
  }
  if (!options.help && options.paths.empty()) return args.fail("no plugin given");
  *out = options;
  return true;
}

bool expand_plugin_paths(const std::vector<std::string>& paths, std::vector<std::string>* files, std::string* error) {
  std::vector<std::string> result;
  for (const std::string& path : paths) {
    std::error_code ec;
    if (fs::is_directory(path, ec)) {
      std::vector<std::string> found;
      for (const auto& item : fs::directory_iterator(path, ec))
        if (item.path().extension() == ".so" && item.is_regular_file(ec)) found.push_back(item.path().string());
      if (found.empty()) {
        *error = path + ": no plugin (*.so) in this folder";
        return false;
      }
      std::sort(found.begin(), found.end());
      result.insert(result.end(), found.begin(), found.end());
    } else if (fs::exists(path, ec)) {
      result.push_back(path);
    } else {
      *error = path + ": no such file or folder";
      return false;
    }
  }
  *files = result;
  return true;
}

}  // namespace pfx::validate
