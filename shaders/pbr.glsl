// A glTF material (docs/pbr.md#the-scenes-lights), formula for formula as src/math/pbr.ts and src/software/lighting.ts:
// per light Ia⊙c_diff + π·f(l, v)⊙Id·(N·L), f = (1 − F)·c_diff/π + F·D·Vis where N·L > 0 and N·V > 0.
// The PBR variant's part of standard.frag, after lighting.glsl; in the chunk pbr-gl (render/pbr-gl.ts),
// fetched by the first frame with a glTF material.
uniform vec3 uBaseColor;
uniform vec3 uPbr; // metallic, roughness, unlit (1) or not (0)
// The maps besides the base colour (docs/gltf.md#drawing), white where a material has none: G roughness and B metallic, R
// occlusion (by uOcclusionStrength), the emission's colour.
uniform sampler2D uMetalRough;
uniform sampler2D uOcclusion;
uniform sampler2D uEmissiveMap;
uniform float uOcclusionStrength;
// Each texture's KHR_texture_transform as two rows (u' = row0·(u, v, 1), v' = row1·(u, v, 1)): the base colour's, the
// metallic-roughness map's, the occlusion map's, the emissive map's, the normal map's.
uniform vec3 uUvRows[10];

/** The UV texture i reads at the mesh's UV `uv`. */
vec2 moveUv(int i, vec2 uv) {
  vec3 p = vec3(uv, 1.0);
  return vec2(dot(uUvRows[2 * i], p), dot(uUvRows[2 * i + 1], p));
}

/** Where an image is read for texture i: at (u', 1 − v'). */
vec2 mapUv(int i, vec2 uv) {
  vec2 m = moveUv(i, uv);
  return vec2(m.x, 1.0 - m.y);
}

// s: metallic, roughness, occlusion (the factors times the maps).
void addPbrLight(vec3 l, vec3 ia, vec3 id, vec3 n, vec3 v, vec3 base, vec3 s, inout vec3 c) {
  // α = roughness² clamped to [0, 1], at least 0.002 under a point or directional light (punctualAlpha).
  float r = clamp(s.y, 0.0, 1.0);
  float alpha = max(r * r, 0.002);
  float metallic = s.x, a2 = alpha * alpha;
  vec3 cdiff = base * (1.0 - metallic);
  // Light from everywhere (the ambient term, the environment) is what occlusion dims.
  c += ia * cdiff * s.z;
  float nl = dot(n, l), nv = dot(n, v);
  if (nl <= 0.0 || nv <= 0.0) return;
  vec3 h = normalize(l + v);
  float nh = dot(n, h);
  // 1 − (n·h)² as |n × h|²: no cancellation near the lobe's peak, where α² is far below float's step at 1.
  vec3 nxh = cross(n, h);
  float q = dot(nxh, nxh) + nh * nh * a2;
  float d = nh > 0.0 ? a2 / (3.141592653589793 * q * q) : 0.0;
  float vis = 0.5 / (nl * sqrt(nv * nv * (1.0 - a2) + a2) + nv * sqrt(nl * nl * (1.0 - a2) + a2));
  vec3 f0 = vec3(0.04) * (1.0 - metallic) + base * metallic;
  float k = 1.0 - min(abs(dot(v, h)), 1.0);
  float k2 = k * k;
  vec3 fr = f0 + (1.0 - f0) * (k2 * k2 * k);
  c += 3.141592653589793 * id * nl * ((1.0 - fr) * cdiff / 3.141592653589793 + fr * (d * vis));
}

#ifdef NORMAL_MAP
uniform sampler2D uNormalMap;
uniform float uNormalScale; // 0 where the map's image is not in: the interpolated normal

/**
 * The interpolated normal n (unit, not yet turned to the viewer) perturbed by the normal map (docs/gltf.md#the-normal-map): the
 * tangent made orthogonal to it, the bitangent w·(n × t), normalize(x·T + y·B + z·N) for the texel's 2·RGB − 1 (x and y times
 * the scale); turned to the viewer as n would be. Without a tangent (a clustered copy in the reflection), n as it is.
 */
vec3 mappedNormal(vec3 n, vec4 t, vec2 uv, vec3 v) {
  vec3 tt = t.xyz - n * dot(n, t.xyz);
  float tl = length(tt);
  if (tl == 0.0) return facing(n, v);
  tt /= tl;
  vec3 b = (t.w < 0.0 ? -1.0 : 1.0) * cross(n, tt);
  vec3 m = mapRead(uNormalMap, mapUv(4, uv)).rgb * 2.0 - 1.0;
  m.xy *= uNormalScale;
  vec3 p = normalize(m.x * tt + m.y * b + m.z * n);
#ifdef TWO_SIDED
  if (dot(n, v) < 0.0) p = -p;
#endif
  return p;
}
#endif

#define ADD_PBR_LIGHT(i, point) addPbrLight(LIGHT_DIR(i, point), uLightAmbient[i], uLightDiffuse[i], n, v, base, s, c)

/**
 * The colour of a glTF material whose base colour (times its texture) is `base` and emission `e`, its maps read at the UV `uv`
 * (an image's: at (u, 1 − v)) where the mapping is uv; unlit: `base` + `e`.
 */
vec3 pbrColor(vec3 n, vec3 v, vec3 relPos, vec3 base, vec3 e, vec2 uv) {
  if (uPbr.z > 0.5) return base + e;
  vec3 s = vec3(uPbr.xy, 1.0);
#ifdef MAPPING_UV
  s *= vec3(mapRead(uMetalRough, mapUv(1, uv)).bg, 1.0);
  s.z = 1.0 + uOcclusionStrength * (mapRead(uOcclusion, mapUv(2, uv)).r - 1.0);
  e *= mapRead(uEmissiveMap, mapUv(3, uv)).rgb;
#endif
  vec3 c = e;
  ADD_PBR_LIGHT(0, LIGHT0_POINT);
#if LIGHT_COUNT > 1
  ADD_PBR_LIGHT(1, LIGHT1_POINT);
#endif
#if LIGHT_COUNT > 2
  ADD_PBR_LIGHT(2, LIGHT2_POINT);
#endif
#if LIGHT_COUNT > 3
  ADD_PBR_LIGHT(3, LIGHT3_POINT);
#endif
#ifdef ENVIRONMENT
  c += s.z * environmentLight(n, v, base, s.x, s.y);
#endif
  return c;
}
