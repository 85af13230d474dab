// custom-elements.json against the attribute tables: every attribute of docs/element.md#attribute-table and docs/scene-model.md#glass-object with its
// type and default, every event and the public methods and properties, so the JSDoc the
// manifest is made from cannot fall behind the tables. The manifest is generated afresh here.
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { beforeAll, describe, expect, it } from 'vitest';
import { ATTRIBUTES } from '../../src/element/attributes';
import { OBJECT_ATTRIBUTES } from '../../src/element/children/object-attributes';
import { LIGHT_ATTRIBUTES } from '../../src/element/children/light-attributes';

interface Attribute { name: string; type?: { text: string }; default?: string; description?: string }
interface Declaration {
  name: string; tagName: string; attributes: Attribute[];
  events: { name: string; type?: { text: string } }[];
  members: { kind: string; name: string; description?: string }[];
}

const OUT = 'node_modules/.cache/manifest-test';
let elements: Map<string, Declaration>;

beforeAll(() => {
  execFileSync(process.execPath, ['node_modules/@custom-elements-manifest/analyzer/cem.js', 'analyze', '--quiet', '--outdir', OUT]);
  const manifest = JSON.parse(readFileSync(`${OUT}/custom-elements.json`, 'utf8'));
  const declarations: Declaration[] = manifest.modules.flatMap((m: { declarations: Declaration[] }) => m.declarations);
  elements = new Map(declarations.map((d) => [d.tagName, d]));
}, 60_000);

/** The manifest's default: the attribute's text (quoted), a number, a boolean, or null for absent. */
function defaultText(value: unknown): string {
  if (value === null || typeof value === 'number' || typeof value === 'boolean') return String(value);
  return JSON.stringify(Array.isArray(value) ? value.join(' ') : value);
}

interface Row { attribute: string; default: unknown; parse(raw: string | null): { value: unknown; problem?: string } }

const TABLES: [string, readonly Row[], string[]][] = [
  ['glass-plane-scene', ATTRIBUTES as readonly Row[], ['alt']],
  ['glass-object', OBJECT_ATTRIBUTES as readonly Row[], []],
  ['glass-light', LIGHT_ATTRIBUTES as readonly Row[], []],
];

describe.each(TABLES)('<%s> in custom-elements.json', (tag, table, extra) => {
  it('lists exactly the attributes of its table', () => {
    const names = elements.get(tag)!.attributes.map((a) => a.name).sort();
    expect(names).toEqual([...table.map((r) => r.attribute), ...extra].sort());
  });

  it.each(table.map((r) => [r.attribute, r] as const))('%s: type, the table\'s default, a description', (name, row) => {
    const a = elements.get(tag)!.attributes.find((x) => x.name === name)!;
    expect(a.type?.text).toMatch(/\S/);
    expect(a.description).toMatch(/\S/);
    expect(a.default).toBe(defaultText(row.default));
  });

  it.each(table.map((r) => [r.attribute, r] as const))('%s: a keyword type is exactly what the parser accepts', (name, row) => {
    const type = elements.get(tag)!.attributes.find((x) => x.name === name)!.type!.text;
    const parts = type.split('|').map((t) => t.trim());
    const words = parts.filter((t) => /^'.*'$/.test(t)).map((t) => t.slice(1, -1));
    const numbers = parts.filter((t) => /^-?\d+(\.\d+)?$/.test(t));
    for (const w of words) expect(row.parse(w), `${name}="${w}"`).toEqual({ value: w });
    for (const n of numbers) expect(row.parse(n), `${name}="${n}"`).toEqual({ value: Number(n) });
    if (words.length && !parts.includes('number')) {
      // The parser's own list of words, from its warning for a value it does not know.
      const problem = row.parse('not-a-keyword').problem ?? '';
      const listed = /expected one of ([^;]+);/.exec(problem)?.[1].split(', ') ?? [];
      expect(listed.sort(), problem).toEqual([...words].sort());
    }
    if (parts.includes('number')) expect(['1', '0.5', '8'].some((x) => row.parse(x).problem === undefined), name).toBe(true);
  });
});

describe('events, methods and properties in custom-elements.json', () => {
  const events = (tag: string) => Object.fromEntries(elements.get(tag)!.events.map((e) => [e.name, e.type?.text]));
  const members = (tag: string, kind: string) => elements.get(tag)!.members.filter((m) => m.kind === kind).map((m) => m.name);

  it('<glass-plane-scene> fires ready, frame, error and camera-change with typed details', () => {
    expect(events('glass-plane-scene')).toEqual({
      ready: 'CustomEvent<FrameReport>', frame: 'CustomEvent<FrameReport>', refined: 'CustomEvent<FrameReport>',
      error: 'CustomEvent<GlassPlaneSceneErrorDetail>', 'camera-change': 'CustomEvent<CameraChangeDetail>',
    });
  });

  it('<glass-object> fires progress, load and error', () => {
    expect(Object.keys(events('glass-object')).sort()).toEqual(['error', 'load', 'progress']);
  });

  it('<glass-plane-scene> has requestRender, capture and whenRefined, scene, stats and objectRotation, nothing private', () => {
    expect(members('glass-plane-scene', 'method')).toEqual(expect.arrayContaining(['requestRender', 'capture', 'whenRefined']));
    expect(members('glass-plane-scene', 'field')).toEqual(expect.arrayContaining(['scene', 'stats', 'objectRotation']));
    for (const d of elements.values()) {
      for (const m of d.members) expect(m.description, `${d.tagName} ${m.name}`).toMatch(/\S/);
      expect(d.members.map((m) => m.name)).not.toContain('values');
    }
  });
});
