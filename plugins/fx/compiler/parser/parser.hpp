#pragma once
// A recursive-descent parser for ReShade FX (HLSL's DX9-style syntax plus textures, samplers,
// storages, namespaces, annotations and techniques). Recursion is bounded by a nesting limit so
// hostile input gives an error, never a stack overflow.
#include <set>
#include <string>

#include "../ast/ast.hpp"
#include "../diagnostics.hpp"
#include "../token.hpp"

namespace pfx::fx {

class Parser {
 public:
  Parser(const TokenList& tokens, Diagnostics& diagnostics);
  TranslationUnit parse();

 private:
  friend class NestingGuard;

  // Tokens (parser_core.cpp).
  const Token& peek(std::size_t ahead = 0) const;
  const Token& advance();
  bool at(Punct punct, std::size_t ahead = 0) const { return peek(ahead).is(punct); }
  bool at_word(const char* word, std::size_t ahead = 0) const { return peek(ahead).is_identifier(word); }
  bool accept(Punct punct);
  bool accept_word(const char* word);
  bool expect(Punct punct, const char* context);
  bool expect_identifier(std::string& name, const char* what);
  void error_here(const std::string& message);
  void error_at(SourceLocation where, const std::string& message);
  void recover(std::size_t start, bool inside_block);
  bool enter();  // false (after an error) when nesting passes the limit
  void leave() { --depth_; }
  bool extend_chain(long& local);  // one more chained operator; false past the limit
  bool stopped() const { return diagnostics_.too_many_errors() || failed_nesting_; }

  // Types (parse_types.cpp).
  bool at_type(std::size_t ahead = 0) const;
  bool at_declaration() const;
  unsigned parse_qualifiers();
  bool parse_type(TypeSyntax& type);
  bool parse_qualified_name(std::string& name);

  // Expressions (parse_expressions.cpp).
  ExprPtr parse_expression();  // with the comma operator
  ExprPtr parse_assignment();
  ExprPtr parse_conditional();
  ExprPtr parse_binary(int level);
  ExprPtr parse_unary();
  ExprPtr parse_postfix(ExprPtr expression);
  ExprPtr parse_primary();
  ExprPtr parse_literal();
  ExprPtr parse_initializer();  // an expression or a { ... } list
  bool parse_arguments(std::vector<ExprPtr>& arguments);
  bool at_cast() const;

  // Statements (parse_statements.cpp).
  StmtPtr parse_statement();
  StmtPtr parse_statement_body();
  StmtPtr parse_block();
  StmtPtr parse_if();
  StmtPtr parse_for();
  StmtPtr parse_while();
  StmtPtr parse_do_while();
  StmtPtr parse_switch();
  StmtPtr parse_jump();
  StmtPtr parse_local_declaration();
  bool parse_attributes(std::vector<Attribute>& attributes);

  // Declarations (parse_declarations.cpp).
  void parse_declarations(std::vector<DeclPtr>& out, bool in_namespace);
  DeclPtr parse_declaration();
  DeclPtr parse_namespace();
  DeclPtr parse_struct();
  DeclPtr parse_function_or_variables(std::vector<Attribute> attributes);
  bool parse_function_rest(FunctionDecl& function);
  bool parse_parameter(VariableDecl& parameter);
  // One or more comma-separated declarators sharing qualifiers and a type.
  bool parse_declarators(unsigned qualifiers, const TypeSyntax& type, bool global, std::vector<VariableDecl>& out);
  bool parse_declarator(VariableDecl& variable, bool global);
  bool parse_array_sizes(std::vector<ExprPtr>& sizes);
  bool parse_semantic(std::string& semantic);
  bool parse_annotations(std::vector<Annotation>& annotations);
  bool parse_state_block(std::vector<StateAssignment>& states, bool pass);

  // Techniques (parse_techniques.cpp).
  DeclPtr parse_technique();
  bool parse_pass(PassDecl& pass);

  const TokenList& tokens_;
  Diagnostics& diagnostics_;
  Token end_;
  std::size_t position_ = 0;
  int depth_ = 0;
  long chain_ = 0;  // operators chained without nesting in the expressions being parsed
  bool failed_nesting_ = false;
  bool in_annotation_ = false;
  std::set<std::string> struct_names_;  // as written and qualified: "S", "N::S"
  std::string namespace_prefix_;        // "A::B::" inside namespaces
};

// Convenience for tests and the runtime.
TranslationUnit parse_tokens(const TokenList& tokens, Diagnostics& diagnostics);

}  // namespace pfx::fx
