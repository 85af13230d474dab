// The path and message of the LoadError a reader throws: what a refusal test compares.
import { expect } from 'vitest';
import { LoadError } from '../../../src/loaders/load-error';

export function refusal(run: () => unknown): { path: string | undefined; message: string } {
  try {
    run();
  } catch (e) {
    expect(e).toBeInstanceOf(LoadError);
    return { path: (e as LoadError).path, message: (e as LoadError).detail.message };
  }
  throw new Error('read without an error');
}
