#pragma once
// Counts one level of syntactic nesting for as long as it lives; `ok` is false once the limit is
// passed (an error is then already reported and the parser winds down).
#include "parser.hpp"

namespace pfx::fx {

class NestingGuard {
 public:
  explicit NestingGuard(Parser& parser) : parser_(parser), ok_(parser.enter()) {}
  ~NestingGuard() {
    if (ok_) parser_.leave();
  }
  NestingGuard(const NestingGuard&) = delete;
  NestingGuard& operator=(const NestingGuard&) = delete;
  bool ok() const { return ok_; }

 private:
  Parser& parser_;
  bool ok_;
};

}  // namespace pfx::fx
