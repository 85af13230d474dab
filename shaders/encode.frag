#version 300 es
// The last step of a frame in linear light (docs/colour.md#eight-bit-targets): the frame, held in an SRGB8_ALPHA8 target
// (read back as linear), encoded once with the IEC 61966-2-1 curve (src/math/srgb.ts) into the
// canvas. Values above 1 clip first; a TONE_* variant (docs/pbr.md#tone-mapping) exposes and tone maps them before.
// COPY writes the frame as it is, linear and unclamped: refinement's average (docs/refinement.md#averaging).
precision highp float;

uniform sampler2D uSource;
#ifdef COPY
uniform float uScale;          // a factor on the copy: a share of refinement's mean (docs/refinement.md#averaging)
#endif
out vec4 outColor;

vec3 encode(vec3 l) {
  l = clamp(l, 0.0, 1.0);
  vec3 curve = 1.055 * pow(l, vec3(1.0 / 2.4)) - 0.055;
  return mix(curve, 12.92 * l, vec3(lessThanEqual(l, vec3(0.0031308))));
}

void main() {
  // Same size as the viewport: one texel per pixel, no filtering.
  vec3 c = texelFetch(uSource, ivec2(gl_FragCoord.xy), 0).rgb;
#ifdef COPY
  outColor = vec4(c * uScale, 1.0);
  return;
#endif
#if defined(TONE_NEUTRAL) || defined(TONE_ACES) || defined(TONE_NONE)
  c = toneMap(c * uExposure);
#endif
  outColor = vec4(encode(c), 1.0);
}
