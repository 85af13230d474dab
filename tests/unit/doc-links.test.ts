// Every link into the repository's own documents resolves: the relative Markdown links of
// docs/*.md, README.md, ARCHITECTURE.md, BENCH.md, CHANGELOG.md and bench/*.md (the path, and
// the heading when an anchor is given), and every `docs/<file>.md#<anchor>` the code's comments
// point at in src/, tests/, shaders/ and the other code folders. The design lives in docs/; this keeps the code's pointers into it true when a
// heading is renamed or a page moves.
import { existsSync, readdirSync, readFileSync, statSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const SELF = path.relative(ROOT, fileURLToPath(import.meta.url));

/** GitHub's anchor for a heading's text: lowercase, only letters, digits, spaces, '-' and '_' kept, spaces → '-'. */
export function githubSlug(heading: string): string {
  return heading
    .replace(/\[([^\]]*)\]\([^)]*\)/g, '$1') // a link in a heading anchors by its text
    .trim()
    .toLowerCase()
    .replace(/[^\p{L}\p{N}\p{M} _-]/gu, '')
    .replace(/ /g, '-');
}

/** The lines of a Markdown text outside fenced code blocks (``` or ~~~), with their 1-based numbers. */
function proseLines(text: string): [number, string][] {
  const out: [number, string][] = [];
  let fence: string | null = null;
  text.split(/\r?\n/).forEach((line, i) => {
    const m = /^\s{0,3}(`{3,}|~{3,})/.exec(line);
    if (m) {
      if (fence === null) fence = m[1];
      else if (m[1][0] === fence[0] && m[1].length >= fence.length) fence = null;
      return;
    }
    if (fence === null) out.push([i + 1, line]);
  });
  return out;
}

/** The anchors of a Markdown text's headings; a repeated heading gets -1, -2, … as on GitHub. */
export function headingAnchors(text: string): Set<string> {
  const anchors = new Set<string>();
  const seen = new Map<string, number>();
  for (const [, line] of proseLines(text)) {
    const m = /^\s{0,3}#{1,6}\s+(.*?)(?:\s+#+)?\s*$/.exec(line);
    if (!m) continue;
    const base = githubSlug(m[1]);
    const n = seen.get(base) ?? 0;
    seen.set(base, n + 1);
    anchors.add(n === 0 ? base : `${base}-${n}`);
  }
  return anchors;
}

interface Link { from: string; line: number; target: string }

/** Relative links `[text](target)` of a Markdown text, outside fenced code and inline code spans. */
export function markdownLinks(from: string, text: string): Link[] {
  const links: Link[] = [];
  for (const [line, raw] of proseLines(text)) {
    const prose = raw.replace(/`[^`]*`/g, '');
    for (const m of prose.matchAll(/\]\(\s*<?([^)\s>]+)>?(?:\s+"[^"]*")?\s*\)/g)) {
      const target = m[1];
      if (/^(https?:|mailto:)/i.test(target)) continue;
      links.push({ from, line, target });
    }
  }
  return links;
}

const anchorCache = new Map<string, Set<string>>();
function anchorsOf(file: string): Set<string> {
  let a = anchorCache.get(file);
  if (!a) anchorCache.set(file, (a = headingAnchors(readFileSync(path.join(ROOT, file), 'utf8'))));
  return a;
}

/** What is wrong with `target` (a path relative to `fromFile`'s folder, maybe with #anchor), or null when it resolves. */
export function brokenTarget(fromFile: string, target: string): string | null {
  const hash = target.indexOf('#');
  const rawPath = hash < 0 ? target : target.slice(0, hash);
  const anchor = hash < 0 ? '' : decodeURIComponent(target.slice(hash + 1));
  const file = rawPath === '' ? fromFile : path.normalize(path.join(path.dirname(fromFile), decodeURIComponent(rawPath)));
  if (file.startsWith('..') || path.isAbsolute(file)) return `${target}: outside the repository`;
  if (!existsSync(path.join(ROOT, file))) return `${target}: no file ${file}`;
  if (anchor && /\.md$/i.test(file) && statSync(path.join(ROOT, file)).isFile() && !anchorsOf(file).has(anchor)) {
    return `${target}: ${file} has no heading with the anchor #${anchor}`;
  }
  return null;
}

function filesUnder(dir: string, keep: (name: string) => boolean): string[] {
  const abs = path.join(ROOT, dir);
  if (!existsSync(abs)) return [];
  const out: string[] = [];
  for (const entry of readdirSync(abs, { withFileTypes: true })) {
    const rel = path.join(dir, entry.name);
    if (entry.isDirectory()) {
      if (entry.name !== 'node_modules' && !entry.name.startsWith('.')) out.push(...filesUnder(rel, keep));
    } else if (keep(entry.name)) out.push(rel);
  }
  return out;
}

const MARKDOWN = [
  'README.md', 'ARCHITECTURE.md', 'BENCH.md', 'CHANGELOG.md',
  ...filesUnder('docs', (n) => n.endsWith('.md')), ...filesUnder('bench', (n) => n.endsWith('.md')),
];
const CODE = [
  ...filesUnder('src', (n) => n.endsWith('.ts')),
  ...filesUnder('tests', (n) => n.endsWith('.ts')),
  ...filesUnder('shaders', () => true),
  ...filesUnder('demo', (n) => /\.(ts|html)$/.test(n)),
  ...filesUnder('bench', (n) => n.endsWith('.ts')),
  ...filesUnder('scripts', (n) => /\.(mjs|ts)$/.test(n)),
].filter((f) => f !== SELF);

/** `docs/<file>.md` and `docs/<file>.md#<anchor>` mentioned in a code file, each relative to the repository. */
export function codeReferences(from: string, text: string): Link[] {
  const refs: Link[] = [];
  text.split('\n').forEach((line, i) => {
    for (const m of line.matchAll(/(?<![\w/.-])docs\/[\w-]+\.md(?:#[\w-]+)?/g)) refs.push({ from, line: i + 1, target: m[0] });
  });
  return refs;
}

describe('the GitHub slug', () => {
  it('lowercases, drops punctuation, turns spaces into hyphens', () => {
    expect(githubSlug('Pass 1 reflection')).toBe('pass-1-reflection');
    expect(githubSlug("The course's `.byu` files")).toBe('the-courses-byu-files');
    expect(githubSlug('Write-back and camera-change')).toBe('write-back-and-camera-change');
    expect(githubSlug('snake_case & more!')).toBe('snake_case--more');
    expect(githubSlug('Light and colour (§13)')).toBe('light-and-colour-13');
  });

  it('numbers repeated headings -1, -2, and ignores headings inside fenced code', () => {
    const text = '# Top\n## Glass\n```\n## Not a heading\n```\n## Glass\n### Glass\n';
    expect([...headingAnchors(text)]).toEqual(['top', 'glass', 'glass-1', 'glass-2']);
  });

  it('finds relative links outside code, and leaves web addresses and code alone', () => {
    const text = '[a](docs/x.md#y) [b](https://example.com) [c](mailto:a@b.c) `[d](no.md)`\n```\n[e](no.md)\n```\n[f](#here)';
    expect(markdownLinks('README.md', text).map((l) => l.target)).toEqual(['docs/x.md#y', '#here']);
  });

  it('reports a missing file and a missing heading', () => {
    expect(brokenTarget('README.md', 'docs/rendering.md#the-glass-equation')).toBeNull();
    expect(brokenTarget('README.md', 'docs/rendering.md#no-such-heading')).toMatch(/no heading/);
    expect(brokenTarget('README.md', 'docs/no-such-page.md')).toMatch(/no file/);
    expect(brokenTarget('docs/README.md', '../ARCHITECTURE.md#layers')).toBeNull();
  });
});

describe('links into the repository', () => {
  it('finds the documents to check', () => {
    expect(MARKDOWN.filter((f) => f.startsWith('docs/')).length).toBeGreaterThanOrEqual(10);
    expect(CODE.length).toBeGreaterThan(100);
  });

  it('every relative link of docs/, README.md, ARCHITECTURE.md and the bench pages resolves, anchor included', () => {
    const broken: string[] = [];
    let count = 0;
    for (const file of MARKDOWN) {
      for (const link of markdownLinks(file, readFileSync(path.join(ROOT, file), 'utf8'))) {
        count++;
        const why = brokenTarget(link.from, link.target);
        if (why) broken.push(`${link.from}:${link.line}: ${why}`);
      }
    }
    expect(count).toBeGreaterThan(50);
    expect(broken).toEqual([]);
  });

  it('every docs/<file>.md#<anchor> the code mentions resolves', () => {
    const broken: string[] = [];
    let count = 0;
    for (const file of CODE) {
      for (const ref of codeReferences(file, readFileSync(path.join(ROOT, file), 'utf8'))) {
        count++;
        const why = brokenTarget('README.md', ref.target); // relative to the repository's root
        if (why) broken.push(`${ref.from}:${ref.line}: ${why}`);
      }
    }
    expect(count).toBeGreaterThan(300);
    expect(broken).toEqual([]);
  });
});
