#include "model_import.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <pfx/host/import_result.hpp>

#include "plugin_set.hpp"
#include "python_errors.hpp"

namespace py = pybind11;

namespace pfx::python {
namespace {

// rows x columns values copied out of the result, which is released when import_model returns.
template <typename T>
py::object table(const T* values, size_t rows, size_t columns) {
  if (!values) return py::none();
  py::array_t<T> out(columns == 1 ? std::vector<size_t>{rows} : std::vector<size_t>{rows, columns});
  std::copy(values, values + rows * columns, out.mutable_data());
  return std::move(out);
}

py::dict material_dict(const pfx_import_material& m) {
  auto map = [&](const char* path) -> py::object { return path ? py::object(py::str(path)) : py::none(); };
  py::dict dict;
  dict["name"] = m.name ? m.name : "";
  dict["diffuse"] = py::make_tuple(m.diffuse[0], m.diffuse[1], m.diffuse[2]);
  dict["specular"] = py::make_tuple(m.specular[0], m.specular[1], m.specular[2]);
  dict["emissive"] = py::make_tuple(m.emissive[0], m.emissive[1], m.emissive[2]);
  dict["shininess"] = m.shininess;
  dict["opacity"] = m.opacity;
  dict["diffuse_map"] = map(m.diffuse_map);
  dict["emissive_map"] = map(m.emissive_map);
  // Maps an importer of ABI 1.3 or later fills in; an older one's struct ends before them.
  dict["alpha_map"] = map(PFX_STRUCT_HAS(&m, pfx_import_material, alpha_map) ? m.alpha_map : nullptr);
  dict["bump_map"] = map(PFX_STRUCT_HAS(&m, pfx_import_material, bump_map) ? m.bump_map : nullptr);
  dict["normal_map"] = map(PFX_STRUCT_HAS(&m, pfx_import_material, normal_map) ? m.normal_map : nullptr);
  return dict;
}

}  // namespace

py::object import_model(const std::string& path, const std::optional<std::vector<std::string>>& plugins,
                        unsigned threads) {
  auto registry = load_plugin_set(plugins, [](const std::string& message) {
    PyErr_WarnEx(PyExc_RuntimeWarning, message.c_str(), 1);
  });
  const host::ImporterInfo* importer = registry->find_importer_for_path(path);
  if (!importer) {
    std::string known;
    for (const auto& info : registry->importers())
      for (uint32_t e = 0; e < info.desc->extension_count; ++e) known += (known.empty() ? "" : ", ") + std::string(info.desc->extensions[e]);
    throw Error(path + ": no importer takes this kind of file (loaded importers take: " +
                (known.empty() ? "none" : known) + ")");
  }
  pfx_import_request request{};
  request.struct_size = sizeof request;
  request.path = path.c_str();
  request.threads = threads;
  host::ImportResult result;
  {
    py::gil_scoped_release release;
    result = host::ImportResult(*importer->desc, request);
  }
  if (!result.ok())
    throw Error(result.error() ? result.error() : path + ": the importer ran out of memory");
  const pfx_import_result& r = *result;

  py::list materials;
  const auto* bytes = reinterpret_cast<const unsigned char*>(r.materials);
  for (uint32_t i = 0; i < r.material_count; ++i) {
    // Stepped by the importer's own struct size (pfx/importer.h).
    const auto* material = reinterpret_cast<const pfx_import_material*>(bytes + size_t(i) * r.materials[0].struct_size);
    materials.append(material_dict(*material));
  }
  py::list warnings;
  for (uint32_t i = 0; i < r.warning_count; ++i) warnings.append(r.warnings[i]);
  static_assert(sizeof(pfx_import_submesh) == 3 * sizeof(uint32_t), "sub-meshes are three uint32 each");

  py::dict fields;
  fields["importer"] = importer->desc->id;
  fields["positions"] = table(r.positions, r.vertex_count, 3);
  fields["normals"] = table(r.normals, r.vertex_count, 3);
  fields["uvs"] = table(r.texcoords, r.vertex_count, 2);
  fields["colors"] = table(r.colors, r.vertex_count, 3);
  fields["indices"] = r.indices ? table(r.indices, r.index_count, 1) : py::object(py::array_t<uint32_t>(0));
  fields["submeshes"] = table(reinterpret_cast<const uint32_t*>(r.submeshes), r.submesh_count, 3);
  if (!r.submeshes) fields["submeshes"] = py::array_t<uint32_t>(std::vector<size_t>{0, 3});
  fields["materials"] = materials;
  fields["bounds_min"] = table(r.bounds_min, 3, 1);
  fields["bounds_max"] = table(r.bounds_max, 3, 1);
  fields["faces"] = r.faces;
  fields["lines_skipped"] = r.lines_skipped;
  fields["points_skipped"] = r.points_skipped;
  fields["warnings"] = warnings;
  fields["warning_total"] = r.warning_total;
  if (!r.positions) fields["positions"] = py::array_t<float>(std::vector<size_t>{0, 3});
  return py::module_::import("types").attr("SimpleNamespace")(**fields);
}

}  // namespace pfx::python
