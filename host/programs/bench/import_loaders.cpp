#include "import_loaders.hpp"

#ifdef PFX_BENCH_HAVE_TINYOBJLOADER
#include <tiny_obj_loader.h>
#endif
#ifdef PFX_BENCH_HAVE_ASSIMP
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#endif

#include <filesystem>

#include <pfx/host/import_result.hpp>

namespace pfx::bench {

namespace {

LoadCounts load_pfx(const std::string& path, unsigned threads, const pfx::host::PluginRegistry& registry) {
  LoadCounts counts;
  const pfx::host::ImporterInfo* importer = registry.find_importer_for_path(path);
  if (!importer) {
    counts.error = "no importer plugin for .obj is loaded";
    return counts;
  }
  pfx_import_request request{};
  request.struct_size = sizeof request;
  request.path = path.c_str();
  request.threads = threads;
  const pfx::host::ImportResult result(*importer->desc, request);
  if (!result) {
    counts.error = "out of memory";
    return counts;
  }
  counts.ok = result.ok();
  if (!counts.ok) counts.error = result.error() ? result.error() : "import failed";
  counts.vertices = result->vertex_count;
  counts.triangles = result->index_count / 3;
  return counts;
}

#ifdef PFX_BENCH_HAVE_TINYOBJLOADER
LoadCounts load_tinyobjloader(const std::string& path) {
  LoadCounts counts;
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warn, err;
  const std::string base = std::filesystem::path(path).parent_path().string() + "/";
  counts.ok = tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, path.c_str(), base.c_str(), true);
  if (!counts.ok) counts.error = err;
  counts.vertices = attrib.vertices.size() / 3;
  for (const auto& shape : shapes) counts.triangles += shape.mesh.num_face_vertices.size();
  return counts;
}
#endif

#ifdef PFX_BENCH_HAVE_ASSIMP
LoadCounts load_assimp(const std::string& path) {
  LoadCounts counts;
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
  counts.ok = scene != nullptr;
  if (!scene) {
    counts.error = importer.GetErrorString();
    return counts;
  }
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    counts.vertices += scene->mMeshes[m]->mNumVertices;
    counts.triangles += scene->mMeshes[m]->mNumFaces;
  }
  return counts;
}
#endif

}  // namespace

std::vector<std::string> available_loaders() {
  std::vector<std::string> names = {"pfx"};
#ifdef PFX_BENCH_HAVE_TINYOBJLOADER
  names.push_back("tinyobjloader");
#endif
#ifdef PFX_BENCH_HAVE_ASSIMP
  names.push_back("assimp");
#endif
  return names;
}

bool loader_is_multithreaded(const std::string& name) { return name == "pfx"; }

LoadCounts load_with(const std::string& name, const std::string& path, unsigned threads,
                     const pfx::host::PluginRegistry& registry) {
  if (name == "pfx") return load_pfx(path, threads, registry);
#ifdef PFX_BENCH_HAVE_TINYOBJLOADER
  if (name == "tinyobjloader") return load_tinyobjloader(path);
#endif
#ifdef PFX_BENCH_HAVE_ASSIMP
  if (name == "assimp") return load_assimp(path);
#endif
  LoadCounts counts;
  counts.error = "loader '" + name + "' is not built into this pfx-bench";
  return counts;
}

}  // namespace pfx::bench
