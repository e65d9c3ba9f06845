#pragma once
// The code generator's working parts, shared by its files: types and conversions
// (glsl_types.cpp), expressions (glsl_expressions.cpp), intrinsics (glsl_intrinsics.cpp),
// statements and functions (glsl_statements.cpp), uniform values as constants
// (glsl_constants.cpp). glsl_program.cpp puts a program together.
#include <functional>
#include <set>
#include <string>
#include <vector>

#include "../diagnostics.hpp"
#include "../model/effect_model.hpp"
#include "glsl_generator.hpp"
#include "glsl_names.hpp"

namespace pfx::fx {

enum class Stage { kVertex, kPixel, kCompute };

// GLSL's matrices hold floats only, so an int, uint or bool matrix is an array of its rows
// ("ivec3[2]" for int2x3): indexing and element access read and write it as HLSL does, and
// operators and conversions go row by row (glsl_types.cpp, glsl_expressions.cpp).
bool held_as_rows(const Type& t);
inline Type row_of(const Type& matrix) { return Type::vector(matrix.base, matrix.columns); }

class GlslWriter {
 public:
  GlslWriter(const EffectModel& model, const GlslNames& names, Diagnostics& diagnostics, Stage stage, GlslDialect dialect)
      : model_(model), names_(names), diagnostics_(diagnostics), stage_(stage), dialect_(dialect) {}

  // Types (glsl_types.cpp). `type` has no array dimensions; `full_type` adds them ("float[3]").
  std::string type(const Type& t) const;
  std::string full_type(const Type& t) const;
  std::string array_suffix(const Type& t) const;
  // `text`, of type `from`, as a value of type `to` with HLSL's conversion rules.
  std::string cast(const std::string& text, const Type& from, const Type& to);
  // A constructor call for `to` from a scalar repeated ("vec3(x)", a matrix filled with it).
  std::string splat(const std::string& scalar, const Type& to);
  // A matrix of type `result` computed row by row from matrices `a` and `b` of type `t`, each
  // held once (`row` gives a row of the result from a row of each); `b` may be empty for an
  // operator of one operand.
  std::string by_rows(const Type& t, const Type& result, const std::string& a, const std::string& b,
                      const std::function<std::string(const std::string&, const std::string&)>& row);

  // Expressions (glsl_expressions.cpp).
  std::string expr(const Expr& e);
  std::string init_list(const Expr& list, const Type& target);
  std::string name_of(const VariableDecl& variable) const;
  std::string literal(const Expr& e);

  // A variable of type `t` for a value the code must hold while it uses it more than once or
  // writes it back (an argument converted in and out, a matrix swizzle being stored to). The
  // enclosing function declares it at its top: take_temporaries() gives those declarations and
  // forgets them.
  std::string temporary(const Type& t);
  std::string take_temporaries(int indent);

  // Intrinsics (glsl_intrinsics.cpp).
  std::string intrinsic(const Expr& e);

  // Statements and functions (glsl_statements.cpp).
  void statement(const Stmt& s, int indent, std::string& out);
  void function(const FunctionDecl& f, std::string& out);
  void declaration(const VariableDecl& v, int indent, std::string& out);
  void line_directive(SourceLocation where, std::string& out);

  // What the written code used: helper functions of the prelude, discard.
  std::set<std::string> helpers;
  bool uses_discard = false;
  Stage stage() const { return stage_; }
  // Vulkan GLSL: FX's rows and GL's are the same way up there (glsl_generator.hpp).
  bool vulkan() const { return dialect_ == GlslDialect::kVulkan; }
  const EffectModel& model() const { return model_; }
  const GlslNames& names() const { return names_; }
  void error(SourceLocation where, const std::string& message) { diagnostics_.error(where, message); }

 private:
  std::string binary(const Expr& e);
  std::string unary(const Expr& e);
  std::string assignment(const Expr& e);
  std::string store(const Expr& target, const std::string& value);
  std::string member(const Expr& e);
  std::string call(const Expr& e);
  std::string construct(const Expr& e);
  std::string texture_call(const Expr& e);
  std::string with_hlsl_meaning(const Expr& e);
  std::string reinterpreted(const Expr& e, const std::string& value);
  std::string atomic(const Expr& e);
  std::string all_or_any(const std::string& name, const Type& t, const std::string& value);

  const EffectModel& model_;
  const GlslNames& names_;
  Diagnostics& diagnostics_;
  Stage stage_;
  GlslDialect dialect_;
  std::string temporary_declarations_;
  int temporary_count_ = 0;
};

// The GLSL helper functions a program needs, by the names GlslWriter::helpers holds.
std::string prelude(const std::set<std::string>& helpers, GlslDialect dialect);

// Uniform values as constants (glsl_constants.cpp; can_be_constant is in glsl_generator.hpp). The
// initialiser of such a constant ("vec2(0.5, 1.0)"), each component as the runtime would
// upload it.
std::string constant_initialiser(const GlslWriter& w, const Type& t, const std::vector<double>& values);

}  // namespace pfx::fx
