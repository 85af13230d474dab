// Console warnings for unusable attribute values: once per attribute and value, capped.
import type { AttributeSpec } from './attributes';

export const PREFIX = 'glass-plane-scene:';
const MAX_WARNINGS = 200;

export function warn(text: string): void {
  console.warn(`${PREFIX} ${text}`);
}

export class AttributeWarnings {
  private readonly warned = new Set<string>();

  /** Warns about `raw` for `spec` unless that pair was reported before (or the cap is hit). */
  report(spec: Pick<AttributeSpec, 'attribute'>, raw: string, problem: string, element?: string): void {
    const key = `${spec.attribute}\u0000${raw}`;
    if (this.warned.has(key) || this.warned.size >= MAX_WARNINGS) return;
    this.warned.add(key);
    const shown = raw.length > 40 ? `${raw.slice(0, 40)}…` : raw;
    warn(`${element ? `<${element}> ` : ''}${spec.attribute}=${JSON.stringify(shown)}: ${problem}`);
    if (this.warned.size === MAX_WARNINGS) warn('further attribute warnings are suppressed');
  }
}
