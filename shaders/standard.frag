#version 300 es
// colour = tex ⊙ Σ(Ka⊙Ia + Kd⊙Id·max(N·L, 0)) + Σ Ks⊙Is·(N·H)^n, alpha = opacity; the light sums
// come from blinnPhong (lighting.glsl), per fragment (phong), interpolated from the vertices
// (gouraud), or one per triangle (flat).
precision highp float;

uniform sampler2D uTexture;
uniform float uOpacity;
uniform float uImageTexture;   // 1: an image, read at (u, 1 − v) (OBJ: v = 0 is its bottom row)

in vec2 vUv;
#if defined(SHADING_PHONG)
in vec3 vRelPos;
in vec3 vNormal;
#elif defined(SHADING_FLAT)
flat in vec3 vLightA;
flat in vec3 vLightS;
#else
in vec3 vLightA;
in vec3 vLightS;
#endif
#if defined(CLIP_PLANE) && !defined(CLIP_DISTANCE)
in float vClipDistance;
#endif

out vec4 outColor;

void main() {
#if defined(CLIP_PLANE) && !defined(CLIP_DISTANCE)
  if (vClipDistance < 0.0) discard;
#endif
#if defined(SHADING_PHONG)
  vec3 v = normalize(-vRelPos);
  vec3 a, s;
  blinnPhong(facing(normalize(vNormal), v), v, vRelPos, a, s);
#else
  vec3 a = vLightA, s = vLightS;
#endif
  vec2 uv = uImageTexture > 0.5 ? vec2(vUv.x, 1.0 - vUv.y) : vUv;
  outColor = vec4(texture(uTexture, uv).rgb * a + s, uOpacity);
}
