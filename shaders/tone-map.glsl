// Tone mapping (docs/pbr.md#tone-mapping), formula for formula as src/math/tone-map.ts: encode.frag's TONE_* variants take it
// after their #define, from the chunk pbr-gl (render/pbr-gl.ts). toneMap(c) of the exposed linear colour.
precision highp float;
uniform float uExposure;

#if defined(TONE_NEUTRAL)
// Khronos PBR Neutral.
vec3 toneMap(vec3 c) {
  float x = min(c.r, min(c.g, c.b));
  float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
  c -= offset;
  float peak = max(c.r, max(c.g, c.b));
  if (peak < 0.76) return c;
  float d = 1.0 - 0.76;
  float newPeak = 1.0 - d * d / (peak + d - 0.76);
  c *= newPeak / peak;
  float g = 1.0 - 1.0 / (0.15 * (peak - newPeak) + 1.0);
  return mix(c, vec3(newPeak), g);
}
#elif defined(TONE_ACES)
// Stephen Hill's fit of the ACES RRT and ODT (matrices by rows, as tone-map.ts writes them).
vec3 toneMap(vec3 c) {
  vec3 v = vec3(dot(vec3(0.59719, 0.35458, 0.04823), c), dot(vec3(0.07600, 0.90834, 0.01566), c), dot(vec3(0.02840, 0.13383, 0.83777), c));
  vec3 u = (v * (v + 0.0245786) - 0.000090537) / (v * (0.983729 * v + 0.432951) + 0.238081);
  vec3 o = vec3(dot(vec3(1.60475, -0.53108, -0.07367), u), dot(vec3(-0.10208, 1.10813, -0.00605), u), dot(vec3(-0.00327, -0.07276, 1.07602), u));
  return clamp(o, 0.0, 1.0);
}
#else
vec3 toneMap(vec3 c) {
  return c;
}
#endif
