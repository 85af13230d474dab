// The CPU renderer of docs/software-renderer.md: pure (no DOM, no GL), for a worker or Node.
export { SoftwareRenderer, type SoftwareRendererOptions } from './software-renderer';
export type { SoftwareTiming } from './object-shader';
export { Rasterizer, type FragmentShader, type CullMode } from './raster';
export { splitRows, renderBand, putBand, type Band } from './bands';
