// Shared by the course-file tests: the samples under tests/data/course and LoadError checks.
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { expect } from 'vitest';
import { LoadError } from '../../../src/loaders/load-error';

const DATA = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../../data/course');

/** A sample's text, decoded as the element decodes a fetched body (UTF-8, BOM kept in the string). */
export function sample(name: string): string {
  return new TextDecoder('utf-8', { ignoreBOM: true }).decode(fs.readFileSync(path.join(DATA, name)));
}

/** `run` throws a LoadError for `url` at `line` whose message matches `pattern`. */
export function expectLoadError(run: () => unknown, url: string, line: number | undefined, pattern: RegExp): LoadError {
  let caught: unknown;
  try {
    run();
  } catch (e) {
    caught = e;
  }
  expect(caught, 'a LoadError').toBeInstanceOf(LoadError);
  const e = caught as LoadError;
  expect(e.url).toBe(url);
  expect(e.line).toBe(line);
  expect(e.detail.message).toMatch(pattern);
  expect(e.message.startsWith(`glass-plane-scene: ${url}`)).toBe(true);
  return e;
}

export const xyz = (a: ArrayLike<number>, k: number): [number, number, number] => [a[3 * k], a[3 * k + 1], a[3 * k + 2]];

/** The LoadError `run` throws (failing the test if it throws anything else, or nothing). */
export function loadErrorOf(run: () => unknown): LoadError {
  try {
    run();
  } catch (e) {
    expect(e).toBeInstanceOf(LoadError);
    return e as LoadError;
  }
  throw new Error('expected a LoadError');
}
