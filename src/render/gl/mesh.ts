// A vertex array with position/normal/uv buffers and an index buffer, from MeshData.
import type { MeshData } from '../../scene/geometry/mesh-data';
import type { ResourceCounter } from './resource-counter';

/** Attribute locations fixed by `layout(location = …)` in every shader. */
export const ATTRIB = { position: 0, normal: 1, uv: 2, centroid: 3, tangent: 4, color: 5 } as const;

export class Mesh {
  private readonly vao: WebGLVertexArrayObject;
  private readonly buffers: WebGLBuffer[] = [];
  readonly count: number;
  private readonly indexType: number;

  constructor(private readonly gl: WebGL2RenderingContext, private readonly counter: ResourceCounter, data: MeshData) {
    this.vao = gl.createVertexArray()!;
    counter.add('vertexArrays');
    gl.bindVertexArray(this.vao);
    this.attribute(ATTRIB.position, data.positions, 3);
    this.attribute(ATTRIB.normal, data.normals, 3);
    this.attribute(ATTRIB.uv, data.uvs, 2);
    if (data.centroids) this.attribute(ATTRIB.centroid, data.centroids, 3);
    if (data.tangents) this.attribute(ATTRIB.tangent, data.tangents, 4);
    if (data.colors) this.attribute(ATTRIB.color, data.colors, 3);
    const ibo = this.buffer(gl.ELEMENT_ARRAY_BUFFER, data.indices);
    this.buffers.push(ibo);
    gl.bindVertexArray(null);
    this.count = data.indices.length;
    this.indexType = data.indices instanceof Uint32Array ? gl.UNSIGNED_INT : gl.UNSIGNED_SHORT;
  }

  private buffer(target: number, data: ArrayBufferView): WebGLBuffer {
    const gl = this.gl;
    const b = gl.createBuffer()!;
    this.counter.add('buffers');
    gl.bindBuffer(target, b);
    gl.bufferData(target, data, gl.STATIC_DRAW);
    return b;
  }

  private attribute(location: number, data: Float32Array, size: number): void {
    const gl = this.gl;
    this.buffers.push(this.buffer(gl.ARRAY_BUFFER, data));
    gl.enableVertexAttribArray(location);
    gl.vertexAttribPointer(location, size, gl.FLOAT, false, 0, 0);
  }

  draw(): void {
    const gl = this.gl;
    gl.bindVertexArray(this.vao);
    gl.drawElements(gl.TRIANGLES, this.count, this.indexType, 0);
    gl.bindVertexArray(null);
  }

  dispose(): void {
    const gl = this.gl;
    for (const b of this.buffers) gl.deleteBuffer(b);
    this.counter.add('buffers', -this.buffers.length);
    this.buffers.length = 0;
    gl.deleteVertexArray(this.vao);
    this.counter.add('vertexArrays', -1);
  }
}
