// What one frei0r library of pfx is, told by its file name: pfx_chain.so is the generic plugin
// (a chain of any effects, named in its parameters); pfx_<effect>.so runs that one effect, its
// frei0r parameters made from the effect's descriptors. Both are copies of one library.
//
// frei0r hosts read a plugin's description without f0r_init (MLT scans every plugin that way),
// keep pointers to its strings for as long as the library is loaded (GStreamer), construct
// instances only to read defaults, and call f0r_deinit while instances still live (MLT): the
// description is made at its first use and kept until the library is unloaded. Loading the pfx
// plugins for it runs no GL.
#pragma once

#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include <pfx/host/plugin_registry.hpp>

#include "frei0r_params.hpp"

namespace pfx::frei0r {

struct Library {
  enum class Kind { CHAIN, EFFECT };
  Kind kind = Kind::CHAIN;
  std::string file;       // this library's file
  std::string name;       // frei0r's short name: the file's name without ".so" ("pfx_chain", "pfx_bloom")
  std::string effect_id;  // EFFECT: the effect it runs
  std::string explanation;
  std::vector<ParamSlot> params;
  const pfx_effect_desc* effect = nullptr;  // EFFECT, when the effect was found
  std::unique_ptr<host::PluginRegistry> registry;
  // Plugins that did not load, or why the effect is missing: said once, at the first frame.
  std::vector<std::string> problems;
  std::atomic<bool> problems_said{false};
  ~Library();
};

// The library's description, made at the first call (thread-safe).
std::shared_ptr<Library> library();

}  // namespace pfx::frei0r
