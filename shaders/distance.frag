#version 300 es
// Rough glass (docs/rough-glass.md#the-gather): two layers per texel (frame/rough-glass.ts), from a pass's depth —
// the coverage c (1 where the pass drew a surface, 0 where only the background) into the alpha
// of its target (colour masked off), and c·u into the alpha of the codes beside it, u = h/(1 + h)
// the distance code, h = how far beyond the glass what the pass drew at this texel lies — the
// mirror image of a reflected surface, or a surface seen through the glass — from its depth
// unprojected by the eye-relative view-projection of the frame's camera (the mirrored pass's
// projection is that one times the plane's reflection, so the same inverse gives the mirror
// image). Mip-mapped, the two keep a near surface's code apart from the background around it.
precision highp float;

uniform highp sampler2D uDepth;
uniform highp mat4 uInverseViewProjection;
/** The far side's distance as a function of eye-relative points: h = dot(xyz, rel) + w. */
uniform highp vec4 uFarSide;

in vec2 vUv;
layout(location = 0) out vec4 outCoverage;
layout(location = 1) out vec4 outCodes;

void main() {
  float z = texelFetch(uDepth, ivec2(gl_FragCoord.xy), 0).r;
  float c = 0.0;
  float u = 0.0;
  if (z < 1.0) {
    vec4 p = uInverseViewProjection * vec4(vUv * 2.0 - 1.0, z * 2.0 - 1.0, 1.0);
    float h = max(0.0, dot(uFarSide.xyz, p.xyz / p.w) + uFarSide.w);
    c = 1.0;
    u = h / (1.0 + h);
  }
  outCoverage = vec4(0.0, 0.0, 0.0, c);
  outCodes = vec4(c * u);
}
