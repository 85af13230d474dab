// Blinn-Phong of SPEC §3, shared by both stages (prepended after the #define lines):
// colour = k·(Ia + Id·max(N·L, 0)) + Ks·Is·max(N·H, 0)^n, specular only where N·L > 0.
precision highp float;
uniform vec3 uLightDirection;
uniform vec3 uLightIntensity;   // ambient, diffuse, specular
uniform vec2 uSpecular;         // Ks, shininess

/** x: the factor on the albedo ⊙ texture (ambient + diffuse); y: the white specular term. */
vec2 blinnPhong(vec3 n, vec3 v) {
  float nl = dot(n, uLightDirection);
  float specular = 0.0;
  if (nl > 0.0) {
    vec3 h = normalize(uLightDirection + v);
    specular = uSpecular.x * uLightIntensity.z * pow(max(dot(n, h), 0.0), uSpecular.y);
  }
  return vec2(uLightIntensity.x + uLightIntensity.y * max(nl, 0.0), specular);
}
