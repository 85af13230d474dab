// No function in src/ over 80 lines, no file over 400 (the element's host 300: scripts/check-sizes.mjs), and the
// measuring itself on small inputs.
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { afterEach, describe, expect, it } from 'vitest';
import { check, FILE_LIMITS, functionsOf, MAX_FILE_LINES, MAX_FUNCTION_LINES } from '../../scripts/check-sizes.mjs';

/** A function `name` of exactly `lines` lines (declaration to closing brace). */
const fn = (name: string, lines: number) => `function ${name}() {\n${'  x++;\n'.repeat(lines - 2)}}\n`;

describe('src/', () => {
  it(`has no function over ${MAX_FUNCTION_LINES} lines and no file over ${MAX_FILE_LINES}`, () => {
    expect(check()).toEqual([]);
  });

  it('holds the element\'s thin host to 300 lines, and exempts nothing', () => {
    expect([...FILE_LIMITS]).toEqual([['src/element/glass-plane-scene.ts', 300]]);
  });
});

describe('functionsOf', () => {
  it('measures declarations from their first line to their last', () => {
    expect(functionsOf(`let x = 0;\n${fn('a', 3)}${fn('b', 81)}`)).toEqual([
      { name: 'a', line: 2, lines: 3 },
      { name: 'b', line: 5, lines: 81 },
    ]);
  });

  it('names methods, arrows and function expressions by what holds them; counts nested ones apart', () => {
    const code = [
      'class C {',
      '  /** doc */',
      '  private run(): void {',
      '    const inner = (a: number): number => {',
      '      return a;',
      '    };',
      '  }',
      '}',
      'const f = function () {',
      '  return 1;',
      '};',
      'const o = { m() { return 2; } };',
    ].join('\n');
    expect(functionsOf(code)).toEqual([
      { name: 'run', line: 3, lines: 5 },
      { name: 'inner', line: 4, lines: 3 },
      { name: 'f', line: 9, lines: 3 },
      { name: 'm', line: 12, lines: 1 },
    ]);
  });
});

describe('check', () => {
  let dir = '';
  afterEach(() => {
    if (dir) fs.rmSync(dir, { recursive: true, force: true });
    dir = '';
  });

  function tree(files: Record<string, string>): string {
    dir = fs.mkdtempSync(path.join(os.tmpdir(), 'gps-sizes-'));
    for (const [name, text] of Object.entries(files)) {
      fs.mkdirSync(path.dirname(path.join(dir, name)), { recursive: true });
      fs.writeFileSync(path.join(dir, name), text);
    }
    return dir;
  }

  it('reports a function of 81 lines and a file of 401, not one of 80 or 400', () => {
    const root = tree({
      'src/a.ts': fn('fine', 80),
      'src/b/c.ts': `// long\n${fn('long', 81)}`,
      'src/d.ts': 'let x = 0;\n'.repeat(400),
      'src/e.ts': 'let x = 0;\n'.repeat(401),
    });
    expect(check(root).sort()).toEqual([
      'src/b/c.ts:2: long is 81 lines (at most 80)',
      'src/e.ts: 401 lines (at most 400)',
    ]);
  });

  it('holds a file with a limit of its own to it: 300 lines pass, 301 do not', () => {
    const file = 'src/element/glass-plane-scene.ts';
    expect(check(tree({ [file]: 'let x = 0;\n'.repeat(300) }))).toEqual([]);
    expect(check(tree({ [file]: 'let x = 0;\n'.repeat(301) }))).toEqual([`${file}: 301 lines (at most 300)`]);
  });
});
