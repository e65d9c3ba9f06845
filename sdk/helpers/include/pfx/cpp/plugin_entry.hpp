// A plugin's entry point and what every plugin's calls check the same way: the host in init and
// create, the arguments of declare, a CPU reference request, the wall that keeps C++ exceptions
// from crossing the C ABI, get_factory over the factories the plugin offers, the lookup of the
// host's thread pool, and the entry itself, made from a named description (Plugin,
// PFX_PLUGIN_ENTRY at the end).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <new>

#include <pfx/pfx.h>

namespace pfx::plugin {

// init's check: a host struct of at least the first published size (an older host's is smaller
// than this plugin's sizeof, and fine), with the two callbacks plugins call (logging and GL lookup).
inline bool usable_host(const pfx_host* host) {
  return host && host->struct_size >= PFX_HOST_MIN_SIZE && host->log && host->get_proc_address;
}

// Whether the request carries the G-buffer fields appended in ABI 1.1. A reference must accept a
// request of the first published size (an ABI 1.0 host's) and read them only when it does.
inline bool has_gbuffer_fields(const pfx_reference_request& request) {
  return PFX_STRUCT_HAS(&request, pfx_reference_request, emissive);
}

// What every CPU reference needs of a request: a readable struct, a frame of at least one pixel,
// the parameters, the colour in and the output.
inline bool usable_reference_request(const pfx_reference_request* request) {
  return request && request->struct_size >= PFX_REFERENCE_REQUEST_MIN_SIZE && request->frame &&
         request->frame->struct_size >= PFX_FRAME_MIN_SIZE && request->params && request->color && request->output &&
         request->frame->width > 0 && request->frame->height > 0;
}

// declare's check of what the host hands it: a frame and a declaration this ABI can read, and the
// parameter values.
inline bool usable_declare_arguments(const pfx_frame* frame, const pfx_value* params, const pfx_declaration* out) {
  return frame && params && out && frame->struct_size >= PFX_FRAME_MIN_SIZE && out->struct_size >= PFX_DECLARATION_MIN_SIZE;
}

// Runs work (a callable returning pfx_status) and turns an exception into a status: nothing may
// unwind through the C ABI.
template <class Work>
pfx_status without_exceptions(Work&& work) {
  try {
    return work();
  } catch (const std::bad_alloc&) {
    return PFX_OUT_OF_MEMORY;
  } catch (...) {
    return PFX_ERROR;
  }
}

// get_factory for a plugin offering these factories (nullptr for a kind it does not offer):
// the factory for the id, or nullptr for an id it does not know.
inline const void* factory_for(const char* factory_id, const pfx_effect_factory* effects,
                               const pfx_reference_factory* references, const pfx_importer_factory* importers = nullptr,
                               const pfx_source_factory* sources = nullptr) {
  if (!factory_id) return nullptr;
  if (sources && std::strcmp(factory_id, PFX_SOURCES_FACTORY_ID) == 0) return sources;
  if (effects && std::strcmp(factory_id, PFX_EFFECTS_FACTORY_ID) == 0) return effects;
  if (references && std::strcmp(factory_id, PFX_REFERENCES_FACTORY_ID) == 0) return references;
  if (importers && std::strcmp(factory_id, PFX_IMPORTERS_FACTORY_ID) == 0) return importers;
  return nullptr;
}

// The host's thread pool ("pfx.thread_pool/1", pfx/services.h), or nullptr when the host offers
// none: a host older than ABI 1.2 (no get_service), one without the service, or a pool struct too
// small or incomplete. Without it a plugin runs its work serially on the calling thread.
inline const pfx_thread_pool* host_thread_pool(const pfx_host* host) {
  if (!host || !PFX_STRUCT_HAS(host, pfx_host, get_service) || !host->get_service) return nullptr;
  const auto* pool = static_cast<const pfx_thread_pool*>(host->get_service(host->host_data, PFX_SERVICE_THREAD_POOL));
  if (!pool || pool->struct_size < PFX_THREAD_POOL_MIN_SIZE || !pool->concurrency || !pool->run) return nullptr;
  return pool;
}

// What a plugin offers, given by name: its identity and its factories. A constexpr object of it,
// handed to PFX_PLUGIN_ENTRY, is the plugin's whole entry point:
//
//   constexpr const pfx_effect_desc* kEffects[] = {&kBloomEffect, &kGlareEffect};
//   constexpr auto kPlugin = pfx::plugin::Plugin("org.pfx.bloom").name("pfx bloom").version("0.1.0")
//                                .effects(kEffects).references(&kReferenceFactory);
//   PFX_PLUGIN_ENTRY(kPlugin)
//
// Left out: the name is the id, the version "0.0.0", and a factory kind not given is not offered
// (get_factory returns nullptr for it). init checks the host with usable_host and then runs
// on_init, if given; deinit runs on_deinit, if given.
class Plugin {
 public:
  constexpr explicit Plugin(const char* id) : id_(id), name_(id) {}
  constexpr Plugin name(const char* text) const {
    Plugin p = *this;
    p.name_ = text;
    return p;
  }
  constexpr Plugin version(const char* text) const {
    Plugin p = *this;
    p.version_ = text;
    return p;
  }
  // The effects, in the order the effect factory lists them (the table keeps the pointers).
  template <std::size_t N>
  constexpr Plugin effects(const pfx_effect_desc* const (&list)[N]) const {
    Plugin p = *this;
    p.effects_ = list;
    p.effect_count_ = static_cast<uint32_t>(N);
    return p;
  }
  // An effect factory of the plugin's own instead of the one made from effects() (a list known
  // only at run time).
  constexpr Plugin effect_factory(const pfx_effect_factory* factory) const {
    Plugin p = *this;
    p.effect_factory_ = factory;
    p.own_effect_factory_ = true;
    return p;
  }
  // Where effects made at run time came from ("pfx.sources/1", pfx/sources.h).
  constexpr Plugin sources(const pfx_source_factory* factory) const {
    Plugin p = *this;
    p.sources_ = factory;
    return p;
  }
  // A factory of a kind this header does not name, offered under its id: "pfx.vulkan_effects/1"
  // (pfx/vulkan_effects.h, which needs Vulkan's headers, so only its users include it).
  constexpr Plugin factory(const char* factory_id, const void* factory) const {
    Plugin p = *this;
    p.other_id_ = factory_id;
    p.other_ = factory;
    return p;
  }
  constexpr Plugin references(const pfx_reference_factory* factory) const {
    Plugin p = *this;
    p.references_ = factory;
    return p;
  }
  template <std::size_t N>
  constexpr Plugin importers(const pfx_importer_desc* const (&list)[N]) const {
    Plugin p = *this;
    p.importers_ = list;
    p.importer_count_ = static_cast<uint32_t>(N);
    return p;
  }
  // Runs in init once the host passed usable_host (cheap, no GL, no file I/O, idempotent).
  constexpr Plugin on_init(pfx_status (*fn)(const pfx_host*)) const {
    Plugin p = *this;
    p.on_init_ = fn;
    return p;
  }
  constexpr Plugin on_deinit(void (*fn)()) const {
    Plugin p = *this;
    p.on_deinit_ = fn;
    return p;
  }

 private:
  template <const Plugin&>
  friend struct Entry;

  const char* id_;
  const char* name_;
  const char* version_ = "0.0.0";
  const pfx_effect_desc* const* effects_ = nullptr;
  uint32_t effect_count_ = 0;
  const pfx_effect_factory* effect_factory_ = nullptr;
  const pfx_reference_factory* references_ = nullptr;
  const pfx_source_factory* sources_ = nullptr;
  const char* other_id_ = nullptr;
  const void* other_ = nullptr;
  const pfx_importer_desc* const* importers_ = nullptr;
  uint32_t importer_count_ = 0;
  bool own_effect_factory_ = false;
  // Nothing to do is a function too: a test of a function's address against null is one the
  // compiler calls always true (-Waddress) once the plugin has named one.
  static pfx_status init_nothing(const pfx_host*) { return PFX_OK; }
  static void deinit_nothing() {}
  pfx_status (*on_init_)(const pfx_host*) = init_nothing;
  void (*on_deinit_)() = deinit_nothing;
};

// The functions and structs of the ABI made from one Plugin: its factories and its pfx_entry.
template <const Plugin& P>
struct Entry {
  static uint32_t effect_count() { return P.effect_count_; }
  static const pfx_effect_desc* get_effect(uint32_t index) {
    return index < P.effect_count_ ? P.effects_[index] : nullptr;
  }
  static constexpr pfx_effect_factory kEffects = {sizeof(pfx_effect_factory), effect_count, get_effect};

  static uint32_t importer_count() { return P.importer_count_; }
  static const pfx_importer_desc* get_importer(uint32_t index) {
    return index < P.importer_count_ ? P.importers_[index] : nullptr;
  }
  static constexpr pfx_importer_factory kImporters = {sizeof(pfx_importer_factory), importer_count, get_importer};

  static pfx_status init(const pfx_host* host) {
    if (!usable_host(host)) return PFX_INVALID_ARGUMENT;
    return P.on_init_(host);
  }
  static void deinit() { P.on_deinit_(); }
  static const void* get_factory(const char* factory_id) {
    const pfx_effect_factory* effects = P.own_effect_factory_ ? P.effect_factory_
                                        : P.effect_count_     ? &kEffects
                                                              : nullptr;
    if constexpr (P.other_id_ != nullptr) {
      if (factory_id && std::strcmp(factory_id, P.other_id_) == 0) return P.other_;
    }
    return factory_for(factory_id, effects, P.references_, P.importer_count_ ? &kImporters : nullptr, P.sources_);
  }

  static constexpr pfx_entry kEntry = {sizeof(pfx_entry), PFX_ABI_MAJOR, PFX_ABI_MINOR, P.id_,      P.name_,
                                       P.version_,        init,          deinit,        get_factory};
};

}  // namespace pfx::plugin

// The plugin's exported entry symbol, for a constexpr pfx::plugin::Plugin (a qualified name).
#define PFX_PLUGIN_ENTRY(description) \
  extern "C" PFX_EXPORT const pfx_entry* pfx_get_entry(void) { return &::pfx::plugin::Entry<description>::kEntry; }
