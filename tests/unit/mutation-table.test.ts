// The browser's mutation table (scripts/mutations/*.mjs, `npm run test:mutations:browser`) kept true as the code moves:
// every entry has a why and tests that exist, and each search text is in its file exactly once (a stale entry would
// only show when the table is run, which npm test does not do).
import { readdirSync, readFileSync, existsSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';

const ROOT = join(__dirname, '../..');
const DIR = join(ROOT, 'scripts/mutations');

interface Entry { name: string; why: string; edits: { file: string; find: string; replace: string }[]; tests: string[] }

describe('the browser mutation table', async () => {
  const areas = await Promise.all(readdirSync(DIR).filter((f) => f.endsWith('.mjs')).map(async (f) => [f, (await import(join(DIR, f))).default as Entry[]] as const));

  it('has its areas, PBR among them', () => {
    expect(areas.map(([f]) => f)).toContain('pbr.mjs');
  });

  for (const [file, entries] of areas) {
    it(`${file}: each entry's search text is in its file exactly once, its replacement differs, its tests exist`, () => {
      for (const e of entries) {
        expect(e.why, e.name).toMatch(/\S/);
        expect(e.tests.length, e.name).toBeGreaterThan(0);
        for (const t of e.tests) expect(existsSync(join(ROOT, t.split(':')[0])), `${e.name}: ${t}`).toBe(true);
        for (const ed of e.edits) {
          const text = readFileSync(join(ROOT, ed.file), 'utf8');
          expect(text.split(ed.find).length - 1, `${e.name}: ${ed.file}`).toBe(1);
          expect(ed.replace, e.name).not.toBe(ed.find);
        }
      }
    });
  }
});
