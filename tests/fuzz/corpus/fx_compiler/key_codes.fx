// Hand-written for the fuzz seeds: a table of key codes as headers define them, used in
// annotations, #if chains and token pasting.
#define KEY_BACKSPACE 0x08
#define KEY_TAB 0x09
#define KEY_ENTER 0x0D
#define KEY_SHIFT 0x10
#define KEY_CONTROL 0x11
#define KEY_ESCAPE 0x1B
#define KEY_SPACE 0x20
#define KEY_0 0x30
#define KEY_1 0x31
#define KEY_A 0x41
#define KEY_B 0x42
#define KEY_Z 0x5A
#define KEY_F1 0x70
#define KEY_F12 0x7B
#define KEY_NUMPAD(n) (0x60 + (n))
#define KEY_NAMED(name) KEY_##name
#ifndef TOGGLE_KEY
  #define TOGGLE_KEY KEY_NAMED(F12)
#endif
#if TOGGLE_KEY == KEY_F12 && KEY_NUMPAD(3) == 0x63
  #define TOGGLE_TEXT "F12"
#elif TOGGLE_KEY >= KEY_A && TOGGLE_KEY <= KEY_Z
  #define TOGGLE_TEXT "a letter"
#else
  #define TOGGLE_TEXT "another key"
#endif
uniform bool Toggle < source = "key"; keycode = TOGGLE_KEY; mode = "toggle"; ui_label = TOGGLE_TEXT; >;
uniform bool Held < source = "key"; keycode = KEY_NAMED(SHIFT); >;
uniform bool Pad < source = "key"; keycode = KEY_NUMPAD(7); >;
texture2D BackTex : COLOR;
sampler2D Back { Texture = BackTex; };
float4 PS(float4 p : SV_Position, float2 uv : TEXCOORD) : SV_Target {
  float4 c = tex2D(Back, uv);
  return Toggle ? 1.0 - c : (Held || Pad ? c.bgra : c);
}
void VS(uint id : SV_VertexID, out float4 p : SV_Position, out float2 uv : TEXCOORD) {
  uv = float2(id == 2 ? 2 : 0, id == 1 ? 2 : 0);
  p = float4(uv * float2(2, -2) + float2(-1, 1), 0, 1);
}
technique Keys < ui_tooltip = "toggled by " TOGGLE_TEXT; toggle = TOGGLE_KEY; > {
  pass { VertexShader = VS; PixelShader = PS; }
}
