#version 300 es
// colour = tex ⊙ Σ(Ka⊙Ia + Kd⊙Id·max(N·L, 0)) + Σ Ks⊙Is·(N·H)^n + E, alpha = opacity (a glTF material: pbrLights + E); the light sums
// come from blinnPhong (lighting.glsl), per fragment (phong), interpolated from the vertices
// (gouraud), or one per triangle (flat).
precision highp float;

uniform sampler2D uTexture;
uniform float uOpacity;
uniform vec3 uEmissive;        // light given off, added to the lit colour (docs/gltf.md#drawing)
uniform float uImageTexture;   // 1: an image, read at (u, 1 − v) (OBJ: v = 0 is its bottom row)
#ifndef MAPPING_UV
uniform vec4 uBounds;          // the object's bounding sphere (object space): centre, radius
#endif

in vec2 vUv;
#ifndef MAPPING_UV
in vec3 vObjPos;
in vec3 vObjNormal;
#endif
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
#ifdef NORMAL_MAP
in vec4 vTangent;
#endif
#ifdef VERTEX_COLORS
in vec3 vColor;
#endif
#ifdef ALPHA_MASK
uniform vec2 uAlphaMask;       // glTF's alpha mask (docs/gltf.md#alpha): the base colour factor's alpha, the cutoff
#endif

out vec4 outColor;

const float PI = 3.141592653589793;

vec3 tex(vec2 uv) {
  return mapRead(uTexture, uImageTexture > 0.5 ? vec2(uv.x, 1.0 - uv.y) : uv).rgb;
}

/** The texture mappings (one per variant, docs/scene-model.md#texture-mappings), formula for formula as src/scene/mapping.ts writes them. */
vec3 surfaceTexture() {
#if defined(MAPPING_UV)
  return tex(vUv);
#else
  float r = uBounds.w > 0.0 ? uBounds.w : 1.0;
  vec3 q = vObjPos - uBounds.xyz;
#if defined(MAPPING_TRIPLANAR)
  float len = length(vObjNormal);
  vec3 n = len > 0.0 ? abs(vObjNormal / len) : vec3(1.0);
  vec3 w = n * n * n * n; // TRIPLANAR_SHARPNESS = 4
  w /= (w.x + w.y + w.z);
  vec3 s = 0.5 + q / (2.0 * r);
  return w.x * tex(s.zy) + w.y * tex(s.xz) + w.z * tex(s.xy);
#else
  float u = 0.5 + atan(q.x, q.z) / (2.0 * PI);
#if defined(MAPPING_CYLINDRICAL)
  return tex(vec2(u, 0.5 + q.y / (2.0 * r)));
#else
  float len = length(q);
  float ny = len > 0.0 ? q.y / len : 0.0;
  return tex(vec2(u, acos(clamp(-ny, -1.0, 1.0)) / PI));
#endif
#endif
#endif
}

void main() {
#if defined(CLIP_PLANE) && !defined(CLIP_DISTANCE)
  if (vClipDistance < 0.0) discard;
#endif
#if defined(PBR)
#ifdef ALPHA_MASK
  // The base colour's alpha, its factor times its texture's (read as the base colour is) where the mapping is uv, against the cutoff.
#ifdef MAPPING_UV
  vec2 at = moveUv(0, vUv);
  float alpha = uAlphaMask.x * mapRead(uTexture, uImageTexture > 0.5 ? vec2(at.x, 1.0 - at.y) : at).a;
#else
  float alpha = uAlphaMask.x;
#endif
  if (alpha < uAlphaMask.y) discard;
#endif
  vec3 v = viewVector(vRelPos);
  // The texture is in the base colour, which also sets a metal's F0 (docs/pbr.md#the-scenes-lights).
#ifdef MAPPING_UV
  vec3 t = tex(moveUv(0, vUv)); // the base colour texture through its transform
#else
  vec3 t = surfaceTexture();
#endif
#ifdef VERTEX_COLORS
  t *= vColor;
#endif
#ifdef NORMAL_MAP
  vec3 n = mappedNormal(normalize(vNormal), vTangent, vUv, v);
#else
  vec3 n = facing(normalize(vNormal), v);
#endif
  outColor = vec4(pbrColor(n, v, vRelPos, uBaseColor * t, uEmissive, vUv), uOpacity);
#else
#if defined(SHADING_PHONG)
  vec3 v = viewVector(vRelPos);
  vec3 a, s;
  blinnPhong(facing(normalize(vNormal), v), v, vRelPos, a, s);
#else
  vec3 a = vLightA, s = vLightS;
#endif
  outColor = vec4(surfaceTexture() * a + s + uEmissive, uOpacity);
#endif
}
