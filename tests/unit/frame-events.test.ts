// FrameEvents (src/element/frame-events.ts): `ready` once, `frame` every frame, `refined` after a still view's last frame, the
// counts, and whenRefined(): pending until a frame leaves the element at rest with nothing on its way (docs/refinement.md#events).
import { describe, expect, it } from 'vitest';
import { FrameEvents } from '../../src/element/frame-events';
import { defaultFrameState } from './helpers/frame-state';
import type { FrameReport, RenderStats } from '../../src/frame/types';

function setup() {
  const element = new EventTarget() as unknown as HTMLElement;
  const host = { element, drawn: () => {}, loading: () => false, atRest: () => true, failed: () => false };
  const events = new FrameEvents(host);
  const fired: string[] = [];
  for (const type of ['ready', 'frame', 'refined']) element.addEventListener(type, (e) => fired.push(`${type} ${(e as CustomEvent).detail.refinement}`));
  const draw = (k: number, frames = 3) => events.drawn(defaultFrameState({ refinement: k, refinementFrames: frames }), { time: 0, width: 1, height: 1, drawCalls: 0, passes: {} as FrameReport['passes'] });
  /** Whether `p` has settled once pending microtasks have run. */
  const settled = async (p: Promise<void>) => {
    let done: string = 'pending';
    p.then(() => { done = 'resolved'; }, (e: Error) => { done = `rejected: ${e.message}`; });
    for (let i = 0; i < 5; i++) await Promise.resolve();
    return done;
  };
  return { element, host, events, fired, draw, settled };
}

describe('FrameEvents', () => {
  it('fires ready once, frame each time, refined after frame N, and counts refinement frames apart', () => {
    const { events, fired, draw } = setup();
    draw(1);
    draw(2);
    draw(3);
    draw(0);
    draw(0, 0); // refinement off
    expect(fired).toEqual(['ready 1', 'frame 1', 'frame 2', 'frame 3', 'refined 3', 'frame 0', 'frame 0']);
    const stats = {} as RenderStats;
    events.count(stats);
    expect(stats).toEqual({ frames: 5, refinementFrames: 3 });
  });

  it('whenRefined(): pending before any frame, resolved after the frame that leaves the element at rest', async () => {
    const { events, host, draw, settled } = setup();
    const p = events.whenRefined();
    expect(await settled(p)).toBe('pending');
    host.atRest = () => false;
    draw(1);
    expect(await settled(p)).toBe('pending');
    host.atRest = () => true;
    draw(2);
    expect(await settled(p)).toBe('resolved');
    // Final now: at once, with no frame.
    expect(await settled(events.whenRefined())).toBe('resolved');
  });

  it('whenRefined(): a frame on its way (started, not drawn) is not final, even at rest', async () => {
    const { events, draw, settled } = setup();
    draw(3);
    events.started();
    const p = events.whenRefined();
    expect(await settled(p)).toBe('pending');
    draw(3);
    expect(await settled(p)).toBe('resolved');
  });

  it('whenRefined(): checks rest after the frame loop has counted the frame (a microtask later), not inside drawn()', async () => {
    const { events, host, draw, settled } = setup();
    const p = events.whenRefined();
    host.atRest = () => false;
    draw(3);
    host.atRest = () => true; // what the loop does once the backend returns
    expect(await settled(p)).toBe('resolved');
  });

  it('whenRefined(): rejects on an error that stops the frames, not on one the scene draws on through', async () => {
    const { element, events, host, settled } = setup();
    const p = events.whenRefined();
    element.dispatchEvent(new CustomEvent('error', { detail: { type: 'load', message: 'a model failed' } }));
    expect(await settled(p)).toBe('pending');
    host.failed = () => true;
    element.dispatchEvent(new CustomEvent('error', { detail: { type: 'context-lost', message: 'the context was lost' } }));
    expect(await settled(p)).toBe('rejected: the context was lost');
    // Failed: nothing is final.
    expect(await settled(events.whenRefined())).toBe('pending');
  });
});
