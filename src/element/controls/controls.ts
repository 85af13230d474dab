// The `controls` chunk (docs/interaction.md#controls): the flyby's keys and mouse look, orbit and trackball
// pointers with their inertia, and the write-back at a gesture's end (controls-input.ts); with
// them the group rotation (scene/group-rotation.ts), handed to the element's SceneValue, so the
// trackball's first turn finds what applies it to `scene` already in.
// Loaded by CameraRig the first time `controls` asks for any of them; a page without
// `controls` never fetches it.
export { ControlsInput } from './controls-input';
export * as groupRotation from '../../scene/group-rotation';
