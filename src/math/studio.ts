// The "neutral" studio (docs/pbr.md#the-studio): the light a scene with PBR materials is lit by when
// the page names no environment. A room of our own design, defined in directions so that the
// reference can evaluate it exactly and sample it by its light: a grey room darker below the
// horizon, and four soft white panels, each a rectangle in azimuth and elevation, whose solid angle
// is Δφ·(sin e₁ − sin e₀) and over which a direction is drawn uniformly by drawing φ and sin e.
// Tied down by tests/unit/studio.test.ts (panels hit and missed by hand, solid angles by quadrature).

/** A panel: azimuth φ from +Z toward +X and elevation e above the horizon (radians), and its radiance. */
export interface StudioPanel {
  name: string;
  phi0: number;
  phi1: number;
  e0: number;
  e1: number;
  radiance: number;
}

const DEG = Math.PI / 180;

/** The room's radiance above the horizon (walls and ceiling) and below it (the floor). */
export const STUDIO_WALL = 0.3;
export const STUDIO_FLOOR = 0.1;
/** The room's radiance blends from floor to wall between these sines of elevation (±5°). */
export const STUDIO_BLEND = Math.sin(5 * DEG);

export const STUDIO_PANELS: readonly StudioPanel[] = [
  // A large soft key light front left, high; a dimmer fill front right, low; a rim light behind; a
  // softbox overhead. Azimuth 0 is +Z (toward a camera on the default scene's side of the glass).
  { name: 'key', phi0: -70 * DEG, phi1: -20 * DEG, e0: 30 * DEG, e1: 60 * DEG, radiance: 6 },
  { name: 'fill', phi0: 30 * DEG, phi1: 80 * DEG, e0: 5 * DEG, e1: 35 * DEG, radiance: 2 },
  { name: 'rim', phi0: 150 * DEG, phi1: 210 * DEG, e0: 15 * DEG, e1: 45 * DEG, radiance: 4 },
  { name: 'top', phi0: -180 * DEG, phi1: 180 * DEG, e0: 75 * DEG, e1: 90 * DEG, radiance: 3 },
];

/**
 * Whether (φ, e) lies on the panel: φ in (−π, π], tried as φ + 2π too for a panel that spans past π
 * (φ₀ ≤ π for every panel, so φ + 2π is past φ₀). Edges count as in: a set of no solid angle.
 */
function inPanel(p: StudioPanel, phi: number, e: number): boolean {
  // Stryker disable next-line EqualityOperator: an edge is a set of no solid angle (no direction drawn lies exactly on one)
  if (e < p.e0 || e > p.e1) return false;
  // Stryker disable next-line EqualityOperator: an edge is a set of no solid angle (no direction drawn lies exactly on one)
  return (phi >= p.phi0 && phi <= p.phi1) || phi + 2 * Math.PI <= p.phi1;
}

/** The index in STUDIO_PANELS of the panel the unit direction (x, y, z) meets, or −1 (the panels do not overlap). */
export function studioPanelAt(x: number, y: number, z: number): number {
  const e = Math.asin(Math.max(-1, Math.min(1, y)));
  const phi = Math.atan2(x, z);
  for (let i = 0; i < STUDIO_PANELS.length; i++) if (inPanel(STUDIO_PANELS[i], phi, e)) return i;
  return -1;
}

/** The studio's radiance (grey: the same in every channel) toward the unit direction (x, y, z), y up. */
export function studioRadiance(x: number, y: number, z: number): number {
  const i = studioPanelAt(x, y, z);
  if (i >= 0) return STUDIO_PANELS[i].radiance;
  // Stryker disable next-line EqualityOperator: at y = sin 5° (no solid angle) the blend gives the wall's radiance to an ulp
  if (y >= STUDIO_BLEND) return STUDIO_WALL;
  // Stryker disable next-line EqualityOperator: at y = −sin 5° (no solid angle) the blend gives the floor's radiance
  if (y <= -STUDIO_BLEND) return STUDIO_FLOOR;
  return STUDIO_FLOOR + ((y + STUDIO_BLEND) / (2 * STUDIO_BLEND)) * (STUDIO_WALL - STUDIO_FLOOR);
}

/** A panel's solid angle: Δφ·(sin e₁ − sin e₀). */
export function panelSolidAngle(p: StudioPanel): number {
  return (p.phi1 - p.phi0) * (Math.sin(p.e1) - Math.sin(p.e0));
}

/**
 * out = a unit direction drawn uniformly over the panel's solid angle from (u, v) ∈ [0, 1)²:
 * φ = φ₀ + u·Δφ, sin e = sin e₀ + v·(sin e₁ − sin e₀). Its density is 1 / panelSolidAngle(p).
 */
export function samplePanel(out: Float64Array | number[], p: StudioPanel, u: number, v: number): Float64Array | number[] {
  const phi = p.phi0 + u * (p.phi1 - p.phi0);
  const s = Math.sin(p.e0) + v * (Math.sin(p.e1) - Math.sin(p.e0));
  const c = Math.sqrt(Math.max(0, 1 - s * s));
  out[0] = c * Math.sin(phi);
  out[1] = s;
  out[2] = c * Math.cos(phi);
  return out;
}
