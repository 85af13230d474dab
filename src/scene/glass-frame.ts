// The glass rectangle's frame: its plane and the axes its width and height run along (docs/element.md#glass-placement).
// Shared by the reference (reference/ray-scene.ts) and both renderers (frame/frame-setup.ts):
// tied down by tests/unit/glass-frame.test.ts's frames worked out by hand (oblique and off the
// origin, floor, ceiling) and geometry.test.ts's glass mesh.
import type { Glass, Vec3 } from './scene';

export interface GlassFrame {
  /** [nx, ny, nz, d] with n unit: points x with n·x + d = 0. */
  plane: [number, number, number, number];
  /** Unit width axis a = normalize(+Y × n), or +X when n ∥ Y. */
  a: [number, number, number];
  /** Unit height axis b = n × a. */
  b: [number, number, number];
  /** The four corners, counter-clockwise seen from the + side: c ∓ a·w/2 ∓ b·h/2. */
  corners: [Vec3, Vec3, Vec3, Vec3];
}

/** Below this |n × Y| the normal is taken as parallel to Y (a floor or ceiling). */
const PARALLEL = 1e-9;

export function glassFrame(glass: Glass): GlassFrame {
  const [nx, ny, nz] = glass.normal;
  // +Y × n = (nz, 0, −nx)
  let ax = nz, ay = 0, az = -nx;
  let len = Math.hypot(ax, az);
  // Stryker disable next-line EqualityOperator: at |n × Y| = 1e-9 exactly both branches give a unit a ⊥ n (an exact tie no input reaches in practice)
  if (len < PARALLEL) { ax = 1; az = 0; len = 1; }
  ax /= len; az /= len;
  const b: [number, number, number] = [ny * az - nz * ay, nz * ax - nx * az, nx * ay - ny * ax];
  const [cx, cy, cz] = glass.center;
  const hw = glass.size[0] / 2, hh = glass.size[1] / 2;
  const corner = (s: number, t: number): Vec3 => [
    cx + s * hw * ax + t * hh * b[0], cy + s * hw * ay + t * hh * b[1], cz + s * hw * az + t * hh * b[2],
  ];
  return {
    plane: [nx, ny, nz, -(nx * cx + ny * cy + nz * cz)],
    a: [ax, ay, az], b,
    corners: [corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1)],
  };
}
