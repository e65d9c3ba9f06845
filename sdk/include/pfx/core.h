/* pfx C ABI v1 — versions, status codes, the host services and the plugin entry point.
 * Pure C99. Every struct that may grow starts with its size in bytes; a reader only touches the
 * fields that fit inside the size it was given. A published struct never changes: a new version
 * gets a new factory id. */
#ifndef PFX_CORE_H
#define PFX_CORE_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define PFX_ABI_MAJOR 1u
#define PFX_ABI_MINOR 1u

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
  /* GL thread only, with the host's context current. NULL for a name the context does not have. */
  pfx_gl_proc (*get_proc_address)(void* host_data, const char* name);
} pfx_host;

/* The versioned entry struct the entry symbol returns. Static storage owned by the plugin. */
typedef struct pfx_entry {
  uint32_t struct_size;
  uint32_t abi_major;            /* must equal the host's PFX_ABI_MAJOR or the host refuses the plugin */
  uint32_t abi_minor;            /* minor versions only add; a host accepts any minor */
  const char* id;                /* unique, reverse-DNS style: "org.pfx.bloom" */
  const char* name;              /* human-readable */
  const char* version;           /* the plugin's own version, "1.2.0" */
  /* Cheap and idempotent: no GL, no file I/O. May be called again after deinit. */
  pfx_status (*init)(const pfx_host* host);
  /* Undoes init; every object the plugin created has been destroyed before this is called. */
  void (*deinit)(void);
  /* Returns the factory struct for a versioned id ("pfx.effects/1"), or NULL for an id it does not
   * know. Callable only between init and deinit. */
  const void* (*get_factory)(const char* factory_id);
} pfx_entry;

typedef const pfx_entry* (*pfx_get_entry_fn)(void);

#ifdef __cplusplus
}
#endif
#endif /* PFX_CORE_H */
