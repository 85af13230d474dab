// The import direction of src/ (ARCHITECTURE.md's ```layers block), and the check that keeps it.
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { afterEach, describe, expect, it } from 'vitest';
import { check, importsOf, readLayers } from '../../scripts/check-layers.mjs';

const ROOT = path.resolve(__dirname, '../..');
const LAYERS = readLayers(fs.readFileSync(path.join(ROOT, 'ARCHITECTURE.md'), 'utf8'));

describe('the layers of src/', () => {
  it('are the ones ARCHITECTURE.md lists, top first', () => {
    expect(LAYERS).toEqual([
      ['index'], ['element'], ['render', 'software', 'reference'], ['frame', 'loaders'], ['scene'], ['math'],
    ]);
  });

  it('every import goes down: none to a higher layer or a sibling', () => {
    expect(check(LAYERS)).toEqual([]);
  });
});

describe('importsOf', () => {
  it('finds static imports, re-exports, bare imports and import() with their lines; skips packages', () => {
    const text = [
      "import { a } from './a';",
      "import type { B } from '../scene/b';",
      "export { c } from './c';",
      "export type * from '../frame/types';",
      "import './side-effect';",
      "import { mat4 } from 'gl-matrix';",
      "const m = await import('../software/renderer');",
      "import raw from '../../shaders/glass.frag?raw';",
    ].join('\n');
    expect(importsOf(text)).toEqual([
      { spec: './a', line: 1 },
      { spec: '../scene/b', line: 2 },
      { spec: './c', line: 3 },
      { spec: '../frame/types', line: 4 },
      { spec: '../../shaders/glass.frag?raw', line: 8 },
      { spec: './side-effect', line: 5 },
      { spec: '../software/renderer', line: 7 },
    ]);
  });

  it('reads a multi-line import at the line of its specifier', () => {
    expect(importsOf("import {\n  a,\n  b,\n} from '../math/camera';\n")).toEqual([{ spec: '../math/camera', line: 4 }]);
  });
});

describe('check', () => {
  let dir = '';
  afterEach(() => {
    if (dir) fs.rmSync(dir, { recursive: true, force: true });
    dir = '';
  });

  /** A temporary src/ of the given files (path → text). */
  function tree(files: Record<string, string>): string {
    dir = fs.mkdtempSync(path.join(os.tmpdir(), 'gps-layers-'));
    const src = path.join(dir, 'src');
    for (const [name, text] of Object.entries(files)) {
      fs.mkdirSync(path.dirname(path.join(src, name)), { recursive: true });
      fs.writeFileSync(path.join(src, name), text);
    }
    return src;
  }

  it('passes imports that go down, within a folder, and out of src/', () => {
    const src = tree({
      'scene/scene.ts': "import { CAMERA } from '../math/camera';\nimport { x } from './x';\n",
      'scene/x.ts': 'export const x = 1;\n',
      'math/camera.ts': "import frag from '../../shaders/a.frag?raw';\n",
      'render/renderer.ts': "import { FrameSetup } from '../frame/frame-setup';\n",
      'frame/frame-setup.ts': "import { s } from '../scene/scene';\n",
    });
    expect(check(LAYERS, src)).toEqual([]);
  });

  it('reports an import planted upwards (math → scene), with its file and line', () => {
    const src = tree({
      'math/camera.ts': "// the one constant\nimport { CAMERA } from '../scene/default-scene';\n",
      'scene/default-scene.ts': 'export const CAMERA = {};\n',
    });
    expect(check(LAYERS, src)).toEqual([
      'src/math/camera.ts:2: math imports ../scene/default-scene, a higher layer (scene)',
    ]);
  });

  it('reports a sibling import (software → reference), a dynamic one included', () => {
    const src = tree({
      'software/a.ts': "const r = import('../reference/image-texture');\n",
      'reference/image-texture.ts': 'export {};\n',
    });
    expect(check(LAYERS, src)).toEqual([
      'src/software/a.ts:1: software imports ../reference/image-texture, a sibling on its own layer (reference)',
    ]);
  });

  it('reports a folder that no layer names', () => {
    const src = tree({ 'input/flyby.ts': 'export {};\n' });
    expect(check(LAYERS, src)).toEqual(['src/input/flyby.ts: src/input is in no layer of ARCHITECTURE.md']);
  });
});
