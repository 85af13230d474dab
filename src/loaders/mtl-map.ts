// A texture statement of an MTL file (`map_Kd -s 2 2 1 -clamp on dir\my tex.png`): options
// stripped with their own argument counts, the rest of the line the path.
import { isNumberToken } from './number-token';

export interface MtlTexture {
  /** Relative to the MTL file; `\` read as `/`, spaces kept. */
  path: string;
  /** `path` resolved against the MTL file's URL; absent when the file was read without an absolute URL. */
  url?: string;
  /** -s u v w (v, w default 1) and -o u v w (v, w default 0). */
  scale?: [number, number, number];
  offset?: [number, number, number];
  /** -clamp on|off. */
  clamp?: boolean;
}

/** Fixed argument counts from the MTL spec; -o, -s and -t take 1 to 3 numbers. */
const FIXED_ARGS: Record<string, number> = {
  '-blendu': 1, '-blendv': 1, '-bm': 1, '-boost': 1, '-cc': 1, '-clamp': 1, '-imfchan': 1, '-mm': 2, '-texres': 1,
  '-type': 1,
};
const VECTOR_ARGS = new Set(['-o', '-s', '-t']);

export function readMapStatement(rest: string, warn: (message: string) => void): MtlTexture | null {
  const map: MtlTexture = { path: '' };
  let at = 0;
  const token = (): { text: string; start: number; end: number } | null => {
    const m = /\S+/g;
    m.lastIndex = at;
    const found = m.exec(rest);
    return found ? { text: found[0], start: found.index, end: found.index + found[0].length } : null;
  };
  for (;;) {
    const t = token();
    if (t === null) break;
    const option = t.text.toLowerCase();
    if (!option.startsWith('-') || isNumberToken(option)) {
      map.path = rest.slice(t.start).trim().replace(/\\/g, '/');
      break;
    }
    at = t.end;
    if (VECTOR_ARGS.has(option)) {
      const values: number[] = [];
      for (let k = 0; k < 3; k++) {
        const v = token();
        if (v === null || !isNumberToken(v.text)) break;
        values.push(Number(v.text));
        at = v.end;
      }
      if (values.length === 0) warn(`${option} without a number`);
      const fill = option === '-s' ? 1 : 0;
      const vec: [number, number, number] = [values[0] ?? fill, values[1] ?? fill, values[2] ?? fill];
      if (option === '-s' && values.length > 0) map.scale = vec;
      if (option === '-o' && values.length > 0) map.offset = vec;
    } else if (option in FIXED_ARGS) {
      for (let k = 0; k < FIXED_ARGS[option]; k++) {
        const v = token();
        if (v === null) break;
        if (option === '-clamp') map.clamp = v.text.toLowerCase() === 'on';
        at = v.end;
      }
    } else {
      warn(`unknown option ${JSON.stringify(t.text.slice(0, 40))} skipped`);
    }
  }
  if (map.path === '') {
    warn('no file name; ignored');
    return null;
  }
  return map;
}
