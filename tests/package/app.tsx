// Consumer test (scripts/check-package.mjs): React 19 JSX with every attribute of the three
// elements (the script checks that this file names every attribute in custom-elements.json).
import 'glass-plane-scene/react';
import type { GlassPlaneScene } from 'glass-plane-scene';
import { useRef } from 'react';

export function App() {
  const ref = useRef<GlassPlaneScene>(null);
  return (
    <glass-plane-scene
      ref={ref}
      className="scene"
      style={{ width: '100%', height: 360 }}
      alt="Glass"
      transparency={0.5}
      cube-distance="0.75"
      ior={1.5}
      fresnel="schlick"
      camera-position="3.6 2.4 0.2"
      camera-rotation="-169 -23.6"
      fov={60}
      projection="orthographic"
      controls="orbit"
      renderer="software"
      camera-target="0 0.5 -1"
      camera-src="course/camera.cfg"
      spin={0}
      time={1.25}
      debug-view="reflection"
      reflection-scale={0.5}
      samples={2}
      refine={10}
      shading="gouraud"
      tessellation="auto"
      pixel-ratio={2}
      reflection-format="rgba16f" color-space="srgb" tone-mapping="aces" exposure={1.5} environment="neutral" environment-intensity={1.2} roughness={0.3} roughness-quality="high"
      glass-center="0 1 0"
      glass-normal="0 0 1"
      glass-size="8 4"
      background="#202020"
      poster="poster.jpg"
      onready={(e) => console.log(e.detail.width)}
      onframe={(e) => console.log(e.detail.time)}
      onerror={(e) => console.log(e.detail.type)}
      oncamera-change={(e) => console.log(e.detail.position)}
    >
      <glass-object
        src="model.obj"
        shape="sphere"
        resolution={64}
        position="0 0.5 -1"
        rotation="0 45 0"
        scale="0.5"
        normalizeModel
        ambient="0.2 0.2 0.2"
        diffuse="0.8 0.2 0.2"
        specular="1 1 1"
        shininess={64}
        opacity={0.5}
        texture="wood.png"
        mapping="triplanar"
        reflect={false}
        onload={(e) => console.log(e.detail.url)}
        onprogress={(e) => console.log(e.detail.loaded)}
        onerror={(e) => console.log(e.detail.message)}
      />
      <glass-light
        position="2 3 1"
        direction="0 1 0"
        ambient="0.1 0.1 0.1"
        diffuse="0.9 0.9 0.9"
        specular="1 1 1"
        src="course/iluminacao.txt"
        onprogress={(e) => console.log(e.detail.loaded)}
        onload={(e) => console.log(e.detail.warnings)}
        onerror={(e) => console.log(e.detail.line)}
      />
      <glass-plane-scene controls />
      {/* @ts-expect-error controls is flyby, orbit, trackball or a boolean */}
      <glass-plane-scene controls="orbitt" />
    </glass-plane-scene>
  );
}
