// Blinn-Phong of docs/scene-model.md#lights (Ka, Kd, Ks; Ia, Id, Is), shared by both stages (prepended after the #defines):
// for each light, Ka⊙Ia + Kd⊙Id·max(N·L, 0) (which the texture multiplies) and
// Ks⊙Is·max(N·H, 0)^n (specular only where N·L > 0). Positions are eye-relative.
precision highp float;
#define MAX_LIGHTS 4
// LIGHT_COUNT (1..4) and LIGHTi_POINT (true/false) come with the variant: each light is written
// out with constant indices and a constant kind, so nothing is indexed or selected at run time
// (a loop over uniform arrays cost the default scene 40% on SwiftShader).
// Material textures are read through footprint.glsl's mapRead, which comes before.
uniform vec4 uLightVector[MAX_LIGHTS];   // a unit vector towards the light, or its eye-relative position
uniform vec3 uLightAmbient[MAX_LIGHTS];
uniform vec3 uLightDiffuse[MAX_LIGHTS];
uniform vec3 uLightSpecular[MAX_LIGHTS];
uniform vec3 uKa;
uniform vec3 uKd;
uniform vec3 uKs;
uniform float uShininess;
// V = normalize(xyz − w·relPos): (0, 0, 0, 1) for a perspective eye (towards the eye), or
// (towards the viewer, 0) for an orthographic one, whose view vector is constant (docs/interaction.md#orthographic-projection).
uniform vec4 uViewVector;

vec3 viewVector(vec3 relPos) {
  return normalize(uViewVector.xyz - uViewVector.w * relPos);
}

void addLight(vec3 l, vec3 ia, vec3 id, vec3 is, vec3 n, vec3 v, inout vec3 a, inout vec3 s) {
  float nl = dot(n, l);
  a += uKa * ia + uKd * id * max(nl, 0.0);
  if (nl > 0.0) s += uKs * is * pow(max(dot(n, normalize(l + v)), 0.0), uShininess);
}

#define LIGHT_DIR(i, point) ((point) ? normalize(uLightVector[i].xyz - relPos) : uLightVector[i].xyz)
#define ADD_LIGHT(i, point) addLight(LIGHT_DIR(i, point), uLightAmbient[i], uLightDiffuse[i], uLightSpecular[i], n, v, a, s)

/** `a`: the sum the texture multiplies (ambient + diffuse); `s`: the specular sum. */
void blinnPhong(vec3 n, vec3 v, vec3 relPos, out vec3 a, out vec3 s) {
  a = vec3(0.0);
  s = vec3(0.0);
  ADD_LIGHT(0, LIGHT0_POINT);
#if LIGHT_COUNT > 1
  ADD_LIGHT(1, LIGHT1_POINT);
#endif
#if LIGHT_COUNT > 2
  ADD_LIGHT(2, LIGHT2_POINT);
#endif
#if LIGHT_COUNT > 3
  ADD_LIGHT(3, LIGHT3_POINT);
#endif
}

/** Meshes from files are open and inconsistently wound: lit on the side facing the viewer. */
vec3 facing(vec3 n, vec3 v) {
#ifdef TWO_SIDED
  return dot(n, v) < 0.0 ? -n : n;
#else
  return n;
#endif
}

