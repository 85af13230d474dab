// Controls: orbit, pan, trackball, flyby, inertia, gesture end.
// Each: { name, why (what keeps it out of Stryker's reach), edits: [{ file, find, replace }], tests: Playwright specs (*.spec.ts) or vitest files (*.test.ts) }.
const CONTROLS = 'tests/e2e/controls.spec.ts';
const INERTIA = 'tests/e2e/inertia.spec.ts';
const POINTER = 'src/element/controls/pointer-controls.ts';
const INPUT = 'src/element/controls/controls-input.ts';

export default [
  {
    name: '9 inertia stepped by Euler (frame-rate dependent)',
    why: 'inertia in a page: pointer events and the frames on the wall clock',
    edits: [{ file: 'src/element/controls/inertia.ts', find: '    const f = INERTIA_TAU * (1 - ks);', replace: '    const f = s;' }],
    tests: [INERTIA],
  },
  {
    name: '10 touch-action none without controls',
    why: 'the element\'s shadow CSS: touch-action only a browser applies',
    edits: [{ file: 'src/element/element-style.ts', find: 'canvas{display:block;width:100%;height:100%}', replace: 'canvas{display:block;width:100%;height:100%;touch-action:none}' }],
    tests: [CONTROLS],
  },
  {
    name: '11 pointer-lock entry movement turned by',
    why: 'pointer lock in a page: browser-only events',
    edits: [{ file: 'src/element/controls/flyby-input.ts', find: '    this.skipNext = true;', replace: '' }],
    tests: [CONTROLS],
  },
  {
    name: 'C1 orbit pan moves the wrong way',
    why: 'controls in a page: real pointer events on the element, seen on its canvas',
    edits: [{ file: 'src/element/controls/orbit.ts', find: 'const sx = -dx * unitsPerPx, sy = dy * unitsPerPx;', replace: 'const sx = dx * unitsPerPx, sy = dy * unitsPerPx;' }],
    tests: [CONTROLS],
  },
  {
    name: 'C2 orbit drag up tilts the camera down',
    why: 'controls in a page: real pointer events on the element, seen on its canvas',
    edits: [{ file: POINTER, find: 'pitch = -dy * ORBIT_DEG_PER_PX;', replace: 'pitch = dy * ORBIT_DEG_PER_PX;' }],
    tests: [CONTROLS],
  },
  {
    name: 'C3 trackball arcball y not flipped (a drag up turns the objects down)',
    why: 'controls in a page: real pointer events on the element, seen on its canvas',
    edits: [{ file: 'src/element/controls/arcball.ts', find: 'const y = (height / 2 - py) / r;', replace: 'const y = (py - height / 2) / r;' }],
    tests: [CONTROLS],
  },
  {
    name: 'C4 trackball axis from b × a (turns against the pointer)',
    why: 'controls in a page: real pointer events on the element, seen on its canvas',
    edits: [{ file: POINTER, find: 'vec3.cross(this.axis, this.a, this.b);', replace: 'vec3.cross(this.axis, this.b, this.a);' }],
    tests: [CONTROLS],
  },
  {
    name: 'C5 flyby strafe sign flipped (D moves left)',
    why: 'flyby in a page: real key events on the element, seen on its canvas',
    edits: [{ file: 'src/element/controls/flyby-controller.ts', find: 'const mx = fwd * fx - side * fz;', replace: 'const mx = fwd * fx + side * fz;' }],
    tests: [CONTROLS],
  },
  {
    name: 'C6 pinch dollies the wrong way (spread moves away)',
    why: 'pinch in a page: two real touch pointers on the element',
    edits: [{ file: POINTER, find: 'this.orbit.dolly(pose, span / this.span);', replace: 'this.orbit.dolly(pose, this.span / span);' }],
    tests: [CONTROLS],
  },
  {
    name: 'C7 pinch zooms about the view centre, not the fingers',
    why: 'pinch in a page: two real touch pointers on the element',
    edits: [{ file: POINTER, find: 'this.last.x - cx - (lx - cx) / k, this.last.y - cy - (ly - cy) / k,', replace: 'this.last.x - lx, this.last.y - ly,' }],
    tests: [CONTROLS],
  },
  {
    name: 'C8 wheel sign flipped (scrolling up dollies out)',
    why: 'the wheel in a page: real wheel events on the element',
    edits: [{ file: POINTER, find: 'Math.exp(dy * WHEEL_RATE)', replace: 'Math.exp(-dy * WHEEL_RATE)' }],
    tests: [CONTROLS],
  },
  {
    name: 'C9 camera-change fired at pointer up, before the inertia ends',
    why: 'inertia in a page: pointer events and the frames on the wall clock',
    edits: [{ file: POINTER, find: "    if (this.spin.active) this.host.changed(this.spinKind === 'orbit');\n    else if (this.moved) this.end();", replace: "    if (this.spin.active) this.host.changed(this.spinKind === 'orbit');\n    if (this.moved) this.end();" }],
    tests: [INERTIA],
  },
  {
    name: 'C10 camera-target left out of the write-back after a pan',
    why: 'the element in a page: the camera written back to its attributes after a drag',
    edits: [{ file: INPUT, find: "        element.setAttribute('camera-target', `${t[0]} ${t[1]} ${t[2]}`);\n", replace: '' }],
    tests: [CONTROLS],
  },
  {
    name: 'C11 a trackball turn fires camera-change (the camera did not move)',
    why: 'the element in a page: camera-change events after a drag',
    edits: [{ file: INPUT, find: '        if (camera) this.cameraDirty = true;', replace: '        this.cameraDirty = true;' }],
    tests: [CONTROLS],
  },
  {
    name: 'C12 orbit inertia in degrees per second again (capped at 6.3°/s, stops at 0.00087°/s)',
    why: 'inertia in a page: pointer events and the frames on the wall clock',
    edits: [
      { file: POINTER, find: 'this.delta[0] = yaw * DEG; this.delta[1] = pitch * DEG;', replace: 'this.delta[0] = yaw; this.delta[1] = pitch;' },
      { file: POINTER, find: 'this.orbit.rotate(this.host.pose(), d[0] / DEG, d[1] / DEG);', replace: 'this.orbit.rotate(this.host.pose(), d[0], d[1]);' },
    ],
    tests: [INERTIA],
  },
  {
    name: 'C13 stop threshold 0.05 rad/s, not 0.05°/s',
    why: 'inertia in a page: pointer events and the frames on the wall clock',
    edits: [{ file: 'src/element/controls/inertia.ts', find: 'export const INERTIA_STOP = (0.05 * Math.PI) / 180;', replace: 'export const INERTIA_STOP = 0.05;' }],
    tests: [INERTIA],
  },
  {
    name: 'C14 MAX_STEP clamp back on the clock (slow frames slow the decay)',
    why: 'inertia in a page: pointer events and the frames on the wall clock',
    edits: [{ file: 'src/element/controls/inertia.ts', find: '    const t = dt > 0 ? dt : 0;', replace: '    const t = dt > 0 ? Math.min(dt, 1 / 30) : 0;' }],
    tests: [INERTIA],
  },
  {
    name: 'C15 inertia clock not restarted at release',
    why: 'inertia in a page: pointer events and the frames on the wall clock',
    edits: [{ file: POINTER, find: '      this.spinTime = performance.now(); // the motion runs from the release, on the wall clock\n', replace: '' }],
    tests: [INERTIA],
  },
  {
    name: 'C16 the frame setup leaves out the trackball turn of the objects (a drag turns nothing on screen)',
    why: 'the element in a page: a drag\'s turn seen in the WebGL frame',
    edits: [{ file: 'src/frame/frame-setup.ts', find: '      this.modelMatrix(o, objects[i], time, this.objectsTurn);', replace: '      this.modelMatrix(o, objects[i], time, null);' }],
    tests: [CONTROLS],
  },
  {
    name: 'C17 the frame setup leaves out the turn of the first light (a right-drag relights nothing)',
    why: 'the element in a page: a right-drag\'s relighting seen in the WebGL frame',
    edits: [{ file: 'src/frame/frame-setup.ts', find: '      const g = i === 0 ? g0 : null, t', replace: '      const g = null, t' }],
    tests: [CONTROLS],
  },
  {
    name: 'C18 frames not held while the controls\' chunk loads (a drag after the next frame is lost)',
    why: 'lazy chunks in a page: the controls\' chunk holding frames while it loads',
    edits: [{ file: 'src/element/parts.ts', find: 'needed: (h) => h.values.controls !== null, holds: true', replace: 'needed: (h) => h.values.controls !== null, holds: false' }],
    tests: [CONTROLS],
  },
  {
    name: 'C19 the controls\' chunk arrives but its pointer listeners are never added',
    why: 'lazy chunks in a page: the controls\' chunk adding its pointer listeners',
    edits: [{ file: 'src/element/controls/controls-input.ts', find: '    this.pointer.hostConnected();\n', replace: '' }],
    tests: [CONTROLS],
  },
  {
    name: 'C21 the controls\' chunk arrives but the flyby\'s keys are never listened to',
    why: 'lazy chunks in a page: the controls\' chunk listening to keys',
    edits: [{ file: 'src/element/controls/controls-input.ts', find: '    this.input.hostConnected();\n', replace: '' }],
    tests: [CONTROLS],
  },
  {
    name: 'C22 the controls\' chunk fetched only for orbit and trackball (flyby never moves)',
    why: 'lazy chunks in a page: the controls\' chunk fetched for flyby',
    edits: [{ file: 'src/element/parts.ts', find: 'needed: (h) => h.values.controls !== null,', replace: 'needed: (h) => h.values.controls !== null && h.values.controls !== \'flyby\',' }],
    tests: [CONTROLS],
  },
  {
    name: 'C23 the controls\' chunk fetched without controls',
    why: 'lazy chunks in a page: the controls\' chunk not fetched without controls',
    edits: [{ file: 'src/element/parts.ts', find: 'needed: (h) => h.values.controls !== null,', replace: 'needed: () => true,' }],
    tests: [CONTROLS],
  },
  {
    name: 'C24 a press does not stop the trackball\'s spin after a flick (held, the objects turn on)',
    why: 'inertia in a page: pointer events and the frames on the wall clock',
    edits: [{ file: POINTER, find: '    this.spin.stop();\n    if (this.pointers.size === 1)', replace: '    if (this.pointers.size === 1)' }],
    tests: [INERTIA],
  },
  {
    name: 'C25 controls changed during an orbit\'s inertia drops the gesture (nothing written back, no camera-change)',
    why: 'inertia in a page: pointer events and the frames on the wall clock',
    edits: [{ file: INPUT, find: '    this.pointer.cancel();\n    this.gestureEnd();', replace: '    this.pointer.cancel();' }],
    tests: [INERTIA],
  },
  {
    name: 'C26 camera-change details share the pose\'s position array (a kept detail moves with the camera)',
    why: 'the element in a page: camera-change event details kept by a listener',
    edits: [{ file: 'src/element/camera-rig.ts', find: '{ position: [...position], rotation: [yaw, pitch] };', replace: '{ position, rotation: [yaw, pitch] };' }],
    tests: [CONTROLS],
  },
  {
    name: 'C20 no frame asked for once the element\'s lazy parts settle (frames held for ever)',
    why: 'lazy chunks in a page: frames asked for again once the parts settle',
    edits: [{ file: 'src/element/glass-plane-scene.ts', find: '{ settled: requestRender, warn }', replace: '{ settled: () => {}, warn }' }],
    tests: [CONTROLS],
  },
];
