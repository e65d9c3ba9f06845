#include "preprocessor.hpp"

#include <optional>

#include "../limits.hpp"
#include "preprocessor_frame.hpp"

namespace pfx::fx {


Preprocessor::Preprocessor(const PreprocessorOptions& options, FileReader reader, FileNames& names,
                           Diagnostics& diagnostics)
    : options_(options),
      reader_(std::move(reader)),
      names_(names),
      diagnostics_(diagnostics),
      expander_(macros_, names, diagnostics) {}

Preprocessor::~Preprocessor() = default;

void Preprocessor::define_from_text(const std::string& name, const std::string& text) {
  Macro macro;
  macro.name = name;
  macro.body = lex_all(text, names_.add("<command line>"), diagnostics_);
  if (!macro.body.empty()) macro.body.front().space_before = false;
  macros_.define(std::move(macro));
}

void Preprocessor::define_predefined_macros() {
  const std::pair<const char*, BuiltinMacro> builtins[] = {{"__FILE__", BuiltinMacro::kFile},
                                                           {"__FILE_NAME__", BuiltinMacro::kFileName},
                                                           {"__FILE_STEM__", BuiltinMacro::kFileStem},
                                                           {"__LINE__", BuiltinMacro::kLine}};
  for (const auto& [name, kind] : builtins) {
    Macro macro;
    macro.name = name;
    macro.builtin = kind;
    macros_.define(std::move(macro));
  }
  const PreprocessorOptions& o = options_;
  define_from_text("BUFFER_WIDTH", std::to_string(o.buffer_width));
  define_from_text("BUFFER_HEIGHT", std::to_string(o.buffer_height));
  define_from_text("BUFFER_RCP_WIDTH", "(1.0 / BUFFER_WIDTH)");
  define_from_text("BUFFER_RCP_HEIGHT", "(1.0 / BUFFER_HEIGHT)");
  define_from_text("BUFFER_COLOR_BIT_DEPTH", std::to_string(o.buffer_color_bit_depth));
  define_from_text("BUFFER_COLOR_SPACE", std::to_string(o.buffer_color_space));
  define_from_text("__RESHADE__", std::to_string(o.reshade_version));
  define_from_text("__RENDERER__", std::to_string(o.renderer));
  define_from_text("__VENDOR__", std::to_string(o.vendor));
  define_from_text("__DEVICE__", std::to_string(o.device));
  define_from_text("__APPLICATION__", std::to_string(o.application) + "u");
  define_from_text("__RESHADE_PERFORMANCE_MODE__", o.performance_mode ? "1" : "0");
  for (const auto& [name, text] : o.defines) define_from_text(name, text);
}

PreprocessedSource Preprocessor::run(const std::string& path) {
  define_predefined_macros();
  std::string contents;
  SourceLocation start{names_.add(path), 1, 1};
  if (!reader_(path, contents)) {
    diagnostics_.error(start, "cannot read file '" + path + "'");
    return {};
  }
  if (!push_file_contents(path, std::move(contents), start)) return {};
  MacroExpander::Pull pull = [this](Token& token) { return next_source_token(token); };
  Token token;
  while (expander_.next(pull, token)) {
    if (result_.tokens.size() >= limits::kMaxOutputTokens) {
      diagnostics_.error(token.location, "effect has more than " + std::to_string(limits::kMaxOutputTokens) +
                                             " tokens after preprocessing");
      break;
    }
    token.hide_set.clear();
    result_.tokens.push_back(std::move(token));
    if (diagnostics_.too_many_errors()) break;
  }
  return std::move(result_);
}

bool Preprocessor::push_file_contents(const std::string& path, std::string contents, SourceLocation where) {
  if (contents.size() > limits::kMaxSourceBytes) {
    diagnostics_.error(where, "file '" + path + "' is larger than " + std::to_string(limits::kMaxSourceBytes >> 20) +
                                  " MiB");
    return false;
  }
  auto frame = std::make_unique<Frame>();
  frame->path = path;
  frame->text = std::move(contents);
  frame->lexer = std::make_unique<Lexer>(frame->text, names_.add(path), diagnostics_);
  frame->conditional_base = conditionals_.size();
  frames_.push_back(std::move(frame));
  result_.included_files.push_back(path);
  return true;
}

Token Preprocessor::take_raw(Frame& frame) {
  if (frame.lookahead) {
    Token token = std::move(*frame.lookahead);
    frame.lookahead.reset();
    return token;
  }
  frame.lexer->set_quiet(skipping());
  return frame.lexer->next();
}

TokenList Preprocessor::rest_of_line(Frame& frame) {
  TokenList line;
  for (;;) {
    Token token = take_raw(frame);
    if (token.line_start) {
      frame.lookahead = std::move(token);
      return line;
    }
    line.push_back(std::move(token));
  }
}

bool Preprocessor::next_source_token(Token& out) {
  while (!frames_.empty()) {
    Frame& frame = *frames_.back();
    Token token = take_raw(frame);
    if (token.kind == TokenKind::kEnd) {
      while (conditionals_.size() > frame.conditional_base) {
        diagnostics_.error(conditionals_.back().location, "unterminated conditional directive");
        conditionals_.pop_back();
      }
      frames_.pop_back();
      continue;
    }
    if (token.line_start && token.is(Punct::kHash)) {
      directive(token, rest_of_line(frame));
      if (diagnostics_.too_many_errors()) frames_.clear();
      continue;
    }
    if (skipping()) continue;
    out = std::move(token);
    return true;
  }
  return false;
}

PreprocessedSource preprocess(const std::string& path, const PreprocessorOptions& options, const FileReader& reader,
                              FileNames& names, Diagnostics& diagnostics) {
  return Preprocessor(options, reader, names, diagnostics).run(path);
}

}  // namespace pfx::fx
