// A syntax error on line 3.
technique Syntax {
  pass { VertexShader = ; }
}
