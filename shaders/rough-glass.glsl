// Rough glass (docs/rough-glass.md#the-gather), put into glass.frag for its ROUGH variant: R̃ and B̃ gathered as
// frame/rough-glass.ts says ("scatter as gather"), the same steps as software/rough-gather.ts.
// At the glass point P: the lobe's 2×2 map A = M·J from microfacet slope to texels of an image
// (M: texels per radian of the eye ray's turn along e1, e2; J: the ray's turn per unit slope),
// then rings doubling in radius around P's texel, each read at the mip level its spacing leaves.
// Each neighbour gives two parts: the surfaces it covers (coverage c in the image's alpha, their
// code u = cu/c from the codes' alpha, their colour the texel's less the background's share) and
// the background where it covers none; each part weighted by the share of the GGX lobe that lands
// on it at its own distance from the glass, dropped where its ray would pass P's own surface
// first, the background's also where the eye ray through its texel does not go to the glass's
// far side. Images: the reflection (mirror images, pass 1) and the frame beyond the glass, both
// drawn with the frame's camera, both mip-mapped with c and cu (software/rough-gather.ts alike).

uniform highp mat4 uViewProjection; // the frame's camera, eye-relative points → clip
uniform vec3 uGlassNormal;          // unit, on the viewer's side
uniform vec3 uForward;              // orthographic: the view direction
uniform float uOrthographic;         // 1: orthographic (the view direction is uForward)
uniform float uAlpha;               // GGX α = roughness²
uniform int uAngles;                // neighbours per ring
uniform float uLodBias;             // added to each ring's mip level
uniform vec3 uGatherJitter;         // refinement (docs/refinement.md#rough-glass): each sample's place in its sector (u, v), its level's shift
uniform vec4 uReflectionSize;       // texels: the image's size (xy), its storage's (zw)
uniform sampler2D uTransmission;    // the frame beyond the glass (when uTransmits is 1)
uniform vec4 uTransmissionSize;
uniform float uTransmits;           // 0: the glass lets nothing through
uniform sampler2D uReflectionCodes; // coverage × distance code (alpha), as large as the image
uniform sampler2D uTransmissionCodes;
uniform highp mat4 uInverseViewProjection; // the inverse of uViewProjection
uniform vec3 uBackground;           // the clear colour (linear light in srgb)
uniform float uFixedLevel;          // ≥ 0: the bench's comparison, the reflection at this level (FrameState.fixedBlurLevel)

/** A code at or above this is nothing (the background). */
const float ROUGH_NOTHING = 0.9999;
/** A neighbour farther than P's own surface by this ratio of scales… */
const float ROUGH_FARTHER = 1.05;
/** …is hidden by it where the surface its ray passes first is nearer than this ratio. */
const float ROUGH_HIDDEN = 0.9;
const float ROUGH_PI = 3.14159265358979;

// The pixel's frame, shared by both gathers (roughFrame): the unit view direction, e1 ⟂ it
// toward the viewer's side of the glass, e2 = d × e1, cosθ, the distance from the eye, P in NDC,
// and M in NDC per radian (row-major 2×2: x = ∂x/∂e1, y = ∂x/∂e2, z = ∂y/∂e1, w = ∂y/∂e2).
vec3 rD, rE1, rE2;
float rC, rL;
vec2 rQ;
vec4 rM;
bool rOk;

vec2 mul2(vec4 m, vec2 v) {
  return vec2(m.x * v.x + m.y * v.y, m.z * v.x + m.w * v.y);
}

vec4 mul22(vec4 a, vec4 b) {
  return vec4(a.x * b.x + a.y * b.z, a.x * b.y + a.y * b.w, a.z * b.x + a.w * b.z, a.z * b.y + a.w * b.w);
}

void roughFrame(vec3 rel) {
  vec3 n = uGlassNormal;
  rL = length(rel);
  rD = uOrthographic > 0.5 ? uForward : rel / rL;
  float dn = dot(rD, n);
  rC = max(-dn, 1e-6);
  vec3 e1 = n - dn * rD;
  // Head-on: any unit vector ⟂ d.
  if (length(e1) < 1e-5) e1 = abs(rD.x) < 0.9 ? vec3(0.0, -rD.z, rD.y) : vec3(rD.z, 0.0, -rD.x);
  rE1 = normalize(e1);
  rE2 = cross(rD, rE1);
  vec4 q = uViewProjection * vec4(rel, 1.0);
  rOk = q.w > 1e-9;
  rQ = q.xy / q.w;
  // The projection's differential: a turn by θ moves P's point by L·θ.
  vec4 a = uViewProjection * vec4(rE1 * rL, 0.0);
  vec4 b = uViewProjection * vec4(rE2 * rL, 0.0);
  vec2 ma = (a.xy - rQ * a.w) / q.w;
  vec2 mb = (b.xy - rQ * b.w) / q.w;
  rM = vec4(ma.x, mb.x, ma.y, mb.y);
}

/**
 * The lobe's scale at a texel of code u: how far across the image a turn of the ray moves what
 * it meets there, s/(L + s), s = h/cosθ; nothing: 1. Orthographic too, L then the distance from
 * the camera's point: s/(L + s)·L·θ is the exact s·θ while s ≪ L, and the background keeps a
 * finite scale the rings reach (with s itself and nothing at 1e6, as frame/rough-glass.ts has
 * it, the background's share of the lobe vanishes and any surface near a pixel takes its whole
 * lobe: the bench's floor at roughness 0.3 fell to 29.4 dB against 38.2 for the sharp frame;
 * 45.2 this way).
 */
float roughScale(float u) {
  if (u >= ROUGH_NOTHING) return 1.0;
  float s = u / (1.0 - u) / rC;
  return max(s / (rL + s), 1e-6);
}

/** Snell through the facet m into glass of index `ior`, and out through the face (normal n): ggx.ts's refractThin. */
bool refractThin(out vec3 o, vec3 d, vec3 m, vec3 n, float ior) {
  o = d;
  float c = dot(d, m);
  if (c >= 0.0) return false;
  float eta = 1.0 / ior;
  float k = 1.0 - eta * eta * (1.0 - c * c);
  if (k < 0.0) return false;
  vec3 t = eta * d - (eta * c + sqrt(k)) * m;
  c = dot(t, n);
  if (c >= 0.0) return false;
  k = 1.0 - ior * ior * (1.0 - c * c);
  if (k < 0.0) return false;
  o = ior * t - (ior * c + sqrt(k)) * n;
  return true;
}

/** The transmitted ray's turn along e1, e2 per unit slope along each's tangent of the glass, by differences. */
bool transmissionLobe(out vec4 J) {
  const float eps = 1e-3;
  vec3 n = uGlassNormal;
  J = vec4(0.0);
  for (int col = 0; col < 2; col++) {
    vec3 e = col == 0 ? rE1 : rE2;
    vec3 t = e - dot(e, n) * n;
    float lt = length(t);
    vec3 m = normalize(n + eps * (lt > 0.0 ? t / lt : t));
    vec3 dir;
    if (!refractThin(dir, rD, m, n, uIor)) return false;
    vec3 turn = (dir - rD) / eps;
    if (col == 0) { J.x = dot(turn, rE1); J.z = dot(turn, rE2); }
    else { J.y = dot(turn, rE1); J.w = dot(turn, rE2); }
  }
  return true;
}

/** Whether the eye ray through texel x of an image of `size` texels goes to the glass's far side. */
bool roughLeaves(vec2 x, vec2 size) {
  vec2 ndc = x / size * 2.0 - 1.0;
  vec4 a = uInverseViewProjection * vec4(ndc, -1.0, 1.0);
  vec4 b = uInverseViewProjection * vec4(ndc, 1.0, 1.0);
  return dot(b.xyz / b.w - a.xyz / a.w, uGlassNormal) < 0.0;
}

/** The mixed code cu + (1 − c) at uv, level `lod`: a surface's code, nothing's 1. */
float roughMixed(sampler2D image, sampler2D codes, vec2 uv, float lod) {
  return textureLod(codes, uv, lod).a + 1.0 - textureLod(image, uv, lod).a;
}

/** Σ w·colour and Σ w over the rings around P in `image` (`size` texels; its codes beside it), for the lobe J. */
vec4 roughGather(sampler2D image, sampler2D codes, vec4 sizes, vec4 J, bool clampColour) {
  vec2 size = sizes.xy, storage = sizes.zw;
  vec4 A = mul22(vec4(rM.xy * (0.5 * size.x), rM.zw * (0.5 * size.y)), J);
  float det = abs(A.x * A.w - A.y * A.z);
  if (!(det > 1e-12)) return vec4(0.0);
  float sq = dot(A, A);
  float smax = sqrt(0.5 * (sq + sqrt(max(0.0, sq * sq - 4.0 * det * det))));
  // roughRings(α, smax)
  float reach = ROUGH_REACH * uAlpha * smax / ROUGH_FIRST_RING;
  int rings = reach > 1.0 ? min(int(ceil(log2(reach))) + 1, ROUGH_MAX_RINGS) : 1;
  vec2 q = (rQ * 0.5 + 0.5) * size;
  float gq = roughScale(roughMixed(image, codes, q / storage, 0.0));
  // α² floored: a roughness whose square underflows gathers its centre alone, not NaN.
  float a2 = max(uAlpha * uAlpha, 1e-30);
  vec4 acc = vec4(0.0);
  for (int ring = -1; ring < ROUGH_MAX_RINGS; ring++) {
    if (ring >= rings) break;
    // The centre stands for the disc of radius ρ0/2; ring j ≥ 0 for ρ0·2^(j−1)..ρ0·2^j (the first from ρ0/2).
    float outer = ring < 0 ? 0.5 * ROUGH_FIRST_RING : ROUGH_FIRST_RING * exp2(float(ring));
    float inner = ring < 0 ? 0.0 : ring == 0 ? 0.5 * ROUGH_FIRST_RING : ROUGH_FIRST_RING * exp2(float(ring - 1));
    int count = ring < 0 ? 1 : uAngles;
    // Alone the sample lies mid-ring; a strata frame puts it at its share u of the sector's area.
    float mid = ring < 0 ? 0.0 : uGatherJitter.z == 0.0 ? 0.5 * (inner + outer) : sqrt(mix(inner * inner, outer * outer, uGatherJitter.x));
    float area = ROUGH_PI * (outer * outer - inner * inner) / float(count) * det / (smax * smax);
    float level = ring < 0 ? 0.0 : max(0.0, 0.5 * log2(area) + uLodBias + uGatherJitter.z);
    float xo = outer / smax, xi = inner / smax;
    for (int i = 0; i < count; i++) {
      float phi = 2.0 * ROUGH_PI * (float(i) + 0.5 * float(ring & 1) + uGatherJitter.y - 0.5) / float(count);
      vec2 delta = mul2(A, vec2(cos(phi), sin(phi)) * (mid / smax));
      vec2 uv = (q + delta) / storage;
      vec4 texel = textureLod(image, uv, level);
      // Clamped as an 8-bit target would: the reflection is what pass 1 shows, highlights included.
      vec3 rgb = clampColour ? min(texel.rgb, vec3(uCeiling)) : texel.rgb;
      float cover = texel.a;
      float cu = textureLod(codes, uv, level).a;
      // Two parts: the surfaces the sample covers, and the background where it covers none.
      for (int layer = 0; layer < 2; layer++) {
        float part = layer == 0 ? cover : 1.0 - cover;
        if (!(part > 1e-6)) continue;
        float g = 1.0;
        if (layer == 0) g = roughScale(cu / cover);
        // A ray turned toward the background must still leave on the far side (docs/rough-glass.md#the-gather drops
        // the rest): at grazing incidence much of the lobe would go beyond the horizon.
        else if (!roughLeaves(q + delta, size)) continue;
        if (ring >= 0 && g > ROUGH_FARTHER * gq) {
          // Hidden where the ray passes P's own surface first.
          float go = roughScale(roughMixed(image, codes, (q + delta * (gq / g)) / storage, level));
          if (go < ROUGH_HIDDEN * g) continue;
        }
        // The lobe's share of this part's piece of the ring: P(|slope| < x) = x²/(α² + x²),
        // written as differences of α²/(α² + x²) (no cancellation when both are near 1).
        float o = xo / g, ii = xi / g;
        float w = part * (a2 / (a2 + ii * ii) - a2 / (a2 + o * o)) / float(count);
        if (!(w > 0.0)) continue;
        // The surfaces' own colour: the sample's less the background's share of it.
        vec3 colour = layer == 0 ? (rgb - uBackground * (1.0 - cover)) / cover : uBackground;
        acc += w * vec4(colour, 1.0);
      }
    }
  }
  return acc;
}

/** R̃ at the glass point eye + rel (uv: its texel of the reflection); sets up the pixel's frame. */
vec3 roughReflection(vec3 rel, vec2 uv) {
  roughFrame(rel);
  // Clamped as an 8-bit target would: the reflection is what pass 1 shows, highlights included.
  vec3 sharp = min(textureLod(uReflection, uv * uReflectionSize.xy / uReflectionSize.zw, 0.0).rgb, vec3(uCeiling));
  if (!rOk) return sharp;
  if (uFixedLevel >= 0.0) {
    // The bench's comparison: the reflection at one level wherever the pixel is, no gather.
    return min(textureLod(uReflection, uv * uReflectionSize.xy / uReflectionSize.zw, uFixedLevel).rgb, vec3(uCeiling));
  }
  // A facet tilted by slope σ along the view's slope turns the mirrored ray by 2σ; across it by 2σ·cosθ.
  vec4 acc = roughGather(uReflection, uReflectionCodes, uReflectionSize, vec4(2.0, 0.0, 0.0, 2.0 * rC), true);
  return acc.a > 0.0 ? acc.rgb / acc.a : sharp;
}

/** B̃ at the pixel roughReflection set up (black when the glass lets nothing through; sharp for the bench's comparison). */
vec3 roughTransmission() {
  if (uTransmits < 0.5) return vec3(0.0);
  vec3 sharp = textureLod(uTransmission, (rQ * 0.5 + 0.5) * uTransmissionSize.xy / uTransmissionSize.zw, 0.0).rgb;
  vec4 J;
  // The bench's comparison leaves what is behind the glass sharp.
  if (!rOk || uFixedLevel >= 0.0 || !transmissionLobe(J)) return sharp;
  vec4 acc = roughGather(uTransmission, uTransmissionCodes, uTransmissionSize, J, false);
  return acc.a > 0.0 ? acc.rgb / acc.a : sharp;
}
