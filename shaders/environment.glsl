// The environment's light on a glTF material (docs/pbr.md#the-environment), formula for formula as addEnvironment
// (src/math/environment-maps.ts): the split sum read from the prefiltered maps (a 2D array, one layer a level, each
// equirectangular) and the split-sum table. The ENVIRONMENT variant's part of standard.frag, before pbr.glsl; in the
// chunk environment (render/environment-gl.ts), fetched by the first frame with a glTF material and an environment.
uniform highp sampler2DArray uEnvironment;
uniform highp sampler2D uDfg;
uniform float uEnvironmentIntensity;

// The last level's index: eight levels, level k at roughness (k/7)² (math/prefilter.ts).
const float LAST_LEVEL = 7.0;

/** Level `layer` read toward the unit direction d: u from azimuth atan2(x, z) (−π at 0), v from the zenith. */
vec3 environmentRead(vec3 d, float layer) {
  vec2 uv = vec2(atan(d.x, d.z) / 6.283185307179586 + 0.5, acos(clamp(d.y, -1.0, 1.0)) / 3.141592653589793);
  return texture(uEnvironment, vec3(uv, layer)).rgb;
}

/** The two levels about √r·7, mixed. */
vec3 prefilteredAt(vec3 d, float roughness) {
  float p = sqrt(clamp(roughness, 0.0, 1.0)) * LAST_LEVEL;
  float k = min(LAST_LEVEL - 1.0, floor(p));
  return mix(environmentRead(d, k), environmentRead(d, k + 1.0), p - k);
}

vec3 environmentLight(vec3 n, vec3 v, vec3 base, float metallic, float roughness) {
  float nv = dot(n, v);
  if (nv <= 0.0) return vec3(0.0);
  float r = clamp(roughness, 0.0, 1.0), a = r * r, s = (1.0 - a) * (sqrt(1.0 - a) + a);
  // The lobe's dominant direction: the mirror direction drawn toward n by 1 − s (dominantDirection, math/split-sum.ts).
  vec3 mirror = reflect(-v, n);
  vec3 dominant = normalize(n + (mirror - n) * s);
  // The table's entries at texel centres: row by roughness, column by n·v, 32 of each (dfgCoordinate, math/dfg.ts).
  vec2 ab = texture(uDfg, (vec2(nv, r) * 31.0 + 0.5) / 32.0).rg;
  vec3 f0 = vec3(0.04) * (1.0 - metallic) + base * metallic;
  vec3 specular = prefilteredAt(dominant, r) * (f0 * ab.x + ab.y);
  vec3 diffuse = base * (1.0 - metallic) * (1.0 - f0) * prefilteredAt(n, 1.0);
  return uEnvironmentIntensity * (specular + diffuse);
}
