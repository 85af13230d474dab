// Milliseconds per frame of the software renderer on the default scene at 640×360 in Node,
// printed for the record against SPEC's ≤ 25 ms target; not asserted (machines differ).
import { expect, it } from 'vitest';
import { DEFAULT_CAMERA_POSITION, DEFAULT_CAMERA_ROTATION } from '../../src/element/attributes';
import type { FrameState } from '../../src/render/types';
import { defaultScene } from '../../src/scene/default-scene';
import { SoftwareRenderer } from '../../src/software';

const STATE: FrameState = {
  width: 640, height: 360, time: 1.25, spin: 0.8, cubeDistance: 0.75, transparency: 0.5, ior: 1.5, fresnel: 'exact',
  fov: 60, cameraPosition: DEFAULT_CAMERA_POSITION, yaw: DEFAULT_CAMERA_ROTATION[0], pitch: DEFAULT_CAMERA_ROTATION[1],
  view: 'final', reflectionScale: 1, samples: 0, shading: 'phong', tessellation: 'auto', reflectionFormat: 'rgba8',
};

it('prints ms per frame, default scene, 640×360 (median of 15 after 3 warm-up frames)', () => {
  const scene = defaultScene(STATE.cubeDistance, STATE.spin);
  for (const [samplesPerAxis, shading] of [[1, 'phong'], [1, 'gouraud'], [2, 'phong']] as const) {
    const renderer = new SoftwareRenderer({ samplesPerAxis });
    const times: number[] = [];
    for (let i = 0; i < 18; i++) {
      const t0 = performance.now();
      // The clock moves so the cube turns: every frame is a new one.
      renderer.render({ ...STATE, shading, time: STATE.time + i / 60 }, scene);
      if (i >= 3) times.push(performance.now() - t0);
    }
    times.sort((a, b) => a - b);
    const median = times[times.length >> 1];
    console.log(`software renderer, default scene 640×360, ${samplesPerAxis}×${samplesPerAxis} samples, ${shading}: `
      + `${median.toFixed(1)} ms/frame median (min ${times[0].toFixed(1)}, max ${times[times.length - 1].toFixed(1)})`);
    expect(median).toBeGreaterThan(0);
  }
});
