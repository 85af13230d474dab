// The float64 reference's own formulas: its glass mix, its clip, its shading, its sampler, its blend;
// then the modules it shares with the renderers (R8 on), which the software-vs-reference comparison
// cannot see, each caught by its own hand-computed test.
// Each: { name, edits: [{ file, find, replace }], tests: Playwright specs (*.spec.ts) or vitest files (*.test.ts) }.
const PIXELS = 'tests/unit/reference-pixels.test.ts';
const ANY = 'tests/unit/reference-any-scene.test.ts';
const SRGB = 'tests/unit/reference-srgb.test.ts';
const METRICS = 'tests/unit/reference-metrics.test.ts';
// The rough-glass reference and the microfacet maths it shares with the renderers (docs/rough-glass.md#reference-monte-carlo).
const ROUGH = ['tests/unit/reference-rough.test.ts', 'tests/unit/ggx.test.ts'];
const unit = (name) => `tests/unit/${name}.test.ts`;

export default [
  {
    name: 'R1 glass mix: T and 1 − T swapped',
    edits: [{ file: 'src/reference/shade.ts', find: ': f * r[k] + (1 - f) * (t * b[k] + (1 - t) * d);', replace: ': f * r[k] + (1 - f) * ((1 - t) * b[k] + t * d);' }],
    tests: [PIXELS],
  },
  {
    name: 'R2 classic glass: mix(R, D, F) for mix(D, R, F)',
    edits: [{ file: 'src/reference/shade.ts', find: '? (d + (r[k] - d) * f) * a + b[k] * (1 - a)', replace: '? (r[k] + (d - r[k]) * f) * a + b[k] * (1 - a)' }],
    tests: [PIXELS],
  },
  {
    name: 'R3 Fresnel cos θ = N·V without abs()',
    edits: [{
      file: 'src/reference/shade.ts',
      find: 'const c = Math.abs(n[0] * d[0] + n[1] * d[1] + n[2] * d[2]) / Math.hypot(d[0], d[1], d[2]);',
      replace: 'const c = (n[0] * d[0] + n[1] * d[1] + n[2] * d[2]) / Math.hypot(d[0], d[1], d[2]);',
    }],
    tests: [PIXELS],
  },
  {
    name: 'R4 Blinn-Phong half vector L − V',
    edits: [{ file: 'src/reference/shade.ts', find: 'const hx = lx + vx, hy = ly + vy, hz = lz + vz;', replace: 'const hx = lx - vx, hy = ly - vy, hz = lz - vz;' }],
    tests: [PIXELS],
  },
  {
    name: 'R5 mirrored pass keeps the far side of the glass (clip sign flipped)',
    edits: [{
      file: 'src/reference/clip.ts',
      find: 'return hit.t > tMin && visible(hit.t) && (clipSide === 0 || clipSide * signedDistance(plane!, hit.p) >= MIRROR_CONTACT);',
      replace: 'return hit.t > tMin && visible(hit.t) && (clipSide === 0 || clipSide * signedDistance(plane!, hit.p) <= -MIRROR_CONTACT);',
    }],
    tests: [PIXELS],
  },
  {
    name: 'R6 bilinear sampler: x and y weights swapped',
    edits: [{
      file: 'src/reference/texture-sampler.ts',
      find: '    return t00 + (t10 - t00) * x + (t01 - t00) * y + (t11 - t10 - t01 + t00) * x * y;',
      replace: '    return t00 + (t10 - t00) * y + (t01 - t00) * x + (t11 - t10 - t01 + t00) * x * y;',
    }],
    tests: [PIXELS],
  },
  {
    name: 'R7 transparency: colour·(1 − α) + behind·α',
    edits: [{ file: 'src/reference/sample-tracer.ts', find: 'out[k] = clamp01(out[k] * alpha + behind[k] * (1 - alpha));', replace: 'out[k] = clamp01(out[k] * (1 - alpha) + behind[k] * alpha);' }],
    tests: [ANY],
  },
  {
    name: 'R8 shared mapping.ts: spherical v flipped (v = 0 at the top pole)',
    edits: [{ file: 'src/scene/mapping.ts', find: 'Math.acos(Math.max(-1, Math.min(1, -ny)))', replace: 'Math.acos(Math.max(-1, Math.min(1, ny)))' }],
    tests: [unit('mapping')],
  },
  {
    name: 'R9 shared mapping.ts: triplanar sharpness 2 (the shader has 4)',
    edits: [{ file: 'src/scene/mapping.ts', find: 'export const TRIPLANAR_SHARPNESS = 4;', replace: 'export const TRIPLANAR_SHARPNESS = 2;' }],
    tests: [unit('mapping')],
  },
  {
    name: 'R10 shared fresnel.ts: Schlick\'s exponent 4',
    edits: [{ file: 'src/math/fresnel.ts', find: '(1 - clamp01(cosTheta)) ** 5', replace: '(1 - clamp01(cosTheta)) ** 4' }],
    tests: [unit('fresnel')],
  },
  {
    name: 'R11 shared glass-frame.ts: plane offset d = +n·c',
    edits: [{ file: 'src/scene/glass-frame.ts', find: 'plane: [nx, ny, nz, -(nx * cx + ny * cy + nz * cz)],', replace: 'plane: [nx, ny, nz, nx * cx + ny * cy + nz * cz],' }],
    tests: [unit('glass-frame')],
  },
  {
    name: 'R12 shared course-depth.ts: the far margin (×1.001) forgotten on the mirrored points',
    edits: [{ file: 'src/scene/course-depth.ts', find: 'far = Math.max(far, z * 1.001);', replace: 'far = Math.max(far, z);' }],
    tests: [unit('course-depth')],
  },
  {
    name: 'R13 image texels not decoded: srgb reads the stored level',
    edits: [{ file: 'src/reference/image-texture.ts', find: 'grey[j * w + i] = levels[data[(row + i) * 4 + c]];', replace: 'grey[j * w + i] = data[(row + i) * 4 + c] / 255;' }],
    tests: [SRGB],
  },
  {
    name: 'R14 the final encode missing: linear light written as the displayed value',
    edits: [{ file: 'src/reference/reference-renderer.ts', find: 'const c = encode ? linearToSrgb(mean) : mean;', replace: 'const c = mean;' }],
    tests: [SRGB],
  },
  {
    name: 'R15 the encode applied twice',
    edits: [{ file: 'src/reference/reference-renderer.ts', find: 'const c = encode ? linearToSrgb(mean) : mean;', replace: 'const c = encode ? linearToSrgb(linearToSrgb(mean)) : mean;' }],
    tests: [SRGB],
  },
  {
    name: 'R16 samples encoded one by one, then averaged',
    edits: [
      { file: 'src/reference/reference-renderer.ts', find: 'for (let k = 0; k < 3; k++) sum[k] += colour[k];', replace: 'for (let k = 0; k < 3; k++) sum[k] += encode ? linearToSrgb(colour[k]) : colour[k];' },
      { file: 'src/reference/reference-renderer.ts', find: 'const c = encode ? linearToSrgb(mean) : mean;', replace: 'const c = mean;' },
    ],
    tests: [SRGB],
  },
  {
    name: 'R17 the background (a CSS colour) not decoded',
    edits: [{ file: 'src/reference/sample-tracer.ts', find: "this.backgroundColour[k] = view.colorSpace === 'srgb' ? srgbToLinear(bg[k]) : bg[k];", replace: 'this.backgroundColour[k] = bg[k];' }],
    tests: [SRGB],
  },
  {
    name: 'R18 the fresnel view encoded like a picture',
    edits: [{ file: 'src/reference/reference-renderer.ts', find: "const encode = state.colorSpace === 'srgb' && state.view !== 'fresnel';", replace: "const encode = state.colorSpace === 'srgb';" }],
    tests: [SRGB],
  },
  {
    name: 'R19 procedural texels not decoded: its 200/255 read as 0.784 of light',
    edits: [{ file: 'src/reference/texture-sampler.ts', find: 'for (let i = 0; i < grey.length; i++) grey[i] = levels[rgba[i * 4]];', replace: 'for (let i = 0; i < grey.length; i++) grey[i] = rgba[i * 4] / 255;' }],
    tests: [SRGB],
  },
  {
    name: 'R20 image texels decoded after the box filter: the texture filtered as encoded numbers',
    edits: [
      { file: 'src/reference/image-texture.ts', find: 'grey[j * w + i] = levels[data[(row + i) * 4 + c]];', replace: 'grey[j * w + i] = data[(row + i) * 4 + c] / 255;' },
      { file: 'src/reference/surface-texture.ts', find: 'for (let k = 0; k < 3; k++) out[k] = channels[k].boxFilter(u, v, a[0], a[1], b[0], b[1]);', replace: "for (let k = 0; k < 3; k++) out[k] = decodeIf(this.colorSpace, channels[k].boxFilter(u, v, a[0], a[1], b[0], b[1]));" },
      { file: 'src/reference/surface-texture.ts', find: 'function bilinearInto(', replace: "const decodeIf = (s: string, c: number): number => (s === 'srgb' ? (c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4) : c);\nfunction bilinearInto(" },
    ],
    tests: [SRGB],
  },
  {
    name: "R21 metrics: 'dark' read from the reference's bytes, not its values",
    edits: [{ file: 'src/reference/metrics.ts', find: 'const dark = Math.max(ref.rgb[3 * i], ref.rgb[3 * i + 1], ref.rgb[3 * i + 2]) < DARK_LEVEL;', replace: 'const dark = Math.max(ref.rgba[4 * i], ref.rgba[4 * i + 1], ref.rgba[4 * i + 2]) < 32;' }],
    tests: [METRICS],
  },
  {
    name: 'R22 rough glass: the lobe width squared twice (α = roughness⁴)',
    edits: [{ file: 'src/math/ggx.ts', find: '  return r * r;\n}', replace: '  return r * r * r * r;\n}' }],
    tests: ROUGH,
  },
  {
    name: 'R23 rough glass: roughness ignored for the transmission (B̃ = B)',
    edits: [{ file: 'src/reference/rough-glass.ts', find: 'for (let pass = 0; pass < 2; pass++) {', replace: 'for (let pass = 0; pass < 1; pass++) {' }],
    tests: ROUGH,
  },
  {
    name: 'R24 rough glass: reflected samples into the far side kept',
    edits: [{ file: 'src/reference/rough-glass.ts', find: '          if (dir[0] * n[0] + dir[1] * n[1] + dir[2] * n[2] <= 0) continue;\n', replace: '' }],
    tests: ROUGH,
  },
  {
    name: 'R25 rough glass: dropped samples averaged in as black (sum ÷ all samples, not the kept ones)',
    edits: [{ file: 'src/reference/rough-glass.ts', find: 'for (let k = 0; k < 3; k++) out[k] = sum[k] / kept;', replace: 'for (let k = 0; k < 3; k++) out[k] = sum[k] / mf.count;' }],
    tests: ROUGH,
  },
  {
    name: 'R26 rough glass: ξ2 tied to ξ1 (the N-rooks pairing dropped: φm follows θm)',
    edits: [{ file: 'src/reference/microfacet-samples.ts', find: 'this.xi2[slot[i]] = (order[i] + next()) / m;', replace: 'this.xi2[slot[i]] = (i + next()) / m;' }],
    tests: ROUGH,
  },
  {
    name: 'R27 thin glass: the exit through the flat face skipped (the ray kept at its inside angle)',
    edits: [{ file: 'src/math/ggx.ts', find: '  return refract(out, out, n, ior);', replace: '  return true;' }],
    tests: ROUGH,
  },
];
