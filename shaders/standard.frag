#version 300 es
// Blinn-Phong of SPEC §3: Ka = Kd = albedo ⊙ tex; specular only where N·L > 0.
precision highp float;

uniform sampler2D uTexture;
uniform vec3 uAlbedo;
uniform vec3 uLightDirection;
uniform vec3 uLightIntensity;   // ambient, diffuse, specular
uniform vec2 uSpecular;         // Ks, shininess

in vec3 vRelPos;
in vec3 vNormal;
in vec2 vUv;
#if defined(CLIP_PLANE) && !defined(CLIP_DISTANCE)
in float vClipDistance;
#endif

out vec4 outColor;

void main() {
#if defined(CLIP_PLANE) && !defined(CLIP_DISTANCE)
  if (vClipDistance < 0.0) discard;
#endif
  vec3 n = normalize(vNormal);
  vec3 v = normalize(-vRelPos);
  vec3 k = uAlbedo * texture(uTexture, vUv).rgb;
  float nl = dot(n, uLightDirection);
  vec3 color = k * (uLightIntensity.x + uLightIntensity.y * max(nl, 0.0));
  if (nl > 0.0) {
    vec3 h = normalize(uLightDirection + v);
    color += uSpecular.x * uLightIntensity.z * pow(max(dot(n, h), 0.0), uSpecular.y);
  }
  outColor = vec4(color, 1.0);
}
