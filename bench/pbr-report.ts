// bench/pbr.md from bench/pbr.spec.ts's measurements: the rows, our cost at three.js's accuracy, the preparation times,
// the reference's noise and the peer's conversion check.
import type { PerRegion } from '../src/reference';

export interface Row { label: string; ms: number; iqr: number; psnr: PerRegion }

export interface Prep {
  /** Ours in the page: prepareEnvironment at once (the first making), prepareEnvironmentSliced (wall), and in Node. */
  once: number; sliced: number; node: number; nodeWasPrepared: boolean;
  /** three's: our studio baked to an equirect, then PMREM (first: programs compiled; again), RoomEnvironment's PMREM. */
  bake: number; bakeAgain: number; pmremFirst: number; pmremAgain: number; room: number; roomAgain: number;
}

export interface Check { scene: 'lights' | 'studio'; matched: PerRegion; stock: PerRegion; webgl: PerRegion; software: PerRegion; matchedVsOurs: PerRegion }

export interface Report {
  date: string; gpu: string; maxSamples: number; node: string; size: { width: number; height: number }; refSpp: number; envSamples: number;
  refMs: number; refCached: boolean; runs: number; frames: number;
  webgl: Row[]; software: Row[]; three: Row[]; prep: Prep;
  noise: { self: PerRegion; samples: number; move: number; moved: string };
  checks: Check[];
}

const f1 = (x: number) => (Number.isFinite(x) ? x.toFixed(1) : '–');
const ms = (x: number) => (Number.isFinite(x) ? (x >= 100 ? x.toFixed(0) : x.toFixed(1)) : '–');
const psnr = (p: PerRegion) => [p.all, p.objects, p.glass, p.edges, p.dark].map(f1).join(' | ');

/** Our cheapest row at least as accurate on the objects as `dB`, or null. */
function cheapestAtLeast(rows: Row[], dB: number): Row | null {
  return rows.filter((r) => r.psnr.objects >= dB).reduce<Row | null>((a, b) => (a === null || b.ms < a.ms ? b : a), null);
}

function ratioRows(r: Report): string[] {
  const out = ['| three.js | ms | objects dB | our cheapest WebGL at ≥ its objects dB | ms | ours ÷ three.js | our cheapest software at ≥ | ms | ÷ three.js |', '|---|---|---|---|---|---|---|---|---|'];
  for (const t of r.three) {
    const g = cheapestAtLeast(r.webgl, t.psnr.objects), s = cheapestAtLeast(r.software, t.psnr.objects);
    const cell = (x: Row | null) => (x ? [`${x.label} (${f1(x.psnr.objects)})`, ms(x.ms), (x.ms / t.ms).toFixed(2)] : ['none reaches it', '–', '–']);
    out.push(`| ${t.label} | ${ms(t.ms)} | ${f1(t.psnr.objects)} | ${cell(g).join(' | ')} | ${cell(s).join(' | ')} |`);
  }
  return out;
}

export function pbrReport(r: Report): string {
  const { width, height } = r.size, p = r.prep;
  const rows = (name: string, list: Row[]) => list.map((x) => `| ${name} | ${x.label} | ${ms(x.ms)} (${ms(x.iqr)}) | ${psnr(x.psnr)} |`);
  const check = (c: Check) => `| ${c.scene === 'lights' ? 'the lights alone' : 'the studio alone'} | ${f1(c.matched.objects)} (${f1(c.matched.all)}) | ${f1(c.stock.objects)} (${f1(c.stock.all)}) | ${f1(c.webgl.objects)} (${f1(c.webgl.all)}) | ${f1(c.software.objects)} (${f1(c.software.all)}) | ${f1(c.matchedVsOurs.objects)} (${f1(c.matchedVsOurs.all)}) |`;
  return [
    '# PBR: the grid of glTF spheres in the studio ([PBR](../docs/pbr.md))', '',
    `Written by \`npm run bench\` (bench/pbr.spec.ts) on ${r.date}; WebGL: ${r.gpu} (MAX_SAMPLES ${r.maxSamples}); software: Node ${r.node}. The machine has`,
    'two cores and was shared with other browser runs while this ran: the ms are rough (median of the runs, interquartile',
    'range in brackets) and measured, never asserted.', '',
    `Scene: bench/pbr-scene.ts, the tests' grid (twelve spheres, metallic 0, ½, 1 × roughness 0.05, 0.3, 0.6, 1, over a glass`,
    `floor) with its directional and point light, in the studio at intensity 1, tone mapped (neutral), color-space srgb, at`,
    `${width}×${height}, the tests' camera. PSNR (dB: all | objects | glass | edges | dark) against the float64 reference at`,
    `${r.refSpp}×${r.refSpp} strata and ${r.envSamples} environment directions a pixel, which took ${(r.refMs / 1000).toFixed(0)} s${r.refCached ? ' (when it was made and cached)' : ''}`,
    `— cheap enough for ${width}×${height} (the tests draw the grid at 320×180): the`,
    `larger frame gives the edges and the spheres' rims four times the pixels. ms: median of ${r.runs} runs of ${r.frames} frames`,
    '(1 for the software renderer\'s supersampled rows) after one untimed; the software renderer\'s frames alternate the yaw by',
    '1e-9° so its frame-to-frame cache of shaded pixels does not skip the shading.', '',
    '| renderer | configuration | ms | all | objects | glass | edges | dark |', '|---|---|---|---|---|---|---|---|',
    ...rows('WebGL', r.webgl), ...rows('software', r.software), ...rows('three.js', r.three), '',
    'The objects are shaded once a pixel at any MSAA setting (the edge band is a region of its own), so WebGL\'s objects do',
    'not move with samples; its edges do. "our BRDF": the three.js peer with our single-scattering BRDF in its shader',
    '([below](#the-peers-conversion-of-our-lights-and-studio)); as it comes, its objects are far from the reference mostly',
    'because its model is not ours — multiple-scattering compensation (rough metals brighter) and the half metals\' diffuse',
    'Fresnel — not because its method is coarser: its objects PSNR measures the distance to our model, which the reference judges.', '',
    'Why our objects are under 40 dB: each renderer shades a pixel once (WebGL, the software renderer\'s 1×1 and MSAA rows) or 4',
    'and 16 times (its supersampled rows) where the reference takes 16 strata of 1,024 directions of the studio, and the split sum',
    'errs at grazing views of rough metals (docs/pbr.md#the-split-sum: 16–18 % at roughness ½–¾), which the spheres\' rims show;',
    'the reference\'s own noise on the objects is in [its noise](#the-references-noise).', '',
    '## Our cost at three.js\'s accuracy', '',
    'For each configuration of the three.js peer (bench/three-pbr-peer.ts: MeshStandardMaterial, PMREM of our studio,', 
    'NeutralToneMapping, Reflector floor with our glass equation), our cheapest configuration whose objects PSNR is at least',
    'the peer\'s, and the ratio of the times (below 1: ours is faster at equal or better accuracy).', '',
    ...ratioRows(r), '',
    '## Preparing the environment', '',
    '| what | where | ms |', '|---|---|---|',
    `| ours: the studio's maps and split-sum table, at once (prepareEnvironment, the first making) | page | ${ms(p.once)} |`,
    `| ours: the same in slices of 8 ms (prepareEnvironmentSliced, wall time; the page answers between) | page | ${ms(p.sliced)} |`,
    `| ours: prepareEnvironment${p.nodeWasPrepared ? ' (the table emptied first)' : ''} | Node | ${ms(p.node)} |`,
    `| three.js: our studio baked into a 1024×512 float equirect (4×4 directions a texel, on the CPU) | page | ${ms(p.bake)} (again ${ms(p.bakeAgain)}) |`,
    `| three.js: PMREMGenerator.fromEquirectangular of it, first (its programs compiled) | page | ${ms(p.pmremFirst)} |`,
    `| three.js: the same again | page | ${ms(p.pmremAgain)} |`,
    `| three.js: PMREMGenerator.fromScene(RoomEnvironment, 0.04), first | page | ${ms(p.room)} |`,
    `| three.js: the same again | page | ${ms(p.roomAgain)} |`, '',
    'three.js\'s times end with a one-pixel read, so its GPU work is in them.', '',
    '## The reference\'s noise', '',
    `The reference at ${r.noise.samples} directions a pixel against itself at ${2 * r.noise.samples}: ${psnr(r.noise.self)} dB`,
    `(all | objects | glass | edges | dark). Scored against the doubled reference, the software renderer's ${r.noise.moved} row`,
    `moves by ${r.noise.move >= 0 ? '+' : ''}${r.noise.move.toFixed(2)} dB on the objects.`, '',
    '## The peer\'s conversion of our lights and studio', '',
    'The grid under the lights alone (no environment) and under the studio alone (no lights), objects dB (all in brackets)',
    'against the reference, everything at samples 4 (the software renderer 4×4). "our BRDF": the peer with three\'s',
    'multiple-scattering compensation, its roughness widening by the normal\'s derivatives, its ambient\'s energy factor and',
    'its half metals\' diffuse Fresnel (the dielectric\'s, where ours is Appendix B\'s blended F0) replaced by ours in the shader',
    '(bench/three-pbr-matched.ts), so the lights row measures the conversion of our lights (intensity π, decay 0, ambient',
    'π·ΣIa) and the studio row the bake\'s direction convention and three\'s PMREM. The last column holds that peer against our',
    'WebGL frame itself (both MSAA 4, our geometry), where the reference\'s sixteen samples a pixel do not blur the comparison.', '',
    '| scene | three.js, our BRDF | three.js as it comes | ours, WebGL | ours, software | three.js with our BRDF against our WebGL frame |', '|---|---|---|---|---|---|',
    ...r.checks.map(check), '',
  ].join('\n');
}
