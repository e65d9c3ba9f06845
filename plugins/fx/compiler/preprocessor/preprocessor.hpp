#pragma once
// The FX preprocessor. Written here rather than taken from Debian's libmcpp: mcpp works on text
// and reports its own messages on its own streams, while this one works on tokens, so every
// token the parser sees keeps the file, line and column it was written at (through #include and
// macro expansion), and every problem is a Diagnostic with that location.
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "../diagnostics.hpp"
#include "../lexer.hpp"
#include "file_reader.hpp"
#include "macro_expander.hpp"
#include "preprocessor_options.hpp"

namespace pfx::fx {

// A #pragma the preprocessor does not act on itself (e.g. "#pragma reshade skipoptimization"),
// kept for the runtime.
struct Pragma {
  SourceLocation location;
  TokenList tokens;  // after "pragma"
};

struct PreprocessedSource {
  TokenList tokens;  // every token after expansion, ending without a kEnd token
  std::vector<Pragma> pragmas;
  std::vector<std::string> included_files;  // every file read, the main file first
};

class Preprocessor {
 public:
  Preprocessor(const PreprocessorOptions& options, FileReader reader, FileNames& names, Diagnostics& diagnostics);
  ~Preprocessor();

  // Preprocesses `path` (read through the reader). Errors are in the Diagnostics.
  PreprocessedSource run(const std::string& path);

 private:
  struct Frame;
  struct Conditional {
    SourceLocation location;
    bool active = false;        // this group's tokens are kept
    bool taken = false;         // some group of this #if was already chosen
    bool parent_active = true;  // the enclosing group is kept
    bool seen_else = false;
  };

  void define_predefined_macros();
  void define_from_text(const std::string& name, const std::string& text);
  bool push_file_contents(const std::string& path, std::string contents, SourceLocation where);
  std::string current_path() const;
  bool next_source_token(Token& out);
  Token take_raw(Frame& frame);
  TokenList rest_of_line(Frame& frame);
  bool skipping() const { return !conditionals_.empty() && !conditionals_.back().active; }

  void directive(const Token& hash, TokenList line);
  void directive_include(const Token& name, TokenList line);
  void directive_define(const Token& name, const TokenList& line);
  void directive_undef(const Token& name, const TokenList& line);
  void directive_if(const Token& name, const TokenList& line);
  void directive_elif(const Token& name, const TokenList& line);
  void directive_else_endif(const Token& name, const TokenList& line);
  void directive_line(const Token& name, const TokenList& line);
  void directive_pragma(const Token& name, const TokenList& line);
  void directive_message(const Token& name, const TokenList& line);
  bool evaluate_condition(const Token& name, const TokenList& expression);
  // Replaces each `exists "file"` of an expanded #if expression by 1 or 0; false after an error.
  bool answer_exists(TokenList& expression);
  // The path of the first candidate the reader can read (its text in `contents`), or "".
  std::string resolve_include(const std::string& name, bool quoted, std::string& contents);

  const PreprocessorOptions& options_;
  FileReader reader_;
  FileNames& names_;
  Diagnostics& diagnostics_;
  MacroTable macros_;
  MacroExpander expander_;
  std::vector<std::unique_ptr<Frame>> frames_;
  std::vector<Conditional> conditionals_;
  std::set<std::string> once_files_;
  PreprocessedSource result_;
};

// Convenience: one call with a fresh Preprocessor.
PreprocessedSource preprocess(const std::string& path, const PreprocessorOptions& options, const FileReader& reader,
                              FileNames& names, Diagnostics& diagnostics);

}  // namespace pfx::fx
