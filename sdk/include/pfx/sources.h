/* pfx C ABI v1 — effects made from source files (since 1.5). A plugin that makes its effects at run
 * time from files it finds (the FX plugin: one effect per technique of each ReShade FX file) says
 * which file and which part of it each effect came from, and which files it could not use and why,
 * so hosts can list them. Optional: get_factory(PFX_SOURCES_FACTORY_ID) returns NULL when the plugin
 * has none. Any thread, no GL, unless a member says otherwise; the strings live until deinit. */
#ifndef PFX_SOURCES_H
#define PFX_SOURCES_H

#include "pfx/core.h"
#include "pfx/params.h"

#ifdef __cplusplus
extern "C" {
#endif

#define PFX_SOURCES_FACTORY_ID "pfx.sources/1"

typedef struct pfx_source_factory {
  uint32_t struct_size;
  /* The file effect `effect_id` was made from, or NULL for an effect of another kind. */
  const char* (*effect_file)(const char* effect_id);
  /* Its name in that file (an FX technique's name), or NULL. */
  const char* (*effect_source_name)(const char* effect_id);
  /* The files that gave no effect, each as a compiler reports it: "FILE:LINE:COLUMN: error: ...",
   * one problem per line. */
  uint32_t (*error_count)(void);
  const char* (*error)(uint32_t index);
  /* Appended after error: a host checks PFX_STRUCT_HAS before calling it, and it may be NULL (a
   * factory without it still pairs: PFX_SOURCE_FACTORY_MIN_SIZE ends at error). Preprocessor
   * definitions for `instance`, made by this plugin's create for an effect that effect_file names:
   * "NAME=VALUE,NAME2=VALUE2,FLAG" as a ReShade preset writes them. White space around each entry,
   * name and value is dropped and empty entries are skipped; a name without a value (FLAG, or
   * FLAG=) is defined as 1, as ReShade does. They replace any set before; "" sets none. The
   * instance compiles with them before its next frame: they override the file's own defaults
   * (#ifndef X #define X ...), and a version that fails to compile is logged while the last one
   * that compiled keeps running. The plugin may keep names it defines itself, saying so in the
   * log. GL thread, between frames. PFX_OK, or PFX_INVALID_ARGUMENT for a malformed list (an entry
   * whose name is not an identifier) or an instance it did not make, which then keeps the
   * definitions it had. */
  pfx_status (*set_definitions)(void* instance, const char* definitions); /* since 1.5 */
  /* Appended after set_definitions, the same way (check PFX_STRUCT_HAS; may be NULL). The
   * parameters of effect `effect_id` as they are for a frame of width x height: the effect's own
   * param_count descriptors, same ids, types and order, with the defaults and display ranges of
   * the parameters flagged PFX_PARAM_FOLLOWS_FRAME_SIZE computed for that size (BUFFER_WIDTH and
   * its kin). NULL for an unknown effect, a size outside 1..16384 or an effect without such
   * parameters. Any thread, no GL; compiles the effect's file on the first call for a size, so a
   * host asks when the size changes, not every frame. The array lives until deinit. */
  const pfx_param_desc* (*params_at)(const char* effect_id, uint32_t width, uint32_t height); /* since 1.5 */
} pfx_source_factory;
#define PFX_SOURCE_FACTORY_MIN_SIZE PFX_STRUCT_SIZE_THROUGH(pfx_source_factory, error)

#ifdef __cplusplus
}
#endif
#endif /* PFX_SOURCES_H */
