// Blinn-Phong of SPEC §9 (seed 001's names), shared by both stages (prepended after the #defines):
// for each light, Ka⊙Ia + Kd⊙Id·max(N·L, 0) (which the texture multiplies) and
// Ks⊙Is·max(N·H, 0)^n (specular only where N·L > 0). Positions are eye-relative.
precision highp float;
precision highp int; // the default differs between stages, and uLightCount is in both
#define MAX_LIGHTS 4
uniform int uLightCount;
uniform vec4 uLightVector[MAX_LIGHTS];   // w 0: unit vector towards the light; w 1: its eye-relative position
uniform vec3 uLightAmbient[MAX_LIGHTS];
uniform vec3 uLightDiffuse[MAX_LIGHTS];
uniform vec3 uLightSpecular[MAX_LIGHTS];
uniform vec3 uKa;
uniform vec3 uKd;
uniform vec3 uKs;
uniform float uShininess;

/** `a`: the sum the texture multiplies (ambient + diffuse); `s`: the specular sum. */
void blinnPhong(vec3 n, vec3 v, vec3 relPos, out vec3 a, out vec3 s) {
  a = vec3(0.0);
  s = vec3(0.0);
  for (int i = 0; i < MAX_LIGHTS; i++) {
    if (i >= uLightCount) break;
    vec4 lv = uLightVector[i];
    vec3 l = lv.w > 0.5 ? normalize(lv.xyz - relPos) : lv.xyz;
    float nl = dot(n, l);
    a += uKa * uLightAmbient[i] + uKd * uLightDiffuse[i] * max(nl, 0.0);
    if (nl > 0.0) {
      vec3 h = normalize(l + v);
      s += uKs * uLightSpecular[i] * pow(max(dot(n, h), 0.0), uShininess);
    }
  }
}

/** Meshes from files are open and inconsistently wound: lit on the side facing the viewer. */
vec3 facing(vec3 n, vec3 v) {
#ifdef TWO_SIDED
  return dot(n, v) < 0.0 ? -n : n;
#else
  return n;
#endif
}
