// Export macro of libpfxhost: everything else in the library is hidden.
#pragma once

#if defined(PFX_HOST_BUILDING)
#define PFX_HOST_API __attribute__((visibility("default")))
#else
#define PFX_HOST_API
#endif
