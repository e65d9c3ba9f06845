#pragma once
// The syntax tree of one effect, as the parser builds it. Semantic analysis (sema/) fills the
// `resolved` members so the code generator can walk one typed tree.
#include <memory>
#include <string>
#include <vector>

#include "../literals.hpp"
#include "../source_location.hpp"
#include "../token.hpp"
#include "intrinsic.hpp"
#include "semantic_type.hpp"
#include "type_syntax.hpp"

namespace pfx::fx {

struct Expr;
struct Stmt;
struct Decl;
struct VariableDecl;
struct FunctionDecl;
using ExprPtr = std::unique_ptr<Expr>;
using StmtPtr = std::unique_ptr<Stmt>;
using DeclPtr = std::unique_ptr<Decl>;

// Storage and parameter qualifiers (a bit set).
enum Qualifier : unsigned {
  kQualStatic = 1u << 0, kQualConst = 1u << 1, kQualUniform = 1u << 2, kQualExtern = 1u << 3,
  kQualGroupShared = 1u << 4, kQualPrecise = 1u << 5, kQualIn = 1u << 6, kQualOut = 1u << 7,
  kQualInline = 1u << 8, kQualVolatile = 1u << 9, kQualRowMajor = 1u << 10, kQualColumnMajor = 1u << 11,
  kQualLinear = 1u << 12, kQualNoInterpolation = 1u << 13, kQualNoPerspective = 1u << 14, kQualCentroid = 1u << 15,
  kQualSample = 1u << 16, kQualShared = 1u << 17,
};

struct Attribute {  // [unroll], [loop], [numthreads(8, 8, 1)]
  SourceLocation location;
  std::string name;
  std::vector<ExprPtr> arguments;
};

enum class ExprKind {
  kInt, kFloat, kBool, kString,  // literals
  kName,                         // a variable or function, possibly qualified ("A::b")
  kUnary,                        // prefix - + ! ~ ++ --
  kPostfix,                      // x++ x--
  kBinary, kAssign, kConditional, kSequence,
  kCall,       // name(arguments)
  kConstruct,  // float3(...)
  kCast,       // (float3)x
  kMember,     // x.rgb, s.field, m._m01
  kIndex,      // a[i]
  kInitList,   // { a, b, c }
};

struct Expr {
  ExprKind kind = ExprKind::kInt;
  SourceLocation location;
  Punct op = Punct::kNone;  // operator of kUnary/kPostfix/kBinary/kAssign
  std::string text;         // name, member, literal spelling, string value
  NumberLiteral number;     // kInt/kFloat
  bool boolean = false;     // kBool
  TypeSyntax type;          // kConstruct/kCast
  std::vector<ExprPtr> operands;

  // Filled by semantic analysis:
  Type resolved;                                  // the expression's type
  const VariableDecl* variable = nullptr;  // kName naming a variable
  const FunctionDecl* function = nullptr;  // kCall of a user function
  Intrinsic intrinsic = Intrinsic::kNone;         // kCall of an intrinsic (e.text spells it)
  std::vector<int> swizzle;                       // kMember swizzle: component indices (matrix: row * 4 + column)
  bool implicit = false;                          // kCast inserted by analysis (an implicit conversion)
  bool lvalue = false;
};

struct Annotation {  // < ui_min = 0.0; >
  SourceLocation location;
  std::string name;
  ExprPtr value;
};

struct StateAssignment {  // Key = Value; in object and pass blocks
  SourceLocation location;
  std::string name;
  ExprPtr value;
  std::vector<ExprPtr> thread_group;  // ComputeShader = Main<8, 8, 1>;
};

struct VariableDecl {
  SourceLocation location;
  unsigned qualifiers = 0;
  TypeSyntax type;
  std::string name;
  std::vector<ExprPtr> array_sizes;  // outermost first; null for an unsized dimension ("[]")
  std::string semantic;              // ": SV_Position", without the colon
  std::vector<Annotation> annotations;
  ExprPtr initializer;
  bool has_state_block = false;  // texture/sampler/storage { ... }
  std::vector<StateAssignment> states;

  Type resolved;  // filled by semantic analysis
};

enum class StmtKind {
  kEmpty, kExpression, kDeclaration, kBlock, kIf, kFor, kWhile, kDoWhile, kSwitch,
  kBreak, kContinue, kReturn, kDiscard,
};

struct SwitchCase {
  SourceLocation location;
  std::vector<ExprPtr> labels;  // empty with is_default for "default:"
  bool has_default = false;
  std::vector<StmtPtr> body;
};

struct Stmt {
  StmtKind kind = StmtKind::kEmpty;
  SourceLocation location;
  std::vector<Attribute> attributes;
  ExprPtr expression;  // condition, returned value, expression statement, switch selector
  StmtPtr init;        // for
  ExprPtr increment;   // for
  StmtPtr body;        // loops, if's then-branch
  StmtPtr else_body;
  std::vector<StmtPtr> statements;       // block
  std::vector<VariableDecl> variables;   // declaration
  std::vector<SwitchCase> cases;
};

struct FunctionDecl {
  SourceLocation location;
  unsigned qualifiers = 0;
  std::vector<Attribute> attributes;
  TypeSyntax return_type;
  std::string name;
  std::vector<VariableDecl> parameters;
  std::string return_semantic;
  StmtPtr body;  // null for a prototype

  Type resolved;  // the return type, filled by semantic analysis
};

struct StructDecl {
  SourceLocation location;
  std::string name;
  std::vector<VariableDecl> fields;
};

struct PassDecl {
  SourceLocation location;
  std::string name;  // may be empty
  std::vector<Annotation> annotations;
  std::vector<StateAssignment> states;
};

struct TechniqueDecl {
  SourceLocation location;
  std::string name;
  std::vector<Annotation> annotations;
  std::vector<PassDecl> passes;
};

enum class DeclKind { kVariables, kFunction, kStruct, kTechnique, kNamespace };

struct Decl {
  DeclKind kind = DeclKind::kVariables;
  SourceLocation location;
  std::vector<VariableDecl> variables;  // kVariables: one per declarator
  std::unique_ptr<FunctionDecl> function;
  std::unique_ptr<StructDecl> structure;
  std::unique_ptr<TechniqueDecl> technique;
  std::string namespace_name;  // kNamespace
  std::vector<DeclPtr> members;
};

struct TranslationUnit {
  std::vector<DeclPtr> declarations;
};

}  // namespace pfx::fx
