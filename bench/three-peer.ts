// The benchmark's peer: the default scene (docs/default-scene.md, docs/rendering.md) built with three.js and its stock
// `Reflector` (planar reflection by rendering the scene from a mirrored camera into a render
// target, near plane replaced by the mirror plane with Lengyel's oblique projection).
//
// three.js is a devDependency used here only; nothing under src/ imports it.
//
// What is matched on purpose, so an accuracy comparison measures the reflection technique and
// not unrelated differences:
//  - geometry and UVs: our own MeshData builders (boxMesh, sphereMesh, glassMesh);
//  - the texture: proceduralTexture(), row 0 first (flipY false), repeat, trilinear mips;
//  - colour (docs/colour.md#srgb), from state.colorSpace. 'srgb': three.js's own default pipeline — linear
//    light, sRGB output (renderer.outputColorSpace SRGBColorSpace, ColorManagement on), the texture
//    tagged SRGBColorSpace (three stores it SRGB8_ALPHA8: decoded on read, filtered in linear
//    light) and read anisotropically up to 16 taps as ours is, the background set as an sRGB
//    colour (three decodes it, and encodes it again when it clears the canvas), the 8-bit
//    targets tagged SRGBColorSpace (SRGB8_ALPHA8: blended and resolved in linear light), and every
//    fragment shader ending in three's <colorspace_fragment> (linearToOutputTexel: sRGB's OETF
//    when drawing to the canvas, nothing when drawing into a render target). 'none': values as
//    stored, as before color-space existed — RGBA8 texture and targets with no colour space, linear output,
//    ColorManagement off, isotropic reads (linearToOutputTexel is then the identity: measured,
//    the frames are bit for bit those of the peer before it had <colorspace_fragment>);
//  - no tone mapping;
//  - shading: ShaderMaterials that evaluate our Blinn-Phong (docs/default-scene.md#material-and-lighting) per fragment, and the
//    glass equation of docs/rendering.md#the-glass-equation (exact / Schlick / classic Fresnel, premultiplied blending);
//  - camera: same fov, near/far, position and lookAt(position + forward, +Y).
//
// Measured (bench/check-peer.mjs, SwiftShader, 640×360): off the glass the peer's pixels equal
// ours exactly (also with MSAA). On the glass, with reflectionType 'byte', they match to within
// 1 level at samples 0 (every Fresnel model and shading tried) and to within 4 levels on ~50
// edge pixels with MSAA (the sample pattern is not mirror-symmetric and the reflection image is
// flipped); with the stock 'half' target the mean difference on the glass is ~0.1–0.3 levels
// (reflected highlights above 1 are not clamped), max 1 at samples 0, up to 16 with MSAA at ior 10.
// Those figures are for color-space none; with 'srgb' (`cs=srgb`) and MSAA 4 the peer's pixels
// equal ours off the glass, and on it differ by 0.03–0.06 levels on average with the stock 'half'
// target (0.002–0.008 with 'byte'), max 20 on ~30 pixels along the reflected cube's edges; at
// samples 0 the glass differs by ~6 levels on average (max 32): the peer's blend mixes encoded
// values there (see below).
//
// Known differences from our renderer (each is what three.js does, or the simplest honest
// equivalent of it):
//  - Reflection clipping: oblique near plane (Reflector) instead of gl_ClipDistance; depth
//    precision in the reflection degrades as the camera nears the plane.
//  - Reflection texture: Reflector allocates a HalfFloatType target (values above 1, e.g.
//    reflected specular highlights, survive into F·R); ours is 8-bit (RGBA8, SRGB8_ALPHA8 in
//    'srgb'; clamped at 1). Set `reflectionType: 'byte'` to match ours.
//  - The mirrored camera is a proper rotation (Reflector reflects position, target and up), so
//    the reflection texture is ours flipped left-right. The flip maps texel centres onto texel
//    centres, so projective lookups sample the same values (measured: no difference).
//  - Two-sided glass: stock Reflector renders nothing when the camera is behind its plane (it
//    returns early and the glass shows whatever the texture last held). docs/default-scene.md#the-glass wants the
//    reflection of the camera's side, so the Reflector is turned to face the camera each frame (scale
//    (−1, 1, −1), a rotation by π about Y: what a three.js user would do for a two-sided
//    mirror). The glass UVs are computed from world x, y so the body texture does not flip.
//  - MSAA: three's `antialias` is a context flag with a browser-chosen sample count, so with
//    `samples` > 0 the scene is drawn into a multisampled WebGLRenderTarget (three resolves it
//    into a texture) and copied to the canvas with a full-screen triangle, as three's
//    EffectComposer/OutputPass would. Ours resolves straight into the canvas with one blit, so
//    the peer pays one extra full-screen pass there. With samples 0 both draw straight into
//    the canvas.
//  - The reflection pass renders the whole scene (no culling of objects wholly behind the glass,
//    no scissor to the glass's screen rectangle, unlike docs/knobs.md#reflection-skips). It is skipped only when three's
//    frustum culling drops the Reflector mesh (onBeforeRender runs for visible meshes only).
//  - sRGB at samples 0: the objects and the glass encode as they draw into the canvas, so the
//    glass's premultiplied blend mixes encoded values (three's default without a render target).
//    With MSAA the scene target is SRGB8_ALPHA8 and the blend is in linear light, as ours.
//    three's encode is pow(x, 0.41666), not 1/2.4: at most 0.0016 of a level off the exact curve.
//  - Only view 'final' is drawn (debug views are ignored); `state.tessellation` is ignored in
//    favour of `options.sphereSegments`.
import lighting from '../shaders/lighting.glsl?raw';
import * as THREE from 'three';
import { Reflector } from 'three/addons/objects/Reflector.js';
import type { ColorSpace, FrameState } from '../src/frame/types';
import type { MeshData } from '../src/scene/geometry/mesh-data';
import { boxMesh } from '../src/scene/geometry/box';
import { sphereMesh } from '../src/scene/geometry/sphere';
import { glassMesh } from '../src/scene/geometry/rectangle';
import { glassFrame } from '../src/scene/glass-frame';
import { proceduralTexture } from '../src/scene/procedural-texture';
import { forwardFromYawPitch } from '../src/math/camera';
import { signedDistance } from '../src/math/mirror';
import { BACKGROUND, CAMERA, CUBE, DEFAULT_GLASS, GLASS, LIGHT, MATERIAL, SPHERE, TEXTURE_SIZE } from '../src/scene/default-scene';

export interface PeerOptions {
  /** MSAA samples of the reflection and of the scene (0 = none). */
  samples: 0 | 2 | 4;
  /** Reflection target size ÷ drawing-buffer size. */
  reflectionScale: number;
  /** Sphere segments around the equator (sphereMesh). */
  sphereSegments: number;
  /** Reflection target format: 'half' = Reflector's stock HalfFloatType (default), 'byte' = RGBA8 like ours. */
  reflectionType?: 'half' | 'byte';
}

// ---- shaders (three's GLSL1-style dialect; three compiles them as GLSL ES 3.00) --------------

// The very Blinn-Phong our renderer uses, so the two scenes differ only in the reflection technique.
const BLINN_PHONG = lighting;

const LIGHTING_VARYINGS = /* glsl */ `
varying vec2 vUv;
#if defined(SHADING_PHONG)
varying vec3 vWorldPosition;
varying vec3 vNormal;
#elif defined(SHADING_FLAT)
flat varying vec3 vLightA;
flat varying vec3 vLightS;
#else
varying vec3 vLightA;
varying vec3 vLightS;
#endif
`;

const OBJECT_VERTEX = /* glsl */ `
${BLINN_PHONG}
${LIGHTING_VARYINGS}
void main() {
  vec4 world = modelMatrix * vec4(position, 1.0);
  vec3 n = mat3(modelMatrix) * normal; // rotation + translation only: its own normal matrix
  vUv = uv;
#if defined(SHADING_PHONG)
  vWorldPosition = world.xyz;
  vNormal = n;
#else
  // One directional light: the position argument (for point lights) is not read.
  blinnPhong(normalize(n), normalize(cameraPosition - world.xyz), world.xyz, vLightA, vLightS);
#endif
  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
}
`;

const OBJECT_FRAGMENT = /* glsl */ `
${BLINN_PHONG}
${LIGHTING_VARYINGS}
uniform sampler2D uTexture;
void main() {
#if defined(SHADING_PHONG)
  vec3 a, s;
  blinnPhong(normalize(vNormal), normalize(cameraPosition - vWorldPosition), vWorldPosition, a, s);
#else
  vec3 a = vLightA, s = vLightS;
#endif
  gl_FragColor = vec4(texture2D(uTexture, vUv).rgb * a + s, 1.0);
  #include <colorspace_fragment>
}
`;

/** Passed to Reflector as `options.shader`: Reflector supplies tDiffuse and textureMatrix. */
const GLASS_VERTEX = /* glsl */ `
uniform mat4 textureMatrix;
uniform vec4 uGlassRect;        // xMin, yMin, 1/(xMax − xMin), 1/(yMax − yMin)
varying vec4 vReflectionUv;
varying vec3 vWorldPosition;
varying vec3 vNormal;
varying vec2 vUv;
void main() {
  vReflectionUv = textureMatrix * vec4(position, 1.0);
  vec4 world = modelMatrix * vec4(position, 1.0);
  vWorldPosition = world.xyz;
  vNormal = mat3(modelMatrix) * normal;
  // docs/default-scene.md#texture-coordinates glass UVs from world x, y: unchanged when the Reflector is turned to face the camera.
  vUv = (world.xy - uGlassRect.xy) * uGlassRect.zw;
  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
}
`;

export const GLASS_FRAGMENT = /* glsl */ `
uniform sampler2D tDiffuse;
uniform sampler2D uTexture;
uniform float uTransparency;
uniform float uIor;
uniform vec3 uBodyTint;
varying vec4 vReflectionUv;
varying vec3 vWorldPosition;
varying vec3 vNormal;
varying vec2 vUv;

float fresnel(float c) {
#if defined(FRESNEL_EXACT)
  float ct = sqrt(max(uIor * uIor - 1.0 + c * c, 0.0)) / uIor;
  float rs = (c - uIor * ct) / max(c + uIor * ct, 1e-30);
  float rp = (ct - uIor * c) / max(ct + uIor * c, 1e-30);
  return 0.5 * (rs * rs + rp * rp);
#elif defined(FRESNEL_SCHLICK)
  float r0 = (uIor - 1.0) / (uIor + 1.0);
  r0 *= r0;
  return r0 + (1.0 - r0) * pow(1.0 - c, 5.0);
#else
  return pow(1.0 - c, 3.0);
#endif
}

void main() {
  float c = clamp(abs(dot(normalize(vNormal), normalize(cameraPosition - vWorldPosition))), 0.0, 1.0);
  float f = fresnel(c);
  vec3 r = texture2DProj(tDiffuse, vReflectionUv).rgb;
  vec3 d = texture2D(uTexture, vUv).rgb * uBodyTint;
#if defined(FRESNEL_CLASSIC)
  float a = (1.0 - uTransparency) * (0.2 + 0.8 * f);
  gl_FragColor = vec4(mix(d, r, f) * a, a);
#else
  gl_FragColor = vec4(f * r + (1.0 - f) * (1.0 - uTransparency) * d, 1.0 - (1.0 - f) * uTransparency);
#endif
  #include <colorspace_fragment>
}
`;

export const COPY_VERTEX = /* glsl */ `
void main() { gl_Position = vec4(position.xy, 0.0, 1.0); }
`;

export const COPY_FRAGMENT = /* glsl */ `
uniform sampler2D tSource;
void main() {
  gl_FragColor = texelFetch(tSource, ivec2(gl_FragCoord.xy), 0);
  #include <colorspace_fragment>
}
`;

// ---- helpers ---------------------------------------------------------------------------------

export function toGeometry(m: MeshData): THREE.BufferGeometry {
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.BufferAttribute(m.positions, 3));
  g.setAttribute('normal', new THREE.BufferAttribute(m.normals, 3));
  g.setAttribute('uv', new THREE.BufferAttribute(m.uvs, 2));
  g.setIndex(new THREE.BufferAttribute(m.indices, 1));
  return g;
}

type Defines = Record<string, string>;

/** Our lighting.glsl's variant for the peer's scene: one light. */
function shadingDefines(shading: FrameState['shading']): Defines {
  return { [shading === 'flat' ? 'SHADING_FLAT' : shading === 'gouraud' ? 'SHADING_GOURAUD' : 'SHADING_PHONG']: '', LIGHT_COUNT: '1', LIGHT0_POINT: 'false' };
}

export function fresnelDefines(fresnel: FrameState['fresnel']): Defines {
  return { [fresnel === 'schlick' ? 'FRESNEL_SCHLICK' : fresnel === 'classic' ? 'FRESNEL_CLASSIC' : 'FRESNEL_EXACT']: '' };
}

function v3(a: readonly number[]): THREE.Vector3 {
  return new THREE.Vector3(a[0], a[1], a[2]);
}

const DEFAULT_OPTIONS: PeerOptions = { samples: 0, reflectionScale: 1, sphereSegments: 64 };

/** Most taps of an anisotropic read in 'srgb', as ours (src/render/gl/texture.ts). */
export const MAX_ANISOTROPY = 16;

/** three's name for the colour space 8-bit colour is held in: sRGB-encoded, or as stored. */
export const held = (cs: ColorSpace): THREE.ColorSpace => (cs === 'srgb' ? THREE.SRGBColorSpace : THREE.NoColorSpace);

/** The procedural texture as three holds it in colour space `cs`: row 0 first, repeat, trilinear mips (anisotropic in 'srgb'). */
export function proceduralDataTexture(r: THREE.WebGLRenderer, cs: ColorSpace, texels: Uint8Array = proceduralTexture()): THREE.DataTexture {
  const t = new THREE.DataTexture(texels, TEXTURE_SIZE, TEXTURE_SIZE, THREE.RGBAFormat, THREE.UnsignedByteType);
  t.flipY = false; // row y = 0 is the first row uploaded: texel (x, y) at UV ((x+0.5)/512, (y+0.5)/512)
  t.wrapS = t.wrapT = THREE.RepeatWrapping;
  t.magFilter = THREE.LinearFilter;
  t.minFilter = THREE.LinearMipmapLinearFilter;
  t.generateMipmaps = true;
  t.colorSpace = held(cs);
  t.anisotropy = cs === 'srgb' ? Math.min(MAX_ANISOTROPY, r.capabilities.getMaxAnisotropy()) : 1;
  t.unpackAlignment = 1;
  t.needsUpdate = true;
  return t;
}

// ---- the peer --------------------------------------------------------------------------------

export class ThreePeer {
  readonly renderer: THREE.WebGLRenderer;
  private readonly gl: WebGL2RenderingContext;
  private readonly scene = new THREE.Scene();
  private readonly camera = new THREE.PerspectiveCamera(60, 1, CAMERA.near, CAMERA.far);
  /** The procedural texture in each colour space (three fixes a texture's storage at its first upload). */
  private readonly textures: Record<ColorSpace, THREE.DataTexture>;
  private colorSpace: ColorSpace = 'none';
  private readonly cube: THREE.Mesh;
  private readonly sphere: THREE.Mesh;
  private readonly cubeMaterial: THREE.ShaderMaterial;
  private readonly sphereMaterial: THREE.ShaderMaterial;
  private readonly glassGeometry: THREE.BufferGeometry;
  private readonly reflector: Reflector;
  private reflectionType: 'half' | 'byte' = 'half';
  private sphereSegments = 0;
  private shading: FrameState['shading'] = 'phong';
  private fresnel: FrameState['fresnel'] = 'exact';
  /** Multisampled scene target (samples > 0) and the full-screen copy to the canvas. */
  private sceneTarget: THREE.WebGLRenderTarget | null = null;
  private readonly copyScene = new THREE.Scene();
  private readonly copyCamera = new THREE.OrthographicCamera(-1, 1, 1, -1, 0, 1);
  private readonly copyMaterial: THREE.ShaderMaterial;
  private readonly forward = new Float64Array(3);
  private readonly target = new THREE.Vector3();
  private width = -1;
  private height = -1;
  private raw = new Uint8Array(0);

  constructor(canvas: HTMLCanvasElement | OffscreenCanvas) {
    // Stored values until a frame asks for 'srgb' (applyColorSpace); never tone mapping.
    THREE.ColorManagement.enabled = false;
    this.renderer = new THREE.WebGLRenderer({
      canvas, antialias: false, alpha: false, depth: true, stencil: false,
      premultipliedAlpha: true, preserveDrawingBuffer: false, powerPreference: 'default',
    });
    const r = this.renderer;
    r.outputColorSpace = THREE.LinearSRGBColorSpace;
    r.toneMapping = THREE.NoToneMapping;
    r.setPixelRatio(1);
    r.setClearColor(new THREE.Color(BACKGROUND[0], BACKGROUND[1], BACKGROUND[2]), 1);
    this.gl = r.getContext() as WebGL2RenderingContext;

    const texels = proceduralTexture();
    this.textures = { srgb: proceduralDataTexture(r, 'srgb', texels), none: proceduralDataTexture(r, 'none', texels) };

    this.cubeMaterial = this.objectMaterial(CUBE.albedo);
    this.sphereMaterial = this.objectMaterial(SPHERE.albedo);
    this.cube = new THREE.Mesh(toGeometry(boxMesh(CUBE.edge)), this.cubeMaterial);
    this.cube.position.set(CUBE.x, CUBE.y, 0);
    this.sphere = new THREE.Mesh(new THREE.BufferGeometry(), this.sphereMaterial);
    this.sphere.position.copy(v3(SPHERE.centre));
    this.scene.add(this.cube, this.sphere);

    this.glassGeometry = toGeometry(glassMesh(glassFrame(DEFAULT_GLASS)));
    this.reflector = this.createReflector(DEFAULT_OPTIONS);
    this.scene.add(this.reflector);

    this.copyMaterial = new THREE.ShaderMaterial({
      name: 'PeerCopy', vertexShader: COPY_VERTEX, fragmentShader: COPY_FRAGMENT,
      uniforms: { tSource: { value: null } }, depthTest: false, depthWrite: false,
    });
    const tri = new THREE.BufferGeometry();
    tri.setAttribute('position', new THREE.BufferAttribute(new Float32Array([-1, -1, 0, 3, -1, 0, -1, 3, 0]), 3));
    const copy = new THREE.Mesh(tri, this.copyMaterial);
    copy.frustumCulled = false;
    this.copyScene.add(copy);
  }

  /** Draws one frame of `state` (view 'final') at state.width × state.height into the canvas. */
  render(state: FrameState, options: PeerOptions): void {
    const r = this.renderer;
    // Global in three; set per frame so Color conversions (the clear) follow this frame's space.
    THREE.ColorManagement.enabled = state.colorSpace === 'srgb';
    const w = Math.max(1, Math.floor(state.width));
    const h = Math.max(1, Math.floor(state.height));
    if (w !== this.width || h !== this.height) {
      r.setSize(w, h, false);
      this.width = w;
      this.height = h;
    }
    this.configure(state, options, w, h);

    // Camera (docs/default-scene.md#the-camera): lookAt(position, position + forward, +Y).
    const cam = this.camera;
    cam.fov = state.fov;
    cam.aspect = w / h;
    cam.updateProjectionMatrix();
    const [x, y, z] = state.cameraPosition;
    cam.position.set(x, y, z);
    const f = forwardFromYawPitch(this.forward, state.yaw, state.pitch);
    cam.lookAt(this.target.set(x + f[0], y + f[1], z + f[2]));

    this.cube.position.z = state.cubeDistance;
    this.cube.rotation.y = state.spin * state.time;

    // Face the Reflector towards the camera (two-sided glass; see the header).
    const behind = signedDistance(GLASS.plane, state.cameraPosition) < 0;
    this.reflector.scale.set(behind ? -1 : 1, 1, behind ? -1 : 1);
    const u = (this.reflector.material as THREE.ShaderMaterial).uniforms;
    u.uTransparency.value = state.transparency;
    u.uIor.value = state.ior;

    const samples = options.samples;
    if (samples > 0) {
      const target = this.ensureSceneTarget(w, h, samples);
      r.setRenderTarget(target);
      r.render(this.scene, cam); // the Reflector draws its pass from onBeforeRender
      r.setRenderTarget(null);
      this.copyMaterial.uniforms.tSource.value = target.texture;
      r.autoClear = false;
      r.render(this.copyScene, this.copyCamera);
      r.autoClear = true;
    } else {
      r.setRenderTarget(null);
      r.render(this.scene, cam);
    }
  }

  /** RGBA8 of the last frame, top row first. Call in the same task as render() (the drawing buffer is not preserved). */
  readPixels(): Uint8ClampedArray {
    const { gl, width: w, height: h } = this;
    if (w <= 0 || h <= 0) return new Uint8ClampedArray(0);
    if (this.raw.length !== w * h * 4) this.raw = new Uint8Array(w * h * 4);
    this.renderer.setRenderTarget(null);
    gl.pixelStorei(gl.PACK_ALIGNMENT, 1);
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, this.raw);
    const out = new Uint8ClampedArray(w * h * 4);
    const row = w * 4;
    for (let j = 0; j < h; j++) out.set(this.raw.subarray((h - 1 - j) * row, (h - j) * row), j * row);
    return out;
  }

  dispose(): void {
    this.cube.geometry.dispose();
    this.sphere.geometry.dispose();
    this.glassGeometry.dispose();
    this.cubeMaterial.dispose();
    this.sphereMaterial.dispose();
    this.reflector.dispose();
    this.textures.srgb.dispose();
    this.textures.none.dispose();
    this.sceneTarget?.dispose();
    this.sceneTarget = null;
    this.copyScene.traverse((o) => { if (o instanceof THREE.Mesh) o.geometry.dispose(); });
    this.copyMaterial.dispose();
    this.renderer.dispose();
  }

  // ---- per-frame configuration (allocates only when a knob changes) ------------------------

  private configure(state: FrameState, options: PeerOptions, w: number, h: number): void {
    if (state.colorSpace !== this.colorSpace) this.applyColorSpace(state.colorSpace);
    const segments = Math.round(options.sphereSegments);
    if (segments !== this.sphereSegments) {
      this.sphere.geometry.dispose();
      this.sphere.geometry = toGeometry(sphereMesh(SPHERE.radius, segments));
      this.sphereSegments = segments;
    }
    if (state.shading !== this.shading) {
      this.shading = state.shading;
      for (const m of [this.cubeMaterial, this.sphereMaterial]) {
        m.defines = shadingDefines(state.shading);
        m.needsUpdate = true;
      }
    }
    const glass = this.reflector.material as THREE.ShaderMaterial;
    if (state.fresnel !== this.fresnel) {
      this.fresnel = state.fresnel;
      glass.defines = fresnelDefines(state.fresnel);
      glass.needsUpdate = true;
    }
    const type = options.reflectionType ?? 'half';
    const rt = this.reflector.getRenderTarget();
    const space = type === 'byte' ? held(this.colorSpace) : THREE.NoColorSpace; // half float: linear either way
    if (type !== this.reflectionType || rt.texture.colorSpace !== space) {
      // The target's storage is created lazily; dispose so it is rebuilt with the new type.
      this.reflectionType = type;
      rt.dispose();
      rt.texture.type = type === 'byte' ? THREE.UnsignedByteType : THREE.HalfFloatType;
      rt.texture.colorSpace = space;
    }
    if (rt.samples !== options.samples) {
      rt.dispose();
      rt.samples = options.samples;
    }
    const rw = Math.max(1, Math.round(w * options.reflectionScale));
    const rh = Math.max(1, Math.round(h * options.reflectionScale));
    if (rt.width !== rw || rt.height !== rh) rt.setSize(rw, rh);
  }

  /** Output, texture and background for `cs`; the 8-bit targets follow (configure, ensureSceneTarget). */
  private applyColorSpace(cs: ColorSpace): void {
    this.colorSpace = cs;
    const r = this.renderer;
    const srgb = cs === 'srgb';
    r.outputColorSpace = srgb ? THREE.SRGBColorSpace : THREE.LinearSRGBColorSpace;
    // An sRGB colour, as a CSS colour is (ColorManagement is on for 'srgb': three decodes it).
    r.setClearColor(srgb
      ? new THREE.Color().setRGB(BACKGROUND[0], BACKGROUND[1], BACKGROUND[2], THREE.SRGBColorSpace)
      : new THREE.Color(BACKGROUND[0], BACKGROUND[1], BACKGROUND[2]), 1);
    const glass = this.reflector.material as THREE.ShaderMaterial;
    for (const m of [this.cubeMaterial, this.sphereMaterial, glass]) m.uniforms.uTexture.value = this.textures[cs];
  }

  private ensureSceneTarget(w: number, h: number, samples: number): THREE.WebGLRenderTarget {
    let t = this.sceneTarget;
    if (t && t.texture.colorSpace !== held(this.colorSpace)) {
      t.dispose();
      t = this.sceneTarget = null;
    }
    if (!t) {
      // 8-bit colour: SRGB8_ALPHA8 for 'srgb' (three picks it from the colour space), RGBA8 for 'none'.
      t = this.sceneTarget = new THREE.WebGLRenderTarget(w, h, {
        samples, type: THREE.UnsignedByteType, format: THREE.RGBAFormat, colorSpace: held(this.colorSpace),
        depthBuffer: true, stencilBuffer: false, generateMipmaps: false,
        minFilter: THREE.NearestFilter, magFilter: THREE.NearestFilter,
      });
    }
    if (t.samples !== samples) {
      t.dispose();
      t.samples = samples;
    }
    if (t.width !== w || t.height !== h) t.setSize(w, h);
    return t;
  }

  private objectMaterial(albedo: readonly number[]): THREE.ShaderMaterial {
    return new THREE.ShaderMaterial({
      name: 'PeerBlinnPhong',
      vertexShader: OBJECT_VERTEX,
      fragmentShader: OBJECT_FRAGMENT,
      defines: shadingDefines('phong'),
      uniforms: {
        uTexture: { value: this.textures.none },
        uKa: { value: v3(albedo) },
        uKd: { value: v3(albedo) },
        uKs: { value: new THREE.Vector3(MATERIAL.ks, MATERIAL.ks, MATERIAL.ks) },
        uShininess: { value: MATERIAL.shininess },
        uLightVector: { value: [new THREE.Vector4(...LIGHT.direction, 0), ...[1, 2, 3].map(() => new THREE.Vector4())] },
        uLightAmbient: { value: [new THREE.Vector3().setScalar(LIGHT.ambient), ...[1, 2, 3].map(() => new THREE.Vector3())] },
        uLightDiffuse: { value: [new THREE.Vector3().setScalar(LIGHT.diffuse), ...[1, 2, 3].map(() => new THREE.Vector3())] },
        uLightSpecular: { value: [new THREE.Vector3().setScalar(LIGHT.specular), ...[1, 2, 3].map(() => new THREE.Vector3())] },
      },
    });
  }

  private createReflector(options: PeerOptions): Reflector {
    const reflector = new Reflector(this.glassGeometry, {
      textureWidth: 1, // sized per frame from reflectionScale
      textureHeight: 1,
      clipBias: 0,
      multisample: options.samples,
      shader: {
        name: 'PeerGlass',
        uniforms: {
          color: { value: null },
          tDiffuse: { value: null },
          textureMatrix: { value: null },
          uTexture: { value: null },
          uTransparency: { value: 0.5 },
          uIor: { value: 1.5 },
          uBodyTint: { value: null },
          uGlassRect: { value: null },
        },
        vertexShader: GLASS_VERTEX,
        fragmentShader: GLASS_FRAGMENT,
      },
    });
    const m = reflector.material as THREE.ShaderMaterial;
    // Set after construction: Reflector clones the shader's uniforms, which would clone a texture.
    m.uniforms.uTexture.value = this.textures.none;
    m.uniforms.uBodyTint.value = new THREE.Vector3(...GLASS.tint.map((c) => c * GLASS.darkness));
    m.uniforms.uGlassRect.value = new THREE.Vector4(
      GLASS.xMin, GLASS.yMin, 1 / (GLASS.xMax - GLASS.xMin), 1 / (GLASS.yMax - GLASS.yMin));
    m.defines = fresnelDefines('exact');
    // Premultiplied "over" (docs/rendering.md#the-glass-equation): src.rgb + (1 − src.a)·dst.
    m.transparent = true;
    m.blending = THREE.CustomBlending;
    m.blendEquation = THREE.AddEquation;
    m.blendSrc = THREE.OneFactor;
    m.blendDst = THREE.OneMinusSrcAlphaFactor;
    m.depthTest = true;
    m.depthWrite = false;
    m.side = THREE.DoubleSide;
    reflector.getRenderTarget().texture.type = THREE.HalfFloatType; // Reflector's own choice, stated
    return reflector;
  }
}
