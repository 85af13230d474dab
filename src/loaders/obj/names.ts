// The name-valued OBJ statements: mtllib's file list and g's group list.

/**
 * `mtllib` names. The spec separates several names with spaces, but exporters also write
 * one name containing spaces (`mtllib my model.mtl`). Rule: a name runs up to and including
 * the next token ending in `.mtl`, so `my model.mtl other.mtl` is two names; tokens after
 * the last `.mtl` token (or on a line with none) are a name each, as the spec says.
 * Backslashes (Windows exporters) are read as `/`.
 */
export function splitMtllib(rest: string): string[] {
  const tokens = rest.replace(/\\/g, '/').match(/\S+/g) ?? [];
  const names: string[] = [];
  let pending: string[] = [];
  for (const token of tokens) {
    pending.push(token);
    if (/\.mtl$/i.test(token)) {
      names.push(pending.join(' '));
      pending = [];
    }
  }
  names.push(...pending);
  return names;
}

/** `g` lists the groups a face belongs to, separated by spaces. */
export function splitGroups(rest: string): string[] {
  return rest.match(/\S+/g) ?? [];
}

/** Adds each name once, keeping the order of first appearance. */
export function addUnique(list: string[], seen: Set<string>, names: string[]): void {
  for (const n of names) {
    if (n === '' || seen.has(n)) continue;
    seen.add(n);
    list.push(n);
  }
}
