// The software renderer: raster, shading, glass, transparency.
// Each: { name, edits: [{ file, find, replace }], tests: Playwright specs (*.spec.ts) or vitest files (*.test.ts) }.
const RASTER = 'tests/unit/software-raster.test.ts';
const PIXELS = 'tests/unit/software-pixels.test.ts';
const GLASS = 'tests/unit/software-glass.test.ts';
const VS_REFERENCE = 'tests/unit/software-reference.test.ts';
const SRGB = 'tests/unit/software-srgb.test.ts';
const ANISO = 'tests/unit/software-anisotropic.test.ts';
const MSAA = 'tests/unit/software-msaa.test.ts';
const BASELINE = 'tests/unit/software-baseline.test.ts';
const CACHES = 'tests/unit/software-caches.test.ts';
const BANDS = 'tests/unit/software-bands.test.ts';
const BANDS_E2E = 'tests/e2e/software-bands.spec.ts';
const ELEMENT = 'tests/e2e/software.spec.ts';

export default [
  {
    name: 'S0 software rasterizer without the top-left rule',
    edits: [{
      file: 'src/software/edges.ts',
      find: "  e[9] = (ay0 === 0 && ax0 > 0) || ay0 < 0 ? 0 : -1;\n  e[10] = (ay1 === 0 && ax1 > 0) || ay1 < 0 ? 0 : -1;\n  e[11] = (ay2 === 0 && ax2 > 0) || ay2 < 0 ? 0 : -1;",
      replace: '  e[9] = 0;\n  e[10] = 0;\n  e[11] = 0;',
    }],
    tests: [RASTER],
  },
  {
    name: 'S1 depth test LEQUAL: of two equal depths the later wins',
    edits: [{ file: 'src/software/raster.ts', find: 'if (!depthTest || z < depth[pixel]) {', replace: 'if (!depthTest || z <= depth[pixel]) {' }],
    tests: [RASTER],
  },
  {
    name: 'S2 depth test reversed: the farther fragment wins',
    edits: [{ file: 'src/software/raster.ts', find: 'if (!depthTest || z < depth[pixel]) {', replace: 'if (!depthTest || z > depth[pixel]) {' }],
    tests: [RASTER],
  },
  {
    name: 'S3 perspective-correct interpolation dropped (screen-space barycentrics)',
    edits: [{ file: 'src/software/raster.ts', find: 'const a0 = l0 * this.w0, a1 = l1 * this.w1, a2 = (1 - l0 - l1) * this.w2;', replace: 'const a0 = l0, a1 = l1, a2 = 1 - l0 - l1;' }],
    tests: [RASTER],
  },
  {
    name: 'S4 Blinn-Phong half vector L − V',
    edits: [{ file: 'src/software/lighting.ts', find: 'const hx = lx + vx, hy = ly + vy, hz = lz + vz;', replace: 'const hx = lx - vx, hy = ly - vy, hz = lz - vz;' }],
    tests: [PIXELS],
  },
  {
    name: 'S5 specular exponent 4n (the course\'s Phong-to-Blinn conversion applied twice)',
    edits: [{ file: 'src/software/lighting.ts', find: 'const p = (nh > 0 ? nh : 0) ** m.shininess;', replace: 'const p = (nh > 0 ? nh : 0) ** (4 * m.shininess);' }],
    tests: [PIXELS],
  },
  {
    name: 'S6 glass: T and 1 − T swapped',
    edits: [{
      file: 'src/software/glass-shader.ts',
      find: 'const x = f * rk + (1 - f) * (t * out[o + k] + (1 - t) * d);',
      replace: 'const x = f * rk + (1 - f) * ((1 - t) * out[o + k] + t * d);',
    }],
    tests: [GLASS, VS_REFERENCE],
  },
  {
    name: 'S7 glass: F always from the exact model',
    edits: [{ file: 'src/software/glass-shader.ts', find: 'this.f = fresnel(this.model, this.cos, this.ior);', replace: "this.f = fresnel('exact', this.cos, this.ior);" }],
    tests: [GLASS, VS_REFERENCE],
  },
  {
    name: 'S8 glass: cos θ = N·V without abs() (from one side F = 1 everywhere)',
    edits: [{
      file: 'src/software/glass-shader.ts',
      find: 'const c = len > 0 ? Math.abs(this.nx * vx + this.ny * vy + this.nz * vz) / len : 1;',
      replace: 'const c = len > 0 ? (this.nx * vx + this.ny * vy + this.nz * vz) / len : 1;',
    }],
    tests: [GLASS],
  },
  {
    name: 'S9 classic glass: alpha T·(0.2 + 0.8F) for (1 − T)·(…)',
    edits: [{ file: 'src/software/glass-shader.ts', find: 'const a = (1 - t) * (0.2 + 0.8 * f);', replace: 'const a = t * (0.2 + 0.8 * f);' }],
    tests: [GLASS],
  },
  {
    name: 'S10 transparency: colour·kt + framebuffer·(1 − kt)',
    edits: [{
      file: 'src/software/object-shader.ts',
      find: '      c[o] = this.cr * a + c[o] * (1 - a);\n      c[o + 1] = this.cg * a + c[o + 1] * (1 - a);\n      c[o + 2] = this.cb * a + c[o + 2] * (1 - a);',
      replace: '      c[o] = this.cr * (1 - a) + c[o] * a;\n      c[o + 1] = this.cg * (1 - a) + c[o + 1] * a;\n      c[o + 2] = this.cb * (1 - a) + c[o + 2] * a;',
    }],
    tests: [PIXELS],
  },
  {
    name: 'S11 mip level from log2 ρ² (one level too blurred)',
    edits: [{ file: 'src/software/mip-texture.ts', find: 'const lambda = rho2 > 1 ? 0.5 * Math.log2(rho2) : 0;', replace: 'const lambda = rho2 > 1 ? Math.log2(rho2) : 0;' }],
    tests: [VS_REFERENCE],
  },
  {
    name: 'S12 the software renderer sizes spheres as if in perspective in an orthographic view (its half-height dropped)',
    edits: [{ file: 'src/software/software-renderer.ts', find: 'm.center, m.radius, s.halfHeight, this.pixelScale', replace: 'm.center, m.radius, 0, this.pixelScale' }],
    tests: ['tests/unit/mesh-choice.test.ts'],
  },
  {
    name: 'S13 srgb: an image texture\'s texels used as stored (not decoded)',
    edits: [{
      file: 'src/software/mip-texture.ts',
      find: 'const rgb = new Float32Array(w * h * 3), level = byteTable(space);',
      replace: "const rgb = new Float32Array(w * h * 3), level = byteTable('none');",
    }],
    tests: [SRGB],
  },
  {
    name: 'S14 srgb: the procedural texture\'s texels used as stored (not decoded)',
    edits: [{ file: 'src/software/mip-texture.ts', find: 'const rgba = proceduralTexture(), level = byteTable(space);', replace: "const rgba = proceduralTexture(), level = byteTable('none');" }],
    tests: [SRGB],
  },
  {
    name: 'S15 srgb: the final encode missing (linear light written to the bytes)',
    edits: [{ file: 'src/software/software-renderer.ts', find: 'width, bottom - top, n, encodesAtEnd(state));', replace: 'width, bottom - top, n, false);' }],
    tests: [SRGB],
  },
  {
    name: 'S16 srgb: the fresnel view encoded like a picture',
    edits: [{ file: 'src/frame/linear-light.ts', find: "export const encodesAtEnd = (state: Pick<FrameState, 'colorSpace' | 'view'>): boolean =>\n  state.colorSpace === 'srgb' && state.view !== 'fresnel';", replace: "export const encodesAtEnd = (state: Pick<FrameState, 'colorSpace' | 'view'>): boolean =>\n  state.colorSpace === 'srgb';" }],
    tests: [SRGB],
  },
  {
    name: 'S17 srgb: each sample encoded, then the box filter (averaging encoded values)',
    edits: [
      {
        file: 'src/software/encode.ts',
        find: 'r += source[o]; g += source[o + 1]; b += source[o + 2];',
        replace: 'r += encode ? encodeByte(source[o]) / 255 : source[o]; g += encode ? encodeByte(source[o + 1]) / 255 : source[o + 1]; b += encode ? encodeByte(source[o + 2]) / 255 : source[o + 2];',
      },
      {
        file: 'src/software/encode.ts',
        find: 'out[p] = encode ? encodeByte(r * mean) : Math.round(r * k);\n      out[p + 1] = encode ? encodeByte(g * mean) : Math.round(g * k);\n      out[p + 2] = encode ? encodeByte(b * mean) : Math.round(b * k);',
        replace: 'out[p] = Math.round(r * k);\n      out[p + 1] = Math.round(g * k);\n      out[p + 2] = Math.round(b * k);',
      },
    ],
    tests: [SRGB],
  },
  {
    name: 'S18 srgb: the background used as stored (not decoded)',
    edits: [{ file: 'src/software/software-renderer.ts', find: "b[k] = space === 'srgb' ? srgbToLinear(bg[k]) : bg[k];", replace: 'b[k] = bg[k];' }],
    tests: [SRGB],
  },
  {
    name: 'S19 srgb: colour held as 8-bit linear levels (the opaque write rounded to 1/255)',
    edits: [{
      file: 'src/software/object-shader.ts',
      find: 'c[o] = this.cr; c[o + 1] = this.cg; c[o + 2] = this.cb;',
      replace: 'c[o] = Math.round(this.cr * 255) / 255; c[o + 1] = Math.round(this.cg * 255) / 255; c[o + 2] = Math.round(this.cb * 255) / 255;',
    }],
    tests: [SRGB],
  },
  {
    name: 'S20 srgb: the background encoded instead of decoded (a doubled encode)',
    edits: [
      { file: 'src/software/software-renderer.ts', find: "import { srgbToLinear, type ColorSpace } from '../math/srgb';", replace: "import { linearToSrgb, srgbToLinear, type ColorSpace } from '../math/srgb';" },
      { file: 'src/software/software-renderer.ts', find: "b[k] = space === 'srgb' ? srgbToLinear(bg[k]) : bg[k];", replace: "b[k] = space === 'srgb' ? linearToSrgb(bg[k]) : bg[k];" },
    ],
    tests: [SRGB],
  },
  {
    name: 'S21 srgb: the encode table with 2048 bins (two steps share a bin in the darks)',
    edits: [{ file: 'src/software/encode.ts', find: 'export const ENCODE_BINS = 4096;', replace: 'export const ENCODE_BINS = 2048;' }],
    tests: [SRGB],
  },
  {
    name: 'S22 srgb: the encode table compares with > (a value exactly at a step rounds down)',
    edits: [{ file: 'src/software/encode.ts', find: 'return l >= NEXT[b] ? b + 1 : b;', replace: 'return l > NEXT[b] ? b + 1 : b;' }],
    tests: [SRGB],
  },
  {
    name: 'S23 anisotropic taps spread along the minor axis instead of the major',
    edits: [{ file: 'src/software/mip-texture.ts', find: 'if (px2 >= py2) { au = dux; av = dvx; } else { au = duy; av = dvy; }', replace: 'if (px2 < py2) { au = dux; av = dvx; } else { au = duy; av = dvy; }' }],
    tests: [ANISO],
  },
  {
    name: 'S24 anisotropic taps read at the level of Pmax, not Pmax / r (the footprint\'s length, not its width)',
    edits: [{ file: 'src/software/mip-texture.ts', find: '        rho2 /= r * r;\n', replace: '' }],
    tests: [ANISO],
  },
  {
    name: 'S25 anisotropic reads with color-space none too (its frames no longer what they were)',
    edits: [
      { file: 'src/software/mip-texture.ts', find: "return (procedural[space] = new MipTexture(1, n, n, grey, space === 'srgb'));", replace: 'return (procedural[space] = new MipTexture(1, n, n, grey, true));' },
      { file: 'src/software/mip-texture.ts', find: "return new MipTexture(3, w, h, rgb, space === 'srgb');", replace: 'return new MipTexture(3, w, h, rgb, true);' },
    ],
    tests: [ANISO],
  },
  {
    name: 'S26 multisampling: the frame state\'s samples ignored (one sample per pixel)',
    edits: [{ file: 'src/software/software-renderer.ts', find: 'const msaa = ssaa === 1 && state.samples >= 2 ? 2 : 1;', replace: 'const msaa = 1;' }],
    tests: [MSAA],
  },
  {
    name: 'S27 multisampling: shaded at the pixel\'s first covered sample, not its centre',
    edits: [{ file: 'src/software/raster.ts', find: 'const h = (n - 1) / 2;', replace: 'const h = 0;' }],
    tests: [MSAA],
  },
  {
    name: 'S28 multisampling: derivatives per sample (textures read one level too sharp)',
    edits: [{ file: 'src/software/raster.ts', find: 'this.interpolate(i, j, k, inv, n * stepX0, n * stepX1, n * stepX2, n * stepY0, n * stepY1, n * stepY2);', replace: 'this.interpolate(i, j, k, inv, stepX0, stepX1, stepX2, stepY0, stepY1, stepY2);' }],
    tests: [MSAA],
  },
  {
    name: 'S29 multisampling: a pixel\'s other samples not written (only the shaded one)',
    edits: [{ file: 'src/software/raster.ts', find: '              shader.repeat!(sample);\n', replace: '' }],
    tests: [MSAA],
  },
  {
    name: 'S30 multisampling: depth per pixel (a pixel\'s first sample decides for all of them)',
    edits: [{ file: 'src/software/raster.ts', find: '            if (depthTest && !(z < depth[sample])) continue;', replace: '            if (depthTest && !(z < depth[sample - (sample % width % n) - ((sample / width | 0) % n) * width])) continue;' }],
    tests: [MSAA],
  },
  {
    name: 'S31 multisampling: the glass footprint marks only a pixel\'s shaded sample (no reflection at the others)',
    edits: [{ file: 'src/software/glass-shader.ts', find: "    if (mode === 'mask') {\n      this.mask[sample] = 1;\n      return;\n    }", replace: "    if (mode === 'mask') return;" }],
    tests: [MSAA],
  },
  {
    name: 'S32 orthographic: the glass\'s F from the eye point (the view vector ignored)',
    edits: [{ file: 'src/software/glass-shader.ts', find: 'const v = this.view, vx = v[3] === 0 ? v[0] : rx,', replace: 'const v = [0, 0, 0, 1], vx = v[3] === 0 ? v[0] : rx,' }],
    tests: [VS_REFERENCE],
  },
  {
    name: 'S33 orthographic: highlights seen from the eye point (the view vector ignored)',
    edits: [{ file: 'src/software/object-shader.ts', find: "if (ov[3] === 0) { g[6] = ov[0]; g[7] = ov[1]; g[8] = ov[2]; } else {", replace: "if (ov[3] === 2) { g[6] = ov[0]; g[7] = ov[1]; g[8] = ov[2]; } else {" }],
    tests: [VS_REFERENCE],
  },
  {
    name: 'S34 glass cache: entries kept when the camera moves (the vertices not in the key)',
    edits: [{ file: 'src/software/glass-shader.ts', find: '    k.set(this.vertices);\n', replace: '' }],
    tests: [BASELINE],
  },
  {
    name: 'S35 glass cache: entries kept when ior changes',
    edits: [{ file: 'src/software/glass-shader.ts', find: 'k[i++] = this.ior;', replace: 'k[i++] = 1.5;' }],
    tests: [BASELINE],
  },
  {
    name: 'S36 glass cache: entries kept when the Fresnel model changes',
    edits: [{ file: 'src/software/glass-shader.ts', find: 'o.push(this.model, this.texture, this.mode);', replace: 'o.push(this.texture, this.mode);' }],
    tests: [BASELINE],
  },
  {
    name: 'S37 glass cache: a new key starts no new generation (every entry still read)',
    edits: [{ file: 'src/software/glass-cache.ts', find: '    this.generation++;\n', replace: '' }],
    tests: [BASELINE, CACHES],
  },
  {
    name: 'S38 glass cache: an entry read whichever sample of its pixel wrote it (multisampled diagonal)',
    edits: [{ file: 'src/software/glass-cache.ts', find: 'return this.stamp[i] === this.generation && this.slot[i] === slot;', replace: 'return this.stamp[i] === this.generation;' }],
    tests: [BASELINE, CACHES],
  },
  {
    name: 'S43 glass cache: −0 and 0 taken for the same key value',
    edits: [{ file: 'src/software/glass-cache.ts', find: 'a === b && (a !== 0 || 1 / a === 1 / b)', replace: 'a === b' }],
    tests: [CACHES],
  },
  {
    name: 'S39 glass: a pixel the cache lacks shaded with the last computed barycentrics (perspective() not called)',
    edits: [{ file: 'src/software/glass-shader.ts', find: '    if (!r.barycentrics) r.perspective();\n', replace: '' }],
    tests: [BASELINE],
  },
  {
    name: 'S40 packed sRGB resolve: red and blue swapped',
    edits: [{ file: 'src/software/encode.ts', find: 'packed[i] = encodeByte(source[o]) | (encodeByte(source[o + 1]) << 8) | (encodeByte(source[o + 2]) << 16) | OPAQUE;', replace: 'packed[i] = encodeByte(source[o + 2]) | (encodeByte(source[o + 1]) << 8) | (encodeByte(source[o]) << 16) | OPAQUE;' }],
    tests: [SRGB, BASELINE],
  },
  {
    name: 'S41 packed sRGB resolve: alpha 0',
    edits: [{ file: 'src/software/encode.ts', find: 'const OPAQUE = 0xff000000 | 0;', replace: 'const OPAQUE = 0;' }],
    tests: [SRGB, BASELINE],
  },
  {
    name: 'S42 RGB texture: green read as red (the taps\' sums mixed up)',
    edits: [{ file: 'src/software/mip-texture.ts', find: 'out[1] = grey ? r : g;', replace: 'out[1] = r;' }],
    tests: [VS_REFERENCE],
  },
  {
    name: 'S44 object cache: entries kept when the object moves (the model matrix not in the key)',
    edits: [{ file: 'src/software/object-shader.ts', find: 'let i = put(k, 0, d.model, 16);', replace: 'let i = 16;' }],
    tests: [BASELINE],
  },
  {
    name: 'S45 object cache: entries kept when the lights change',
    edits: [{ file: 'src/software/object-shader.ts', find: '    for (let j = 0; j < l.count; j++) {\n      i = put(k, i, l.vector.subarray(3 * j), 3);', replace: '    for (let j = 0; j < 0; j++) {\n      i = put(k, i, l.vector.subarray(3 * j), 3);' }],
    tests: [BASELINE],
  },
  {
    name: 'S46 object cache: entries kept when the material\'s diffuse colour changes',
    edits: [{ file: 'src/software/object-shader.ts', find: 'i = put(k, i, m.diffuse, 3);', replace: 'i += 3;' }],
    tests: [BASELINE],
  },
  {
    name: 'S47 object cache: entries kept when the mapping\'s bounds change',
    edits: [{ file: 'src/software/object-shader.ts', find: 'k[i++] = c[0]; k[i++] = c[1]; k[i++] = c[2]; k[i++] = d.bounds.radius;', replace: 'k[i++] = c[0]; k[i++] = c[1]; k[i++] = c[2]; k[i++] = 0;' }],
    tests: [BASELINE],
  },
  {
    name: 'S48 object cache: an entry read by any triangle of its draw',
    edits: [{ file: 'src/software/object-cache.ts', find: 'return this.current !== 0 && this.version[i] === this.current && this.face[i] === face;', replace: 'return this.current !== 0 && this.version[i] === this.current;' }],
    tests: [BASELINE, CACHES],
  },
  {
    name: 'S49 object cache: a multisampled pixel\'s entry shared by its whole column (the row left out)',
    edits: [{ file: 'src/software/raster.ts', find: 'return ((y / n) | 0) * (W / n) + ((x / n) | 0);', replace: 'return (x / n) | 0;' }],
    tests: [BASELINE],
  },
  {
    name: 'S50 object cache: a changed draw read and kept at once (its version not new)',
    edits: [{ file: 'src/software/object-cache.ts', find: '      this.versions[index] = this.nextVersion++;\n      return;\n', replace: '' }],
    tests: [BASELINE, CACHES],
  },
  {
    name: 'S52 rasterizer: a 1-sample fragment keeps the last one\'s screen barycentrics (perspective() reads them)',
    edits: [{ file: 'src/software/raster.ts', find: '              this.l0 = l0; this.l1 = l1; this.z = z;', replace: '              this.z = z;' }],
    tests: [BASELINE],
  },
  {
    name: 'S51 glass cache: read and kept in the frame its key changes (the frame before wrote under another key)',
    edits: [{ file: 'src/software/glass-cache.ts', find: '    this.active = same;\n', replace: '    this.active = true;\n' }],
    tests: [BASELINE, CACHES],
  },
  {
    name: 'S53 bands: a row between two bands drawn by neither (each band starts one row late)',
    edits: [{ file: 'src/software/bands.ts', find: '    top = bottom;\n', replace: '    top = bottom + 1;\n' }],
    tests: [BANDS],
  },
  {
    name: 'S54 bands: the last band dropped (the frame cut into one band fewer than workers)',
    edits: [{ file: 'src/software/bands.ts', find: '  for (let i = 0; i < count; i++) {\n    acc +=', replace: '  for (let i = 0; i < count - 1; i++) {\n    acc +=' }],
    tests: [BANDS, BANDS_E2E],
  },
  {
    name: 'S55 bands: a band\'s rows put back at the top of the frame (its offset ignored)',
    edits: [{ file: 'src/software/bands.ts', find: '(band.bottom - band.top) * width), 4 * band.top * width);', replace: '(band.bottom - band.top) * width), 0);' }],
    tests: [BANDS, BANDS_E2E],
  },
  {
    name: 'S56 bands: the rasterizer draws every row whatever the band (the box not clamped to it)',
    edits: [{ file: 'src/software/raster.ts', find: 'const py0 = Math.max(this.top, Math.ceil(', replace: 'const py0 = Math.max(0, Math.ceil(' }],
    tests: [BANDS],
  },
  {
    name: 'S57 bands: rough glass drawn in bands (the gather reads rows no band drew)',
    edits: [{ file: 'src/software/software-renderer.ts', find: "return state.view !== 'passes' && !isRough(state);", replace: "return state.view !== 'passes';" }],
    tests: [BANDS],
  },
  {
    name: 'S58 bands: the workers never terminated (the element gone, they stay)',
    edits: [{ file: 'src/element/software-host.ts', find: '    this.worker.terminate();\n', replace: '' }],
    tests: [BANDS_E2E],
  },
  {
    name: 'S59 bands: a worker that cannot start leaves the frame waiting (no fall back to the main thread)',
    edits: [{ file: 'src/element/software-host.ts', find: '      e.preventDefault?.();\n      failed();\n', replace: '      e.preventDefault?.();\n' }],
    tests: [ELEMENT],
  },
  {
    name: 'S60 bands: the resolve writes the band\'s rows at the top of the output',
    edits: [{ file: 'src/software/software-renderer.ts', find: 'const out = this.output.subarray(4 * top * width, 4 * bottom * width);', replace: 'const out = this.output.subarray(0, 4 * (bottom - top) * width);' }],
    tests: [BANDS],
  },
  {
    name: 'S61 bands: triangles left out before clipping against the wrong row (the band\'s last rows lose theirs)',
    edits: [{ file: 'src/software/raster.ts', find: 'lo = 1 - (2 * (this.bottom + 1)) / H;', replace: 'lo = 1 - (2 * (this.bottom - 8)) / H;' }],
    tests: [BANDS],
  },
  {
    name: 'S62 a frame in flight when the element goes drawn again on the main thread (a whole CPU frame thrown away)',
    edits: [{ file: 'src/element/software-host.ts', find: '.catch(() => (this.disposed ? new Uint8ClampedArray(0) : this.renderNow(scene, state, samplesPerAxis)));', replace: '.catch(() => this.renderNow(scene, state, samplesPerAxis));' }],
    tests: ['tests/e2e/software-bands.spec.ts'],
  },
];
