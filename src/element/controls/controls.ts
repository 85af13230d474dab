// The `controls` chunk (SPEC §10): the flyby's keys and mouse look, orbit and trackball
// pointers with their inertia, and the write-back at a gesture's end (controls-input.ts).
// Loaded by CameraRig the first time `controls` asks for any of them; a page without
// `controls` never fetches it.
export { ControlsInput } from './controls-input';
