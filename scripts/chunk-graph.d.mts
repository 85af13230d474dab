// Types of scripts/chunk-graph.mjs for the TypeScript that imports it (bench/gltf.spec.ts).
export const DIST: string;
export interface Chunk { file: string; text: string; lazy: boolean; from: string | null }
export function graph(entry: string, dir?: string): Chunk[];
export function nameOf(file: string): string;
