// The PBR bench's peer (bench/pbr.spec.ts): a scene value of glTF spheres over a glass floor (bench/pbr-scene.ts) built with
// three.js as a three.js user would build it — MeshStandardMaterial, its physically based lights, the environment through
// PMREMGenerator, NeutralToneMapping, sRGB output — and the floor a stock `Reflector` with our glass equation, as
// bench/three-peer.ts draws the default scene's glass.
//
// three.js is a devDependency used here only; nothing under src/ imports it.
//
// Matched on purpose, so that a comparison measures the rendering method and not the inputs:
//  - geometry: our sphereMesh at the segments our WebGL renderer picks for each sphere (frame/mesh-choice.ts
//    sphereSegments, 'auto'), the glass our glassMesh (its UVs) laid in the floor's plane;
//  - materials: colour = the base colour (linear), metalness, roughness; F0 0.04 (three's default, ior 1.5);
//  - lights (docs/pbr.md#the-scenes-lights), converted to three's units: three's direct light is
//    irradiance·BRDF with irradiance = (n·l)·colour·intensity and its Lambert term c_diff/π, ours π·f·Id·(n·l), so a light of
//    ours is a three light of colour Id and intensity π; a point light of ours does not fall off with distance (a direction
//    only, software/lighting.ts), so three's PointLight has decay 0 (and distance 0: no cut-off); the lights' ambient terms
//    (Ia ⊙ c_diff, ours) summed into one AmbientLight of intensity π (three's irradiance·c_diff/π);
//  - the environment: our studio (math/studio.ts) baked into a float RGBA equirectangular DataTexture, each texel the mean of
//    4×4 directions over it (three's equirectUv: u = atan2(z, x)/2π + ½, v = asin(y)/π + ½, row 0 at v ≈ 0, flipY off),
//    through PMREMGenerator.fromEquirectangular, as scene.environment at scene.environmentIntensity = the scene's
//    intensity; the bench also times PMREM from three's RoomEnvironment (fromScene, sigma 0.04), three's usual studio;
//  - glass: Reflector (HalfFloatType target, as stock), our glass equation (exact Fresnel, premultiplied over) from
//    bench/three-peer.ts on the procedural texture in sRGB; background our colour, sRGB-decoded;
//  - tone mapping: renderer.toneMapping = NeutralToneMapping (Khronos PBR Neutral, as ours), exposure 1; sRGB output.
//
// Known differences from ours (each what three.js does; `matched: true` removes the first four for the lights check):
//  - Half metals under a light: three takes the diffuse lobe down by 1 − F of the dielectric's F0 = 0.04 (the glTF
//    specification's fresnel_mix, then mixed with the metal by metallic); ours by 1 − F of the blended F0 = mix(0.04, base,
//    metallic), as the specification's Appendix B writes it. The same at metallic 0 and 1; at ½ (the grid's middle row,
//    F0 ≈ (0.50, 0.34, 0.21) on the gold base) three's diffuse under a light is ×1.9, ×1.45, ×1.2 ours by channel.
//  - Multiple-scattering compensation: three's direct specular is multiplied by 1 + F0(1/E_ss − 1) (Turquin), its IBL adds
//    Fms·Ems of Fdez-Agüera's model, and its diffuse (ambient and IBL) is scaled by 1 − (Fss·Ess + Fms·Ems). Ours is the
//    glTF single-scattering BRDF with c_diff(1 − F0)·E/π for the diffuse IBL and no factor on the ambient fill. Rough
//    metals are brighter in three (up to ~×1.9 at roughness 1 on the gold base).
//  - Roughness: three uses max(roughness, 0.045) plus the normal's screen-space derivative (geometryRoughness, a
//    specular anti-aliasing) for lights and environment alike; ours α = max(roughness², 0.002) for lights and the roughness
//    as given for the environment.
//  - The environment's maps: three's PMREM is a cube map (256 texels a face from this equirect) with GGX-importance
//    sampled levels and a lookup direction mixed toward n by roughness⁴; ours equirectangular levels (docs/pbr.md#prefiltered-maps)
//    read toward Frostbite's dominant direction, and an irradiance from the roughness-1 level. three's split-sum table is
//    its own (dfgLUT).
//  - Tone mapping and MSAA: with samples 0 every material is tone mapped and encoded as it draws into the canvas, so the
//    glass's premultiplied blend mixes tone-mapped, encoded values and the background is cleared to its tone-mapped
//    colour; with samples > 0 the scene is drawn into a multisampled half-float target (three resolves it) and a
//    full-screen copy tone maps and encodes once, as three's OutputPass does: then, as ours, once on the composite.
//    Ours resolves and tone maps in its encode pass; the copy is one extra full-screen pass for the peer.
//  - Reflection: as bench/three-peer.ts says (oblique near plane, the whole scene drawn, mirrored camera); the reflected
//    spheres are lit from the mirrored eye by the same world-space environment, as ours.
//  - Only spheres are built (the scenes of bench/pbr-scene.ts); the glass is laid in the floor's plane only.
import * as THREE from 'three';
import { Reflector } from 'three/addons/objects/Reflector.js';
import { RoomEnvironment } from 'three/addons/environments/RoomEnvironment.js';
import type { FrameState } from '../src/frame/types';
import type { Scene } from '../src/scene/scene';
import { sphereMesh } from '../src/scene/geometry/sphere';
import { glassMesh } from '../src/scene/geometry/rectangle';
import { glassFrame } from '../src/scene/glass-frame';
import { forwardFromYawPitch } from '../src/math/camera';
import { studioRadiance } from '../src/math/studio';
import { srgbToLinear } from '../src/math/srgb';
import { toneMapNeutral } from '../src/math/tone-map';
import { sphereSegments } from '../src/frame/mesh-choice';
import { CAMERA, GLASS } from '../src/scene/default-scene';
import { COPY_FRAGMENT, COPY_VERTEX, GLASS_FRAGMENT, fresnelDefines, proceduralDataTexture, toGeometry } from './three-peer';
import { matchedShader } from './three-pbr-matched';

export interface PbrPeerOptions {
  /** MSAA samples of the scene and the reflection (0: none, straight into the canvas). */
  samples: 0 | 2 | 4;
  /** Our single-scattering lighting in three's shader (three-pbr-matched.ts): the lights check, not the benchmark. */
  matched?: boolean;
}

/** The equirectangular bake's size (three's PMREM makes cube faces of width / 4 from it) and directions per texel axis. */
const EQUIRECT_WIDTH = 1024, EQUIRECT_SUPERSAMPLE = 4;

/** Our glass equation on the floor: the mesh's own UVs (the floor is not turned to face the camera). */
const GLASS_VERTEX = /* glsl */ `
uniform mat4 textureMatrix;
varying vec4 vReflectionUv;
varying vec3 vWorldPosition;
varying vec3 vNormal;
varying vec2 vUv;
void main() {
  vReflectionUv = textureMatrix * vec4(position, 1.0);
  vec4 world = modelMatrix * vec4(position, 1.0);
  vWorldPosition = world.xyz;
  vNormal = mat3(modelMatrix) * normal;
  vUv = uv;
  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
}
`;

const toneMapped = (fragment: string): string => fragment.replace('#include <colorspace_fragment>', '#include <tonemapping_fragment>\n  #include <colorspace_fragment>');

const linear = (c: readonly number[]): THREE.Color => new THREE.Color().setRGB(c[0], c[1], c[2], THREE.LinearSRGBColorSpace);

/** Our studio's radiance in three's equirectangular layout, each texel the mean of s×s directions over it. */
export function studioEquirect(width = EQUIRECT_WIDTH, s = EQUIRECT_SUPERSAMPLE): THREE.DataTexture {
  const height = width / 2, data = new Float32Array(width * height * 4);
  for (let j = 0; j < height; j++) {
    for (let i = 0; i < width; i++) {
      let sum = 0;
      for (let b = 0; b < s; b++) {
        const e = ((j + (b + 0.5) / s) / height - 0.5) * Math.PI; // v = asin(y)/π + ½
        for (let a = 0; a < s; a++) {
          const t = ((i + (a + 0.5) / s) / width - 0.5) * 2 * Math.PI; // u = atan2(z, x)/2π + ½
          sum += studioRadiance(Math.cos(t) * Math.cos(e), Math.sin(e), Math.sin(t) * Math.cos(e));
        }
      }
      const k = 4 * (j * width + i);
      data[k] = data[k + 1] = data[k + 2] = sum / (s * s);
      data[k + 3] = 1;
    }
  }
  const t = new THREE.DataTexture(data, width, height, THREE.RGBAFormat, THREE.FloatType);
  t.mapping = THREE.EquirectangularReflectionMapping;
  t.colorSpace = THREE.LinearSRGBColorSpace;
  t.magFilter = t.minFilter = THREE.LinearFilter;
  t.flipY = false;
  t.needsUpdate = true;
  return t;
}

export class ThreePbrPeer {
  readonly renderer: THREE.WebGLRenderer;
  private readonly gl: WebGL2RenderingContext;
  private readonly scene = new THREE.Scene();
  private readonly camera = new THREE.PerspectiveCamera(60, 1, CAMERA.near, CAMERA.far);
  private readonly spheres: { mesh: THREE.Mesh; radius: number; centre: number[]; segments: number }[] = [];
  private readonly stock: THREE.MeshStandardMaterial[] = [];
  private readonly matched: THREE.MeshStandardMaterial[] = [];
  private matchedOn = false;
  private reflector: Reflector | null = null;
  private readonly glassTexture: THREE.DataTexture;
  private pmrem: THREE.PMREMGenerator | null = null;
  private environmentMap: THREE.Texture | null = null;
  private readonly background = new THREE.Color();
  private readonly toneMappedBackground = new THREE.Color();
  private sceneTarget: THREE.WebGLRenderTarget | null = null;
  private readonly copyScene = new THREE.Scene();
  private readonly copyCamera = new THREE.OrthographicCamera(-1, 1, 1, -1, 0, 1);
  private readonly copyMaterial: THREE.ShaderMaterial;
  private readonly forward = new Float64Array(3);
  private readonly target = new THREE.Vector3();
  private width = -1;
  private height = -1;

  constructor(canvas: HTMLCanvasElement) {
    THREE.ColorManagement.enabled = true;
    this.renderer = new THREE.WebGLRenderer({
      canvas, antialias: false, alpha: false, depth: true, stencil: false, premultipliedAlpha: true, preserveDrawingBuffer: false,
    });
    const r = this.renderer;
    r.outputColorSpace = THREE.SRGBColorSpace;
    r.toneMapping = THREE.NeutralToneMapping;
    r.toneMappingExposure = 1;
    r.setPixelRatio(1);
    this.gl = r.getContext() as WebGL2RenderingContext;
    this.glassTexture = proceduralDataTexture(r, 'srgb');
    this.copyMaterial = new THREE.ShaderMaterial({
      name: 'PbrPeerCopy', vertexShader: COPY_VERTEX, fragmentShader: toneMapped(COPY_FRAGMENT),
      uniforms: { tSource: { value: null } }, depthTest: false, depthWrite: false,
    });
    const tri = new THREE.BufferGeometry();
    tri.setAttribute('position', new THREE.BufferAttribute(new Float32Array([-1, -1, 0, 3, -1, 0, -1, 3, 0]), 3));
    const copy = new THREE.Mesh(tri, this.copyMaterial);
    copy.frustumCulled = false;
    this.copyScene.add(copy);
  }

  /** Builds `scene` (spheres, lights, glass floor, environment once prepared); replaces what an earlier call built. */
  setScene(scene: Scene): void {
    this.clearScene();
    for (const o of scene.objects) {
      const pbr = o.material.pbr;
      if (o.geometry.kind !== 'sphere' || !pbr) throw new Error('glass-plane-scene: the PBR peer builds glTF spheres only');
      const params = { color: linear(pbr.baseColor), metalness: pbr.metallic, roughness: pbr.roughness };
      const stock = new THREE.MeshStandardMaterial(params);
      const matched = new THREE.MeshStandardMaterial(params);
      matched.onBeforeCompile = matchedShader;
      matched.customProgramCacheKey = () => 'matched';
      this.stock.push(stock);
      this.matched.push(matched);
      const mesh = new THREE.Mesh(new THREE.BufferGeometry(), this.matchedOn ? matched : stock);
      mesh.position.set(...o.transform.position);
      mesh.scale.set(...o.transform.scale);
      this.spheres.push({ mesh, radius: o.geometry.radius, centre: [...o.transform.position], segments: 0 });
      this.scene.add(mesh);
    }
    const ambient = [0, 0, 0];
    for (const l of scene.lights.slice(0, 4)) {
      for (let k = 0; k < 3; k++) ambient[k] += l.ambient[k];
      const light = l.kind === 'point' ? new THREE.PointLight(linear(l.diffuse), Math.PI, 0, 0) : new THREE.DirectionalLight(linear(l.diffuse), Math.PI);
      light.position.set(...l.vector); // a directional light shines from its position toward its target, the origin
      this.scene.add(light);
    }
    if (ambient.some((a) => a > 0)) this.scene.add(new THREE.AmbientLight(linear(ambient), Math.PI));
    if (scene.glass) this.addGlass(scene.glass);
    this.background.setRGB(...scene.background.map(srgbToLinear) as [number, number, number], THREE.LinearSRGBColorSpace);
    const tm = toneMapNeutral([0, 0, 0], this.background.r, this.background.g, this.background.b);
    this.toneMappedBackground.setRGB(tm[0], tm[1], tm[2], THREE.LinearSRGBColorSpace);
    this.scene.environment = scene.environment ? this.environmentMap : null;
    this.scene.environmentIntensity = scene.environment?.intensity ?? 1;
    this.wantsEnvironment = !!scene.environment;
  }

  private wantsEnvironment = false;

  /** Bakes the studio and prefilters it (PMREM); ms of each, the GPU finished. Call before setScene. */
  prepareEnvironment(): { bake: number; pmrem: number } {
    const t0 = performance.now();
    const equirect = studioEquirect();
    const t1 = performance.now();
    this.pmrem ??= new THREE.PMREMGenerator(this.renderer);
    const target = this.pmrem.fromEquirectangular(equirect);
    this.finish();
    const t2 = performance.now();
    equirect.dispose();
    this.environmentMap?.dispose();
    this.environmentMap = target.texture;
    if (this.wantsEnvironment) this.scene.environment = this.environmentMap;
    return { bake: t1 - t0, pmrem: t2 - t1 };
  }

  /** ms of three's RoomEnvironment through PMREM (fromScene), the GPU finished; the map is thrown away. */
  roomEnvironment(): number {
    const t0 = performance.now();
    this.pmrem ??= new THREE.PMREMGenerator(this.renderer);
    const room = new RoomEnvironment();
    const target = this.pmrem.fromScene(room, 0.04);
    this.finish();
    const ms = performance.now() - t0;
    target.dispose();
    room.dispose();
    return ms;
  }

  /** Draws one frame of `state` (view 'final') into the canvas. */
  render(state: FrameState, options: PbrPeerOptions): void {
    const r = this.renderer;
    const w = Math.max(1, Math.floor(state.width)), h = Math.max(1, Math.floor(state.height));
    if (w !== this.width || h !== this.height) {
      r.setSize(w, h, false);
      this.width = w;
      this.height = h;
    }
    const cam = this.camera;
    cam.fov = state.fov;
    cam.aspect = w / h;
    cam.updateProjectionMatrix();
    const [x, y, z] = state.cameraPosition;
    cam.position.set(x, y, z);
    const f = forwardFromYawPitch(this.forward, state.yaw, state.pitch);
    cam.lookAt(this.target.set(x + f[0], y + f[1], z + f[2]));
    this.configure(state, options, w, h);

    if (options.samples > 0) {
      const target = this.ensureSceneTarget(w, h, options.samples);
      r.setClearColor(this.background, 1);
      r.setRenderTarget(target);
      r.render(this.scene, cam); // the Reflector draws its pass from onBeforeRender
      r.setRenderTarget(null);
      this.copyMaterial.uniforms.tSource.value = target.texture;
      r.autoClear = false;
      r.render(this.copyScene, this.copyCamera);
      r.autoClear = true;
    } else {
      // Straight into the canvas: the clear is not tone mapped, so it is given tone mapped (the Reflector's own pass
      // clears its target to the linear colour: addGlass).
      r.setClearColor(this.toneMappedBackground, 1);
      r.setRenderTarget(null);
      r.render(this.scene, cam);
    }
  }

  /** RGBA8 of the last frame, top row first. Call in the same task as render(). */
  readPixels(): Uint8ClampedArray {
    const { gl, width: w, height: h } = this;
    const raw = new Uint8Array(w * h * 4);
    this.renderer.setRenderTarget(null);
    gl.pixelStorei(gl.PACK_ALIGNMENT, 1);
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, raw);
    const out = new Uint8ClampedArray(w * h * 4), row = w * 4;
    for (let j = 0; j < h; j++) out.set(raw.subarray((h - 1 - j) * row, (h - j) * row), j * row);
    return out;
  }

  /** A one-pixel read: the GPU done with what came before. */
  finish(): void {
    this.renderer.setRenderTarget(null);
    this.gl.readPixels(0, 0, 1, 1, this.gl.RGBA, this.gl.UNSIGNED_BYTE, new Uint8Array(4));
  }

  private configure(state: FrameState, options: PbrPeerOptions, w: number, h: number): void {
    const matched = options.matched === true;
    if (matched !== this.matchedOn) {
      this.matchedOn = matched;
      this.spheres.forEach((s, i) => { s.mesh.material = matched ? this.matched[i] : this.stock[i]; });
    }
    for (const s of this.spheres) {
      const segments = sphereSegments(state, s.centre, s.radius * Math.max(...s.mesh.scale.toArray()), 0);
      if (segments !== s.segments) {
        s.mesh.geometry.dispose();
        s.mesh.geometry = toGeometry(sphereMesh(s.radius, segments));
        s.segments = segments;
      }
    }
    const reflector = this.reflector;
    if (!reflector) return;
    const u = (reflector.material as THREE.ShaderMaterial).uniforms;
    u.uTransparency.value = state.transparency;
    u.uIor.value = state.ior;
    const glass = reflector.material as THREE.ShaderMaterial;
    const defines = fresnelDefines(state.fresnel);
    if (Object.keys(defines)[0] !== Object.keys(glass.defines ?? {})[0]) {
      glass.defines = defines;
      glass.needsUpdate = true;
    }
    const rt = reflector.getRenderTarget();
    if (rt.samples !== options.samples) {
      rt.dispose();
      rt.samples = options.samples;
    }
    const rw = Math.max(1, Math.round(w * state.reflectionScale)), rh = Math.max(1, Math.round(h * state.reflectionScale));
    if (rt.width !== rw || rt.height !== rh) rt.setSize(rw, rh);
  }

  private ensureSceneTarget(w: number, h: number, samples: number): THREE.WebGLRenderTarget {
    // Half float, linear: light above 1 kept until the copy tone maps it, as our tone-mapped frame keeps it.
    const t = (this.sceneTarget ??= new THREE.WebGLRenderTarget(w, h, {
      samples, type: THREE.HalfFloatType, format: THREE.RGBAFormat, colorSpace: THREE.LinearSRGBColorSpace,
      depthBuffer: true, stencilBuffer: false, generateMipmaps: false, minFilter: THREE.NearestFilter, magFilter: THREE.NearestFilter,
    }));
    if (t.samples !== samples) {
      t.dispose();
      t.samples = samples;
    }
    if (t.width !== w || t.height !== h) t.setSize(w, h);
    return t;
  }

  private addGlass(g: NonNullable<Scene['glass']>): void {
    // Our glass mesh of a pane facing +Z (Reflector's plane is its local XY) turned onto the glass's normal: for the floor a
    // turn of −90° about X, which takes the pane's frame (a = +X, b = +Y) onto the floor's (a = +X, b = −Z), UVs and all.
    const geometry = toGeometry(glassMesh(glassFrame({ center: [0, 0, 0], normal: [0, 0, 1], size: g.size })));
    const reflector = new Reflector(geometry, {
      textureWidth: 1, textureHeight: 1, clipBias: 0, multisample: 0,
      shader: {
        name: 'PbrPeerGlass',
        uniforms: {
          color: { value: null }, tDiffuse: { value: null }, textureMatrix: { value: null }, uTexture: { value: null },
          uTransparency: { value: 0.5 }, uIor: { value: 1.5 }, uBodyTint: { value: null },
        },
        vertexShader: GLASS_VERTEX,
        fragmentShader: toneMapped(GLASS_FRAGMENT),
      },
    });
    reflector.quaternion.setFromUnitVectors(new THREE.Vector3(0, 0, 1), new THREE.Vector3(...g.normal).normalize());
    reflector.position.set(...g.center);
    const m = reflector.material as THREE.ShaderMaterial;
    m.uniforms.uTexture.value = this.glassTexture;
    m.uniforms.uBodyTint.value = new THREE.Vector3(...GLASS.tint.map((c) => c * GLASS.darkness));
    m.defines = fresnelDefines('exact');
    m.transparent = true;
    m.blending = THREE.CustomBlending;
    m.blendEquation = THREE.AddEquation;
    m.blendSrc = THREE.OneFactor;
    m.blendDst = THREE.OneMinusSrcAlphaFactor;
    m.depthWrite = false;
    m.side = THREE.DoubleSide;
    // The reflection is drawn into a linear half-float target: cleared to the linear background whatever the canvas is.
    const before = reflector.onBeforeRender, saved = new THREE.Color();
    reflector.onBeforeRender = (...args) => {
      const r = this.renderer;
      r.getClearColor(saved);
      r.setClearColor(this.background, 1);
      before.apply(reflector, args);
      r.setClearColor(saved, 1);
    };
    this.reflector = reflector;
    this.scene.add(reflector);
  }

  private clearScene(): void {
    for (const s of this.spheres) s.mesh.geometry.dispose();
    for (const m of [...this.stock, ...this.matched]) m.dispose();
    this.spheres.length = this.stock.length = this.matched.length = 0;
    if (this.reflector) {
      this.reflector.geometry.dispose();
      this.reflector.dispose();
      this.reflector = null;
    }
    this.scene.clear();
  }
}
