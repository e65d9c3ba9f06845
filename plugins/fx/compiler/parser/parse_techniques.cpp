// technique Name < annotations > { pass Name { State = Value; ... } ... }
#include "parser.hpp"

namespace pfx::fx {

DeclPtr Parser::parse_technique() {
  auto declaration = std::make_unique<Decl>();
  declaration->kind = DeclKind::kTechnique;
  declaration->location = advance().location;
  declaration->technique = std::make_unique<TechniqueDecl>();
  TechniqueDecl& technique = *declaration->technique;
  technique.location = declaration->location;
  if (!expect_identifier(technique.name, "a technique name")) return nullptr;
  if (at(Punct::kLess) && !parse_annotations(technique.annotations)) return nullptr;
  if (!expect(Punct::kLeftBrace, "to open the technique")) return nullptr;
  while (!accept(Punct::kRightBrace)) {
    PassDecl pass;
    if (!parse_pass(pass)) return nullptr;
    technique.passes.push_back(std::move(pass));
  }
  return declaration;
}

bool Parser::parse_pass(PassDecl& pass) {
  pass.location = peek().location;
  if (!accept_word("pass")) return error_here("expected 'pass' or '}'"), false;
  if (peek().kind == TokenKind::kIdentifier) pass.name = advance().text;
  if (at(Punct::kLess) && !parse_annotations(pass.annotations)) return false;
  return parse_state_block(pass.states, true);
}

}  // namespace pfx::fx
