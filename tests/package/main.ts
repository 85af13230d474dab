// Consumer test (scripts/check-package.mjs): the package's two entries as a user imports them.
import { GlassPlaneScene, defineChildren, ATTRIBUTES, type GlassObject, type GlassLight, type FrameReport, type RenderStats } from 'glass-plane-scene';
import * as standalone from 'glass-plane-scene/standalone';

const scene = document.createElement('glass-plane-scene');
const typed: GlassPlaneScene = scene;
typed.fresnel = 'schlick';
typed.controls = 'orbit';
typed.transparency = 0.25;
typed.addEventListener('ready', (e) => {
  const report: FrameReport = e.detail;
  console.log(report.width, typed.capture('final')?.width);
});
typed.addEventListener('camera-change', (e) => console.log(e.detail.position[0], e.detail.rotation[1]));
const stats: RenderStats = typed.stats;
console.log(stats.frames, typed.scene.objects.length, typed.objectRotation[3]);
typed.requestRender();

const object: GlassObject = document.createElement('glass-object');
object.shape = 'sphere';
const light: GlassLight = document.createElement('glass-light');
light.position = [1, 2, 3];
scene.append(object, light);
void defineChildren().then(() => console.log(customElements.get('glass-object') !== undefined));

const fromStandalone: typeof standalone.GlassPlaneScene = standalone.GlassPlaneScene;
console.log(fromStandalone.observedAttributes.length, ATTRIBUTES.length, standalone.TAG_NAME);

// @ts-expect-error fresnel is a keyword union
typed.fresnel = 'fresnel';
