// bench/refine.svg, written by bench/refine.spec.ts: mean PSNR (all) against cumulative ms for a still view's frames, ms on a
// log scale (a still view's first frame and its last are two orders apart), with the moving frames marked. Plain SVG text.
export interface Curve {
  label: string;
  /** Cumulative ms and mean PSNR (all) after each frame, first frame first. */
  points: { ms: number; db: number }[];
  /** Frames to label on the curve (from 1). */
  marks: number[];
  dashed?: boolean;
}

export interface Point {
  label: string;
  ms: number;
  db: number;
  shape: 'circle' | 'square' | 'diamond' | 'triangle';
}

const W = 760, H = 460, LEFT = 64, RIGHT = 220, TOP = 40, BOTTOM = 52;
const COLOURS = ['#1f5fa8', '#6a9fd8', '#c0392b', '#e08e2b', '#2e8b57', '#7d3c98'];

const esc = (s: string) => s.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;');
const n = (x: number) => x.toFixed(1);

/** 1, 2, 5 × powers of ten within [lo, hi]. */
function logTicks(lo: number, hi: number): number[] {
  const out: number[] = [];
  for (let p = Math.floor(Math.log10(lo)); p <= Math.ceil(Math.log10(hi)); p++) {
    for (const m of [1, 2, 5]) {
      const v = m * 10 ** p;
      if (v >= lo && v <= hi) out.push(v);
    }
  }
  return out;
}

function marker(p: Point, x: number, y: number, colour: string): string {
  const r = 6;
  switch (p.shape) {
    case 'circle': return `<circle cx="${n(x)}" cy="${n(y)}" r="${r}" fill="${colour}"/>`;
    case 'square': return `<rect x="${n(x - r)}" y="${n(y - r)}" width="${2 * r}" height="${2 * r}" fill="${colour}"/>`;
    case 'diamond': return `<path d="M${n(x)},${n(y - r - 1)} L${n(x + r + 1)},${n(y)} L${n(x)},${n(y + r + 1)} L${n(x - r - 1)},${n(y)} Z" fill="${colour}"/>`;
    default: return `<path d="M${n(x)},${n(y - r - 1)} L${n(x + r + 1)},${n(y + r)} L${n(x - r - 1)},${n(y + r)} Z" fill="${colour}"/>`;
  }
}

export function refinePlot(title: string, curves: Curve[], points: Point[], thresholds: number[]): string {
  const all = [...curves.flatMap((c) => c.points), ...points].filter((p) => Number.isFinite(p.ms) && p.ms > 0 && Number.isFinite(p.db));
  const lo = 10 ** Math.floor(Math.log10(Math.min(...all.map((p) => p.ms)))), hi = 10 ** Math.ceil(Math.log10(Math.max(...all.map((p) => p.ms))));
  const dbs = [...all.map((p) => p.db), ...thresholds];
  const dbLo = Math.floor(Math.min(...dbs)) - 1, dbHi = Math.ceil(Math.max(...dbs)) + 1;
  const x = (ms: number) => LEFT + ((Math.log10(ms) - Math.log10(lo)) / (Math.log10(hi) - Math.log10(lo))) * (W - LEFT - RIGHT);
  const y = (db: number) => TOP + ((dbHi - db) / (dbHi - dbLo)) * (H - TOP - BOTTOM);
  const out: string[] = [
    `<svg xmlns="http://www.w3.org/2000/svg" width="${W}" height="${H}" viewBox="0 0 ${W} ${H}" font-family="system-ui, sans-serif" font-size="12">`,
    `<rect width="${W}" height="${H}" fill="#fff"/>`,
    `<text x="${LEFT}" y="22" font-size="14" font-weight="bold">${esc(title)}</text>`,
  ];
  // Grid and axes.
  for (const t of logTicks(lo, hi)) {
    out.push(`<line x1="${n(x(t))}" y1="${TOP}" x2="${n(x(t))}" y2="${H - BOTTOM}" stroke="#e4e4e4"/>`,
      `<text x="${n(x(t))}" y="${H - BOTTOM + 16}" text-anchor="middle">${t >= 1000 ? `${t / 1000} s` : t}</text>`);
  }
  const step = dbHi - dbLo > 12 ? 2 : 1;
  for (let d = Math.ceil(dbLo / step) * step; d <= dbHi; d += step) {
    out.push(`<line x1="${LEFT}" y1="${n(y(d))}" x2="${W - RIGHT}" y2="${n(y(d))}" stroke="#e4e4e4"/>`,
      `<text x="${LEFT - 8}" y="${n(y(d) + 4)}" text-anchor="end">${d}</text>`);
  }
  for (const t of thresholds) {
    out.push(`<line x1="${LEFT}" y1="${n(y(t))}" x2="${W - RIGHT}" y2="${n(y(t))}" stroke="#888" stroke-dasharray="2,3"/>`,
      `<text x="${W - RIGHT - 4}" y="${n(y(t) - 4)}" text-anchor="end" fill="#666">${t} dB</text>`);
  }
  out.push(`<rect x="${LEFT}" y="${TOP}" width="${W - LEFT - RIGHT}" height="${H - TOP - BOTTOM}" fill="none" stroke="#333"/>`,
    `<text x="${(LEFT + W - RIGHT) / 2}" y="${H - 12}" text-anchor="middle">cumulative ms (log scale), mean over views</text>`,
    `<text transform="translate(16 ${(TOP + H - BOTTOM) / 2}) rotate(-90)" text-anchor="middle">PSNR dB (all), mean over views</text>`);
  // Curves, their labelled frames, then the points; the legend on the right.
  let legend = TOP + 8;
  curves.forEach((c, i) => {
    const colour = COLOURS[i % COLOURS.length];
    const path = c.points.map((p, j) => `${j ? 'L' : 'M'}${n(x(p.ms))},${n(y(p.db))}`).join(' ');
    out.push(`<path d="${path}" fill="none" stroke="${colour}" stroke-width="2"${c.dashed ? ' stroke-dasharray="6,4"' : ''}/>`);
    for (const k of c.marks) {
      const p = c.points[k - 1];
      if (!p) continue;
      out.push(`<circle cx="${n(x(p.ms))}" cy="${n(y(p.db))}" r="3" fill="${colour}"/>`,
        `<text x="${n(x(p.ms) + 5)}" y="${n(y(p.db) + (c.dashed ? 14 : -6))}" fill="${colour}" font-size="11">${k}</text>`);
    }
    out.push(`<line x1="${W - RIGHT + 14}" y1="${legend}" x2="${W - RIGHT + 40}" y2="${legend}" stroke="${colour}" stroke-width="2"${c.dashed ? ' stroke-dasharray="6,4"' : ''}/>`,
      `<text x="${W - RIGHT + 46}" y="${legend + 4}">${esc(c.label)}</text>`);
    legend += 20;
  });
  points.forEach((p, i) => {
    const colour = COLOURS[(curves.length + i) % COLOURS.length];
    out.push(marker(p, x(p.ms), y(p.db), colour), marker(p, W - RIGHT + 27, legend, colour), `<text x="${W - RIGHT + 46}" y="${legend + 4}">${esc(p.label)}</text>`);
    legend += 20;
  });
  out.push(`<text x="${W - RIGHT + 14}" y="${legend + 8}" fill="#666" font-size="11">numbers: frames of the still view</text>`, '</svg>');
  return out.join('\n') + '\n';
}
