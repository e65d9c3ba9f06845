// Header-only pieces of a plugin's entry point that every plugin writes the same way: the check
// of the host in init, the check of a CPU reference request, the wall that keeps C++ exceptions
// from crossing the C ABI, get_factory over the factories the plugin offers, and the lookup of the
// host's thread pool.
#pragma once

#include <cstddef>
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
                               const pfx_reference_factory* references, const pfx_importer_factory* importers = nullptr) {
  if (!factory_id) return nullptr;
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

}  // namespace pfx::plugin
