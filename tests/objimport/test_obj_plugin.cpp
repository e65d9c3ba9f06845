// The importer through the C ABI as a host sees it: libpfxhost loads the plugin, finds the
// importer by extension, imports a file and bytes, and gets errors as "FILE:LINE: reason".
#include <catch2/catch.hpp>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include <sys/prctl.h>
#include <unistd.h>

#include <pfx/host/plugin_registry.hpp>

namespace fs = std::filesystem;

namespace {

std::unique_ptr<pfx::host::PluginRegistry> load_obj_plugin() {
  auto registry = std::make_unique<pfx::host::PluginRegistry>([](const char*) { return pfx_gl_proc{nullptr}; },
                                                              nullptr, "test_obj_plugin");
  std::string error;
  REQUIRE(registry->load(PFX_TEST_OBJ_PLUGIN, &error));
  return registry;
}

pfx_import_request request_for_path(const char* path) {
  pfx_import_request request{};
  request.struct_size = sizeof request;
  request.path = path;
  request.threads = 2;
  return request;
}

// A "Vm..." or "Rss..." line of /proc/self/status in bytes, 0 when unknown.
uint64_t status_bytes(const char* field) {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(field, 0) == 0) return std::stoull(line.substr(std::strlen(field))) * 1024;
  return 0;
}

// The resident memory the importer's arrays and heap live in: anonymous pages. Not VmRSS, whose
// file-backed part also grows by the code pages the first import touches and the neighbours the
// kernel maps along with them (fault-around: how many depends on what the page cache holds).
uint64_t anonymous_bytes() { return status_bytes("RssAnon:"); }

// A kernel whose transparent huge pages are set to "always" backs a growing heap with whole 2 MiB
// pages, as they are free or not: resident memory then moves in 2 MiB steps the importer did not
// take. The memory tests ask for 4 KiB pages for this process, so that their figures are the
// importer's on every machine, whatever its setting.
void use_small_pages() { REQUIRE(::prctl(PR_SET_THP_DISABLE, 1, 0, 0, 0) == 0); }

}  // namespace

TEST_CASE("obj plugin: the registry finds the importer by id and extension", "[objimport][plugin]") {
  auto registry = load_obj_plugin();
  REQUIRE(registry->importers().size() == 1);
  const pfx::host::ImporterInfo* info = registry->find_importer("obj");
  REQUIRE(info);
  CHECK(std::string(info->desc->label) == "Wavefront OBJ");
  CHECK(registry->find_importer_for_path("/x/model.obj") == info);
  CHECK(registry->find_importer_for_path("MODEL.OBJ") == info);
  CHECK(registry->find_importer_for_path("model.fbx") == nullptr);
  CHECK(registry->find_importer_for_path("obj") == nullptr);
  CHECK(registry->effects().empty());
}

TEST_CASE("obj plugin: a file with a material library, through the C structures", "[objimport][plugin]") {
  auto registry = load_obj_plugin();
  const pfx_importer_desc* importer = registry->find_importer("obj")->desc;
  const fs::path dir = fs::temp_directory_path() / ("pfx-obj-plugin-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "m.mtl") << "newmtl shiny\nKd 0.25 0.5 1\nKe 2 2 2\nmap_Kd albedo.png\n";
  std::ofstream(dir / "quad.obj") << "mtllib m.mtl\nv 0 0 0\nv 2 0 0\nv 2 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                                     "usemtl shiny\nf 1/1 2/2 3/3 4/4\nl 1 2\np 3\n";
  const std::string path = (dir / "quad.obj").string();
  pfx_import_request request = request_for_path(path.c_str());
  float last_progress = -1;
  bool progress_monotonic = true;
  request.progress = [](void* user, float fraction) {
    auto* state = static_cast<std::pair<float*, bool*>*>(user);
    if (fraction < *state->first) *state->second = false;
    *state->first = fraction;
  };
  std::pair<float*, bool*> progress_state{&last_progress, &progress_monotonic};
  request.progress_user = &progress_state;
  pfx_import_result* result = nullptr;
  REQUIRE(importer->import(&request, &result) == PFX_OK);
  REQUIRE(result);
  CHECK(result->struct_size == sizeof(pfx_import_result));
  CHECK(result->status == PFX_OK);
  CHECK(result->error == nullptr);
  CHECK(result->vertex_count == 4);
  CHECK(result->index_count == 6);
  REQUIRE(result->texcoords);
  CHECK(result->colors == nullptr);
  CHECK(result->normals[2] == 1.0f);
  CHECK(result->bounds_min[0] == 0.0f);
  CHECK(result->bounds_max[0] == 2.0f);
  CHECK(result->bounds_max[1] == 1.0f);
  CHECK(result->lines_skipped == 1);
  CHECK(result->points_skipped == 1);
  CHECK(result->faces == 1);
  REQUIRE(result->submesh_count == 1);
  CHECK(result->submeshes[0].material == 0);
  REQUIRE(result->material_count == 1);
  const pfx_import_material& m = result->materials[0];
  CHECK(m.struct_size == sizeof(pfx_import_material));
  CHECK(std::string(m.name) == "shiny");
  CHECK(m.diffuse[1] == 0.5f);
  CHECK(m.emissive[0] == 2.0f);
  CHECK(std::string(m.diffuse_map) == (dir / "albedo.png").string());
  CHECK(m.emissive_map == nullptr);
  CHECK(result->warning_count == 0);
  CHECK(result->parse_seconds >= 0);
  CHECK(progress_monotonic);
  CHECK(last_progress == 1.0f);
  importer->release(result);
  fs::remove_all(dir);
}

TEST_CASE("obj plugin: bytes in memory, errors and release", "[objimport][plugin]") {
  auto registry = load_obj_plugin();
  const pfx_importer_desc* importer = registry->find_importer("obj")->desc;
  const char text[] = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n";
  pfx_import_request request{};
  request.struct_size = sizeof request;
  request.bytes = text;
  request.byte_count = std::strlen(text);
  request.name = "mem.obj";
  pfx_import_result* result = nullptr;
  CHECK(importer->import(&request, &result) == PFX_ERROR);
  REQUIRE(result);
  CHECK(result->status == PFX_ERROR);
  CHECK(std::string(result->error) == "mem.obj:4: f: v index 7 is out of range (the file has 3 v)");
  CHECK(result->vertex_count == 0);
  CHECK(result->indices == nullptr);
  importer->release(result);

  pfx_import_request missing = request_for_path("/nonexistent/pfx/model.obj");
  CHECK(importer->import(&missing, &result) == PFX_ERROR);
  REQUIRE(result);
  CHECK(std::string(result->error) == "/nonexistent/pfx/model.obj: no such file");
  importer->release(result);

  pfx_import_request both = request_for_path("x.obj");
  both.bytes = text;
  CHECK(importer->import(&both, &result) == PFX_INVALID_ARGUMENT);
  importer->release(result);
  CHECK(importer->import(nullptr, &result) == PFX_INVALID_ARGUMENT);
  importer->release(result);
  CHECK(importer->import(&request, nullptr) == PFX_INVALID_ARGUMENT);

  // Release takes NULL and ignores pointers it did not hand out.
  importer->release(nullptr);
  pfx_import_result foreign{};
  importer->release(&foreign);
}

TEST_CASE("obj plugin: a large result, imported on two threads, gives its memory back at release", "[objimport][plugin][memory]") {
  // A 450 x 450 grid with v, vt, vn and v/vt/vn triangles: 202,500 vertices (32 bytes each) and
  // 403,202 triangles (12 bytes): 11.3 MB of arrays, imported on two workers of the host's pool.
  constexpr int n = 450;
  std::string text;
  char line[256];
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      std::snprintf(line, sizeof line, "v %d %d %g\nvt %g %g\nvn 0 0 1\n", x, y, 0.001 * ((x * 7 + y * 13) % 100),
                    x / double(n), y / double(n));
      text += line;
    }
  for (int y = 0; y + 1 < n; ++y)
    for (int x = 0; x + 1 < n; ++x) {
      const int a = y * n + x + 1, b = a + 1, c = a + n, d = c + 1;
      std::snprintf(line, sizeof line, "f %d/%d/%d %d/%d/%d %d/%d/%d\nf %d/%d/%d %d/%d/%d %d/%d/%d\n", a, a, a, b, b, b, d, d,
                    d, a, a, a, d, d, d, c, c, c);
      text += line;
    }
  auto registry = load_obj_plugin();
  const pfx_importer_desc* importer = registry->find_importer("obj")->desc;
  pfx_import_request request{};
  request.struct_size = sizeof request;
  request.bytes = text.data();
  request.byte_count = text.size();
  request.threads = 2;
  use_small_pages();
  const uint64_t before = anonymous_bytes();
  REQUIRE(before > 0);
  pfx_import_result* result = nullptr;
  const pfx_status status = importer->import(&request, &result);
  REQUIRE(result);
  INFO((result->error ? result->error : ""));
  REQUIRE(status == PFX_OK);
  REQUIRE(result->vertex_count == uint32_t{n * n});
  REQUIRE(result->index_count == uint32_t{6 * (n - 1) * (n - 1)});
  const uint64_t arrays = uint64_t{result->vertex_count} * 8 * sizeof(float) + uint64_t{result->index_count} * sizeof(uint32_t);
  // The arrays are resident while the result lives (the last corner is the grid's x = n - 2,
  // y = n - 1) ...
  CHECK(anonymous_bytes() >= before + arrays);
  const uint32_t last = result->indices[result->index_count - 1];
  REQUIRE(last < result->vertex_count);
  CHECK(result->positions[3 * last] == float(n - 2));
  CHECK(result->positions[3 * last + 1] == float(n - 1));
  CHECK(result->texcoords[2 * last] == Approx(double(n - 2) / n));
  CHECK(result->normals[3 * last + 2] == 1.0f);
  // ... and given back by release, all but a little bookkeeping: the small blocks the import freed
  // into the heap, which the allocator keeps (0.3 MB of 11.3 MB here). Not in the sanitizer pass:
  // AddressSanitizer keeps every freed block in its quarantine (up to 256 MB) on purpose, so what
  // stays resident there measures the quarantine, not the importer.
  importer->release(result);
  CHECK(anonymous_bytes() < before + arrays / 4);
}

TEST_CASE("obj plugin: a large file does not count whole towards resident memory while it is read", "[objimport][plugin][memory]") {
  // 48 MB of comments around one triangle, in the page cache once written. The importer maps the
  // file and drops each chunk's pages once read: were they kept, the peak would grow by the file.
  const fs::path path = fs::temp_directory_path() / ("pfx_obj_pages_" + std::to_string(::getpid()) + ".obj");
  {
    std::ofstream out(path, std::ios::binary);
    const std::string comment = "# " + std::string(61, 'c') + "\n";
    for (int i = 0; i < (48 << 20) / 64; ++i) out << comment;
    out << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  }
  auto registry = load_obj_plugin();
  const pfx_importer_desc* importer = registry->find_importer("obj")->desc;
  const std::string name = path.string();
  pfx_import_request request = request_for_path(name.c_str());
  use_small_pages();
  { std::ofstream("/proc/self/clear_refs") << "5"; }  // the peak starts again from what is resident now
  const uint64_t before = status_bytes("VmRSS:");
  pfx_import_result* result = nullptr;
  CHECK(importer->import(&request, &result) == PFX_OK);
  REQUIRE(result);
  CHECK(result->index_count == 3);
  const uint64_t peak = status_bytes("VmHWM:");
  importer->release(result);
  fs::remove(path);
  // The peak counts the file's pages too: they are what this is about. A chunk is at most 4 MB and
  // each of the two workers drops a chunk's pages once it has read it, so the file adds at most 8 MB
  // at once; the bound is twice that, for the import's own heap and the pages the kernel maps
  // around each fault. Keeping the pages would add the whole 48 MB.
  INFO("peak added " << (peak - before) / 1024 << " KiB");
  CHECK(peak - before < uint64_t{2 * 2 * 4} << 20);
}
