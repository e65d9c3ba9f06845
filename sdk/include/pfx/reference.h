/* pfx C ABI v1 — CPU references. An effect may ship, in the same library, a double-precision CPU
 * model of what it computes, so hosts (pfx-bench, the tests) can measure its error without
 * including plugin code. Optional: get_factory(PFX_REFERENCES_FACTORY_ID) returns NULL when the
 * plugin has none. */
#ifndef PFX_REFERENCE_H
#define PFX_REFERENCE_H

#include "pfx/effect.h"

#ifdef __cplusplus
extern "C" {
#endif

#define PFX_REFERENCES_FACTORY_ID "pfx.references/1"

typedef uint32_t pfx_reference_kind;
enum {
  /* The same algorithm as the GPU passes (same taps, wrap modes, level sizes) in double
   * precision: the GPU output must match it within storage and filtering precision. */
  PFX_REFERENCE_MODEL = 0,
  /* The ideal the effect approximates (e.g. the full-resolution convolution): the error against
   * it is the approximation error pfx-bench plots against time. */
  PFX_REFERENCE_IDEAL = 1
};

/* Images are frame-sized, rows bottom first as in GL textures, RGBA interleaved. */
typedef struct pfx_reference_request {
  uint32_t struct_size;
  const char* effect_id;
  pfx_reference_kind kind;
  const pfx_frame* frame;
  const pfx_value* params;   /* one per parameter descriptor of the effect */
  const float* color;        /* width*height*4 */
  const float* depth;        /* width*height, as frame->depth_encoding says; NULL without depth */
  float* output;             /* width*height*4, written by the reference */
  /* Since 1.1: the G-buffer inputs, width*height*4 each (RGB used), NULL where the frame has none.
   * A reference reads them only when struct_size covers them. */
  const float* normal;   /* since 1.1 */
  const float* albedo;   /* since 1.1 */
  const float* emissive; /* since 1.1 */
} pfx_reference_request;
#define PFX_REFERENCE_REQUEST_MIN_SIZE PFX_STRUCT_SIZE_THROUGH(pfx_reference_request, output)

typedef struct pfx_reference_factory {
  uint32_t struct_size;
  /* Whether a reference of this kind exists for the effect (the answer never changes). */
  int (*has_reference)(const char* effect_id, pfx_reference_kind kind);
  /* Any thread, no GL. PFX_UNSUPPORTED when has_reference says no, or when the request asks for
   * a setting the reference does not model (e.g. a debug view of GPU-only data). */
  pfx_status (*evaluate)(const pfx_reference_request* request);
} pfx_reference_factory;
#define PFX_REFERENCE_FACTORY_MIN_SIZE PFX_STRUCT_SIZE_THROUGH(pfx_reference_factory, evaluate)

#ifdef __cplusplus
}
#endif
#endif /* PFX_REFERENCE_H */
