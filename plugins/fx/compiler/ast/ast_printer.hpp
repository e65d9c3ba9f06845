#pragma once
// The syntax tree as S-expressions, e.g. "(+ a (* b c))": how tests state the tree they expect, and
// a readable dump when debugging the parser.
#include <string>

#include "ast.hpp"

namespace pfx::fx {

std::string print_expression(const Expr& expression);
std::string print_statement(const Stmt& statement);
// After semantic analysis: every node followed by ":type", implicit conversions shown as
// "(implicit x:int):float" - what the code generator will see.
std::string print_typed_expression(const Expr& expression);
std::string print_declaration(const Decl& declaration);
std::string print_unit(const TranslationUnit& unit);  // one declaration per line

}  // namespace pfx::fx
