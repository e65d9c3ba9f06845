#include "front_end.hpp"

#include <new>

#include "parser/parser.hpp"
#include "sema/analyzer.hpp"

namespace pfx::fx {

std::unique_ptr<FrontEndResult> compile_front_end(const std::string& path, const FrontEndOptions& options,
                                                  const FileReader& reader) {
  auto result = std::make_unique<FrontEndResult>();
  try {
    result->preprocessed = preprocess(path, options.preprocessor, reader, result->names, result->diagnostics);
    if (result->diagnostics.has_errors()) return result;
    result->unit = parse_tokens(result->preprocessed.tokens, result->diagnostics);
    if (options.check_semantics && !result->diagnostics.has_errors()) analyze(result->unit, result->diagnostics);
  } catch (const std::bad_alloc&) {
    result->diagnostics.error({result->names.add(path), 1, 1}, "out of memory while compiling");
  } catch (const std::exception& e) {  // a bug in the compiler: still an error, never a crash of the host
    result->diagnostics.error({result->names.add(path), 1, 1}, std::string("internal compiler error: ") + e.what());
  }
  return result;
}

}  // namespace pfx::fx
