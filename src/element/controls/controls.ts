// The `controls` chunk (SPEC §10): the flyby's keys and mouse look, orbit and trackball
// pointers with their inertia. Loaded by CameraRig the first time `controls` asks for any of
// them; a page without `controls` never fetches it.
export { FlybyController } from './flyby-controller';
export { FlybyInput } from './flyby-input';
export { PointerControls } from './pointer-controls';
