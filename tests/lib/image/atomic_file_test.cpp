#include <catch2/catch.hpp>

#include <fstream>
#include <stdexcept>

#include "atomic_file.hpp"
#include "exr_io.hpp"
#include "png_io.hpp"
#include "test_files.hpp"

namespace {

pfx::app::WriteFileFn write_text(const std::string& text) {
  return [text](const std::string& temp, std::string* reason) {
    std::ofstream out(temp, std::ios::binary);
    out << text;
    if (!out) *reason = "stream failed";
    return static_cast<bool>(out);
  };
}

bool no_temp_files(const pfx_test::TempDir& dir) {
  for (const std::string& name : dir.entries()) {
    if (name.find(".tmp-") != std::string::npos) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("atomic write into a missing folder fails cleanly", "[image][atomic]") {
  pfx_test::TempDir dir;
  const std::string path = dir.file("no/such/folder/out.txt");
  std::string error;
  CHECK_FALSE(pfx::app::write_atomically(path, write_text("x"), &error));
  CHECK_THAT(error, Catch::Contains(path) && Catch::Contains("does not exist"));
  CHECK(dir.entries().empty());

  pfx::app::Image img;
  img.width = img.height = 1;
  img.rgba = {1, 1, 1, 1};
  CHECK_FALSE(pfx::app::write_exr(path, img, pfx::app::ExrPixelType::Half, &error));
  CHECK_THAT(error, Catch::Contains(path));
  CHECK(dir.entries().empty());
}

TEST_CASE("atomic write replaces an existing file and leaves no temporary file",
          "[image][atomic]") {
  pfx_test::TempDir dir;
  const std::string path = dir.file("out.txt");
  pfx_test::write_text(path, "old content");
  std::string error;
  REQUIRE(pfx::app::write_atomically(path, write_text("new content"), &error));
  const std::vector<char> bytes = pfx_test::read_bytes(path);
  CHECK(std::string(bytes.begin(), bytes.end()) == "new content");
  CHECK(dir.entries() == std::vector<std::string>{"out.txt"});
}

TEST_CASE("atomic write that fails or throws leaves the old file untouched", "[image][atomic]") {
  pfx_test::TempDir dir;
  const std::string path = dir.file("keep.txt");
  pfx_test::write_text(path, "precious");
  std::string error;

  const pfx::app::WriteFileFn half_then_fail = [](const std::string& temp, std::string* reason) {
    std::ofstream(temp) << "partial";
    *reason = "simulated disk full";
    return false;
  };
  CHECK_FALSE(pfx::app::write_atomically(path, half_then_fail, &error));
  CHECK_THAT(error, Catch::Contains(path) && Catch::Contains("simulated disk full"));

  const pfx::app::WriteFileFn throws = [](const std::string& temp, std::string*) -> bool {
    std::ofstream(temp) << "partial";
    throw std::runtime_error("encoder exploded");
  };
  CHECK_FALSE(pfx::app::write_atomically(path, throws, &error));
  CHECK_THAT(error, Catch::Contains("encoder exploded"));

  const std::vector<char> bytes = pfx_test::read_bytes(path);
  CHECK(std::string(bytes.begin(), bytes.end()) == "precious");
  CHECK(no_temp_files(dir));
}

TEST_CASE("atomic write over a folder fails and removes its temporary file", "[image][atomic]") {
  pfx_test::TempDir dir;
  std::filesystem::create_directory(dir.file("taken"));
  std::string error;
  CHECK_FALSE(pfx::app::write_atomically(dir.file("taken"), write_text("x"), &error));
  CHECK_THAT(error, Catch::Contains("taken"));
  CHECK(no_temp_files(dir));
  CHECK(std::filesystem::is_directory(dir.file("taken")));
}

TEST_CASE("EXR and PNG writers overwrite atomically", "[image][atomic]") {
  pfx_test::TempDir dir;
  std::string error;
  pfx::app::Image img;
  img.width = 2;
  img.height = 2;
  img.rgba.assign(16, 0.5f);
  REQUIRE(pfx::app::write_exr(dir.file("a.exr"), img, pfx::app::ExrPixelType::Half, &error));
  img.rgba.assign(16, 0.25f);
  REQUIRE(pfx::app::write_exr(dir.file("a.exr"), img, pfx::app::ExrPixelType::Half, &error));
  pfx::app::Image back;
  REQUIRE(pfx::app::read_exr(dir.file("a.exr"), &back, &error));
  CHECK(back.rgba == img.rgba);

  pfx::app::DisplayImage png;
  png.width = png.height = 1;
  png.pixels = {1, 2, 3};
  REQUIRE(pfx::app::write_png(dir.file("a.png"), png, &error));
  png.pixels = {4, 5, 6};
  REQUIRE(pfx::app::write_png(dir.file("a.png"), png, &error));
  pfx::app::DisplayImage png_back;
  REQUIRE(pfx::app::read_png(dir.file("a.png"), &png_back, &error));
  CHECK(png_back.pixels == png.pixels);
  CHECK(no_temp_files(dir));
  CHECK(dir.entries().size() == 2);
}
