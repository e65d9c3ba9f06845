// pfx-import as a user runs it: exit codes, --help, the text and JSON summaries, --threads,
// progress, and messages on stderr.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>

#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

namespace {

struct Result {
  int exit_code = -1;
  std::string out, err;
};

// Runs pfx-import with the shipped plugin folder and returns its exit code and output; a death
// by signal is 128 + signal, which no test accepts.
Result pfx_import(const std::string& args) {
  static int counter = 0;
  const fs::path err_file =
      fs::temp_directory_path() / ("pfx-import-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  const std::string command = std::string(PFX_IMPORT) + " --plugins " PFX_PLUGIN_DIR " " + args + " 2>" + err_file.string();
  Result result;
  FILE* pipe = popen(command.c_str(), "r");
  REQUIRE(pipe);
  char buffer[4096];
  size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) result.out.append(buffer, n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  std::ifstream in(err_file);
  result.err.assign(std::istreambuf_iterator<char>(in), {});
  fs::remove(err_file);
  return result;
}

struct Scratch {
  fs::path dir = fs::temp_directory_path() / ("pfx-import-files-" + std::to_string(::getpid()));
  Scratch() { fs::create_directories(dir); }
  ~Scratch() { fs::remove_all(dir); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(dir / name, std::ios::binary) << text;
    return (dir / name).string();
  }
};

// A cube of 8 positions and 6 quads in two materials, a polyline and a point, one unknown line.
const char* const kCube =
    "mtllib cube.mtl\n"
    "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 2\nv 1 -1 2\nv 1 1 2\nv -1 1 2\n"
    "s off\nusemtl red\nf 1 4 3 2\nf 5 6 7 8\nusemtl blue\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n"
    "l 1 2 3\np 4\nbogus 1\n";
const char* const kCubeMtl = "newmtl red\nKd 1 0 0\nnewmtl blue\nKd 0 0 1\n";

}  // namespace

TEST_CASE("pfx-import: help documents every option and exit code", "[import]") {
  Result r = pfx_import("--help");
  CHECK(r.exit_code == 0);
  for (const char* text : {"--json", "--threads", "--progress", "--plugins", "exit codes: 0 ok", "2 usage",
                           "3 bad input file", "4 plugin error"})
    CHECK(r.out.find(text) != std::string::npos);
}

TEST_CASE("pfx-import: usage errors exit 2", "[import][errors]") {
  for (const char* args : {"", "--threads", "--threads x a.obj", "--threads -1 a.obj", "--progress maybe a.obj",
                           "--frobnicate a.obj", "a.obj b.obj"}) {
    INFO(args);
    Result r = pfx_import(args);
    CHECK(r.exit_code == 2);
    CHECK(r.err.rfind("pfx-import: ", 0) == 0);
    CHECK(r.out.empty());
  }
}

TEST_CASE("pfx-import: the text summary", "[import]") {
  Scratch scratch;
  scratch.write("cube.mtl", kCubeMtl);
  const std::string cube = scratch.write("cube.obj", kCube);
  Result r = pfx_import(cube);
  REQUIRE(r.exit_code == 0);
  CHECK(r.out.find("vertices   24 (unique)") != std::string::npos);  // smoothing off: 4 per face
  CHECK(r.out.find("triangles  12") != std::string::npos);
  CHECK(r.out.find("sub-meshes 2") != std::string::npos);
  CHECK(r.out.find("materials  2") != std::string::npos);
  CHECK(r.out.find("bounds     (-1, -1, -1) to (1, 1, 2)") != std::string::npos);
  CHECK(r.out.find("skipped    1 lines, 1 points") != std::string::npos);
  CHECK(r.out.find(cube + ":21: unknown statement 'bogus': 1 ignored") != std::string::npos);
}

TEST_CASE("pfx-import: --json is one object with the documented keys, the same for any thread count", "[import]") {
  Scratch scratch;
  scratch.write("cube.mtl", kCubeMtl);
  const std::string cube = scratch.write("cube.obj", kCube);
  nlohmann::json first;
  for (const char* threads : {"1", "2", "5"}) {
    Result r = pfx_import(cube + " --json --threads " + threads);
    REQUIRE(r.exit_code == 0);
    nlohmann::json j = nlohmann::json::parse(r.out);
    CHECK(j["file"] == cube);
    CHECK(j["vertices"] == 24);
    CHECK(j["triangles"] == 12);
    CHECK(j["submeshes"] == 2);
    CHECK(j["materials"] == 2);
    CHECK(j["bounds"] == nlohmann::json::parse("[[-1,-1,-1],[1,1,2]]"));
    CHECK(j["lines"] == 1);
    CHECK(j["points"] == 1);
    CHECK(j["warnings"] == nlohmann::json::array({cube + ":21: unknown statement 'bogus': 1 ignored"}));
    CHECK(j["ms"].is_number());
    CHECK(j["ms"].get<double>() >= 0);
    j.erase("ms");
    if (first.is_null()) first = j;
    CHECK(j == first);
  }
}

TEST_CASE("pfx-import: a malformed file exits 3 with FILE:LINE: reason on stderr", "[import][errors]") {
  Scratch scratch;
  const std::string bad = scratch.write("bad.obj", "v 0 0 0\nv 1 0 0\nf 1 2 3\n");
  for (const char* extra : {"", " --json"}) {
    Result r = pfx_import(bad + extra);
    CHECK(r.exit_code == 3);
    CHECK(r.out.empty());
    CHECK(r.err == "pfx-import: " + bad + ":3: f: v index 3 is out of range (the file has 2 v)\n");
  }
  Result missing = pfx_import((scratch.dir / "none.obj").string());
  CHECK(missing.exit_code == 3);
  CHECK(missing.err == "pfx-import: " + (scratch.dir / "none.obj").string() + ": no such file\n");
  Result folder = pfx_import(scratch.dir.string() + "/.");
  CHECK(folder.exit_code == 4);  // exists, but no extension an importer takes
}

TEST_CASE("pfx-import: a file no importer takes exits 4", "[import][errors]") {
  Scratch scratch;
  const std::string fbx = scratch.write("model.fbx", "binary");
  Result r = pfx_import(fbx);
  CHECK(r.exit_code == 4);
  CHECK(r.err == "pfx-import: " + fbx + ": no importer for this file's extension (importers loaded for: .obj)\n");
}

TEST_CASE("pfx-import: --progress on reports rising percentages up to 100 on stderr", "[import]") {
  Scratch scratch;
  std::string text;
  for (int i = 0; i < 20000; ++i) text += "v " + std::to_string(i) + " 0 0\n";
  for (int i = 1; i + 2 <= 20000; ++i)
    text += "f " + std::to_string(i) + " " + std::to_string(i + 1) + " " + std::to_string(i + 2) + "\n";
  Result r = pfx_import(scratch.write("strip.obj", text) + " --progress on --threads 2");
  REQUIRE(r.exit_code == 0);
  int last = -1;
  size_t at = 0;
  while ((at = r.err.find("pfx-import: ", at)) != std::string::npos) {
    const int percent = std::stoi(r.err.substr(at + 12, 3));
    CHECK(percent > last);
    last = percent;
    at += 12;
  }
  CHECK(last == 100);
  CHECK(pfx_import(scratch.write("s.obj", "v 0 0 0\n") + " --progress off").err.empty());
}

TEST_CASE("pfx-bench --import: a tiny run writes both reports with every loader", "[import][bench]") {
  // A smoke test of the benchmark's plumbing (generation, loads in new processes, reports); the
  // speeds it prints are not checked here.
  Scratch scratch;
  const std::string out = (scratch.dir / "bench").string();
  const std::string command = std::string(PFX_BENCH) + " --import --sizes 0.05 --runs 2 --threads 1,2 --plugins " +
                              PFX_PLUGIN_DIR + " --dir " + (scratch.dir / "files").string() + " --out " + out +
                              " > " + (scratch.dir / "stdout.md").string() + " 2>/dev/null";
  REQUIRE(std::system(command.c_str()) == 0);
  std::ifstream in(out + "/import.json");
  REQUIRE(in);
  nlohmann::json j = nlohmann::json::parse(in);
  // Seven layouts, each read by pfx at 1 and 2 threads, tinyobjloader and assimp.
  REQUIRE(j["rows"].size() == 28);
  std::map<std::string, uint64_t> triangles;  // per layout: the first row's
  for (const auto& row : j["rows"]) {
    INFO(row.dump());
    CHECK(row["ok"] == true);
    const std::string layout = row["layout"];
    if (!triangles.count(layout)) triangles[layout] = row["triangles"];
    CHECK(row["triangles"] == triangles[layout]);  // every loader read the same mesh
    CHECK(row["triangles"].get<uint64_t>() > 0);
    CHECK(row["mb_per_s"].get<double>() > 0);
    CHECK(row["runs"] == 2);  // each in a process of its own, in rounds
  }
  CHECK(triangles.size() == 7);
  CHECK(fs::exists(out + "/import.md"));
  CHECK(fs::file_size(scratch.dir / "stdout.md") > 0);
  CHECK(fs::exists(scratch.dir / "files" / "relative-quads-0.05mb.obj"));  // --dir keeps the generated files
}
