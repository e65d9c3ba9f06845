// Not built: what function_length.py is tested on. Every brace that is not code is here once.
#include <string>
#define OPEN_BRACE {

namespace sample {

enum class Colour : int { red, green, blue };

const int kTable[][2] = {{1, 2}, {3, 4}};

struct Holder {
  int value;
  std::string text;
  Holder(int v) : value{v}, text("}") {
    if (v > 0) value = v;
  }
  int twice() const { return value * 2; }
};

extern "C" {
int c_function(int x) {
  /* a { in a block comment */
  return x + '{' + '}';
}
}

std::string strings() {
  std::string a = "}}}";
  std::string b = R"raw(}"}{ )raw";
  return a + b + "\"}";
}

template <class T>
T generic(T x) {
  auto lambda = [](T y) { return y; };
  return lambda(x);
}

}  // namespace sample

// A macro that defines functions and takes no ';' (as GLib's G_DEFINE_TYPE): the namespace after it
// is a scope, not a function's body.
DEFINE_SOMETHING(Sample, sample)

namespace sample {

int ninety_one_lines() {
  int total = 0;
  int digits = 1'000'000;
  total += 0;  // { a brace in a comment
  total += 1;
  total += 2;
  total += 3;  // { a brace in a comment
  total += 4;
  total += 5;
  total += 6;  // { a brace in a comment
  total += 7;
  total += 8;
  total += 9;  // { a brace in a comment
  total += 10;
  total += 11;
  total += 12;  // { a brace in a comment
  total += 13;
  total += 14;
  total += 15;  // { a brace in a comment
  total += 16;
  total += 17;
  total += 18;  // { a brace in a comment
  total += 19;
  total += 20;
  total += 21;  // { a brace in a comment
  total += 22;
  total += 23;
  total += 24;  // { a brace in a comment
  total += 25;
  total += 26;
  total += 27;  // { a brace in a comment
  total += 28;
  total += 29;
  total += 30;  // { a brace in a comment
  total += 31;
  total += 32;
  total += 33;  // { a brace in a comment
  total += 34;
  total += 35;
  total += 36;  // { a brace in a comment
  total += 37;
  total += 38;
  total += 39;  // { a brace in a comment
  total += 40;
  total += 41;
  total += 42;  // { a brace in a comment
  total += 43;
  total += 44;
  total += 45;  // { a brace in a comment
  total += 46;
  total += 47;
  total += 48;  // { a brace in a comment
  total += 49;
  total += 50;
  total += 51;  // { a brace in a comment
  total += 52;
  total += 53;
  total += 54;  // { a brace in a comment
  total += 55;
  total += 56;
  total += 57;  // { a brace in a comment
  total += 58;
  total += 59;
  total += 60;  // { a brace in a comment
  total += 61;
  total += 62;
  total += 63;  // { a brace in a comment
  total += 64;
  total += 65;
  total += 66;  // { a brace in a comment
  total += 67;
  total += 68;
  total += 69;  // { a brace in a comment
  total += 70;
  total += 71;
  total += 72;  // { a brace in a comment
  total += 73;
  total += 74;
  total += 75;  // { a brace in a comment
  total += 76;
  total += 77;
  total += 78;  // { a brace in a comment
  total += 79;
  total += 80;
  total += 81;  // { a brace in a comment
  total += 82;
  total += 83;
  total += 84;
  total += digits;
  return total;
}

}  // namespace sample
