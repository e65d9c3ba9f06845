#pragma once
// Macro expansion by hide sets (the algorithm the C standard's examples follow): every token
// remembers which macros produced it, and a macro never expands inside its own expansion. This
// terminates on any input and gets the standard's tricky cases (self reference, mutual
// recursion, f(f)(x)) right. Tokens from a macro body take the location of the macro's use.
#include <deque>
#include <functional>

#include "../diagnostics.hpp"
#include "macro.hpp"

namespace pfx::fx {

class MacroExpander {
 public:
  // `pull` yields the next token of the file when a macro use runs past the tokens given (a
  // function-like macro whose arguments continue on later lines); it returns false at the end.
  using Pull = std::function<bool(Token&)>;

  MacroExpander(const MacroTable& macros, const FileNames& names, Diagnostics& diagnostics)
      : macros_(macros), names_(names), diagnostics_(diagnostics) {}

  // Next fully expanded token from `pull`; false at the end of input.
  bool next(const Pull& pull, Token& out);
  // Expands a list in isolation (an #if line, an #include line).
  TokenList expand_list(const TokenList& tokens);
  // Expansion output so far, for the limit on runaway expansion.
  std::size_t produced() const { return produced_; }

 private:
  bool take(std::deque<Token>& pending, const Pull& pull, Token& out);
  bool expand_use(const Macro& macro, Token name, std::deque<Token>& pending, const Pull& pull);
  bool collect_arguments(const Macro& macro, const Token& name, std::deque<Token>& pending, const Pull& pull,
                         std::vector<TokenList>& arguments, Token& right_paren);
  TokenList substitute(const Macro& macro, const Token& use, const std::vector<TokenList>& arguments,
                       const std::vector<std::uint32_t>& hide_set);
  // An argument as substituted: unexpanded next to # or ## (raw), fully expanded otherwise.
  TokenList argument_for(const std::vector<TokenList>& arguments, int index, bool raw, bool& placemarker);
  Token builtin_value(const Macro& macro, const Token& use) const;
  Token stringize(const TokenList& argument, const Token& use) const;
  bool paste(Token& left, const Token& right, const Token& use);

  const MacroTable& macros_;
  const FileNames& names_;
  Diagnostics& diagnostics_;
  std::deque<Token> pending_;
  std::size_t produced_ = 0;
  int argument_depth_ = 0;
  bool limit_reported_ = false;
};

}  // namespace pfx::fx
