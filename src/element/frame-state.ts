// Each frame's state (FrameState, the inputs of a frame, docs/element.md#attribute-table) from the parsed attributes, filled
// in place so a frame allocates none; the camera's part is the CameraRig's. Also keeps a copy of
// the last state drawn, which capture(pass) draws a pass of.
import type { FrameState } from '../frame/types';
import type { SceneAttributes } from './attributes';
import { hasPbrMaterial, type Scene } from '../scene/scene';

/**
 * The frames a still view draws (docs/refinement.md#at-rest): `refine`, or 0 where nothing is refined — with
 * `color-space="none"` (no linear light to average) or a debug view (one pass as it is).
 */
export const refineFrames = (v: Readonly<Pick<SceneAttributes, 'refine' | 'colorSpace' | 'debugView'>>): number =>
  v.colorSpace === 'srgb' && v.debugView === 'none' ? v.refine : 0;

export class FrameStates {
  /** The state of the frame being drawn (one object, filled again every frame). */
  readonly current: FrameState = {
    width: 1, height: 1, time: 0, spin: 0, cubeDistance: 0, transparency: 0, ior: 1, fresnel: 'exact',
    fov: 60, cameraPosition: [0, 0, 0], yaw: 0, pitch: 0, view: 'final',
    reflectionScale: 1, samples: 4, shading: 'phong', tessellation: 'auto', reflectionFormat: 'rgba8', colorSpace: 'srgb',
    projection: 'perspective', target: null, roughness: 0, roughnessQuality: 'medium', toneMapping: 'none', exposure: 1,
    refinement: 0, refinementFrames: 0,
  };
  /** The state of the last frame drawn; null before the first. */
  last: FrameState | null = null;
  // Stryker disable next-line ArrayDeclaration: drawn() writes all three before anything reads them
  private readonly lastPosition: [number, number, number] = [0, 0, 0];
  /** The frame timestamp the live clock counts from (the first frame's). */
  private clockStart = -1;

  /**
   * The attributes' part of the frame at timestamp `now`, the drawing buffer `width` × `height`, the cube turning at `spin`;
   * `scene` decides `tone-mapping="auto"` (docs/pbr.md#tone-mapping: neutral with a glTF material, else none).
   */
  fill(v: Readonly<SceneAttributes>, now: number, width: number, height: number, spin: number, scene: Scene | null = null, refinement = 0): FrameState {
    const s = this.current;
    if (this.clockStart < 0) this.clockStart = now;
    s.width = width;
    s.height = height;
    s.time = v.time ?? (now - this.clockStart) / 1000;
    s.spin = spin;
    s.cubeDistance = v.cubeDistance;
    s.transparency = v.transparency;
    s.ior = v.ior;
    s.fresnel = v.fresnel;
    s.view = v.debugView === 'none' ? 'final' : v.debugView;
    s.reflectionScale = v.reflectionScale;
    // docs/refinement.md#at-rest: with refinement on, moving frames and strata frames draw one sample; the preview as asked.
    s.samples = refineFrames(v) > 0 && refinement !== 1 ? 0 : v.samples;
    s.refinement = refinement;
    s.refinementFrames = v.refine;
    s.shading = v.shading;
    s.tessellation = v.tessellation;
    s.reflectionFormat = v.reflectionFormat;
    s.colorSpace = v.colorSpace;
    s.roughness = v.roughness;
    s.roughnessQuality = v.roughnessQuality;
    s.toneMapping = v.toneMapping !== 'auto' ? v.toneMapping : scene !== null && hasPbrMaterial(scene) ? 'neutral' : 'none';
    s.exposure = v.exposure;
    return s;
  }

  /** A frame of `state` is on the canvas: keep a copy (its camera position copied too: the live pose moves on). */
  drawn(state: FrameState): void {
    // Stryker disable next-line ObjectLiteral: Object.assign below copies every field into the new object either way
    const last = (this.last ??= { ...state });
    Object.assign(last, state);
    this.lastPosition[0] = state.cameraPosition[0];
    this.lastPosition[1] = state.cameraPosition[1];
    this.lastPosition[2] = state.cameraPosition[2];
    last.cameraPosition = this.lastPosition;
  }
}
