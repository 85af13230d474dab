// URL attributes become the keys the page's caches share: one absolute form per resource.
import { describe, expect, it } from 'vitest';
import { absoluteUrl } from '../../src/element/absolute-url';

const PAGE = 'https://example.test/demo/page.html';

describe('absoluteUrl', () => {
  it('gives "a.obj", "./a.obj" and the absolute URL one key', () => {
    for (const u of ['a.obj', './a.obj', '../demo/a.obj', 'https://example.test/demo/a.obj']) {
      expect(absoluteUrl(u, PAGE), u).toBe('https://example.test/demo/a.obj');
    }
  });

  it('resolves a material library against its model, not the page', () => {
    expect(absoluteUrl('mtl/a.mtl', 'https://cdn.test/models/a.obj')).toBe('https://cdn.test/models/mtl/a.mtl');
  });

  it('is null for no URL and for one that cannot be a URL', () => {
    expect(absoluteUrl(null, PAGE)).toBeNull();
    expect(absoluteUrl('http://[', PAGE)).toBeNull();
  });
});
