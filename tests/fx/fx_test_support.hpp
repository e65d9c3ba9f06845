#pragma once
// In-memory FX files and one-call helpers for the FX compiler tests.
#include <map>
#include <memory>
#include <string>

#include "ast/ast_printer.hpp"
#include "front_end.hpp"
#include "parser/parser.hpp"

namespace pfx::fx::test {

struct MemoryFiles {
  std::map<std::string, std::string> files;
  FileReader reader() const {
    return [this](const std::string& path, std::string& contents) {
      auto it = files.find(path);
      if (it == files.end()) return false;
      contents = it->second;
      return true;
    };
  }
};

struct Preprocessed {
  std::string text;    // tokens spelled back, one space where the source had space
  std::string errors;  // every diagnostic, formatted
  PreprocessedSource source;
  FileNames names;
};

inline std::unique_ptr<Preprocessed> preprocess_files(const MemoryFiles& files, const std::string& main,
                                                      const PreprocessorOptions& options = {}) {
  auto out = std::make_unique<Preprocessed>();
  Diagnostics diagnostics(out->names);
  out->source = preprocess(main, options, files.reader(), out->names, diagnostics);
  out->text = spell(out->source.tokens);
  out->errors = diagnostics.format_all();
  return out;
}

// One file "main.fx" holding `source`.
inline std::unique_ptr<Preprocessed> preprocess_text(const std::string& source, const PreprocessorOptions& options = {}) {
  MemoryFiles files;
  files.files["main.fx"] = source;
  return preprocess_files(files, "main.fx", options);
}

// The whole front end over one file "main.fx".
inline std::unique_ptr<FrontEndResult> compile_text(const std::string& source, bool semantics = true) {
  MemoryFiles files;
  files.files["main.fx"] = source;
  FrontEndOptions options;
  options.check_semantics = semantics;
  return compile_front_end("main.fx", options, files.reader());
}

// The parse of "main.fx" printed as S-expressions (one declaration per line) followed by any
// diagnostics.
inline std::string parse_to_text(const std::string& source) {
  auto result = compile_text(source, false);
  return print_unit(result->unit) + result->diagnostics.format_all();
}

// The S-expression of one expression, parsed inside a function body.
inline std::string expression_tree(const std::string& expression) {
  auto result = compile_text("void f() { " + expression + "; }", false);
  if (!result->ok()) return result->diagnostics.format_all();
  const Stmt& body = *result->unit.declarations.at(0)->function->body;
  return print_expression(*body.statements.at(0)->expression);
}

// The S-expression of one statement inside a function body.
inline std::string statement_tree(const std::string& statement) {
  auto result = compile_text("void f() { " + statement + " }", false);
  if (!result->ok()) return result->diagnostics.format_all();
  const Stmt& body = *result->unit.declarations.at(0)->function->body;
  return print_statement(*body.statements.at(0));
}

inline std::string errors_of(const std::string& source, bool semantics = true) {
  return compile_text(source, semantics)->diagnostics.format_all();
}

}  // namespace pfx::fx::test
