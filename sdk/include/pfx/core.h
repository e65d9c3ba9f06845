/* pfx C ABI v1 — versions, status codes, the host and the plugin entry point, and the one rule for
 * how the ABI grows. Pure C99.
 *
 * How structs grow (every header follows it; docs/sdk.md §1.7 publishes the sizes):
 *  1. A struct that may grow starts with uint32_t struct_size, set by whoever fills the struct to
 *     sizeof the struct it was compiled with.
 *  2. A minor version may only append fields at the end of such a struct; nothing is removed,
 *     reordered, retyped or given a new meaning. Each appended field says "since 1.N".
 *  3. A reader reads a field only when struct_size covers it (PFX_STRUCT_HAS) and uses the
 *     documented default otherwise; it refuses a struct smaller than the struct's first published
 *     version (PFX_<NAME>_MIN_SIZE). A writer into a struct it did not allocate (pfx_declaration) writes
 *     only the fields its struct_size covers.
 *  4. An array of sized structs is stepped by the struct_size of its elements, never by the
 *     reader's sizeof: element i starts i * array[0].struct_size bytes in (pfx_at). Every element
 *     of one array has the same struct_size. pfx_light has no size field of its own: lights are
 *     stepped by pfx_frame.light_struct_size, which makes pfx_light a sized struct too.
 *  5. Structs without struct_size (pfx_value, pfx_camera, pfx_enum_item, pfx_pass_input,
 *     pfx_bound_texture, pfx_import_submesh) are frozen for good.
 *  6. Any other change is a new id: a new factory ("pfx.effects/2") or a new service id, which a
 *     plugin or host can offer beside the old one. */
#ifndef PFX_CORE_H
#define PFX_CORE_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define PFX_ABI_MAJOR 1u
#define PFX_ABI_MINOR 9u

/* The size of a struct up to and including one of its fields: the size a writer of the version
 * that ended with that field sets. */
#define PFX_STRUCT_SIZE_THROUGH(type, field) (offsetof(type, field) + sizeof(((type*)0)->field))
/* Whether a struct the caller did not compile carries a field (rule 3). */
#define PFX_STRUCT_HAS(pointer, type, field) \
  ((size_t)(pointer)->struct_size >= PFX_STRUCT_SIZE_THROUGH(type, field))
/* Element index of an array of sized structs, stepped by the elements' own struct_size (rule 4). */
#define pfx_at(type, array, index) \
  ((const type*)(const void*)((const unsigned char*)(array) + (size_t)(index) * (array)[0].struct_size))

/* The one symbol a plugin library exports: const pfx_entry* pfx_get_entry(void). */
#define PFX_ENTRY_SYMBOL "pfx_get_entry"

#if defined(_WIN32)
#define PFX_EXPORT __declspec(dllexport)
#else
#define PFX_EXPORT __attribute__((visibility("default")))
#endif

typedef int32_t pfx_status;
enum {
  PFX_OK = 0,
  PFX_ERROR = -1,             /* anything else; the plugin logged the reason */
  PFX_INVALID_ARGUMENT = -2,  /* a NULL, an out-of-range value, a struct too small */
  PFX_UNSUPPORTED = -3,       /* the request is valid but not implemented by this plugin */
  PFX_OUT_OF_MEMORY = -4,
  PFX_GL_ERROR = -5,          /* the GL reported an error or lacks what the plugin needs */
  PFX_MISSING_INPUT = -6      /* the frame lacks an input the effect needs */
};

typedef int32_t pfx_log_level;
enum { PFX_LOG_DEBUG = 0, PFX_LOG_INFO = 1, PFX_LOG_WARNING = 2, PFX_LOG_ERROR = 3 };

/* A GL entry point as the host returns it; cast to the real type before calling. */
typedef void (*pfx_gl_proc)(void);

/* What the host gives a plugin. Valid from init until deinit returns; the host keeps one per loaded
 * plugin, so messages can be attributed without the plugin naming itself. */
typedef struct pfx_host {
  uint32_t struct_size;
  uint32_t abi_major, abi_minor;  /* the host's ABI version */
  const char* host_name;          /* e.g. "pfx-render 0.1.0" */
  void* host_data;                /* opaque to the plugin; passed back to every callback */
  /* Thread-safe. A plugin never prints to stdout or stderr and never calls exit(): it logs. */
  void (*log)(void* host_data, pfx_log_level level, const char* message);
  /* GL thread only, with the host's context current. A non-NULL result does not prove the context
   * has the function: Mesa and other drivers return dispatch stubs for any name. Check the
   * context's version (glGetIntegerv(GL_MAJOR_VERSION)) or extension before calling one. */
  pfx_gl_proc (*get_proc_address)(void* host_data, const char* name);
  /* Since 1.2. The host's service for a versioned id ("pfx.thread_pool/1", pfx/services.h), or
   * NULL when the host does not offer it. Any thread; the result is valid until deinit. A host
   * without services leaves it NULL (or passes a 1.0/1.1 struct without it): check both. */
  const void* (*get_service)(void* host_data, const char* service_id); /* since 1.2 */
} pfx_host;
#define PFX_HOST_MIN_SIZE PFX_STRUCT_SIZE_THROUGH(pfx_host, get_proc_address)

/* The versioned entry struct the entry symbol returns. Static storage owned by the plugin. */
typedef struct pfx_entry {
  uint32_t struct_size;
  uint32_t abi_major;            /* must equal the host's PFX_ABI_MAJOR or the host refuses the plugin */
  uint32_t abi_minor;            /* minor versions only add; a host accepts any minor */
  const char* id;                /* unique, reverse-DNS style: "org.pfx.bloom" */
  const char* name;              /* human-readable */
  const char* version;           /* the plugin's own version, "1.2.0" */
  /* Cheap and idempotent: no GL, no file I/O. May be called again after deinit.
   * A plugin's globals belong to one host: a host loads its own copy of the library when another
   * host of the process holds it, so each host's init and deinit run on globals of their own. A
   * plugin may keep what it has of its host in globals set here (the host, its thread pool) and
   * cleared in deinit. */
  pfx_status (*init)(const pfx_host* host);
  /* Undoes init; every object the plugin created has been destroyed before this is called. */
  void (*deinit)(void);
  /* Returns the factory struct for a versioned id ("pfx.effects/1"), or NULL for an id it does not
   * know. Callable only between init and deinit. */
  const void* (*get_factory)(const char* factory_id);
} pfx_entry;
#define PFX_ENTRY_MIN_SIZE PFX_STRUCT_SIZE_THROUGH(pfx_entry, get_factory)

typedef const pfx_entry* (*pfx_get_entry_fn)(void);

#ifdef __cplusplus
}
#endif
#endif /* PFX_CORE_H */
