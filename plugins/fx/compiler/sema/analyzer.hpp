#pragma once
// Semantic analysis: resolves names through scopes and namespaces, types every expression with
// HLSL's rules (inserting implicit conversions as kCast nodes marked `implicit`), resolves
// overloads of user functions and intrinsics, checks statements, array sizes and pass states,
// and refuses recursion. Declarations must come before their use, as in HLSL.
#include <map>
#include <set>
#include <string>
#include <vector>

#include "../ast/ast.hpp"
#include "../diagnostics.hpp"
#include "state_tables.hpp"

namespace pfx::fx {

class Analyzer {
 public:
  explicit Analyzer(Diagnostics& diagnostics) : diagnostics_(diagnostics) {}
  void run(TranslationUnit& unit);

 private:
  // Declarations (analyze_declarations.cpp).
  void declare_all(std::vector<DeclPtr>& declarations);
  void declare_variables(std::vector<VariableDecl>& variables, bool global);
  void declare_struct(StructDecl& structure);
  void declare_function(FunctionDecl& function);
  void check_technique(TechniqueDecl& technique);
  void check_object(VariableDecl& object);
  void check_states(std::vector<StateAssignment>& states, StateOwner owner);
  void check_state_value(StateAssignment& state, const StateRule& rule);
  Type resolve_type(const TypeSyntax& syntax, SourceLocation where);
  bool resolve_array_sizes(VariableDecl& variable, Type& type);
  void check_initializer(VariableDecl& variable);

  // Names (analyze_declarations.cpp).
  std::vector<std::string> candidates(const std::string& name) const;  // qualified spellings to try
  const VariableDecl* find_variable(const std::string& name) const;
  const std::vector<FunctionDecl*>* find_functions(const std::string& name, std::string* qualified = nullptr) const;

  // Statements (analyze_statements.cpp).
  void check_statement(Stmt& statement);
  void check_condition(ExprPtr& condition);
  void check_switch(Stmt& statement);
  void push_scope() { scopes_.emplace_back(); }
  void pop_scope() { scopes_.pop_back(); }

  // Expressions (analyze_expressions.cpp, analyze_calls.cpp).
  void check(Expr& expression);
  void check_name(Expr& expression);
  void check_unary(Expr& expression);
  void check_binary(Expr& expression);
  void check_assignment(Expr& expression);
  void check_conditional(Expr& expression);
  void check_member(Expr& expression);
  void check_index(Expr& expression);
  void check_construct(Expr& expression);
  void check_cast(Expr& expression);
  void check_call(Expr& expression);
  bool check_user_call(Expr& expression, const std::vector<FunctionDecl*>& overloads, const std::string& qualified);
  void check_intrinsic_call(Expr& expression);
  void check_init_list(Expr& list, const Type& target);
  // A vector narrower than the vector it is assigned to, widened as ReShade does (its last
  // component repeated), with a warning.
  void widen_for_assignment(ExprPtr& value, const Type& target);
  // Converts `expression` to `to` implicitly (wrapping it in an implicit cast), or reports why not.
  void convert(ExprPtr& expression, const Type& to, const std::string& context);
  void require_lvalue(const Expr& expression, const char* what);

  Diagnostics& diagnostics_;
  std::string namespace_prefix_;
  std::map<std::string, const VariableDecl*> globals_;         // by qualified name
  std::map<std::string, std::vector<FunctionDecl*>> functions_;  // by qualified name
  std::map<std::string, const StructDecl*> structs_;            // by qualified name
  std::set<const VariableDecl*> global_variables_;
  std::set<std::string> textures_;                              // qualified names of texture globals
  std::vector<std::map<std::string, const VariableDecl*>> scopes_;
  FunctionDecl* current_function_ = nullptr;
  int loop_depth_ = 0;
  int switch_depth_ = 0;
  // Who calls whom, for the recursion check (recursion.cpp); prototypes map to their definition.
  std::map<const FunctionDecl*, std::vector<std::pair<const FunctionDecl*, SourceLocation>>> calls_;
  std::map<const FunctionDecl*, const FunctionDecl*> definition_of_;
  void check_recursion();
};

void analyze(TranslationUnit& unit, Diagnostics& diagnostics);

// A type that marks an expression whose checking already failed (no further errors about it).
Type error_type();
bool is_error(const Type& type);

}  // namespace pfx::fx
