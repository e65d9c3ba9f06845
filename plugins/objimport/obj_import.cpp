// The OBJ importer: the stages of obj_stages.hpp run in order, a failure in any turned into a
// message; and the stages that make the result: 1 (cut), 5 (index), 6 (vertices), 8 (warnings).
#include "obj_import.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <new>

#include "obj_normals.hpp"
#include "obj_parallel.hpp"
#include "obj_stages.hpp"

namespace pfx_obj {

namespace {

// Progress: the share of an import's time done when a stage ends. Reading and numbering take most;
// the checks with the materials, the index array, and the vertices with their normals the rest.
constexpr double kShareNumbered = 0.6, kShareMaterialsRead = 0.7, kShareIndexed = 0.85;

// Stage 1's cut: chunks of about chunk_bytes when that is given, else about eight per thread of 1 to
// 4 MB, their count a multiple of the thread count so the threads finish together.
size_t chunk_count(size_t bytes, size_t chunk_bytes, unsigned threads) {
  if (chunk_bytes > 0) return std::max<size_t>(1, (bytes + chunk_bytes - 1) / chunk_bytes);
  const size_t size = std::clamp<size_t>(bytes / (size_t{threads} * 8), 1 << 20, 4 << 20);
  const size_t chunks = (bytes + size - 1) / size;
  return chunks > 1 ? (chunks + threads - 1) / threads * threads : 1;
}

constexpr size_t kBlock = size_t{1} << 15;  // vertices per parallel task

// A usemtl name's (an index into FileStatements::material_names) place among the sub-meshes: its
// material's index, or one past the last material for faces before any usemtl.
uint32_t slot_of(const MaterialTable& table, uint32_t name) {
  return name == kNoIndex ? static_cast<uint32_t>(table.materials.size()) : table.of_name[name];
}

// run(slot, first, end) for each run of the chunk's triangles of one material, in order: the
// triangles [first, end) of the file's.
template <typename Run>
void for_each_run(const NumberedChunk& chunk, const MaterialTable& table, Run run) {
  uint32_t slot = slot_of(table, chunk.start.material);
  uint64_t first = chunk.start.triangles;
  for (const StateChange& change : chunk.changes) {
    if (change.kind != StateChange::kMaterial) continue;
    const uint64_t at = chunk.start.triangles + change.first_triangle;
    if (at > first) run(slot, first, at);
    slot = slot_of(table, change.value);
    first = at;
  }
  if (chunk.end.triangles > first) run(slot, first, chunk.end.triangles);
}

// Each vertex's kWidth floats of *source at the element its key's `field` names (zeros for none),
// in blocks on every worker; *source freed after.
template <int kWidth>
BigVector<float> gather(const BigVector<VertexKey>& keys, BigVector<float>* source, uint32_t VertexKey::*field,
                        const ImportContext& context) {
  const size_t count = keys.size();
  BigVector<float> out(kWidth * count);
  run_parallel(context.pool, context.threads, (count + kBlock - 1) / kBlock, [&](size_t b, unsigned) {
    for (size_t i = b * kBlock; i < std::min(count, (b + 1) * kBlock); ++i) {
      const uint32_t element = keys[i].*field;
      for (int k = 0; k < kWidth; ++k)
        out[kWidth * i + k] = element == kNoIndex ? 0.0f : (*source)[kWidth * size_t{element} + k];
    }
  });
  free_array(source);
  return out;
}

// Stage 8: every stage's warnings, and the skipped statements and an empty mesh said once each, in
// line order (stable), as "FILE:LINE: text": the first kMaxWarnings; *total: how many in all.
std::vector<std::string> mesh_warnings(const NumberedFile& file, const MaterialTable& materials,
                                       const std::string& name, uint64_t* total) {
  std::vector<LocalMessage> warnings = file.warnings;
  warnings.insert(warnings.end(), materials.warnings.begin(), materials.warnings.end());
  for (const auto& [keyword, ignored] : file.statements.ignored) {
    const std::string what = ignored.valid_obj ? "'" + keyword + "' statements are not supported: "
                                               : "unknown statement '" + keyword + "': ";
    warnings.push_back({ignored.first_line, what + std::to_string(ignored.count) + " ignored"});
  }
  if (file.totals().faces == 0)
    warnings.push_back({std::max<uint64_t>(file.totals().line - 1, 1), "no faces: the mesh is empty"});
  std::stable_sort(warnings.begin(), warnings.end(),
                   [](const LocalMessage& a, const LocalMessage& b) { return a.line < b.line; });
  *total = warnings.size();
  std::vector<std::string> first;
  for (size_t i = 0; i < warnings.size() && i < kMaxWarnings; ++i)
    first.push_back(at_line(name, warnings[i].line, warnings[i].text));
  return first;
}

ObjMesh run_stages(std::string_view text, const ImportContext& context, const ImportOptions& options) {
  auto report = [&](double share) { if (options.progress) options.progress(static_cast<float>(share)); };
  report(0.0);
  const std::vector<std::string_view> texts =
      split_at_line_ends(text, chunk_count(text.size(), options.chunk_bytes, context.threads));
  NumberedFile file = number_chunks(texts, context, [&](double numbered) { report(kShareNumbered * numbered); });
  check_indices(texts, file, context);
  clip_deferred_polygons(&file);
  MaterialTable materials = load_materials(file.statements, context.directory);
  report(kShareMaterialsRead);
  TriangleIndex index = index_by_material(file.chunks, materials, std::move(file.triangles));
  report(kShareIndexed);
  MeshVertices vertices = gather_vertices(file.keys, std::move(file.vertices), context);
  generate_normals(file.keys, vertices.positions, index.indices, context.pool, context.threads, &vertices.normals);
  free_array(&file.keys);
  ObjMesh mesh;
  mesh.warnings = mesh_warnings(file, materials, context.name, &mesh.warning_total);
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
  report(1.0);
  return mesh;
}

bool import_text(std::string_view text, const ImportContext& context, const ImportOptions& options, ObjMesh* out,
                 std::string* error) {
  *out = ObjMesh{};
  error->clear();
  try {
    *out = run_stages(text, context, options);
    return true;
  } catch (const ImportError& e) {
    *error = e.what();
  } catch (const std::bad_alloc&) {
    *error = context.name + ": out of memory";
  } catch (const std::exception& e) {  // a limit met below the stages (VertexNumbering's)
    *error = context.name + ": " + e.what();
  }
  return false;
}

}  // namespace

TriangleIndex index_by_material(const std::vector<NumberedChunk>& chunks, const MaterialTable& materials,
                                BigVector<uint32_t> triangles) {
  const size_t slots = materials.materials.size() + 1;
  std::vector<uint64_t> count(slots, 0), first_use(slots, ~uint64_t{0});
  for (const NumberedChunk& chunk : chunks)
    for_each_run(chunk, materials, [&](uint32_t s, uint64_t first, uint64_t end) {
      count[s] += end - first;
      first_use[s] = std::min(first_use[s], first);
    });
  std::vector<uint32_t> order;  // the slots used, in order of first use
  for (uint32_t s = 0; s < slots; ++s)
    if (count[s] > 0) order.push_back(s);
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return first_use[a] < first_use[b]; });
  TriangleIndex index;
  std::vector<uint64_t> place(slots, 0);  // where each slot's next triangle goes
  uint64_t total = 0;
  for (uint32_t s : order) {
    place[s] = total;
    total += 3 * count[s];
    const uint32_t material = s == slots - 1 ? kNoIndex : s;
    index.submeshes.push_back({static_cast<uint32_t>(place[s]), static_cast<uint32_t>(3 * count[s]), material});
  }
  if (order.size() <= 1) {  // one material: the triangles as they are
    index.indices = std::move(triangles);
    return index;
  }
  index.indices.resize(total);
  for (const NumberedChunk& chunk : chunks)
    for_each_run(chunk, materials, [&](uint32_t s, uint64_t first, uint64_t end) {
      std::memcpy(&index.indices[place[s]], &triangles[3 * first], 3 * (end - first) * sizeof(uint32_t));
      place[s] += 3 * (end - first);
    });
  return index;
}

MeshVertices gather_vertices(const BigVector<VertexKey>& keys, FileVertices file, const ImportContext& context) {
  MeshVertices mesh;
  mesh.positions = gather<3>(keys, &file.positions, &VertexKey::v, context);
  if (!file.colors.empty()) mesh.colors = gather<3>(keys, &file.colors, &VertexKey::v, context);
  if (std::any_of(keys.begin(), keys.end(), [](const VertexKey& k) { return k.vt != kNoIndex; }))
    mesh.texcoords = gather<2>(keys, &file.texcoords, &VertexKey::vt, context);
  mesh.normals = gather<3>(keys, &file.normals, &VertexKey::vn, context);  // those without: generated later
  free_array(&file.texcoords);  // when no corner used one
  if (keys.empty()) return mesh;  // the bounds stay zero
  float lo[3] = {HUGE_VALF, HUGE_VALF, HUGE_VALF}, hi[3] = {-HUGE_VALF, -HUGE_VALF, -HUGE_VALF};
  for (size_t i = 0; i < mesh.positions.size(); i += 3)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], mesh.positions[i + k]);
      hi[k] = std::max(hi[k], mesh.positions[i + k]);
    }
  std::copy(lo, lo + 3, mesh.bounds_min);
  std::copy(hi, hi + 3, mesh.bounds_max);
  return mesh;
}

bool import_obj_text(std::string_view text, const std::string& name, const std::string& directory,
                     const ImportOptions& options, ObjMesh* out, std::string* error) {
  const unsigned threads = worker_count(options.pool, options.threads);
  return import_text(text, {name, directory, nullptr, options.pool, threads}, options, out, error);
}

bool import_obj_file(const std::string& path, const ImportOptions& options, ObjMesh* out, std::string* error) {
  FileBytes file;
  if (!file.open(path, error)) return false;
  std::string directory = std::filesystem::path(path).parent_path().string();
  if (directory.empty()) directory = ".";
  const unsigned threads = worker_count(options.pool, options.threads);
  return import_text(file.bytes(), {path, directory, &file, options.pool, threads}, options, out, error);
}

}  // namespace pfx_obj
