// frei0r.h declares the entry points without extern "C": included from C++ only through here, so
// the declarations and the definitions in frei0r_exports.cpp agree on C linkage.
#pragma once

extern "C" {
#include <frei0r.h>
}
