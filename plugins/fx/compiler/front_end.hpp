#pragma once
// The compiler's front end in one call: preprocess, parse, check. Nothing here throws: every
// problem (including running out of memory inside the library) is a diagnostic.
#include <memory>
#include <string>

#include "ast/ast.hpp"
#include "diagnostics.hpp"
#include "preprocessor/preprocessor.hpp"

namespace pfx::fx {

struct FrontEndResult {
  FileNames names;
  Diagnostics diagnostics{names};
  PreprocessedSource preprocessed;
  TranslationUnit unit;

  bool ok() const { return !diagnostics.has_errors(); }
};

struct FrontEndOptions {
  PreprocessorOptions preprocessor;
  bool check_semantics = true;
};

std::unique_ptr<FrontEndResult> compile_front_end(const std::string& path, const FrontEndOptions& options,
                                                  const FileReader& reader = read_file_from_disk);

}  // namespace pfx::fx
