// Where an attribute's change goes once it is parsed into the element's values (ARCHITECTURE.md,
// "Two attribute routes"): the scene value and the frame state read the values themselves; the
// camera, the renderer, the canvas's size and a shader failure's retry are told here.
import type { SceneAttributes } from './attributes';
import type { CameraRig } from './camera-rig';
import type { BackendController } from './backend-controller';
import type { FrameLoop } from './frame-loop';
import type { Failure } from './failure';
import type { LoadingView } from './loading-view';

export interface AttributeRoutes {
  readonly rig: CameraRig;
  readonly backend: BackendController;
  readonly loop: FrameLoop;
  readonly failure: Failure;
  readonly loading: LoadingView;
  readonly element: HTMLElement;
  requestRender(): void;
}

/** After `property` changed: what else it moves, then a frame. */
export function routeAttribute(p: keyof SceneAttributes, r: AttributeRoutes): void {
  // The pose written back at rest is the one just drawn: nothing to move, nothing to draw.
  if (r.rig.writingBack) return;
  if (p === 'cameraPosition' || p === 'cameraRotation' || p === 'cameraTarget') r.rig.cameraAttributeChanged();
  if (p === 'controls') r.rig.controlsChanged();
  if (p === 'renderer' && r.element.isConnected) r.backend.rendererChanged();
  if (p === 'cameraSrc') r.rig.cameraSrcChanged();
  if (p === 'poster') r.loading.posterChanged();
  // Resize only: drawing here, mid-way through a script's batch of attribute changes, would
  // show a frame with half of them applied (the next animation frame comes before paint).
  if (p === 'pixelRatio') r.loop.resize();
  // A shader failure is not final: the change may select a variant that compiles. The message
  // stays up until a frame is drawn.
  r.failure.retry();
  r.requestRender();
}
