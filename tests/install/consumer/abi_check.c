/* Compiled against the installed C ABI headers alone (pfx::sdk, or `pkg-config --cflags pfx`),
 * as C99 with -pedantic: a foreign host or a plugin needs nothing else to start. */
#include <stddef.h>
#include <stdio.h>

#include <pfx/pfx.h>

/* Every struct that may grow starts with its size (docs/sdk.md, "Versioning"). */
typedef char size_first_entry[offsetof(pfx_entry, struct_size) == 0 ? 1 : -1];
typedef char size_first_host[offsetof(pfx_host, struct_size) == 0 ? 1 : -1];
typedef char size_first_frame[offsetof(pfx_frame, struct_size) == 0 ? 1 : -1];
typedef char size_first_effect[offsetof(pfx_effect_desc, struct_size) == 0 ? 1 : -1];
typedef char size_first_param[offsetof(pfx_param_desc, struct_size) == 0 ? 1 : -1];

int main(void) {
  /* pfx/depth.h is usable as is: a standard projection with near 0.1 maps window depth 0 to 0.1 m. */
  double near_depth = pfx_view_depth(0.0, PFX_DEPTH_HARDWARE, 0.1, 100.0);
  if (near_depth < 0.0999 || near_depth > 0.1001) {
    fprintf(stderr, "abi_check: pfx_view_depth(0) = %g, expected 0.1\n", near_depth);
    return 1;
  }
  printf("pfx C ABI %u.%u (%s)\n", (unsigned)PFX_ABI_MAJOR, (unsigned)PFX_ABI_MINOR, PFX_EFFECTS_FACTORY_ID);
  return 0;
}
