#version 300 es
// Dark glass of docs/rendering.md#the-glass-equation: out = F·R + (1 − F)·(T·B + (1 − T)·D), premultiplied over pass 2.
// One of FRESNEL_EXACT / FRESNEL_SCHLICK / FRESNEL_CLASSIC; OUTPUT_FRESNEL writes F as grey.
// ROUGH (docs/rough-glass.md#the-gather): R and B become R̃ and B̃, gathered from mip-mapped images of the reflection
// and of the frame beyond the glass (rough-glass.glsl), and the glass is written opaque.
precision highp float;

uniform sampler2D uTexture;
uniform sampler2D uReflection;
uniform float uTransparency;
uniform float uIor;
uniform vec3 uBodyTint;         // tint ⊙ darkness
uniform vec4 uViewVector;       // V = normalize(xyz − w·relPos): perspective (0,0,0,1), orthographic (−forward, 0)
uniform float uLinearFrame;     // 1: the frame is in linear light, encoded at the end (docs/colour.md#the-transfer-curve)
uniform float uCeiling;         // what R is held to: 1 as an 8-bit target, a half float's largest in a tone-mapped frame (docs/pbr.md#tone-mapping)

in highp vec3 vRelPos;
in vec3 vNormal;
in vec2 vUv;
in highp vec4 vReflectionClip;

out vec4 outColor;

#ifdef ROUGH
// shaders/rough-glass.glsl replaces the next line (render/programs.ts); without it, ROUGH does not compile.
ROUGH_GATHER_SOURCE
#endif

float fresnel(float c) {
#if defined(FRESNEL_EXACT)
  // cosθt = √(n² − 1 + cos²θi)/n, exact for n = 1 (no 1 − cos² rounding at grazing incidence).
  float ct = sqrt(max(uIor * uIor - 1.0 + c * c, 0.0)) / uIor;
  float rs = (c - uIor * ct) / max(c + uIor * ct, 1e-30);
  float rp = (ct - uIor * c) / max(ct + uIor * c, 1e-30);
  return 0.5 * (rs * rs + rp * rp);
#elif defined(FRESNEL_SCHLICK)
  float r0 = (uIor - 1.0) / (uIor + 1.0);
  r0 *= r0;
  return r0 + (1.0 - r0) * pow(1.0 - c, 5.0);
#else
  return pow(1.0 - c, 3.0);
#endif
}

void main() {
  // Two-sided: |N·V|, clamped because a normalised dot can exceed 1 by an ulp.
  vec3 v = normalize(uViewVector.xyz - uViewVector.w * vRelPos);
  float c = clamp(abs(dot(normalize(vNormal), v)), 0.0, 1.0);
  float f = fresnel(c);
#ifdef OUTPUT_FRESNEL
  // F is a number, shown unencoded: in a linear frame it is written decoded, so the final
  // encode gives F back.
  float g = uLinearFrame > 0.5 ? (f <= 0.04045 ? f / 12.92 : pow((f + 0.055) / 1.055, 2.4)) : f;
  outColor = vec4(g, g, g, 1.0);
#else
  vec2 uv = vReflectionClip.xy / vReflectionClip.w * 0.5 + 0.5;
  // Clamped as an 8-bit target would: the reflection is what pass 1 shows, highlights included.
#ifdef ROUGH
  // R̃ and B̃ (B̃ only where the glass lets light through), each its sharp value where no
  // neighbour has weight; opaque over pass 2, which the glass covers.
  vec3 r = roughReflection(vRelPos, uv);
  vec3 b = roughTransmission();
#else
  vec3 r = min(texture(uReflection, uv).rgb, vec3(uCeiling));
#endif
  vec3 d = mapRead(uTexture, vUv).rgb * uBodyTint; // over the stratum in a strata frame (footprint.glsl)
#ifdef FRESNEL_CLASSIC
  // Classic, the original prototype's glass verbatim: colour = mix(D, R, F), alpha = (1 − T)(0.2 + 0.8F), straight alpha.
  float a = (1.0 - uTransparency) * (0.2 + 0.8 * f);
#ifdef ROUGH
  outColor = vec4(mix(d, r, f) * a + (1.0 - a) * b, 1.0);
#else
  outColor = vec4(mix(d, r, f) * a, a);
#endif
#elif defined(ROUGH)
  outColor = vec4(f * r + (1.0 - f) * (uTransparency * b + (1.0 - uTransparency) * d), 1.0);
#else
  outColor = vec4(f * r + (1.0 - f) * (1.0 - uTransparency) * d, 1.0 - (1.0 - f) * uTransparency);
#endif
#endif
}
