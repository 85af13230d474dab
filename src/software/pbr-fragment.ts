// A glTF material's fragment on the CPU (docs/gltf.md#drawing): the base colour times its texture, metallic and roughness
// times the metallic-roughness map's B and G, the occlusion map's R by its strength, the lights (lighting.ts pbrLights), and
// the emission times its map; each texture read through its KHR_texture_transform (docs/gltf.md#the-maps).
import { pbrLights, type Lights } from './lighting';
import type { PbrMaps } from './image-textures';
import type { MipTexture } from './mip-texture';
import { readMap, type PbrMaterial, type PbrTexture } from '../scene/pbr-material';
import type { Material } from '../scene/scene';

const texel = new Float64Array(3), surface = new Float64Array(3), base = new Float64Array(3), moved = new Float64Array(6);

/**
 * Into out[0..2], for g as pbrLights', `tex` the base colour texture `baseTexture`'s value and `color` the vertex colour; `lookup` is the fragment's UV
 * and its derivatives (the texture's lookup), null where the mapping is not `uv` (the maps are then not read: the factors
 * alone, and the base colour texture's transform not applied).
 */
export function pbrFragment(
  lights: Lights, material: Material, twoSided: boolean, g: Float64Array, baseTexture: MipTexture, tex: ArrayLike<number>,
  color: ArrayLike<number>, maps: PbrMaps, tangent: Float64Array, lookup: Float64Array | null, out: Float64Array,
): void {
  const pbr = material.pbr!, bc = pbr.baseColor;
  if (lookup !== null && readMap(pbr.baseColorTexture)?.transform) tex = sampleAt(baseTexture, pbr.baseColorTexture, lookup);
  // The vertex colour (white without) multiplies the base colour with its texture (docs/gltf.md#vertex-colours).
  base[0] = bc[0] * tex[0] * color[0]; base[1] = bc[1] * tex[1] * color[1]; base[2] = bc[2] * tex[2] * color[2];
  let metallic = pbr.metallic, roughness = pbr.roughness, occlusion = 1;
  if (lookup !== null && maps.metalRough !== null) {
    sampleAt(maps.metalRough, pbr.metallicRoughnessTexture, lookup);
    roughness *= texel[1];
    metallic *= texel[2];
  }
  if (lookup !== null && maps.occlusion !== null) occlusion = 1 + pbr.occlusionStrength * (sampleAt(maps.occlusion, pbr.occlusionTexture, lookup)[0] - 1);
  surface[0] = metallic; surface[1] = roughness; surface[2] = occlusion;
  // Stryker disable next-line ConditionalExpression,LogicalOperator: the object shader gives a tangent (w ≠ 0) only where the map is there, and a zero tangent turns nothing (n = normalize(z·N))
  if (lookup !== null && maps.normal !== null && tangent[3] !== 0) {
    mappedNormal(g, tangent, sampleAt(maps.normal, pbr.normalTexture, lookup), pbr.normalScale, twoSided);
    twoSided = false; // turned already, as the interpolated normal decided
  }
  pbrLights(lights, pbr, twoSided, g, base, surface, out);
  const e = material.emissive;
  if (e === undefined) return;
  if (lookup !== null && maps.emissive !== null) {
    sampleAt(maps.emissive, pbr.emissiveTexture, lookup);
    out[0] += e[0] * texel[0]; out[1] += e[1] * texel[1]; out[2] += e[2] * texel[2];
  } else {
    out[0] += e[0]; out[1] += e[1]; out[2] += e[2];
  }
}

/**
 * glTF's alpha mask (docs/gltf.md#alpha): whether the fragment is cut away — under alphaMode `mask`, the base colour's alpha
 * (its factor times its texture's alpha, read as the base colour is, where `lookup` is given) below the cutoff.
 */
export function maskedOut(pbr: PbrMaterial, maps: PbrMaps, lookup: Float64Array | null): boolean {
  if (pbr.alphaMode !== 'mask') return false;
  let a = pbr.baseColor[3];
  if (lookup !== null && maps.alpha !== null) a *= sampleAt(maps.alpha, pbr.baseColorTexture, lookup)[0];
  return a < pbr.alphaCutoff;
}

/**
 * The normal g[3..5] (the interpolated one, unit) perturbed by a normal map's texel `t` (docs/gltf.md#the-normal-map): the
 * tangent made orthogonal to it, the bitangent w·(N × T), normalize(x·T + y·B + z·N) for (x, y, z) = 2t − 1, x and y times
 * `scale`; turned to the viewer (g[6..8]) where `twoSided` and the interpolated normal faces away.
 */
function mappedNormal(g: Float64Array, tg: Float64Array, t: Float64Array, scale: number, twoSided: boolean): void {
  const nx = g[3], ny = g[4], nz = g[5];
  const d = tg[0] * nx + tg[1] * ny + tg[2] * nz;
  let tx = tg[0] - d * nx, ty = tg[1] - d * ny, tz = tg[2] - d * nz;
  const tl = Math.sqrt(tx * tx + ty * ty + tz * tz) || 1;
  tx /= tl; ty /= tl; tz /= tl;
  const w = tg[3], bx = w * (ny * tz - nz * ty), by = w * (nz * tx - nx * tz), bz = w * (nx * ty - ny * tx);
  const x = (2 * t[0] - 1) * scale, y = (2 * t[1] - 1) * scale, z = 2 * t[2] - 1;
  const mx = x * tx + y * bx + z * nx, my = x * ty + y * by + z * ny, mz = x * tz + y * bz + z * nz;
  // Stryker disable next-line EqualityOperator,ArithmeticOperator: at N·V = 0 exactly, turned or not lights nothing; a term's sign flipped — not tied down: the tests' double-sided views (front, behind, the tilted quad) keep N·V's sign whatever one term does (the GLSL's twin, browser mutation P31, is caught)
  const away = twoSided && nx * g[6] + ny * g[7] + nz * g[8] < 0;
  const ml = (away ? -1 : 1) / (Math.sqrt(mx * mx + my * my + mz * mz) || 1);
  g[3] = mx * ml; g[4] = my * ml; g[5] = mz * ml;
}

/** `t` at the lookup `l` ([u, v, ∂u/∂x, ∂v/∂x, ∂u/∂y, ∂v/∂y]) moved by the texture's transform `m` (u' = a·u + b·v + c, …): into texel. */
function sampleAt(t: MipTexture, map: PbrTexture | null, l: Float64Array): Float64Array {
  // Stryker disable next-line OptionalChaining: a map's texture is there only where the material names the map (image-textures.ts)
  const m = map?.transform;
  if (!m) {
    t.sample(l, texel);
    return texel;
  }
  moved[0] = m[0] * l[0] + m[1] * l[1] + m[2]; moved[1] = m[3] * l[0] + m[4] * l[1] + m[5];
  moved[2] = m[0] * l[2] + m[1] * l[3]; moved[3] = m[3] * l[2] + m[4] * l[3];
  moved[4] = m[0] * l[4] + m[1] * l[5]; moved[5] = m[3] * l[4] + m[4] * l[5];
  t.sample(moved, texel);
  return texel;
}
