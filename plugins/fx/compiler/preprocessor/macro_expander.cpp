#include "macro_expander.hpp"

#include <algorithm>
#include <iterator>

#include "../lexer.hpp"
#include "../limits.hpp"

namespace pfx::fx {
namespace {

using HideSet = std::vector<std::uint32_t>;

bool hides(const HideSet& set, std::uint32_t id) { return std::binary_search(set.begin(), set.end(), id); }

HideSet unite(const HideSet& a, const HideSet& b) {
  HideSet out;
  std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
  return out;
}

HideSet intersect(const HideSet& a, const HideSet& b) {
  HideSet out;
  std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
  return out;
}

std::string quote(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

bool is_parameter(const Macro& macro, const Token& token) {
  return macro.function_like && token.kind == TokenKind::kIdentifier && macro.parameter_index(token.text) >= 0;
}

}  // namespace

bool MacroExpander::take(std::deque<Token>& pending, const Pull& pull, Token& out) {
  if (!pending.empty()) {
    out = std::move(pending.front());
    pending.pop_front();
    return true;
  }
  return pull && pull(out);
}

bool MacroExpander::next(const Pull& pull, Token& out) {
  for (;;) {
    if (!take(pending_, pull, out)) return false;
    if (out.kind != TokenKind::kIdentifier) return true;
    const std::shared_ptr<const Macro> macro = macros_.hold(out.text);  // held while its use expands
    if (!macro || hides(out.hide_set, macro->id)) return true;
    if (!expand_use(*macro, out, pending_, pull)) return true;
  }
}

TokenList MacroExpander::expand_list(const TokenList& tokens) {
  if (argument_depth_ >= limits::kMaxSyntaxNesting) {
    if (!tokens.empty()) diagnostics_.error(tokens.front().location, "macro arguments nested too deeply");
    return {};
  }
  ++argument_depth_;
  std::deque<Token> pending(tokens.begin(), tokens.end());
  TokenList out;
  Token token;
  for (;;) {
    if (!take(pending, nullptr, token)) break;
    const std::shared_ptr<const Macro> macro =
        token.kind == TokenKind::kIdentifier ? macros_.hold(token.text) : nullptr;
    if (macro && !hides(token.hide_set, macro->id) && expand_use(*macro, token, pending, nullptr)) continue;
    out.push_back(std::move(token));
  }
  --argument_depth_;
  return out;
}

bool MacroExpander::expand_use(const Macro& macro, Token name, std::deque<Token>& pending, const Pull& pull) {
  if (produced_ > limits::kMaxExpansionTokens) {
    if (!limit_reported_)
      diagnostics_.error(name.location, "macro expansion produced more than " +
                                            std::to_string(limits::kMaxExpansionTokens) + " tokens");
    limit_reported_ = true;
    return false;
  }
  if (macro.builtin != BuiltinMacro::kNone) {
    pending.push_front(builtin_value(macro, name));
    return true;
  }
  HideSet hide_set;
  std::vector<TokenList> arguments;
  if (macro.function_like) {
    Token paren;
    if (!take(pending, pull, paren)) return false;
    if (!paren.is(Punct::kLeftParen)) {
      pending.push_front(std::move(paren));
      return false;
    }
    Token right_paren;
    if (!collect_arguments(macro, name, pending, pull, arguments, right_paren)) return true;
    hide_set = intersect(name.hide_set, right_paren.hide_set);
  } else {
    hide_set = name.hide_set;
  }
  hide_set = unite(hide_set, {macro.id});
  TokenList result = substitute(macro, name, arguments, hide_set);
  produced_ += result.size();
  pending.insert(pending.begin(), std::make_move_iterator(result.begin()), std::make_move_iterator(result.end()));
  return true;
}

bool MacroExpander::collect_arguments(const Macro& macro, const Token& name, std::deque<Token>& pending,
                                      const Pull& pull, std::vector<TokenList>& arguments, Token& right_paren) {
  arguments.assign(1, {});
  int depth = 0;
  Token token;
  for (;;) {
    if (!take(pending, pull, token)) {
      diagnostics_.error(name.location, "unterminated argument list of macro '" + macro.name + "'");
      return false;
    }
    if (token.is(Punct::kLeftParen)) ++depth;
    if (token.is(Punct::kRightParen) && depth-- == 0) break;
    bool splits = token.is(Punct::kComma) && depth == 0 &&
                  !(macro.variadic && arguments.size() >= macro.parameters.size());
    if (splits) {
      if (arguments.size() >= limits::kMaxMacroArguments) {
        diagnostics_.error(name.location, "too many arguments to macro '" + macro.name + "'");
        return false;
      }
      arguments.emplace_back();
    } else {
      arguments.back().push_back(std::move(token));
    }
  }
  right_paren = std::move(token);
  if (macro.parameters.empty() && arguments.size() == 1 && arguments[0].empty()) arguments.clear();
  if (macro.variadic && arguments.size() + 1 == macro.parameters.size()) arguments.emplace_back();
  if (arguments.size() != macro.parameters.size()) {
    diagnostics_.error(name.location, "macro '" + macro.name + "' takes " + std::to_string(macro.parameters.size()) +
                                          " argument(s), but " + std::to_string(arguments.size()) + " were given");
    return false;
  }
  return true;
}

TokenList MacroExpander::argument_for(const std::vector<TokenList>& arguments, int index, bool raw,
                                      bool& placemarker) {
  const TokenList& argument = arguments[static_cast<std::size_t>(index)];
  placemarker = argument.empty();
  return raw ? argument : expand_list(argument);
}

TokenList MacroExpander::substitute(const Macro& macro, const Token& use, const std::vector<TokenList>& arguments,
                                    const HideSet& hide_set) {
  // Pieces between ## operators; an empty piece is a placemarker (an empty argument).
  struct Piece {
    TokenList tokens;
    bool paste_operator = false;
  };
  std::vector<Piece> pieces;
  const TokenList& body = macro.body;
  for (std::size_t i = 0; i < body.size(); ++i) {
    const Token& token = body[i];
    bool pasted_left = i > 0 && body[i - 1].is(Punct::kHashHash);
    bool pasted_right = i + 1 < body.size() && body[i + 1].is(Punct::kHashHash);
    if (macro.function_like && token.is(Punct::kHash) && i + 1 < body.size() && is_parameter(macro, body[i + 1])) {
      pieces.push_back({{stringize(arguments[macro.parameter_index(body[++i].text)], use)}, false});
      pieces.back().tokens[0].space_before = token.space_before;
    } else if (token.is(Punct::kHashHash)) {
      pieces.push_back({{}, true});
    } else if (is_parameter(macro, token)) {
      bool placemarker = false;
      TokenList tokens =
          argument_for(arguments, macro.parameter_index(token.text), pasted_left || pasted_right, placemarker);
      if (!tokens.empty()) tokens.front().space_before = token.space_before;
      pieces.push_back({std::move(tokens), false});
    } else {
      Token copy = token;
      copy.location = use.location;
      pieces.push_back({{std::move(copy)}, false});
    }
  }
  TokenList result;
  bool previous_empty = true;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    if (!pieces[k].paste_operator) {
      result.insert(result.end(), pieces[k].tokens.begin(), pieces[k].tokens.end());
      previous_empty = pieces[k].tokens.empty();
      continue;
    }
    if (++k >= pieces.size()) break;
    const TokenList& right = pieces[k].tokens;
    std::size_t first = 0;
    if (!previous_empty && !right.empty()) first = paste(result.back(), right.front(), use) ? 1 : 0;
    result.insert(result.end(), right.begin() + static_cast<long>(first), right.end());
    previous_empty = previous_empty && right.empty();
  }
  for (Token& token : result) token.hide_set = unite(token.hide_set, hide_set);
  if (!result.empty()) result.front().space_before = use.space_before;
  return result;
}

Token MacroExpander::builtin_value(const Macro& macro, const Token& use) const {
  Token token = use;
  token.hide_set.clear();
  const std::string& path = names_.name(use.location.file);
  std::string file_name = path.substr(path.find_last_of('/') == std::string::npos ? 0 : path.find_last_of('/') + 1);
  token.kind = TokenKind::kString;
  switch (macro.builtin) {
    case BuiltinMacro::kFile: token.text = quote(path); break;
    case BuiltinMacro::kFileName: token.text = quote(file_name); break;
    case BuiltinMacro::kFileStem: token.text = quote(file_name.substr(0, file_name.find_last_of('.'))); break;
    case BuiltinMacro::kLine:
    case BuiltinMacro::kNone:
      token.kind = TokenKind::kNumber;
      token.text = std::to_string(use.location.line);
      break;
  }
  return token;
}

Token MacroExpander::stringize(const TokenList& argument, const Token& use) const {
  Token token;
  token.kind = TokenKind::kString;
  token.location = use.location;
  std::string text;
  for (const Token& t : argument) {
    if (!text.empty() && t.space_before) text += ' ';
    text += t.text;
  }
  token.text = quote(text);
  return token;
}

bool MacroExpander::paste(Token& left, const Token& right, const Token& use) {
  FileNames scratch_names;
  Diagnostics scratch(scratch_names);
  TokenList joined = lex_all(left.text + right.text, left.location.file, scratch);
  if (joined.size() != 1 || scratch.has_errors()) {
    // Text that is not one token but several valid ones (Tint##id##.rgb pastes "Tint1" and ".")
    // stays as those tokens, as ReShade's and MSVC's preprocessors leave it; what does not lex at
    // all is an error.
    const std::string what = "pasting \"" + left.text + "\" and \"" + right.text + "\" does not give a valid token";
    if (scratch.has_errors()) diagnostics_.error(use.location, what);
    else diagnostics_.warning(use.location, what + ": kept as they are");
    return false;
  }
  left.kind = joined[0].kind;
  left.punct = joined[0].punct;
  left.text = joined[0].text;
  left.hide_set = unite(left.hide_set, right.hide_set);
  return true;
}

}  // namespace pfx::fx
