// Pass 2: the opaque objects from the real eye, depth-tested. `depthOnly` primes depth for
// the Fresnel debug view without writing colour.
import { CUBE, SPHERE } from '../../scene/default-scene';
import { setLighting, setMatrices, type PassContext } from './pass-context';

/** Draws into the bound framebuffer and viewport; returns the number of draw calls. */
export function scenePass(ctx: PassContext, depthOnly = false): number {
  const { gl, setup, meshes } = ctx;
  const program = ctx.programs.standard('none', ctx.state.shading);
  gl.enable(gl.DEPTH_TEST);
  gl.enable(gl.CULL_FACE);
  if (depthOnly) gl.colorMask(false, false, false, false);
  try {
    program.use();
    setLighting(gl, program);
    ctx.texture.bind(0);
    setMatrices(gl, program, setup.main.cube);
    gl.uniform3fv(program.location('uAlbedo'), CUBE.albedo);
    meshes.cube.draw();
    setMatrices(gl, program, setup.main.sphere);
    gl.uniform3fv(program.location('uAlbedo'), SPHERE.albedo);
    meshes.sphere.draw();
  } finally {
    if (depthOnly) gl.colorMask(true, true, true, true);
    gl.disable(gl.CULL_FACE);
    gl.disable(gl.DEPTH_TEST);
  }
  return 2;
}
