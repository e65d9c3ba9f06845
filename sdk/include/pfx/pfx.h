/* pfx C ABI v1 — everything a plugin or a foreign host includes. */
#ifndef PFX_PFX_H
#define PFX_PFX_H

#include "pfx/core.h"
#include "pfx/params.h"
#include "pfx/effect.h"
#include "pfx/importer.h"
#include "pfx/depth.h"
#include "pfx/reference.h"
#include "pfx/services.h"
#include "pfx/sources.h"

#endif /* PFX_PFX_H */
