// Mappings the import no longer needs, kept for the arrays it makes next. A fresh page costs a
// fault and the kernel's zero-fill the first time it is written — on the machines this project is
// measured on, about 0.4 ms per MB, which is as much as parsing that MB — so a page already
// written once is worth reusing: a chunk's face corners, freed once they are numbered, become the
// vertex arrays of the result. Process-wide and thread-safe; the import hands back what is left
// when it ends (release_spare_mappings).
#pragma once

#include <cstddef>

namespace pfx_obj {

// Keeps the mapping [p, p + bytes), of which the first `written` bytes were written, for a later
// take_spare_mapping.
void keep_spare_mapping(void* p, size_t bytes, size_t written);

// The start, `bytes` rounded up to whole pages, of a kept mapping at least that large (the one
// with the most written pages); the rest of it stays kept where it has written pages. nullptr
// when none is large enough. Its contents are whatever was written there.
void* take_spare_mapping(size_t bytes);

// Unmaps every kept mapping.
void release_spare_mappings();

}  // namespace pfx_obj
