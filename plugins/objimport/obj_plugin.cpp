// The OBJ importer plugin: importer "obj" behind the C ABI (pfx/importer.h). The result handed
// out is a plain C struct pointing into C++ storage the plugin keeps until release.
#include <chrono>
#include <filesystem>
#include <mutex>
#include <new>
#include <string>
#include <unordered_map>
#include <vector>

#include <pfx/cpp/plugin_entry.hpp>
#include <pfx/pfx.h>

#include "obj_chunk.hpp"
#include "obj_import.hpp"

namespace pfx_obj {
namespace {

static_assert(kNoIndex == PFX_IMPORT_NONE, "no material is the same number on both sides");

struct ResultStorage {
  pfx_import_result result{};
  ObjMesh mesh;
  std::string error;
  std::vector<pfx_import_material> materials;
  std::vector<const char*> warnings;
};

// The host's thread pool, looked up in init (null: the host offers none, and imports run on the
// calling thread alone). The plugin starts no thread of its own.
const pfx_thread_pool* g_pool = nullptr;

// Results handed out and not yet released: release ignores any other pointer.
std::mutex g_results_mutex;
std::unordered_map<const pfx_import_result*, ResultStorage*> g_results;

void publish(ResultStorage* s) {
  pfx_import_result& r = s->result;
  const ObjMesh& m = s->mesh;
  r.vertex_count = m.vertex_count();
  r.positions = m.positions.empty() ? nullptr : m.positions.data();
  r.normals = m.normals.empty() ? nullptr : m.normals.data();
  r.texcoords = m.texcoords.empty() ? nullptr : m.texcoords.data();
  r.colors = m.colors.empty() ? nullptr : m.colors.data();
  r.index_count = static_cast<uint32_t>(m.indices.size());
  r.indices = m.indices.empty() ? nullptr : m.indices.data();
  r.submesh_count = static_cast<uint32_t>(m.submeshes.size());
  r.submeshes = m.submeshes.empty() ? nullptr : m.submeshes.data();
  for (const Material& material : m.materials) {
    pfx_import_material out{};
    out.struct_size = sizeof(pfx_import_material);
    out.name = material.name.c_str();
    std::memcpy(out.diffuse, material.diffuse, sizeof out.diffuse);
    std::memcpy(out.specular, material.specular, sizeof out.specular);
    std::memcpy(out.emissive, material.emissive, sizeof out.emissive);
    out.shininess = material.shininess;
    out.opacity = material.opacity;
    out.diffuse_map = material.diffuse_map.empty() ? nullptr : material.diffuse_map.c_str();
    out.emissive_map = material.emissive_map.empty() ? nullptr : material.emissive_map.c_str();
    out.alpha_map = material.alpha_map.empty() ? nullptr : material.alpha_map.c_str();
    out.bump_map = material.bump_map.empty() ? nullptr : material.bump_map.c_str();
    out.normal_map = material.normal_map.empty() ? nullptr : material.normal_map.c_str();
    s->materials.push_back(out);
  }
  r.material_count = static_cast<uint32_t>(s->materials.size());
  r.materials = s->materials.empty() ? nullptr : s->materials.data();
  std::memcpy(r.bounds_min, m.bounds_min, sizeof r.bounds_min);
  std::memcpy(r.bounds_max, m.bounds_max, sizeof r.bounds_max);
  r.lines_skipped = m.lines_skipped;
  r.points_skipped = m.points_skipped;
  r.faces = m.faces;
  for (const std::string& w : m.warnings) s->warnings.push_back(w.c_str());
  r.warning_count = static_cast<uint32_t>(s->warnings.size());
  r.warnings = s->warnings.empty() ? nullptr : s->warnings.data();
  r.warning_total = m.warning_total;
}

pfx_status import(const pfx_import_request* request, pfx_import_result** out) {
  if (!out) return PFX_INVALID_ARGUMENT;
  *out = nullptr;
  ResultStorage* storage = new (std::nothrow) ResultStorage;
  if (!storage) return PFX_OUT_OF_MEMORY;
  const auto start = std::chrono::steady_clock::now();
  pfx_import_result& r = storage->result;
  r.struct_size = sizeof(pfx_import_result);
  try {
    if (!request || request->struct_size < PFX_IMPORT_REQUEST_MIN_SIZE || !request->path == !request->bytes) {
      r.status = PFX_INVALID_ARGUMENT;
      storage->error = "import request: give either path or bytes";
    } else {
      ImportOptions options;
      options.pool = g_pool;
      options.threads = request->threads;
      if (request->progress)
        options.progress = [fn = request->progress, user = request->progress_user](float fraction) { fn(user, fraction); };
      // Bytes with a name: mtllib files are looked for beside it (without one, not at all).
      const std::string name = request->name ? request->name : "<memory>";
      std::string directory = request->name ? std::filesystem::path(name).parent_path().string() : "";
      if (request->name && directory.empty()) directory = ".";
      const bool ok = request->path ? import_obj_file(request->path, options, &storage->mesh, &storage->error)
                                    : import_obj_text({static_cast<const char*>(request->bytes), request->byte_count},
                                                      name, directory, options, &storage->mesh, &storage->error);
      r.status = ok ? PFX_OK : PFX_ERROR;
      if (ok) publish(storage);
    }
  } catch (...) {  // import_obj_* catch their own failures: what is left is out of memory
    storage->mesh = ObjMesh{};
    storage->error = "out of memory";
    r.status = PFX_OUT_OF_MEMORY;
  }
  if (r.status != PFX_OK) r.error = storage->error.c_str();
  r.parse_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  try {
    std::lock_guard<std::mutex> lock(g_results_mutex);
    g_results[&r] = storage;
  } catch (...) {
    delete storage;
    return PFX_OUT_OF_MEMORY;
  }
  *out = &r;
  return r.status;
}

void release(pfx_import_result* result) {  // (null, like any pointer not handed out, is not found)
  ResultStorage* storage = nullptr;
  {
    std::lock_guard<std::mutex> lock(g_results_mutex);
    auto it = g_results.find(result);
    if (it == g_results.end()) return;
    storage = it->second;
    g_results.erase(it);
  }
  delete storage;
}

constexpr const char* kExtensions[] = {"obj"};
constexpr pfx_importer_desc kObjImporter = {
    sizeof(pfx_importer_desc), "obj", "Wavefront OBJ", kExtensions, 1, import, release};

constexpr const pfx_importer_desc* kImporters[] = {&kObjImporter};

// Imports run their stages on the host's thread pool when it offers one.
pfx_status find_pool(const pfx_host* host) {
  g_pool = pfx::plugin::host_thread_pool(host);
  return PFX_OK;
}
void forget_pool() { g_pool = nullptr; }

constexpr auto kPlugin = pfx::plugin::Plugin("org.pfx.objimport")
                             .name("pfx OBJ importer")
                             .version("0.1.0")
                             .importers(kImporters)
                             .on_init(find_pool)
                             .on_deinit(forget_pool);

}  // namespace
}  // namespace pfx_obj

PFX_PLUGIN_ENTRY(pfx_obj::kPlugin)
