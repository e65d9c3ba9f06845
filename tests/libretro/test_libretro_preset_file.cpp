// A preset file's lines as RetroArch's configuration reader takes them (preset_file.hpp).
#include <catch2/catch.hpp>

#include <cstdio>
#include <cstdlib>
#include <fstream>

#include <unistd.h>

#include "memory_files.hpp"
#include "preset_file.hpp"

using pfx::libretro::PresetFile;
using pfx::test::MemoryFiles;

namespace {

PresetFile read_one(MemoryFiles& files, const std::string& path) {
  PresetFile file;
  std::string error;
  INFO(error);
  REQUIRE(pfx::libretro::read_preset_file(path, files.reader(), &file, &error));
  return file;
}

std::string value_of(const PresetFile& file, const std::string& key) {
  const auto* entry = file.find(key);
  return entry ? entry->value : "<absent>";
}

}  // namespace

TEST_CASE("preset lines: quoted and bare values, comments, the first of two keys, and lines that mean nothing",
          "[preset]") {
  MemoryFiles files;
  files.texts["/p/a.slangp"] =
      "# a comment\n"
      "shaders = 2\n"
      "shader0 = \"shaders/with space.slang\"\n"
      "shader1 = bare.slang trailing words\n"
      "alias0 = \"a#b\"   # the # inside quotes stays, this comment goes\n"
      "alias1 = c#d\n"
      "\tfilter_linear0 = true\n"
      "shaders = 3\n"
      "scale0=2.0\n"
      "// a comment as RetroArch's collections write them\n"
      "   #reference \"indented.slangp\"\n"
      "lonely_key\n"
      "empty = \"\"\n"
      "unterminated = \"runs to the end\n"
      "crlf = yes\r\n"
      "/* a note over lines,\n"
      "   in_comment = 1\n"
      "*/\n"
      "  /* one line */ after_comment = 1\n";
  const PresetFile file = read_one(files, "/p/a.slangp");
  CHECK(value_of(file, "shaders") == "2");  // the first wins
  CHECK(value_of(file, "shader0") == "shaders/with space.slang");
  CHECK(value_of(file, "shader1") == "bare.slang");
  CHECK(value_of(file, "alias0") == "a#b");
  CHECK(value_of(file, "alias1") == "c");
  CHECK(value_of(file, "filter_linear0") == "true");
  CHECK(value_of(file, "scale0") == "2.0");
  CHECK(value_of(file, "empty").empty());
  CHECK(value_of(file, "unterminated") == "runs to the end");
  CHECK(value_of(file, "crlf") == "yes");
  CHECK(value_of(file, "//") == "<absent>");
  CHECK(value_of(file, "in_comment") == "<absent>");
  CHECK(value_of(file, "after_comment") == "<absent>");
  // An indented #reference is a comment, as in RetroArch.
  CHECK(file.references.empty());
  REQUIRE(file.warnings.size() == 1);
  CHECK(file.warnings[0] == "/p/a.slangp:12: 'lonely_key' has no '= value': the line is ignored");
  CHECK(file.find("shader0")->place.text() == "/p/a.slangp:3");
}

TEST_CASE("preset lines: #reference lines in order, quoted or not, and #include spliced where it stands", "[preset]") {
  MemoryFiles files;
  files.texts["/p/top.slangp"] =
      "#reference \"../base/one.slangp\"\n"
      "#reference two.slangp\n"
      "before = top\n"
      "#include \"inc/common.inc\"\n"
      "after = top\n";
  files.texts["/p/inc/common.inc"] = "before = include\nafter = include\nonly = include\n#include \"deeper.inc\"\n";
  files.texts["/p/inc/deeper.inc"] = "deep = yes\n";
  const PresetFile file = read_one(files, "/p/top.slangp");
  REQUIRE(file.references.size() == 2);
  CHECK(file.references[0].value == "../base/one.slangp");
  CHECK(file.references[1].value == "two.slangp");
  CHECK(file.references[1].place.text() == "/p/top.slangp:2");
  // Keys before the include beat it; the include beats keys after it.
  CHECK(value_of(file, "before") == "top");
  CHECK(value_of(file, "after") == "include");
  CHECK(value_of(file, "only") == "include");
  CHECK(value_of(file, "deep") == "yes");  // relative to the file that includes it
  CHECK(file.find("only")->place.text() == "/p/inc/common.inc:3");
}

TEST_CASE("preset lines: a file that includes itself and a missing include are errors naming the line",
          "[preset][bad]") {
  MemoryFiles files;
  files.texts["/p/loop.slangp"] = "a = 1\n#include \"loop.slangp\"\n";
  files.texts["/p/missing.slangp"] = "a = 1\n\n#include \"nowhere.inc\"\n";
  PresetFile file;
  std::string error;
  CHECK_FALSE(pfx::libretro::read_preset_file("/p/loop.slangp", files.reader(), &file, &error));
  CHECK(error == "/p/loop.slangp:2: includes nest more than 16 deep (does a file include itself?)");
  CHECK(files.reads == 17);
  error.clear();
  CHECK_FALSE(pfx::libretro::read_preset_file("/p/missing.slangp", files.reader(), &file, &error));
  CHECK(error == "/p/missing.slangp:3: /p/nowhere.inc: no such file");
  // Includes that multiply: each file includes the next twice.
  for (int i = 0; i < 16; ++i)
    files.texts["/p/m" + std::to_string(i) + ".inc"] = "#include \"m" + std::to_string(i + 1) + ".inc\"\n#include \"m" +
                                                       std::to_string(i + 1) + ".inc\"\n";
  files.texts["/p/m16.inc"] = "x = 1\n";
  error.clear();
  CHECK_FALSE(pfx::libretro::read_preset_file("/p/m0.inc", files.reader(), &file, &error));
  CHECK(error.find(": more than 256 includes in one preset file") != std::string::npos);
}

TEST_CASE("preset paths: relative to the naming file's folder, absolute as written, ~/ in the home folder",
          "[preset]") {
  using pfx::libretro::resolve_preset_path;
  CHECK(resolve_preset_path("shaders/a.slang", "/x/y/p.slangp") == "/x/y/shaders/a.slang");
  CHECK(resolve_preset_path("../a.slang", "/x/y/p.slangp") == "/x/a.slang");
  CHECK(resolve_preset_path("./b/../a.slang", "/x/y/p.slangp") == "/x/y/a.slang");
  CHECK(resolve_preset_path("/abs/a.slang", "/x/y/p.slangp") == "/abs/a.slang");
  CHECK(resolve_preset_path("a.slang", "p.slangp") == "a.slang");
  const char* home = std::getenv("HOME");
  if (home && *home) CHECK(resolve_preset_path("~/s/a.slang", "/x/p.slangp") == std::string(home) + "/s/a.slang");
}

TEST_CASE("preset files on disk: a file larger than 4 MiB is refused before it is read whole", "[preset][bad]") {
  char name[] = "/tmp/pfx-libretro-large-XXXXXX";
  const int fd = mkstemp(name);
  REQUIRE(fd >= 0);
  close(fd);
  {
    std::ofstream out(name, std::ios::binary);
    const std::string line = "# a comment line that fills the file with nothing a preset needs\n";
    for (std::size_t written = 0; written <= pfx::libretro::kMaxPresetFileBytes; written += line.size()) out << line;
  }
  std::string error;
  CHECK_FALSE(pfx::libretro::read_text_file(name, &error));
  CHECK(error == std::string(name) + ": larger than 4 MiB, not a preset or shader");
  std::remove(name);
  error.clear();
  CHECK_FALSE(pfx::libretro::read_text_file("/nonexistent/pfx/preset.slangp", &error));
  CHECK(error == "/nonexistent/pfx/preset.slangp: cannot be opened");
}
