// <glass-light>: one light of the scene (docs/scene-model.md#glass-light). `position` makes a point light, `direction` a
// directional one; with neither it is the default light of docs/default-scene.md#the-light (with its own intensities).
// `src` loads the course's iluminacao.txt (docs/course-files.md#lighting-file): a point light at its Pl with its
// intensities (the attributes win), and a material for the element's objects.
import { DEFAULT_LIGHT } from '../../scene/default-scene';
import type { Light, Vec3 } from '../../scene/scene';
import { AttributeWarnings } from '../warnings';
import { ChildElement, defineChildProperties } from './child-element';
import { courseLight, courseMaterialValues } from './course-lighting';
import type { LoadedLighting } from './course-files';
import { acquireCourseFile, loadErrorDetail, type Handle } from './model-cache';
import { defaultLightAttributes, LIGHT_ATTRIBUTES, type LightAttributes } from './light-attributes';
import { absoluteUrl } from '../absolute-url';
import type { MtlValues } from './object-material';

export { LIGHT_TAG } from './tags';
import { LIGHT_TAG } from './tags';
const conflicts = new AttributeWarnings();

export interface GlassLight extends LightAttributes {}

/**
 * One light of the scene (docs/scene-model.md#glass-light), a child of `<glass-plane-scene>`: `position` makes a point
 * light, `direction` a directional one; with neither it is the default light of docs/default-scene.md#the-light.
 * Every attribute is also a property.
 *
 * @tagname glass-light
 * @attr {string} [position=null] - "x y z": a point light there (wins over direction)
 * @attr {string} [direction=null] - "x y z" towards a directional light; neither: the default light's direction
 * @attr {string} [ambient="0.15 0.15 0.15"] - "r g b" ≥ 0, Ia (above 1 allowed)
 * @attr {string} [diffuse="0.85 0.85 0.85"] - "r g b" ≥ 0, Id (above 1 allowed)
 * @attr {string} [specular="1 1 1"] - "r g b" ≥ 0, Is (above 1 allowed)
 * @attr {string} [src=null] - URL of the course's iluminacao.txt: a point light at Pl, and the material of the element's objects; attributes win over the file
 * @fires {CustomEvent<ModelProgress>} progress - bytes of the `src` file received (bubbles, composed)
 * @fires {CustomEvent<{ url: string; warnings: string[] }>} load - the `src` file is loaded and in the scene (bubbles, composed)
 * @fires {CustomEvent<LoadErrorDetail>} error - the `src` file could not be loaded or read (bubbles, composed)
 */
export class GlassLight extends ChildElement<LightAttributes> {
  static get observedAttributes(): string[] {
    return LIGHT_ATTRIBUTES.map((a) => a.attribute);
  }

  private handle: Handle<LoadedLighting> | null = null;
  private loadingUrl: string | null = null;
  private file: LoadedLighting | null = null;
  private pending = false;

  constructor() {
    super(LIGHT_TAG, LIGHT_ATTRIBUTES, defaultLightAttributes());
  }

  override connectedCallback(): void {
    this.updateLoad();
    super.connectedCallback();
  }

  override disconnectedCallback(): void {
    queueMicrotask(() => {
      if (!this.isConnected) this.stopLoad();
    });
  }

  protected override attributeParsed(property: string): void {
    if ((property === 'position' || property === 'direction') && this.values.position && this.values.direction) {
      conflicts.report({ attribute: 'direction' }, this.getAttribute('direction') ?? '', 'position is set too: a point light, direction ignored', LIGHT_TAG);
    }
    if (property === 'src') this.updateLoad();
    super.attributeParsed(property);
  }

  /** True while a lighting file is being fetched or parsed. */
  get loading(): boolean {
    return this.pending;
  }

  /**
   * This light as a scene value; null while its `src` loads or after it failed (a lighting
   * file that fails adds no light, docs/course-files.md#lighting-file).
   */
  toLight(): Light | null {
    const { src, position, direction, ambient, diffuse, specular } = this.values;
    if (src !== null) {
      if (!this.file) return null;
      const l = courseLight(this.file.light);
      const own = (name: string, v: Vec3, fallback: Vec3): Vec3 => (this.hasAttribute(name) ? v : fallback);
      return {
        kind: 'point', vector: position ?? l.vector,
        ambient: own('ambient', ambient, l.ambient), diffuse: own('diffuse', diffuse, l.diffuse), specular: own('specular', specular, l.specular),
      };
    }
    if (position) return { kind: 'point', vector: position, ambient, diffuse, specular };
    const vector: Vec3 = direction ? unit(direction) : DEFAULT_LIGHT.vector;
    return { kind: 'directional', vector, ambient, diffuse, specular };
  }

  /** The loaded lighting file's material in the scene's terms (course-lighting.ts), or null. */
  toMaterial(): MtlValues | null {
    return this.file ? courseMaterialValues(this.file.material) : null;
  }

  private updateLoad(): void {
    const url = this.isConnected ? absoluteUrl(this.values.src) : null;
    if (url === this.loadingUrl && (url !== null || this.values.src === null)) return;
    this.stopLoad();
    if (this.values.src === null || !this.isConnected) return;
    if (url === null) {
      this.fire('error', { type: 'load', url: this.values.src, message: 'not a usable URL' });
      return;
    }
    this.loadingUrl = url;
    this.pending = true;
    const handle = acquireCourseFile('lighting', url, (p) => {
      if (this.handle === handle) this.fire('progress', p);
    });
    this.handle = handle;
    handle.promise.then(
      (file) => {
        if (this.handle !== handle) return;
        this.file = file;
        this.pending = false;
        this.changed();
        this.fire('load', { url, warnings: [...file.warnings] });
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
    const had = this.file !== null || this.pending;
    this.handle?.release();
    this.handle = null;
    this.loadingUrl = null;
    this.file = null;
    this.pending = false;
    if (had) this.changed();
  }
}

function unit(v: Vec3): Vec3 {
  const l = Math.hypot(v[0], v[1], v[2]);
  return [v[0] / l, v[1] / l, v[2] / l];
}

defineChildProperties(GlassLight.prototype, LIGHT_ATTRIBUTES);
