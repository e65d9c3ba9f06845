// What pfx-import prints about an import result: a text summary or one JSON object.
#pragma once

#include <string>

#include <pfx/importer.h>

namespace pfx::import {

// seconds: the import call's wall-clock time, as pfx-import measured it.
std::string summary_text(const std::string& file, const pfx_import_result& result, double seconds);
std::string summary_json(const std::string& file, const pfx_import_result& result, double seconds);

}  // namespace pfx::import
