// The split-sum table of docs/pbr.md#the-split-sum-table: for a view at n·v = μ and a roughness r (α = r²), the specular lobe of the
// glTF BRDF (math/pbr.ts, F by Schlick) over a white environment, ∫ F·D·V·(n·l) dω = F0·A + B, with
// A = ∫ (1 − Fc)·D·V·(n·l) dω and B = ∫ Fc·D·V·(n·l) dω, Fc = (1 − v·h)⁵. The renderers read it to light a
// metallic-roughness surface from a prefiltered environment; the reference integrates the BRDF itself.
// Tied down by tests/unit/dfg.test.ts (the albedos of pbr.test.ts at μ = 1, a quadrature over l elsewhere).

/**
 * Smith's height-correlated visibility, ½/((n·l)√((n·v)²(1 − α²) + α²) + (n·v)√((n·l)²(1 − α²) + α²)): smithVisibility of
 * math/pbr.ts written again (dfg.test.ts holds the two equal), so that the table's making (the environment's chunk) does
 * not share a module, and with it a chunk, with the CPU renderer's BRDF. Zero where n·l ≤ 0 (n·v is at least 10⁻⁴ here).
 */
function visibility(alpha: number, nl: number, nv: number): number {
  if (nl <= 0) return 0;
  const a2 = alpha * alpha;
  return 0.5 / (nl * Math.sqrt(nv * nv * (1 - a2) + a2) + nv * Math.sqrt(nl * nl * (1 - a2) + a2));
}

/** The table's visibility, for its test. */
export const dfgVisibility = visibility;

/** Samples per entry of the table: a Hammersley set over the GGX lobe. */
export const DFG_SAMPLES = 4096;

/** The i-th of n points of the Hammersley set: (i + ½)/n and the bits of i reversed. */
export function hammersley(i: number, n: number, out: Float64Array): void {
  let bits = i >>> 0;
  bits = ((bits << 16) | (bits >>> 16)) >>> 0;
  bits = (((bits & 0x55555555) << 1) | ((bits & 0xaaaaaaaa) >>> 1)) >>> 0;
  bits = (((bits & 0x33333333) << 2) | ((bits & 0xcccccccc) >>> 2)) >>> 0;
  bits = (((bits & 0x0f0f0f0f) << 4) | ((bits & 0xf0f0f0f0) >>> 4)) >>> 0;
  bits = (((bits & 0x00ff00ff) << 8) | ((bits & 0xff00ff00) >>> 8)) >>> 0;
  out[0] = (i + 0.5) / n;
  out[1] = bits / 4294967296;
}

const xi = new Float64Array(2);

/**
 * out = [A, B] at n·v = μ (clamped to [10⁻⁴, 1]) and roughness r (α = r², clamped; at least 10⁻⁴): h drawn with density
 * D(h)(n·h) from `samples` Hammersley points, l = v reflected about h, each weighing D·V·(n·l)/(D(n·h)/(4 v·h)) =
 * 4·V·(n·l)(v·h)/(n·h).
 */
export function dfg(out: Float64Array | number[], mu: number, roughness: number, samples = DFG_SAMPLES): Float64Array | number[] {
  const nv = Math.min(1, Math.max(1e-4, mu));
  const r = Math.min(1, Math.max(0, roughness));
  const alpha = Math.max(1e-4, r * r), a2 = alpha * alpha;
  // v in the xz-plane, n = +z.
  const vx = Math.sqrt(1 - nv * nv), vz = nv;
  let a = 0, b = 0;
  for (let i = 0; i < samples; i++) {
    hammersley(i, samples, xi);
    // GGX: cos²θh = (1 − ξ)/(1 + (α² − 1)ξ).
    const c2 = (1 - xi[0]) / (1 + (a2 - 1) * xi[0]);
    const nh = Math.sqrt(c2), sh = Math.sqrt(1 - c2), phi = 2 * Math.PI * xi[1];
    const hx = sh * Math.cos(phi), hz = nh;
    const vh = vx * hx + vz * hz;
    // Below the surface (n·l ≤ 0) V is 0 and the sample weighs nothing; v·h ≤ 0 puts l there.
    const nl = 2 * vh * hz - vz;
    const w = (4 * visibility(alpha, nl, nv) * nl * vh) / nh;
    const k = 1 - vh, fc = k * k * k * k * k;
    a += (1 - fc) * w;
    b += fc * w;
  }
  out[0] = a / samples;
  out[1] = b / samples;
  return out;
}

/** Entries per side of the table. */
export const DFG_SIZE = 32;

/**
 * The table: `size` × `size` pairs (A, B), row j at roughness j/(size − 1), column i at μ = i/(size − 1), so that the
 * first and last rows and columns hold r = 0 and 1, μ = 0 and 1 exactly (a texture reads them at texel centres:
 * dfgCoordinate).
 */
export function dfgTable(size = DFG_SIZE, samples = DFG_SAMPLES): Float32Array {
  const steps = dfgTableSteps(size, samples);
  for (;;) {
    const step = steps.next();
    if (step.done) return step.value;
  }
}

/** dfgTable a row at a time: each next() fills one roughness; the last returns the table. */
export function* dfgTableSteps(size = DFG_SIZE, samples = DFG_SAMPLES): Generator<void, Float32Array, void> {
  const t = new Float32Array(size * size * 2), ab = new Float64Array(2);
  for (let j = 0; j < size; j++) {
    for (let i = 0; i < size; i++) {
      dfg(ab, i / (size - 1), j / (size - 1), samples);
      t[2 * (j * size + i)] = ab[0];
      t[2 * (j * size + i) + 1] = ab[1];
    }
    yield;
  }
  return t;
}

/** The texture coordinate of x ∈ [0, 1] in a table of `size` entries whose first and last sit at x = 0 and 1: texel centres. */
export const dfgCoordinate = (x: number, size = DFG_SIZE): number => (Math.min(1, Math.max(0, x)) * (size - 1) + 0.5) / size;

/** out = [A, B] read from `table` at (μ, r), bilinear between its entries (as a linear texture read at dfgCoordinate). */
export function dfgLookup(out: Float64Array | number[], table: ArrayLike<number>, mu: number, roughness: number, size = DFG_SIZE): Float64Array | number[] {
  const x = Math.min(1, Math.max(0, mu)) * (size - 1), y = Math.min(1, Math.max(0, roughness)) * (size - 1);
  const i0 = Math.min(size - 2, Math.floor(x)), j0 = Math.min(size - 2, Math.floor(y));
  const fx = x - i0, fy = y - j0;
  for (let c = 0; c < 2; c++) {
    const t00 = table[2 * (j0 * size + i0) + c], t10 = table[2 * (j0 * size + i0 + 1) + c];
    const t01 = table[2 * ((j0 + 1) * size + i0) + c], t11 = table[2 * ((j0 + 1) * size + i0 + 1) + c];
    out[c] = (t00 * (1 - fx) + t10 * fx) * (1 - fy) + (t01 * (1 - fx) + t11 * fx) * fy;
  }
  return out;
}
