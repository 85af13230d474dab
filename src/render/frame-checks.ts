// The checks a renderer runs with `checks: true` (tests, debugging): gl.getError() after each
// frame, every uniform finite. A chunk of their own (docs/package.md#chunks), fetched by Renderer.load when a
// renderer has checks on; the element holds its first frame until they are in.
export { reportGlErrors } from './gl/errors';
export { findNonFinite } from '../frame/finite-check';
