// What pfx-import prints about an import result: a text summary or one JSON object.
#pragma once

#include <string>

#include <pfx/importer.h>

namespace pfx::import {

std::string summary_text(const std::string& file, const pfx_import_result& result);
std::string summary_json(const std::string& file, const pfx_import_result& result);

}  // namespace pfx::import
