// <glass-object>: one object of the scene (docs/scene-model.md#glass-object): a built-in shape, or a model loaded from
// `src`. Fires `progress`, `load` and `error` (bubbling, composed); never throws. A changed or
// removed `src` aborts the old load, whose result is never shown.
import { normalizeObj } from '../../loaders/obj-normalize';
import type { ObjResult } from '../../loaders/obj';
import { materialImages, type SceneObject, type Transform } from '../../scene/scene';
import { builtinShape } from './builtin-shapes';
import { ChildElement, defineChildProperties } from './child-element';
import { acquireModel, loadErrorDetail, type ModelHandle } from './model-cache';
import type { LoadedModel } from './model-loader';
import { meshParts, type MeshPart } from './mesh-parts';
import { defaultObjectAttributes, OBJECT_ATTRIBUTES, type ObjectAttributes } from './object-attributes';
import { absoluteUrl } from '../absolute-url';
import { resolveMaterial, type MtlValues } from './object-material';
import { decodeImage } from '../texture-images';

export { OBJECT_TAG } from './tags';
import { OBJECT_TAG } from './tags';

/**
 * Parts per loaded model, raw and normalised, by Bézier resolution ('' for the model as
 * loaded): shared by every element showing it.
 */
const partsCache = new WeakMap<LoadedModel, Map<string, MeshPart[]>>();

/** `resolution`: a Bézier `.byu` re-evaluated on that grid (null: the file's E). */
function partsOf(model: LoadedModel, normalize: boolean, resolution: number | null): MeshPart[] {
  let entry = partsCache.get(model);
  if (!entry) partsCache.set(model, (entry = new Map()));
  const grid = model.bezier && resolution !== null && resolution !== model.bezier.fileResolution ? resolution : null;
  const key = `${normalize ? '#normalized' : ''}${grid === null ? '' : `#E${grid}`}`;
  let parts = entry.get(key);
  if (!parts) {
    let obj: ObjResult = grid === null || !model.bezierAt ? model.obj : model.bezierAt(grid);
    if (normalize) obj = normalizeObj(obj);
    entry.set(key, (parts = meshParts(obj, `${model.url}${key}`)));
  }
  return parts;
}

export interface GlassObject extends ObjectAttributes {}

/**
 * One object of the scene (docs/scene-model.md#glass-object): a built-in shape, or a model loaded from `src`. A child of
 * `<glass-plane-scene>`; every attribute is also a camelCase property (`normalize`:
 * `normalizeModel`). Material attributes win over the MTL's values, the MTL over the defaults.
 *
 * @tagname glass-object
 * @attr {string} [src=null] - URL of an .obj model (its mtllib resolved against it); the format is sniffed from the content
 * @attr {'cube' | 'sphere' | 'gaussian'} [shape=null] - cube (edge 1), sphere (radius 0.5) or gaussian; cube when there is no src, ignored when there is
 * @attr {number} [resolution=40] - N×N vertices of the gaussian grid
 * @attr {string} [position="0 0 0"] - "x y z" of the object's origin
 * @attr {string} [rotation="0 0 0"] - "x y z" in degrees, applied X then Y then Z
 * @attr {string} [scale="1 1 1"] - one number or "x y z"
 * @attr {boolean} [normalize=false] - centre the model on the origin and scale its longest side to 2, before the transform
 * @attr {string} [ambient=null] - "r g b" 0..1, Ka; the MTL's value, else "0.2 0.2 0.2"
 * @attr {string} [diffuse=null] - "r g b" 0..1, Kd; the MTL's value, else "0.8 0.8 0.8"
 * @attr {string} [specular=null] - "r g b" 0..1, Ks; the MTL's value, else "0.5 0.5 0.5"
 * @attr {number} [shininess=null] - Blinn-Phong exponent 0..10000; the MTL's Ns, else 32
 * @attr {number} [opacity=null] - 1 − kt, 0..1; the MTL's d, else 1
 * @attr {string} [texture=null] - URL of an image multiplying Ka and Kd; the MTL's map_Kd, else the procedural texture
 * @attr {'uv' | 'triplanar' | 'cylindrical' | 'spherical'} [mapping=null] - uv where the model has UVs, else spherical
 * @attr {boolean} [reflect=true] - "false" keeps the object out of the glass's reflection (it is drawn everywhere else)
 * @fires {CustomEvent<ModelProgress>} progress - bytes of the model received (bubbles, composed)
 * @fires {CustomEvent<{ url: string; warnings: string[] }>} load - the model is loaded and shown (bubbles, composed)
 * @fires {CustomEvent<LoadErrorDetail>} error - the model could not be loaded or read (bubbles, composed)
 */
export class GlassObject extends ChildElement<ObjectAttributes> {
  static get observedAttributes(): string[] {
    return OBJECT_ATTRIBUTES.map((a) => a.attribute);
  }

  private handle: ModelHandle | null = null;
  /** The URL being loaded or shown. */
  private loadingUrl: string | null = null;
  private model: LoadedModel | null = null;
  private pending = false;

  constructor() {
    super(OBJECT_TAG, OBJECT_ATTRIBUTES, defaultObjectAttributes());
  }

  override connectedCallback(): void {
    this.updateLoad();
    super.connectedCallback();
  }

  override disconnectedCallback(): void {
    // A move (removed and inserted in one task) keeps its load; a removal aborts it.
    queueMicrotask(() => {
      if (!this.isConnected) this.stopLoad();
    });
  }

  protected override attributeParsed(property: string): void {
    if (property === 'src') this.updateLoad();
    super.attributeParsed(property);
  }

  /** True while a model is being fetched or parsed. */
  get loading(): boolean {
    return this.pending;
  }

  /**
   * The object as scene parts: one per material of a model; none while it loads or after it
   * failed. `fileMaterial`: the element's lighting-file material (docs/course-files.md#lighting-file), below the
   * object's attributes and its MTL.
   */
  toSceneObjects(fileMaterial: MtlValues | null = null): SceneObject[] {
    const v = this.values;
    const transform: Transform = { position: v.position, rotation: v.rotation, scale: v.scale, spin: 0 };
    const texture = absoluteUrl(v.texture);
    if (v.src !== null) {
      if (!this.model) return [];
      const model = this.model;
      // `resolution` re-evaluates a Bézier .byu only when set: its default is the Gaussian's.
      const resolution = this.hasAttribute('resolution') ? v.resolution : null;
      const context = { file: fileMaterial, plain: model.byu || model.gltf };
      return partsOf(model, v.normalizeModel, resolution).map((part) => ({
        geometry: part.geometry,
        transform,
        material: resolveMaterial(v, part.material === null ? undefined : model.materials.get(part.material), part.hasUvs, texture, context),
        bounds: part.bounds,
        ...(v.reflect ? {} : { reflected: false }),
      }));
    }
    const { geometry, bounds } = builtinShape(v.shape ?? 'cube', v.resolution);
    return [{ geometry, transform, material: resolveMaterial(v, undefined, true, texture, { file: fileMaterial }), bounds, ...(v.reflect ? {} : { reflected: false }) }];
  }

  /** The first scene part (a built-in shape is one), or null while no model is shown. */
  toSceneObject(): SceneObject | null {
    return this.toSceneObjects()[0] ?? null;
  }

  private updateLoad(): void {
    const url = this.isConnected ? absoluteUrl(this.values.src) : null;
    if (url === this.loadingUrl && (url !== null || this.values.src === null)) return;
    this.stopLoad();
    if (this.values.src === null || !this.isConnected) return;
    if (url === null) {
      this.pending = false;
      this.fire('error', { type: 'load', url: this.values.src, message: 'not a usable URL' });
      return;
    }
    this.loadingUrl = url;
    this.pending = true;
    const handle = acquireModel(url, (p) => {
      if (this.handle === handle) this.fire('progress', p);
    });
    this.handle = handle;
    handle.promise.then(
      (model) => {
        if (this.handle !== handle) return; // superseded: never shown
        this.model = model;
        this.changed();
        // `load` when the object can be drawn with its textures (docs/scene-model.md#loading): after its images
        // decode (or fail, with a warning), the scene element draws them on its next frame.
        const images = new Set<string>();
        for (const o of this.toSceneObjects()) for (const url of materialImages(o.material)) images.add(url);
        void Promise.all([...images].map(decodeImage)).then(() => {
          if (this.handle !== handle) return;
          this.pending = false;
          this.changed();
          // A Bézier .byu says which index of its control points varies fastest (docs/course-files.md#bezier-byu).
          const order = model.bezier ? { order: model.bezier.order } : {};
          this.fire('load', { url, warnings: [...model.warnings], ...order });
        });
      },
      (e) => {
        if (this.handle !== handle) return;
        this.pending = false;
        // Forgotten here as in the cache: src set again, even to this URL, fetches again.
        this.loadingUrl = null;
        this.changed();
        this.fire('error', loadErrorDetail(url, e));
      },
    );
  }

  private stopLoad(): void {
    const hadModel = this.model !== null || this.pending;
    this.handle?.release();
    this.handle = null;
    this.loadingUrl = null;
    this.model = null;
    this.pending = false;
    if (hadModel) this.changed();
  }
}

defineChildProperties(GlassObject.prototype, OBJECT_ATTRIBUTES);
