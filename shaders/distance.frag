#version 300 es
// Rough glass (SPEC §14): the distance code u = h/(1 + h) of frame/rough-glass.ts, written into
// the alpha of a pass's target (colour masked off), h = how far beyond the glass what the pass
// drew at this texel lies — the mirror image of a reflected surface, or a surface seen through
// the glass — from its depth unprojected by the eye-relative view-projection of the frame's
// camera (the mirrored pass's projection is that one times the plane's reflection, so the same
// inverse gives the mirror image). u = 1 where nothing was drawn (the background).
precision highp float;

uniform highp sampler2D uDepth;
uniform highp mat4 uInverseViewProjection;
/** The far side's distance as a function of eye-relative points: h = dot(xyz, rel) + w. */
uniform highp vec4 uFarSide;

in vec2 vUv;
out vec4 outColor;

void main() {
  float z = texelFetch(uDepth, ivec2(gl_FragCoord.xy), 0).r;
  float u = 1.0;
  if (z < 1.0) {
    vec4 p = uInverseViewProjection * vec4(vUv * 2.0 - 1.0, z * 2.0 - 1.0, 1.0);
    float h = max(0.0, dot(uFarSide.xyz, p.xyz / p.w) + uFarSide.w);
    u = h / (1.0 + h);
  }
  outColor = vec4(0.0, 0.0, 0.0, u);
}
