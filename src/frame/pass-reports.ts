// Which passes a frame runs, and why one does not: the reports both renderers give (the WebGL
// renderer's frame report, the element's for a software frame). No GL here.
import type { FrameSetup } from './frame-setup';
import type { ScreenRect } from './glass-bounds';
import type { PassName, PassReport, RenderView } from './types';

export const PASSES: readonly PassName[] = ['reflection', 'scene', 'glass'];

/** Below this projected area (px²) the glass covers no pixel centre worth a pass. */
const MIN_GLASS_AREA = 0.5;
/** A perspective eye this close to the glass plane sees it edge-on. */
const EDGE_ON_DISTANCE = 1e-3;
/**
 * An orthographic camera sees the glass edge-on when its view direction lies in the plane,
 * wherever its eye is: |forward·n| below this (the angular counterpart of EDGE_ON_DISTANCE,
 * an eye 1e-3 off the plane per unit of depth).
 */
const EDGE_ON_COS = 1e-3;

/** Why each pass does not run in a debug view. */
const SKIPPED_BY_VIEW: Record<RenderView, Partial<Record<PassName, string>>> = {
  final: {},
  passes: {},
  reflection: { scene: 'debug-view reflection', glass: 'debug-view reflection' },
  scene: { reflection: 'debug-view scene', glass: 'debug-view scene' },
  fresnel: { reflection: 'debug-view fresnel (F needs no reflection)' },
};

type PassReports = Readonly<Record<PassName, Readonly<PassReport>>>;

/** Frozen reports of the three passes given why each was skipped (absent: it ran). */
function passReports(skipped: Partial<Record<PassName, string>>): PassReports {
  const one = (p: PassName): Readonly<PassReport> =>
    Object.freeze(skipped[p] === undefined ? { ran: true } : { ran: false, reason: skipped[p] });
  return Object.freeze({ reflection: one('reflection'), scene: one('scene'), glass: one('glass') });
}

// Every frame's passes are one of these few shared, frozen records: a frame report kept by a
// listener never changes, and none is built per frame.
const PASSES_BY_VIEW = Object.fromEntries(
  Object.entries(SKIPPED_BY_VIEW).map(([view, skipped]) => [view, passReports(skipped)]),
) as Record<RenderView, PassReports>;
/** The final view with the glass (and so the reflection) skipped, by reason; filled on first use. */
const GLASS_SKIPPED = new Map<string, PassReports>();

/** The shared frozen pass reports of `view`, with the glass skipped for `glassSkip` in the final view. */
export function passesFor(view: RenderView, glassSkip?: string): PassReports {
  // Stryker disable next-line ConditionalExpression: without a reason the cached record says the same (every pass ran), frozen too
  if (view !== 'final' || glassSkip === undefined) return PASSES_BY_VIEW[view];
  let passes = GLASS_SKIPPED.get(glassSkip);
  if (!passes) GLASS_SKIPPED.set(glassSkip, (passes = passReports({ reflection: glassSkip, glass: glassSkip })));
  return passes;
}


/**
 * Why the final view needs neither the reflection nor the glass this frame, or undefined when
 * both run. `rect`: the glass on screen (glassScreenRect). `optimize` off (to measure what the
 * skips save): only a scene without glass skips them.
 */
export function glassSkipReason(setup: FrameSetup, rect: ScreenRect, optimize: boolean): string | undefined {
  const edgeOn = setup.orthographic ? Math.abs(setup.viewDot) < EDGE_ON_COS : Math.abs(setup.eyeDistance) < EDGE_ON_DISTANCE;
  return !setup.hasGlass ? 'no glass'
    : !optimize ? undefined
    // An eye in the plane (perspective), or a view direction in it (orthographic), sees the
    // glass as a line, which can round to an empty rectangle: that is edge-on, not off screen.
    : rect.area < MIN_GLASS_AREA && edgeOn ? 'glass edge-on'
    : rect.x1 <= rect.x0 || rect.y1 <= rect.y0 ? 'glass off screen'
    : rect.area < MIN_GLASS_AREA ? 'glass too small'
    : undefined;
}
