// Types of check-layers.mjs for the unit test that imports it (tests/unit/layers.test.ts).
export function readLayers(markdown: string): string[][];
export function importsOf(text: string): { spec: string; line: number }[];
export function check(layers: string[][], src?: string): string[];
export function sourceFiles(dir: string): string[];
