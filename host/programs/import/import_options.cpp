#include "import_options.hpp"

#include <cstdlib>

#include "arg_reader.hpp"

namespace pfx::import {

std::string import_usage() {
  return
      "usage: pfx-import FILE [--json] [--threads N] [--progress auto|on|off] [--plugins DIR]...\n"
      "\n"
      "Loads a model file through the importer plugins (the importer is chosen by the file's\n"
      "extension: obj) and prints what the import gave: unique vertices, triangles, sub-meshes,\n"
      "materials, bounds, lines and points skipped, warnings, and the import time.\n"
      "\n"
      "  --json            one JSON object on stdout instead of the text summary:\n"
      "                    {\"file\", \"vertices\", \"triangles\", \"submeshes\", \"materials\", \"bounds\",\n"
      "                     \"lines\", \"points\", \"warnings\", \"warnings_total\", \"ms\"}\n"
      "  --threads N       most threads the import uses at once, from libpfxhost's pool (default 0: every hardware thread)\n"
      "  --progress MODE   a progress line on stderr: auto (default: when stderr is a terminal), on, off\n"
      "  --plugins DIR     plugin folder (repeatable; default: the one next to this program's folder;\n"
      "                    PFX_PLUGIN_PATH adds more)\n"
      "\n"
      "A malformed file fails with one line FILE:LINE: reason on stderr. Warnings (a missing .mtl,\n"
      "ignored statements, polygons cut as fans) do not fail the import.\n"
      "\n"
      "exit codes: 0 ok, 2 usage, 3 bad input file (missing, unreadable or malformed),\n"
      "4 plugin error (no importer for the file's extension, or the importer failed)\n";
}

bool parse_import_options(const std::vector<std::string>& list, ImportOptions* out, std::string* error) {
  ImportOptions options;
  pfx::app::ArgReader args(list, error);
  while (args.next()) {
    const std::string& arg = args.arg();
    std::string text;
    if (arg == "-h" || arg == "--help") {
      options.help = true;
    } else if (arg == "--json") {
      options.json = true;
    } else if (arg == "--threads") {
      if (!args.value(&text)) return false;
      char* end = nullptr;
      long n = std::strtol(text.c_str(), &end, 10);
      if (text.empty() || *end || n < 0 || n > 1024) return args.fail("--threads " + text + ": expected a whole number 0 to 1024");
      options.threads = static_cast<unsigned>(n);
    } else if (arg == "--progress") {
      if (!args.value(&text)) return false;
      if (text != "auto" && text != "on" && text != "off") return args.fail("--progress " + text + ": expected auto, on or off");
      options.progress = text;
    } else if (arg == "--plugins") {
      if (!args.value(&options.plugin_dirs)) return false;
    } else if (!arg.empty() && arg[0] == '-' && arg != "-") {
      return args.unknown();
    } else if (options.file.empty()) {
      options.file = arg;
    } else {
      return args.fail("one file at a time ('" + options.file + "' and '" + arg + "')");
    }
  }
  if (!options.help && options.file.empty()) return args.fail("no file given");
  *out = options;
  return true;
}

}  // namespace pfx::import
