// Walks a program's argument list the same way in every one of our programs: the argument in
// hand, the value that follows an option, and one error message for the caller to print.
//
//   ArgReader args(list, error);
//   while (args.next()) {
//     const std::string& arg = args.arg();
//     if (arg == "-h" || arg == "--help") options.help = true;
//     else if (arg == "--out") { if (!args.value(&options.out)) return false; }
//     else return args.unknown();
//   }
#pragma once

#include <string>
#include <vector>

namespace pfx::app {

class ArgReader {
 public:
  ArgReader(const std::vector<std::string>& args, std::string* error) : args_(args), error_(error) {}

  // Moves to the next argument; false past the last.
  bool next() { return ++index_ < args_.size(); }
  // The argument in hand; the reference stays valid while the list lives.
  const std::string& arg() const { return args_[index_]; }

  // Takes the argument after this option as its value: false, with "--x needs a value", when
  // there is none.
  bool value(std::string* into);
  // The same, appended to a list (repeatable options such as --set and --plugins).
  bool value(std::vector<std::string>* list);

  // Records message as the error and returns false, so a parser can `return args.fail(...)`.
  bool fail(const std::string& message);
  // fail("unknown option '--x' (see --help)").
  bool unknown() { return fail("unknown option '" + arg() + "' (see --help)"); }

 private:
  const std::vector<std::string>& args_;
  std::string* error_;
  size_t index_ = static_cast<size_t>(-1);  // next() moves to 0 first
};

}  // namespace pfx::app
