/* An importer plugin with one fault, chosen at compile time (BROKEN_*), for the loader's checks on
 * importer descriptors. Without a fault it is a valid importer of ".fixture" files that imports
 * nothing. */
#include <stddef.h>
#include <string.h>

#include <pfx/pfx.h>

static pfx_status import(const pfx_import_request* request, pfx_import_result** out) {
  (void)request;
  if (out) *out = NULL;
  return PFX_UNSUPPORTED;
}

#if !defined(BROKEN_NO_RELEASE)
static void release(pfx_import_result* result) { (void)result; }
#endif

#if defined(BROKEN_UPPERCASE_EXTENSION)
static const char* const k_extensions[] = {"OBJX"};
#elif defined(BROKEN_DOT_EXTENSION)
static const char* const k_extensions[] = {".objx"};
#else
static const char* const k_extensions[] = {"fixture"};
#endif

static const pfx_importer_desc k_importer = {
    sizeof(pfx_importer_desc),
#if defined(BROKEN_DUPLICATE_ID)
    "obj",
#elif defined(BROKEN_BAD_ID)
    "Bad-Id",
#else
    "fixture",
#endif
    "broken fixture importer",
    k_extensions,
#if defined(BROKEN_NO_EXTENSIONS)
    0,
#else
    1,
#endif
    import,
#if defined(BROKEN_NO_RELEASE)
    NULL
#else
    release
#endif
};

static uint32_t importer_count(void) { return 1; }
static const pfx_importer_desc* get_importer(uint32_t index) { return index == 0 ? &k_importer : NULL; }

#if defined(BROKEN_INCOMPLETE_FACTORY)
/* A factory struct smaller than the published one. */
static const pfx_importer_factory k_factory = {sizeof(pfx_importer_factory) - 4, importer_count, get_importer};
#else
static const pfx_importer_factory k_factory = {sizeof(pfx_importer_factory), importer_count, get_importer};
#endif

static pfx_status plugin_init(const pfx_host* host) { return host ? PFX_OK : PFX_INVALID_ARGUMENT; }
static void plugin_deinit(void) {}
static const void* plugin_get_factory(const char* id) {
  return id && strcmp(id, PFX_IMPORTERS_FACTORY_ID) == 0 ? &k_factory : NULL;
}

static const pfx_entry k_entry = {sizeof(pfx_entry), PFX_ABI_MAJOR, PFX_ABI_MINOR, FIXTURE_PLUGIN_ID,
                                  "broken importer fixture", "1.0.0", plugin_init, plugin_deinit,
                                  plugin_get_factory};

PFX_EXPORT const pfx_entry* pfx_get_entry(void) { return &k_entry; }
