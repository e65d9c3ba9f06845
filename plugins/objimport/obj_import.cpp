// The OBJ importer: the stages of obj_stages.hpp run in order, the result put together from their
// outputs, and a failure in any of them turned into a message.
#include "obj_import.hpp"

#include <algorithm>
#include <filesystem>
#include <new>

#include "obj_normals.hpp"
#include "obj_stages.hpp"

namespace pfx_obj {

namespace {

// Progress: the share of an import's time done by the end of a stage. Reading and numbering take
// most of it; checking and the materials, the index array, and the vertex arrays with the normals
// take the rest.
constexpr double kShareNumbered = 0.6;
constexpr double kShareMaterialsRead = 0.7;
constexpr double kShareIndexed = 0.85;

// Where the text came from.
struct Source {
  std::string_view text;
  const std::string& name;       // the file name in messages
  const std::string& directory;  // where mtllib files are looked for; empty: not at all
  const FileBytes* file;         // where the text is a file's mapping, the mapping; else null
};

// Stage 1: the text cut at line ends, into chunks of about chunk_bytes when that is given, else
// into about eight chunks per thread of 1 to 4 MB, their count a multiple of the thread count so
// the threads finish together.
std::vector<std::string_view> cut_into_chunks(std::string_view text, size_t chunk_bytes, unsigned threads) {
  const size_t bytes = text.size();
  size_t chunks;
  if (chunk_bytes > 0) {
    chunks = (bytes + chunk_bytes - 1) / chunk_bytes;
  } else {
    const size_t size = std::clamp<size_t>(bytes / (size_t{threads} * 8), 1 << 20, 4 << 20);
    chunks = (bytes + size - 1) / size;
    if (chunks > 1) chunks = (chunks + threads - 1) / threads * threads;
  }
  return split_at_line_ends(text, std::max<size_t>(1, chunks));
}

// Stage 8: every stage's warnings, with the skipped statements and an empty mesh said once each,
// in line order (stable: warnings of one line in the order the stages gave them).
std::vector<LocalMessage> in_line_order(std::vector<LocalMessage> warnings, const FileStatements& statements,
                                        uint64_t faces, uint64_t last_line) {
  for (const auto& [keyword, ignored] : statements.ignored) {
    const std::string what = ignored.valid_obj ? "'" + keyword + "' statements are not supported: "
                                               : "unknown statement '" + keyword + "': ";
    warnings.push_back({ignored.first_line, what + std::to_string(ignored.count) + " ignored"});
  }
  if (faces == 0) warnings.push_back({std::max<uint64_t>(last_line, 1), "no faces: the mesh is empty"});
  std::stable_sort(warnings.begin(), warnings.end(),
                   [](const LocalMessage& a, const LocalMessage& b) { return a.line < b.line; });
  return warnings;
}

ObjMesh run_stages(const Source& source, const ImportOptions& options) {
  auto report = [&](double share) {
    if (options.progress) options.progress(static_cast<float>(share));
  };
  report(0.0);
  const unsigned threads = worker_count(options.pool, options.threads);
  const std::vector<std::string_view> texts = cut_into_chunks(source.text, options.chunk_bytes, threads);
  NumberedFile file = number_chunks(texts, {source.name, options.pool, threads, source.file,
                                            [&](double numbered) { report(kShareNumbered * numbered); }});
  check_indices(texts, file, source.name);
  clip_deferred_polygons(&file);
  MaterialTable materials = load_materials(file.statements, source.directory);
  report(kShareMaterialsRead);
  TriangleIndex index = index_by_material(file.chunks, materials, std::move(file.triangles));
  report(kShareIndexed);
  MeshVertices vertices = gather_vertices(file.keys, std::move(file.vertices), options.pool, threads);
  generate_normals(file.keys, vertices.positions, index.indices, options.pool, threads, &vertices.normals);
  free_array(&file.keys);

  ObjMesh mesh;
  mesh.positions = std::move(vertices.positions);
  mesh.normals = std::move(vertices.normals);
  mesh.texcoords = std::move(vertices.texcoords);
  mesh.colors = std::move(vertices.colors);
  std::copy(vertices.bounds_min, vertices.bounds_min + 3, mesh.bounds_min);
  std::copy(vertices.bounds_max, vertices.bounds_max + 3, mesh.bounds_max);
  mesh.indices = std::move(index.indices);
  mesh.submeshes = std::move(index.submeshes);
  mesh.materials = std::move(materials.materials);
  mesh.faces = file.totals().faces;
  mesh.lines_skipped = file.statements.lines_skipped;
  mesh.points_skipped = file.statements.points_skipped;
  std::vector<LocalMessage> warnings = std::move(file.warnings);
  warnings.insert(warnings.end(), materials.warnings.begin(), materials.warnings.end());
  warnings = in_line_order(std::move(warnings), file.statements, mesh.faces, file.totals().line - 1);
  mesh.warning_total = warnings.size();
  for (size_t i = 0; i < warnings.size() && i < kMaxWarnings; ++i)
    mesh.warnings.push_back(at_line(source.name, warnings[i].line, warnings[i].text));
  report(1.0);
  return mesh;
}

bool import_text(const Source& source, const ImportOptions& options, ObjMesh* out, std::string* error) {
  *out = ObjMesh{};
  error->clear();
  try {
    *out = run_stages(source, options);
    return true;
  } catch (const ImportError& e) {
    *error = e.what();
  } catch (const std::bad_alloc&) {
    *error = source.name + ": out of memory";
  } catch (const std::exception& e) {  // a limit met below the stages (VertexNumbering's)
    *error = source.name + ": " + e.what();
  }
  return false;
}

}  // namespace

bool import_obj_text(std::string_view text, const std::string& name, const std::string& directory,
                     const ImportOptions& options, ObjMesh* out, std::string* error) {
  return import_text({text, name, directory, nullptr}, options, out, error);
}

bool import_obj_file(const std::string& path, const ImportOptions& options, ObjMesh* out, std::string* error) {
  FileBytes file;
  if (!file.open(path, error)) return false;
  const std::string directory = std::filesystem::path(path).parent_path().string();
  return import_text({file.bytes(), path, directory.empty() ? "." : directory, &file}, options, out, error);
}

}  // namespace pfx_obj
