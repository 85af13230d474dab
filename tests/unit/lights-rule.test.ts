// One rule for lights (docs/scene-model.md#lights): a scene value lit by more than MAX_LIGHTS
// lights is drawn with its first MAX_LIGHTS, by the software renderer and the reference alike
// (WebGL: tests/e2e/scene-reference.spec.ts).
import { describe, expect, it } from 'vitest';
import { SoftwareRenderer } from '../../src/software';
import { renderScene } from '../../src/reference';
import { MAX_LIGHTS } from '../../src/scene/scene';
import { FIFTH, FOUR, litBy } from './helpers/lights';
import { defaultFrameState } from './helpers/frame-state';
import { differingBytes } from './helpers/pixel-diff';

const state = defaultFrameState({ width: 96, height: 54, spin: 0 });

describe(`lights past the first ${MAX_LIGHTS}`, () => {
  it(`the rule's subject: ${MAX_LIGHTS} lights, the fifth alone would show`, () => {
    expect(FOUR.length).toBe(MAX_LIGHTS);
    const four = renderScene(litBy(FOUR), state).rgba;
    expect(differingBytes(renderScene(litBy([...FOUR.slice(1), FIFTH]), state).rgba, four)).toBeGreaterThan(1000);
  });

  it('the reference leaves the fifth out', () => {
    expect(differingBytes(renderScene(litBy([...FOUR, FIFTH]), state).rgba, renderScene(litBy(FOUR), state).rgba)).toBe(0);
  });

  it('the software renderer leaves the fifth out', () => {
    const r = new SoftwareRenderer();
    const four = r.render(litBy(FOUR), state).slice();
    expect(differingBytes(r.render(litBy([...FOUR, FIFTH]), state), four)).toBe(0);
  });
});
