/* pfx C ABI v1 — importers: a plugin that reads a model file (OBJ, ...) into plain C arrays a host
 * can upload to GL as they are.
 *
 * get_factory(PFX_IMPORTERS_FACTORY_ID) returns a pfx_importer_factory: a count and a getter of
 * pfx_importer_desc. An importer declares the file extensions it reads and imports a file (by path,
 * or bytes in memory) into a pfx_import_result, which the caller gives back with the importer's
 * release function — the only way to free it.
 *
 * Threading: import and release run on any thread, make no GL call, and may be called
 * concurrently (each call has its own result). An importer starts no thread of its own: its
 * parallel work runs on the host's thread pool (pfx/services.h), at most
 * pfx_import_request.threads tasks at once, or serially on the calling thread when the host
 * offers no pool. Like every plugin it leaves the calling thread's affinity, scheduling and
 * signal mask, and the process's state, as it found them. */
#ifndef PFX_IMPORTER_H
#define PFX_IMPORTER_H

#include "pfx/core.h"

#ifdef __cplusplus
extern "C" {
#endif

#define PFX_IMPORTERS_FACTORY_ID "pfx.importers/1"

/* "Not present" for the optional index fields below (material of a sub-mesh, ...). */
#define PFX_IMPORT_NONE 0xFFFFFFFFu

/* A material as the file's material library (.mtl) gives it. Defaults where the library is silent
 * (or a usemtl names a material no library defines): diffuse 0.8, specular 0, emissive 0,
 * shininess 0, opacity 1, no maps. */
typedef struct pfx_import_material {
  uint32_t struct_size;      /* sizeof(pfx_import_material) of the importer; also the array stride */
  const char* name;          /* as in newmtl / usemtl, UTF-8 */
  float diffuse[3];          /* Kd, linear RGB as written */
  float specular[3];         /* Ks */
  float emissive[3];         /* Ke */
  float shininess;           /* Ns */
  float opacity;             /* d, or 1 - Tr; 1 is opaque */
  /* map_Kd and map_Ke: the path as written, resolved against the folder of the .mtl file that
   * names it ("textures/wood.png" in /m/a.mtl -> "/m/textures/wood.png"); NULL when absent.
   * Texture options (-s, -o, -bm, ...) are skipped. The importer does not check that it exists. */
  const char* diffuse_map;
  const char* emissive_map;
  /* map_d (a cut-out: alpha, or the first channel of a map without alpha), bump / map_Bump (a
   * height map, or a normal map that exporters often put under this name) and norm (a
   * tangent-space normal map), resolved like the maps above; NULL when absent. */
  const char* alpha_map; /* since 1.3 */
  const char* bump_map; /* since 1.3 */
  const char* normal_map; /* since 1.3 */
} pfx_import_material;
#define PFX_IMPORT_MATERIAL_MIN_SIZE PFX_STRUCT_SIZE_THROUGH(pfx_import_material, emissive_map)

/* A range of the index array drawn with one material. Frozen (no size field). */
typedef struct pfx_import_submesh {
  uint32_t first_index;      /* into pfx_import_result.indices; a multiple of 3 */
  uint32_t index_count;      /* a multiple of 3 */
  uint32_t material;         /* index into materials, or PFX_IMPORT_NONE for faces before any usemtl */
} pfx_import_submesh;

/* Everything an import gives back. All arrays belong to the result and live until release. */
typedef struct pfx_import_result {
  uint32_t struct_size;
  pfx_status status;         /* PFX_OK, or why the import failed (then only error is meaningful) */
  /* On failure: "FILE:LINE: reason" (or "FILE: reason" when no line applies). NULL on success. */
  const char* error;

  /* One vertex per distinct corner: (position, texture coordinate, normal) after deduplication. */
  uint32_t vertex_count;
  const float* positions;    /* vertex_count x (x, y, z) */
  const float* normals;      /* vertex_count x (x, y, z): from the file, or generated (unit length) */
  const float* texcoords;    /* vertex_count x (u, v), or NULL when no corner has one (absent: 0, 0) */
  const float* colors;       /* vertex_count x (r, g, b), or NULL when the file has none (absent: 1, 1, 1) */

  uint32_t index_count;      /* a multiple of 3: triangles, counter-clockwise as in the file */
  const uint32_t* indices;   /* 32-bit, grouped by sub-mesh */
  uint32_t submesh_count;
  const pfx_import_submesh* submeshes;  /* in order of first use in the file */
  uint32_t material_count;
  const pfx_import_material* materials; /* step material->struct_size bytes from one to the next */

  float bounds_min[3];       /* of the vertices; all zero when there are none */
  float bounds_max[3];

  uint64_t lines_skipped;    /* `l` statements (polylines): counted, not meshed */
  uint64_t points_skipped;   /* `p` statements: counted, not meshed */
  uint64_t faces;            /* `f` statements meshed (before triangulation) */

  /* "FILE:LINE: text", in file order. At most PFX_IMPORT_MAX_WARNINGS are kept; warning_total
   * counts them all. */
  uint32_t warning_count;
  const char* const* warnings;
  uint64_t warning_total;

  double parse_seconds;      /* wall-clock time of the import, reading the file included */
} pfx_import_result;
#define PFX_IMPORT_RESULT_MIN_SIZE PFX_STRUCT_SIZE_THROUGH(pfx_import_result, parse_seconds)

#define PFX_IMPORT_MAX_WARNINGS 100u

/* Reports progress from 0 to 1 (non-decreasing); called only on the thread that called import. */
typedef void (*pfx_import_progress_fn)(void* user, float fraction);

typedef struct pfx_import_request {
  uint32_t struct_size;
  /* Either a file path ... */
  const char* path;
  /* ... or the file's bytes (path NULL). The bytes are only read, and only during import. */
  const void* bytes;
  size_t byte_count;
  /* With bytes: the name used in messages and whose folder resolves relative paths (mtllib).
   * NULL: "<memory>", and material libraries are not read (a warning says so). */
  const char* name;
  uint32_t threads;          /* most tasks at once on the host's pool; 0 = what the pool offers, 1 = serial */
  pfx_import_progress_fn progress;  /* optional */
  void* progress_user;
} pfx_import_request;
#define PFX_IMPORT_REQUEST_MIN_SIZE PFX_STRUCT_SIZE_THROUGH(pfx_import_request, progress_user)

typedef struct pfx_importer_desc {
  uint32_t struct_size;
  const char* id;            /* unique across loaded plugins: "obj" */
  const char* label;         /* "Wavefront OBJ" */
  /* Lower-case file extensions without the dot: {"obj"}; the host matches them case-insensitively. */
  const char* const* extensions;
  uint32_t extension_count;
  /* Imports; *out receives a result (also on failure, with status and error set) unless the
   * result itself could not be allocated (then *out is NULL and PFX_OUT_OF_MEMORY is returned).
   * Returns result->status. Never prints, never exits, never throws. */
  pfx_status (*import)(const pfx_import_request* request, pfx_import_result** out);
  /* Frees a result of this importer and everything it points to; NULL is ignored. */
  void (*release)(pfx_import_result* result);
} pfx_importer_desc;
#define PFX_IMPORTER_DESC_MIN_SIZE PFX_STRUCT_SIZE_THROUGH(pfx_importer_desc, release)

/* What get_factory(PFX_IMPORTERS_FACTORY_ID) returns. */
typedef struct pfx_importer_factory {
  uint32_t struct_size;
  uint32_t (*importer_count)(void);
  const pfx_importer_desc* (*get_importer)(uint32_t index);
} pfx_importer_factory;
#define PFX_IMPORTER_FACTORY_MIN_SIZE PFX_STRUCT_SIZE_THROUGH(pfx_importer_factory, get_importer)

#ifdef __cplusplus
}
#endif
#endif /* PFX_IMPORTER_H */
