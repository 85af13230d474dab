// Files from the wild through the element (issue 9): each malformed model gives `load` with a
// warning naming the line, or `error` naming the URL — never a hang, never an exception out of
// the element — and the rest of the scene keeps drawing.
import { test, expect, openPage, capture } from './fixtures';
import { mountHtml } from './helpers/scene-children';

const GOOD = 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n';
const CASES: { name: string; body: string | Buffer; expect: 'load' | 'error'; mention?: RegExp }[] = [
  { name: 'truncated mid-line', body: GOOD + 'v 0 0 1\nf 1 2 4\nf 1 3', expect: 'load', mention: /line 7/ },
  { name: 'an index out of range', body: GOOD + 'f 1 2 9\n', expect: 'load', mention: /line 5/ },
  { name: '10 MB on one line', body: GOOD + 'v 0 0 ' + '1'.repeat(10_000_000) + '\n', expect: 'load' },
  { name: 'binary garbage', body: Buffer.from(Array.from({ length: 4096 }, (_, i) => (i * 7919) % 256)), expect: 'error' },
  { name: 'an HTML page', body: '<!doctype html><html><body>Not found</body></html>', expect: 'error', mention: /HTML/ },
  { name: 'CRLF, a BOM, no final newline', body: '\ufeffv 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3', expect: 'load' },
];

for (const c of CASES) {
  test(`${c.name}: ${c.expect}, and the scene keeps drawing`, async ({ page, consoleLog }) => {
    test.setTimeout(60_000);
    await page.route('**/wild/model.obj', (route) => route.fulfill({ status: 200, contentType: 'text/plain', body: c.body }));
    await openPage(page);
    const seen = await mountHtml(page, `<glass-plane-scene time="0" spin="0">
      <glass-object shape="cube" position="-1 1 1"></glass-object>
      <glass-object src="/wild/model.obj" position="1 1 1"></glass-object>
    </glass-plane-scene>`);
    const ending = seen.filter((e) => e.target === 'glass-object' && (e.type === 'load' || e.type === 'error'));
    expect(ending.map((e) => e.type), 'the model ends in exactly one load or error').toEqual([c.expect]);
    const detail = ending[0].detail;
    expect(detail.url).toMatch(/\/wild\/model\.obj$/);
    const text = c.expect === 'load' ? (detail.warnings as string[]).join('\n') : `${detail.message} line ${detail.line ?? ''}`;
    if (c.mention) expect(text).toMatch(c.mention);
    // The other object is still drawn: the frame is not the bare background.
    const img = await capture(page);
    let lit = 0;
    for (let i = 0; i < img.data.length; i += 4) if (Math.abs(img.data[i] - 26) + Math.abs(img.data[i + 1] - 26) > 30) lit++;
    expect(lit, 'pixels other than the background').toBeGreaterThan(100);
    // Warnings and errors are the element's own, once; nothing thrown.
    expect(consoleLog.take('pageerror')).toEqual([]);
    consoleLog.take('warning');
    consoleLog.take('error');
  });
}
