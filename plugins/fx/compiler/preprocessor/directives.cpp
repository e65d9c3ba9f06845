// The preprocessor's directives: #define/#undef, the conditionals, #include, #line, #pragma,
// #error and #warning.
#include <algorithm>
#include <optional>

#include "../limits.hpp"
#include "../literals.hpp"
#include "if_expression.hpp"
#include "known_headers.hpp"
#include "preprocessor.hpp"
#include "preprocessor_frame.hpp"

namespace pfx::fx {

namespace {

TokenList tail(const TokenList& line) { return TokenList(line.begin() + (line.empty() ? 0 : 1), line.end()); }

}  // namespace

void Preprocessor::directive(const Token& hash, TokenList line) {
  if (line.empty()) return;  // the null directive
  const Token& name = line.front();
  const std::string& word = name.text;
  bool opens = word == "if" || word == "ifdef" || word == "ifndef";
  if (skipping()) {
    // Inside a skipped group only the nesting of conditionals matters.
    if (opens && conditionals_.size() >= static_cast<std::size_t>(limits::kMaxConditionalDepth)) directive_if(name, line);
    else if (opens) conditionals_.push_back({name.location, false, true, false, false});
    else if (word == "elif") directive_elif(name, line);
    else if (word == "else" || word == "endif") directive_else_endif(name, line);
    return;
  }
  if (opens) directive_if(name, line);
  else if (word == "elif") directive_elif(name, line);
  else if (word == "else" || word == "endif") directive_else_endif(name, line);
  else if (word == "define") directive_define(name, line);
  else if (word == "undef") directive_undef(name, line);
  else if (word == "include") directive_include(name, line);
  else if (word == "line") directive_line(name, line);
  else if (word == "pragma") directive_pragma(name, line);
  else if (word == "error" || word == "warning") directive_message(name, line);
  else if (name.kind == TokenKind::kNumber) directive_line(name, line);  // "# 12 \"file\"" markers
  else diagnostics_.error(hash.location, "unknown preprocessor directive '#" + word + "'");
}

void Preprocessor::directive_if(const Token& name, const TokenList& line) {
  if (conditionals_.size() >= static_cast<std::size_t>(limits::kMaxConditionalDepth)) {
    diagnostics_.error(name.location, "conditional directives nested deeper than " +
                                          std::to_string(limits::kMaxConditionalDepth) + " levels");
    frames_.clear();  // stop: the rest of the input cannot be read correctly
    return;
  }
  bool value = false;
  if (name.text == "if") {
    value = evaluate_condition(name, tail(line));
  } else if (line.size() < 2 || line[1].kind != TokenKind::kIdentifier) {
    diagnostics_.error(name.location, "#" + name.text + " needs a macro name");
  } else {
    value = (macros_.find(line[1].text) != nullptr) == (name.text == "ifdef");
  }
  conditionals_.push_back({name.location, value, value, true, false});
}

void Preprocessor::directive_elif(const Token& name, const TokenList& line) {
  if (conditionals_.size() <= frames_.back()->conditional_base) {
    diagnostics_.error(name.location, "#elif without #if");
    return;
  }
  Conditional& c = conditionals_.back();
  if (c.seen_else) diagnostics_.error(name.location, "#elif after #else");
  if (!c.parent_active || c.taken) {
    c.active = false;
    return;
  }
  c.active = evaluate_condition(name, tail(line));
  c.taken = c.active;
}

void Preprocessor::directive_else_endif(const Token& name, const TokenList& line) {
  (void)line;
  if (conditionals_.size() <= frames_.back()->conditional_base) {
    diagnostics_.error(name.location, "#" + name.text + " without #if");
    return;
  }
  if (name.text == "endif") {
    conditionals_.pop_back();
    return;
  }
  Conditional& c = conditionals_.back();
  if (c.seen_else) diagnostics_.error(name.location, "#else after #else");
  c.seen_else = true;
  c.active = c.parent_active && !c.taken;
  c.taken = true;
}

bool Preprocessor::evaluate_condition(const Token& name, const TokenList& expression) {
  // "defined X" and "defined(X)" are answered before expansion, as the standard says.
  TokenList resolved;
  for (std::size_t i = 0; i < expression.size(); ++i) {
    if (!expression[i].is_identifier("defined")) {
      resolved.push_back(expression[i]);
      continue;
    }
    bool parenthesised = i + 1 < expression.size() && expression[i + 1].is(Punct::kLeftParen);
    std::size_t at = i + (parenthesised ? 2 : 1);
    if (at >= expression.size() || expression[at].kind != TokenKind::kIdentifier ||
        (parenthesised && (at + 1 >= expression.size() || !expression[at + 1].is(Punct::kRightParen)))) {
      diagnostics_.error(expression[i].location, "'defined' needs a macro name");
      return false;
    }
    Token value = expression[i];
    value.kind = TokenKind::kNumber;
    value.text = macros_.find(expression[at].text) ? "1" : "0";
    resolved.push_back(value);
    i = at + (parenthesised ? 1 : 0);
  }
  TokenList expanded = expander_.expand_list(resolved);
  if (!answer_exists(expanded)) return false;
  auto value = evaluate_if_expression(expanded, name.location, diagnostics_);
  return value && *value != 0;
}

bool Preprocessor::answer_exists(TokenList& expression) {
  // ReShade's `exists "file"` (after expansion, so `exists MACRO` names the macro's file): 1 when
  // a quoted #include of the file would find it, else 0.
  TokenList answered;
  for (std::size_t i = 0; i < expression.size(); ++i) {
    if (!expression[i].is_identifier("exists")) {
      answered.push_back(expression[i]);
      continue;
    }
    const bool parenthesised = i + 1 < expression.size() && expression[i + 1].is(Punct::kLeftParen);
    const std::size_t at = i + (parenthesised ? 2 : 1);
    if (at >= expression.size() || expression[at].kind != TokenKind::kString ||
        (parenthesised && (at + 1 >= expression.size() || !expression[at + 1].is(Punct::kRightParen)))) {
      diagnostics_.error(expression[i].location, "'exists' needs a file name in quotes");
      return false;
    }
    std::string file = expression[at].text.substr(1, expression[at].text.size() - 2);
    std::replace(file.begin(), file.end(), '\\', '/');
    std::string contents;
    Token value = expression[i];
    value.kind = TokenKind::kNumber;
    value.text = !file.empty() && !resolve_include(file, true, contents).empty() ? "1" : "0";
    answered.push_back(value);
    i = at + (parenthesised ? 1 : 0);
  }
  expression = std::move(answered);
  return true;
}

void Preprocessor::directive_define(const Token& name, const TokenList& line) {
  if (line.size() < 2 || line[1].kind != TokenKind::kIdentifier) {
    diagnostics_.error(name.location, "#define needs a macro name");
    return;
  }
  Macro macro;
  macro.name = line[1].text;
  macro.location = line[1].location;
  if (macro.name == "defined") return diagnostics_.error(line[1].location, "'defined' cannot be a macro name");
  std::size_t i = 2;
  if (i < line.size() && line[i].is(Punct::kLeftParen) && !line[i].space_before) {
    macro.function_like = true;
    for (++i; i < line.size() && !line[i].is(Punct::kRightParen); ++i) {
      if (line[i].is(Punct::kComma) && !macro.parameters.empty()) continue;
      if (line[i].is(Punct::kEllipsis)) {
        macro.variadic = true;
        macro.parameters.push_back("__VA_ARGS__");
      } else if (line[i].kind == TokenKind::kIdentifier && !macro.variadic &&
                 macro.parameter_index(line[i].text) < 0) {
        macro.parameters.push_back(line[i].text);
      } else {
        return diagnostics_.error(line[i].location, "bad parameter list of macro '" + macro.name + "'");
      }
    }
    if (i >= line.size()) return diagnostics_.error(name.location, "missing ')' in macro parameter list");
    ++i;
  }
  macro.body.assign(line.begin() + static_cast<long>(i), line.end());
  if (!macro.body.empty()) {
    macro.body.front().space_before = false;
    if (macro.body.front().is(Punct::kHashHash) || macro.body.back().is(Punct::kHashHash))
      return diagnostics_.error(name.location, "'##' cannot be at either end of a macro");
  }
  for (std::size_t k = 0; macro.function_like && k < macro.body.size(); ++k) {
    const Token& t = macro.body[k];
    bool names_parameter = k + 1 < macro.body.size() && macro.body[k + 1].kind == TokenKind::kIdentifier &&
                           macro.parameter_index(macro.body[k + 1].text) >= 0;
    if (t.is(Punct::kHash) && !names_parameter)
      return diagnostics_.error(t.location, "'#' is not followed by a macro parameter");
  }
  if (const Macro* old = macros_.find(macro.name)) {
    if (old->builtin != BuiltinMacro::kNone || spell(old->body) != spell(macro.body) ||
        old->parameters != macro.parameters)
      diagnostics_.warning(line[1].location, "'" + macro.name + "' redefined");
  }
  macros_.define(std::move(macro));
}

void Preprocessor::directive_undef(const Token& name, const TokenList& line) {
  if (line.size() < 2 || line[1].kind != TokenKind::kIdentifier)
    return diagnostics_.error(name.location, "#undef needs a macro name");
  macros_.undefine(line[1].text);
}

void Preprocessor::directive_line(const Token& name, const TokenList& line) {
  TokenList args = expander_.expand_list(name.kind == TokenKind::kNumber ? line : tail(line));
  std::string error;
  auto number = args.empty() || args[0].kind != TokenKind::kNumber ? std::nullopt : parse_number(args[0].text, error);
  if (!number || number->kind == NumberLiteral::Kind::kFloat || number->integer == 0)
    return diagnostics_.error(name.location, "#line needs a positive line number");
  Frame& frame = *frames_.back();
  long last_physical = static_cast<long>((line.back().location.line)) - frame.line_offset;
  long offset = static_cast<long>(number->integer) - (last_physical + 1);
  std::uint32_t file = name.location.file;
  if (args.size() > 1 && args[1].kind == TokenKind::kString)
    file = names_.add(unescape_string(args[1].text, error));
  if (frame.lookahead && frame.lookahead->kind != TokenKind::kEnd) {
    long physical = static_cast<long>(frame.lookahead->location.line) - frame.line_offset;
    frame.lookahead->location.line = static_cast<std::uint32_t>(std::max(1L, physical + offset));
    frame.lookahead->location.file = file;
  }
  frame.line_offset = offset;
  frame.lexer->set_line_offset(offset);
  frame.lexer->set_file(file);
}

void Preprocessor::directive_pragma(const Token& name, const TokenList& line) {
  if (line.size() >= 2 && line[1].is_identifier("once")) {
    once_files_.insert(frames_.back()->path);
    return;
  }
  result_.pragmas.push_back({name.location, tail(line)});
}

void Preprocessor::directive_message(const Token& name, const TokenList& line) {
  std::string text = "#" + name.text + " " + spell(tail(line));
  if (name.text == "error") diagnostics_.error(name.location, text);
  else diagnostics_.warning(name.location, text);
}

std::string Preprocessor::resolve_include(const std::string& name, bool quoted, std::string& contents) {
  std::vector<std::string> candidates;
  if (quoted) candidates.push_back(join_path(parent_folder(frames_.back()->path), name));
  for (const std::string& folder : options_.include_folders) candidates.push_back(join_path(folder, name));
  for (const std::string& candidate : candidates)
    if (reader_(candidate, contents)) return candidate;
  return {};
}

void Preprocessor::directive_include(const Token& name, TokenList line) {
  TokenList args = tail(line);
  if (!args.empty() && args[0].kind != TokenKind::kString && !args[0].is(Punct::kLess))
    args = expander_.expand_list(args);  // #include MACRO
  std::string file;
  bool quoted = !args.empty() && args[0].kind == TokenKind::kString;
  if (quoted) {
    file = args[0].text.substr(1, args[0].text.size() - 2);
  } else if (!args.empty() && args[0].is(Punct::kLess)) {
    for (std::size_t i = 1; i < args.size() && !args[i].is(Punct::kGreater); ++i) file += args[i].text;
  }
  std::replace(file.begin(), file.end(), '\\', '/');  // Windows-style paths in shader collections
  if (file.empty()) return diagnostics_.error(name.location, "#include needs \"file\" or <file>");
  std::string contents;
  std::string path = resolve_include(file, quoted, contents);
  if (path.empty()) {
    const std::string collection = collection_of_header(file);
    return diagnostics_.error(name.location, "cannot open include file '" + file + "'" +
                                                 (collection.empty() ? "" : ": it comes with " + collection +
                                                                                "; add the folder that holds it to the shader folders"));
  }
  if (once_files_.count(path)) return;
  for (std::size_t i = 0; i < frames_.size(); ++i) {
    if (frames_[i]->path != path) continue;
    std::string chain;
    for (std::size_t k = i; k < frames_.size(); ++k) chain += frames_[k]->path + " -> ";
    return diagnostics_.error(name.location, "#include cycle: " + chain + path);
  }
  if (frames_.size() >= static_cast<std::size_t>(limits::kMaxIncludeDepth))
    return diagnostics_.error(name.location, "#include nested deeper than " +
                                                 std::to_string(limits::kMaxIncludeDepth) + " levels");
  push_file_contents(path, std::move(contents), name.location);
}

}  // namespace pfx::fx
