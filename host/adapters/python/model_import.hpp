// pfx.import_model: a model file through the importer plugins, as numpy arrays.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

namespace pfx::python {

// A types.SimpleNamespace: positions (N x 3 float32), normals (N x 3), uvs (N x 2, or None),
// colors (N x 3, or None), indices (M uint32, triangles), submeshes (S x 3 uint32: first index,
// index count, material or 0xffffffff), materials (list of dicts), bounds_min, bounds_max (3
// float32), faces, lines_skipped, points_skipped, warnings, warning_total, importer. Raises
// pfx.Error when no importer takes the file or the import fails. `threads`: most tasks at once
// on the plugins' thread pool, 0 for what it offers, 1 for none.
pybind11::object import_model(const std::string& path, const std::optional<std::vector<std::string>>& plugins,
                              unsigned threads);

}  // namespace pfx::python
