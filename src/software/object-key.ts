// The key of an opaque draw's cached colours (object-cache.ts): everything a fragment's colour depends on besides the pixel and
// the triangle, for ObjectShader.
import type { ObjectDraw } from './object-shader';
import type { Rasterizer } from './raster';

/**
 * Everything a fragment's colour depends on besides the pixel and the triangle: the vertex
 * stage's inputs, lights, material, mapping bounds and the grid (values into `k`, objects
 * into `o`). Meshes and textures are compared by identity: scene values are never
 * written in place.
 */
export function objectKey(d: ObjectDraw, r: Rasterizer, top: number, k: Float64Array, o: unknown[]): Float64Array {
  const m = d.material, l = d.lights, cp = d.clipPlane, mesh = d.mesh, c = d.bounds.center;
  k.fill(0);
  let i = put(k, 0, d.model, 16);
  i = put(k, i, d.normal, 9);
  i = put(k, i, d.viewProjection, 16);
  i = put(k, i, d.eye, 3);
  i = put(k, i, d.view, 4);
  // Stryker disable next-line ConditionalExpression,EqualityOperator: no plane keys as (0, 0, 0, 0), which keeps all (0 ≥ 0)
  k[i++] = cp === null ? 0 : 1;
  if (cp !== null) i = put(k, i, cp, 4); else i += 4;
  k[i++] = c[0]; k[i++] = c[1]; k[i++] = c[2]; k[i++] = d.bounds.radius;
  i = put(k, i, m.ambient, 3);
  i = put(k, i, m.diffuse, 3);
  i = put(k, i, m.specular, 3);
  k[i++] = m.shininess; k[i++] = m.opacity; k[i++] = d.twoSided ? 1 : 0; k[i++] = top; k[i++] = l.intensity;
  if (m.emissive) i = put(k, i, m.emissive, 3); else i += 3;
  // Stryker disable next-line ConditionalExpression,EqualityOperator,StringLiteral: culling picks faces, not colours
  k[i++] = r.width; k[i++] = r.height; k[i++] = r.shadeEvery; k[i++] = r.frontCCW ? 1 : 0; k[i++] = r.cull === 'back' ? 1 : 0;
  // Stryker disable next-line UpdateOperator: all lights' values stay keyed; a light of zeros lights nothing
  k[i++] = l.count;
  for (let j = 0; j < l.count; j++) {
    i = put(k, i, l.vector.subarray(3 * j), 3);
    k[i++] = l.point[j];
    i = put(k, i, l.ambient.subarray(3 * j), 3);
    i = put(k, i, l.diffuse.subarray(3 * j), 3);
    i = put(k, i, l.specular.subarray(3 * j), 3);
  }
  o.length = 0;
  const t = d.maps;
  o.push(mesh, mesh.positions, mesh.normals, mesh.uvs, mesh.indices, mesh.centroids, mesh.tangents, mesh.colors, d.texture, d.shading, m.mapping, m.pbr, l.environment);
  o.push(t.metalRough, t.occlusion, t.emissive, t.normal);
  return k;
}

/** Copies n values of `xs` into k from i; the next free index. */
function put(k: Float64Array, i: number, xs: ArrayLike<number>, n: number): number {
  for (let j = 0; j < n; j++) k[i + j] = xs[j];
  return i + n;
}
