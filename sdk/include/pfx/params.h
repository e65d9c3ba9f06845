/* pfx C ABI v1 — typed parameters with metadata.
 * The host owns the values: it validates every set against the descriptor and hands the effect the
 * current values (one pfx_value per descriptor, in descriptor order) on every declare and run call. */
#ifndef PFX_PARAMS_H
#define PFX_PARAMS_H

#include "pfx/core.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef uint32_t pfx_param_type;
enum {
  PFX_PARAM_FLOAT = 0, /* v[0] */
  PFX_PARAM_INT = 1,   /* v[0], a whole number */
  PFX_PARAM_BOOL = 2,  /* v[0], 0 or 1 */
  PFX_PARAM_ENUM = 3,  /* v[0], the index of an item; text and JSON use the item's id */
  PFX_PARAM_COLOR = 4, /* v[0..2], linear RGB */
  PFX_PARAM_VEC2 = 5,  /* v[0..1] */
  PFX_PARAM_VEC3 = 6   /* v[0..2] */
};

enum {
  /* Out-of-range values are refused with an error instead of clamped to [hard_min, hard_max]. */
  PFX_PARAM_REJECT_OUT_OF_RANGE = 1u << 0,
  /* A UI should use a logarithmic slider over the display range (which must then be > 0). */
  PFX_PARAM_LOGARITHMIC = 1u << 1,
  /* Since 1.4: display_default holds this parameter's default for display-referred frames. */
  PFX_PARAM_HAS_DISPLAY_DEFAULT = 1u << 2,
  /* Since 1.5: the default or the display range depends on the frame's size (an FX uniform whose
   * default is BUFFER_WIDTH). The descriptor gives them for a 1920x1080 frame; the plugin's
   * sources factory says what they are at another size (pfx/sources.h, params_at), and an instance
   * takes a value equal to default_value as "not set": it runs with the default of its frame. */
  PFX_PARAM_FOLLOWS_FRAME_SIZE = 1u << 3
};

/* Every value, whatever its type, travels as four doubles: exact for any int up to 2^53. */
typedef struct pfx_value {
  double v[4];
} pfx_value;

typedef struct pfx_enum_item {
  const char* id;     /* stable, used in text and JSON: "chain13" */
  const char* label;  /* for a UI: "13-tap chain" */
} pfx_enum_item;

typedef struct pfx_param_desc {
  uint32_t struct_size;
  const char* id;       /* stable, [a-z0-9_]+, unique within the effect: "threshold" */
  const char* label;    /* "Threshold" */
  const char* tooltip;  /* one or two sentences for a UI */
  const char* unit;     /* "px", "m", "mm", "EV", "" for none */
  const char* group;    /* a UI group, "" for none */
  pfx_param_type type;
  uint32_t flags;                    /* PFX_PARAM_* flags */
  double hard_min, hard_max;         /* every component; NaN is always refused */
  double display_min, display_max;   /* a UI's slider range, inside the hard range */
  double step;                       /* a UI's increment; 1 for INT */
  pfx_value default_value;
  const pfx_enum_item* items;        /* ENUM only: item_count items, index = value */
  uint32_t item_count;
  /* The default for a display-referred frame (values in [0, 1] shown as they are: an 8-bit video
   * frame, an application's back buffer), where nothing is brighter than 1.0 and a threshold made
   * for scene-linear light would never be reached. Read only with PFX_PARAM_HAS_DISPLAY_DEFAULT;
   * otherwise default_value serves every frame. Hosts that know their frames are display-referred
   * start from it (libpfxhost: ParamStore with DefaultSet::DISPLAY_REFERRED). */
  pfx_value display_default; /* since 1.4 */
} pfx_param_desc;
#define PFX_PARAM_DESC_MIN_SIZE PFX_STRUCT_SIZE_THROUGH(pfx_param_desc, item_count)

#ifdef __cplusplus
}
#endif
#endif /* PFX_PARAMS_H */
