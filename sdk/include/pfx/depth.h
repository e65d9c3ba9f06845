/* pfx C ABI v1 — depth decoding shared by host and plugins, so every effect reads a depth input
 * the same way. Plain C99 inline functions; GLSL twins live in the plugins' shader helpers. */
#ifndef PFX_DEPTH_H
#define PFX_DEPTH_H

#include <math.h>

#include "pfx/effect.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Linear view depth (metres, positive) from a stored depth value. A stored value at the far plane
 * of an infinite projection, or past the far plane, gives +INFINITY (sky); NaN stays NaN so the
 * caller decides what a broken depth means. near must be > 0. */
static inline double pfx_view_depth(double stored, pfx_depth_encoding encoding, double near_plane,
                                    double far_plane) {
  const double inf = (double)INFINITY;
  switch (encoding) {
    case PFX_DEPTH_LINEAR:
      return stored;
    case PFX_DEPTH_HARDWARE: {
      /* window z in [0,1] -> NDC z in [-1,1]; invert the standard perspective depth mapping */
      double z = 2.0 * stored - 1.0;
      if (far_plane == inf) {
        /* limit of the finite formula as far -> infinity */
        return (z >= 1.0) ? inf : 2.0 * near_plane / (1.0 - z);
      }
      {
        double denom = (far_plane + near_plane) - z * (far_plane - near_plane);
        return (denom <= 0.0) ? inf : 2.0 * near_plane * far_plane / denom;
      }
    }
    case PFX_DEPTH_HARDWARE_REVERSED: {
      /* zero-to-one clip: d = near*(far - z)/(z*(far - near)), or near/z when far is infinite */
      if (stored < 0.0) return inf; /* past the far plane */
      if (far_plane == inf) return (stored == 0.0) ? inf : near_plane / stored;
      return near_plane * far_plane / (stored * (far_plane - near_plane) + near_plane);
    }
    default:
      return (double)NAN;
  }
}

#ifdef __cplusplus
}
#endif
#endif /* PFX_DEPTH_H */
