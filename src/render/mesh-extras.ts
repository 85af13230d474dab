// What only some scenes' meshes need, a chunk of its own (docs/package.md#chunks): flat shading's per-face
// copies, the Gaussian surface, and the reflection's clustering of dense meshes. ObjectMeshes
// fetches it (through Renderer.load) the first time a frame asks for one of them; the element
// holds that frame until it is in.
export { flatMesh } from '../scene/geometry/flat';
export { GAUSSIAN_EXTENT, gaussianMesh } from '../scene/geometry/gaussian';
export { clusterMesh, meshExtent } from '../scene/geometry/cluster';
