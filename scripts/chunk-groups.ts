// Vite's chunk groups from the chunk table (src/frame/chunks.ts): one group per chunk that lists
// its files, in the table's order (an earlier group keeps a module two groups would take).
import { CHUNKS, type Chunk } from '../src/frame/chunks.ts';

export interface ChunkGroup {
  name: string;
  /** Matches a module's id (an absolute path, either separator) when it is one of the chunk's files. */
  test: RegExp;
}

const escape = (s: string): string => s.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');

export function chunkGroups(table: Readonly<Record<string, Chunk>> = CHUNKS): ChunkGroup[] {
  return Object.entries(table).flatMap(([name, chunk]) => {
    if (!chunk.modules) return [];
    const paths = chunk.modules.map((m) => m.split('/').map(escape).join('[\\\\/]'));
    return [{ name, test: new RegExp(`(^|[\\\\/])(${paths.join('|')})$`) }];
  });
}
