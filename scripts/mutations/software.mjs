// The software renderer: raster, shading, glass, transparency.
// Each: { name, edits: [{ file, find, replace }], tests: Playwright specs (*.spec.ts) or vitest files (*.test.ts) }.
const RASTER = 'tests/unit/software-raster.test.ts';
const PIXELS = 'tests/unit/software-pixels.test.ts';
const GLASS = 'tests/unit/software-glass.test.ts';
const VS_REFERENCE = 'tests/unit/software-reference.test.ts';

export default [
  {
    name: '13 software rasterizer without the top-left rule',
    edits: [{
      file: 'src/software/raster.ts',
      find: '    const bias0 = (ay0 === 0 && ax0 > 0) || ay0 < 0 ? 0 : -1;\n    const bias1 = (ay1 === 0 && ax1 > 0) || ay1 < 0 ? 0 : -1;\n    const bias2 = (ay2 === 0 && ax2 > 0) || ay2 < 0 ? 0 : -1;',
      replace: '    const bias0 = 0;\n    const bias1 = 0;\n    const bias2 = 0;',
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
    edits: [{ file: 'src/software/raster.ts', find: 'const a0 = l0 * w0, a1 = l1 * w1, a2 = l2 * w2;', replace: 'const a0 = l0, a1 = l1, a2 = l2;' }],
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
      find: 'const c = len > 0 ? Math.abs(this.nx * rx + this.ny * ry + this.nz * rz) / len : 1;',
      replace: 'const c = len > 0 ? (this.nx * rx + this.ny * ry + this.nz * rz) / len : 1;',
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
      find: '      c[o] = cr * a + c[o] * (1 - a);\n      c[o + 1] = cg * a + c[o + 1] * (1 - a);\n      c[o + 2] = cb * a + c[o + 2] * (1 - a);',
      replace: '      c[o] = cr * (1 - a) + c[o] * a;\n      c[o + 1] = cg * (1 - a) + c[o + 1] * a;\n      c[o + 2] = cb * (1 - a) + c[o + 2] * a;',
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
    edits: [{ file: 'src/software/software-renderer.ts', find: 'm.center, m.radius, s.halfHeight, r.width', replace: 'm.center, m.radius, 0, r.width' }],
    tests: ['tests/unit/mesh-choice.test.ts'],
  },
];
