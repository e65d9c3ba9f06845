// Writes the textured test models of tests/programs/import/models and the texture seeds of the image fuzz
// target (tests/fuzz/corpus/texture), with Debian's stb_image_write. Build and run it from the
// repository root:
//   c++ -std=c++17 tests/programs/import/models/make_textured_models.cpp -o /tmp/make_textured_models
//   /tmp/make_textured_models
//
// assimp_style/: an OBJ as exporters ship them and assimp's test models look: three boxes, one
//   material each, textures in a textures/ folder named by relative paths, JPEG (one with an
//   upper-case .JPG) and a grey JPEG glow map (map_Ke), comments and groups.
// tinyobj_style/: tinyobjloader's kind of example: quads, a material library with Ka/Ks/Ns/illum,
//   a TGA (RLE), a PNG and an uncompressed BMP texture beside the model.
// broken/: the same as tinyobj_style with a truncated JPEG, a truncated TGA and a JPEG whose
//   header is overwritten: each must give one warning and its material's flat colour.
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

// A flat colour with a faint 4-texel checker (+-8 codes), so the texture's mean is the colour.
std::vector<uint8_t> swatch(int size, int r, int g, int b) {
  std::vector<uint8_t> p(static_cast<size_t>(size) * size * 3);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const int d = ((x / 4 + y / 4) % 2) ? 8 : -8;
      uint8_t* q = &p[(static_cast<size_t>(y) * size + x) * 3];
      q[0] = static_cast<uint8_t>(r + d);
      q[1] = static_cast<uint8_t>(g + d);
      q[2] = static_cast<uint8_t>(b + d);
    }
  return p;
}

void text(const fs::path& path, const std::string& content) { std::ofstream(path, std::ios::binary) << content; }

std::vector<char> bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::vector<char>(std::istreambuf_iterator<char>(in), {});
}

void write_bytes(const fs::path& path, const std::vector<char>& data) {
  std::ofstream(path, std::ios::binary).write(data.data(), static_cast<std::streamsize>(data.size()));
}

// Three boxes side by side along x (centres -3, 0, 3), 2 m cubes, one material each.
std::string three_boxes(const char* header, const char* const names[3]) {
  std::string obj = header;
  int base = 0;
  for (int b = 0; b < 3; ++b) {
    const double cx = -3.0 + 3.0 * b;
    for (int corner = 0; corner < 8; ++corner)
      obj += "v " + std::to_string(cx + ((corner & 1) ? 1 : -1)) + " " + std::to_string((corner & 2) ? 2 : 0) + " " +
             std::to_string((corner & 4) ? 1 : -1) + "\n";
    obj += "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n";
    obj += std::string("g box") + std::to_string(b) + "\nusemtl " + names[b] + "\n";
    // Faces counter-clockwise from outside: -z, +z, -x, +x, -y, +y.
    const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}};
    for (const auto& f : faces) {
      obj += "f";
      for (int k = 0; k < 4; ++k)
        obj += " " + std::to_string(base + f[k] + 1) + "/" + std::to_string(4 * b + k + 1);
      obj += "\n";
    }
    base += 8;
  }
  return obj;
}

}  // namespace

int main() {
  const fs::path root = "tests/programs/import/models";
  const int n = 32;

  // assimp-style: JPEG textures in a subfolder.
  const fs::path a = root / "assimp_style";
  fs::create_directories(a / "textures");
  auto red = swatch(n, 190, 60, 40), green = swatch(n, 60, 170, 70), glow = swatch(n, 230, 230, 230);
  stbi_write_jpg((a / "textures/brick_red.jpg").string().c_str(), n, n, 3, red.data(), 95);
  stbi_write_jpg((a / "textures/moss_green.JPG").string().c_str(), n, n, 3, green.data(), 95);
  std::vector<uint8_t> grey(static_cast<size_t>(n) * n);
  for (size_t i = 0; i < grey.size(); ++i) grey[i] = glow[i * 3];
  stbi_write_jpg((a / "textures/lamp_glow.jpg").string().c_str(), n, n, 1, grey.data(), 95);
  const char* assimp_names[3] = {"Brick", "Moss", "Lamp"};
  text(a / "crates.obj", three_boxes("# Exported in the style of assimp's test models\nmtllib crates.mtl\n", assimp_names));
  text(a / "crates.mtl",
       "# three materials\nnewmtl Brick\nKa 0 0 0\nKd 1 1 1\nKs 0.1 0.1 0.1\nmap_Kd textures/brick_red.jpg\n\n"
       "newmtl Moss\nKd 1.000000 1.000000 1.000000\nmap_Kd textures/moss_green.JPG\n\n"
       "newmtl Lamp\nKd 0.2 0.2 0.2\nKe 4 3 1\nmap_Ke textures/lamp_glow.jpg\n");

  // tinyobjloader-style: TGA, PNG and BMP beside the model.
  const fs::path t = root / "tinyobj_style";
  fs::create_directories(t);
  auto blue = swatch(n, 50, 80, 200), yellow = swatch(n, 210, 190, 50), purple = swatch(n, 150, 60, 170);
  stbi_write_tga_with_rle = 1;
  stbi_write_tga((t / "blue.tga").string().c_str(), n, n, 3, blue.data());
  stbi_write_png((t / "yellow.png").string().c_str(), n, n, 3, yellow.data(), n * 3);
  stbi_write_bmp((t / "purple.bmp").string().c_str(), n, n, 3, purple.data());
  const char* tiny_names[3] = {"blue", "yellow", "purple"};
  text(t / "cubes.obj", three_boxes("mtllib cubes.mtl\n", tiny_names));
  text(t / "cubes.mtl",
       "newmtl blue\nKa 0 0 0\nKd 1 1 1\nKs 0 0 0\nNs 10\nillum 2\nmap_Kd blue.tga\n\n"
       "newmtl yellow\nKa 0 0 0\nKd 1 1 1\nKs 0 0 0\nNs 10\nillum 2\nmap_Kd yellow.png\n\n"
       "newmtl purple\nKa 0 0 0\nKd 1 1 1\nKs 0 0 0\nNs 10\nillum 2\nmap_Kd purple.bmp\n");

  // Broken textures: the materials' Kd is what must show instead.
  const fs::path b = root / "broken";
  fs::create_directories(b);
  stbi_write_tga_with_rle = 0;
  stbi_write_jpg((b / "whole.jpg").string().c_str(), n, n, 3, red.data(), 95);
  stbi_write_tga((b / "whole.tga").string().c_str(), n, n, 3, blue.data());
  std::vector<char> jpg = bytes(b / "whole.jpg"), tga = bytes(b / "whole.tga");
  // Cut inside the scan (after the tables), where a decoder would make up the rest.
  write_bytes(b / "truncated.jpg", std::vector<char>(jpg.begin(), jpg.begin() + static_cast<long>(jpg.size() * 4 / 5)));
  write_bytes(b / "truncated.tga", std::vector<char>(tga.begin(), tga.begin() + static_cast<long>(tga.size() / 2)));
  std::vector<char> corrupt = jpg;
  for (size_t i = 4; i < 40 && i < corrupt.size(); ++i) corrupt[i] = static_cast<char>(0x5A);
  write_bytes(b / "corrupt.jpg", corrupt);
  fs::remove(b / "whole.jpg");
  fs::remove(b / "whole.tga");
  const char* broken_names[3] = {"half_jpeg", "half_tga", "bad_jpeg"};
  text(b / "broken.obj", three_boxes("mtllib broken.mtl\n", broken_names));
  text(b / "broken.mtl",
       "newmtl half_jpeg\nKd 0.5 0.1 0.1\nmap_Kd truncated.jpg\n"
       "newmtl half_tga\nKd 0.1 0.5 0.1\nmap_Kd truncated.tga\n"
       "newmtl bad_jpeg\nKd 0.1 0.1 0.5\nmap_Kd corrupt.jpg\n");

  // Fuzz seeds: each format and variant once (progressive JPEG is not written by stb).
  const fs::path seeds = "tests/fuzz/corpus/texture";
  fs::create_directories(seeds);
  auto small = swatch(8, 120, 100, 80);
  stbi_write_jpg((seeds / "rgb.jpg").string().c_str(), 8, 8, 3, small.data(), 90);
  std::vector<uint8_t> small_grey(64, 100);
  stbi_write_jpg((seeds / "grey.jpg").string().c_str(), 8, 8, 1, small_grey.data(), 90);
  stbi_write_tga_with_rle = 1;
  stbi_write_tga((seeds / "rle.tga").string().c_str(), 8, 8, 3, small.data());
  stbi_write_tga_with_rle = 0;
  stbi_write_tga((seeds / "raw.tga").string().c_str(), 8, 8, 3, small.data());
  std::vector<uint8_t> rgba(8 * 8 * 4, 200);
  stbi_write_tga((seeds / "rgba.tga").string().c_str(), 8, 8, 4, rgba.data());
  stbi_write_bmp((seeds / "rgb.bmp").string().c_str(), 8, 8, 3, small.data());
  for (const char* name : {"truncated.jpg", "truncated.tga", "corrupt.jpg"})
    fs::copy_file(b / name, seeds / name, fs::copy_options::overwrite_existing);
  return 0;
}
