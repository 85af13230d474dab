// The build's shader minifier (scripts/glsl-minify.ts) must leave every shader the same program:
// the same tokens in the same order once comments are gone, each preprocessor directive still on
// a line of its own, and no two operators fused into another. The e2e standalone spec checks the
// built bundle draws what the sources draw; this names the token that went wrong.
import fs from 'node:fs';
import path from 'node:path';
import { describe, expect, it } from 'vitest';
import { minifyGlsl } from '../../scripts/glsl-minify';

const DIR = path.resolve('shaders');
const SHADERS = fs.readdirSync(DIR).filter((f) => /\.(vert|frag|glsl)$/.test(f));

/** GLSL tokens, longest operator first (`--` is one token, `- -` two). */
const TOKEN = /[A-Za-z_]\w*|\d+\.\d*(?:[eE][+-]?\d+)?|\.\d+(?:[eE][+-]?\d+)?|\d+(?:[eE][+-]?\d+)?[uU]?|<<=|>>=|\+\+|--|&&|\|\||\^\^|<<|>>|[-+*/%<>=!&|^]=|\S/g;
const withoutComments = (s: string) => s.replace(/\/\*[\s\S]*?\*\//g, ' ').replace(/\/\/[^\n]*/g, ' ');
const tokens = (s: string) => withoutComments(s).match(TOKEN) ?? [];
const directives = (s: string) => withoutComments(s).split('\n').map((l) => l.trim()).filter((l) => l.startsWith('#')).map((l) => l.replace(/\s+/g, ' '));

describe('glsl-minify', () => {
  it('finds the shaders', () => {
    expect(SHADERS.length).toBeGreaterThanOrEqual(10);
  });

  for (const file of SHADERS) {
    it(`${file}: the same tokens and directives, shorter`, () => {
      const source = fs.readFileSync(path.join(DIR, file), 'utf8');
      const min = minifyGlsl(source);
      expect(tokens(min)).toEqual(tokens(source));
      expect(directives(min)).toEqual(directives(source));
      // Each directive alone on its line, as the preprocessor reads it.
      for (const line of min.split('\n')) if (line.includes('#')) expect(line.startsWith('#'), line).toBe(true);
      expect(min.length).toBeLessThan(source.length);
      expect(min).not.toMatch(/\/\/|\/\*/);
    });
  }

  it('keeps operators apart that would fuse (a - -b, x + +y, p < <q is not GLSL but stays two tokens)', () => {
    const src = 'float a = b - -c;\nfloat d = e + +f;\nbool g = h < -i && j > -k;\n';
    expect(tokens(minifyGlsl(src))).toEqual(tokens(src));
  });

  it('keeps a line that is not a comment (glass.frag\'s marker for the rough gather)', () => {
    expect(minifyGlsl('#ifdef ROUGH\n  // a comment\nROUGH_GATHER_SOURCE\n#endif\n')).toBe('#ifdef ROUGH\nROUGH_GATHER_SOURCE\n#endif');
  });
});
