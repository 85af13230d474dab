#version 300 es
// Ka = Kd = albedo ⊙ tex; the lighting factors come from blinnPhong (lighting.glsl),
// per fragment (phong), interpolated from the vertices (gouraud), or one per triangle (flat).
precision highp float;

uniform sampler2D uTexture;
uniform vec3 uAlbedo;

in vec2 vUv;
#if defined(SHADING_PHONG)
in vec3 vRelPos;
in vec3 vNormal;
#elif defined(SHADING_FLAT)
flat in vec2 vLight;
#else
in vec2 vLight;
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
  vec2 light = blinnPhong(normalize(vNormal), normalize(-vRelPos));
#else
  vec2 light = vLight;
#endif
  vec3 k = uAlbedo * texture(uTexture, vUv).rgb;
  outColor = vec4(k * light.x + light.y, 1.0);
}
