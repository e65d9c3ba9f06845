#include "effect_compiler.hpp"

#include <new>

namespace pfx::fx {

std::unique_ptr<CompiledEffect> compile_effect(const std::string& path, const FrontEndOptions& options, bool generate_code,
                                               const FileReader& reader) {
  auto result = std::make_unique<CompiledEffect>();
  result->front = compile_front_end(path, options, reader);
  if (!result->front->ok()) return result;
  Diagnostics& diagnostics = result->front->diagnostics;
  try {
    result->model = build_effect_model(result->front->unit, diagnostics);
    if (!generate_code || diagnostics.has_errors()) return result;
    for (const TechniqueInfo& technique : result->model.techniques) {
      result->passes.emplace_back();
      for (const PassInfo& pass : technique.passes)
        result->passes.back().push_back(generate_pass(result->front->unit, result->model, pass, diagnostics));
    }
  } catch (const std::bad_alloc&) {
    diagnostics.error({result->front->names.add(path), 1, 1}, "out of memory while compiling");
  } catch (const std::exception& e) {
    diagnostics.error({result->front->names.add(path), 1, 1}, std::string("internal compiler error: ") + e.what());
  }
  return result;
}

}  // namespace pfx::fx
