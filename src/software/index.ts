// The CPU renderer of SPEC §11: pure (no DOM, no GL), for a worker or Node.
export { SoftwareRenderer, type SoftwareRendererOptions } from './software-renderer';
export { Rasterizer, type FragmentShader, type CullMode } from './raster';
