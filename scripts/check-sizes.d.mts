// Types of check-sizes.mjs for the unit test that imports it (tests/unit/sizes.test.ts).
export const MAX_FUNCTION_LINES: number;
export const MAX_FILE_LINES: number;
export const FILE_LIMITS: Map<string, number>;
export function functionsOf(code: string, filename?: string): { name: string; line: number; lines: number }[];
export function check(root?: string, all?: { name: string; line: number; lines: number; file: string }[]): string[];
