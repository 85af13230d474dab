// Consumer test (scripts/check-package.mjs): each line marked BAD must be a type error. React's own
// onLoad, onError and onProgress never hear the elements' events (React 19 calls only `on` + the
// exact event name), so the typings reject them.
import 'glass-plane-scene/react';

export const bad = (
  <>
    <glass-plane-scene fresnel="fresnel" /> {/* BAD */}
    <glass-plane-scene renderer="gpu" /> {/* BAD */}
    <glass-plane-scene projection="fisheye" /> {/* BAD */}
    <glass-plane-scene debug-view="normals" /> {/* BAD */}
    <glass-plane-scene shading="smooth" /> {/* BAD */}
    <glass-plane-scene samples={3} /> {/* BAD */}
    <glass-plane-scene transparency="half" /> {/* BAD */}
    <glass-plane-scene roughness-quality="ultra" /> {/* BAD */}
    <glass-object mapping="planar" /> {/* BAD */}
    <glass-object shape="torus" /> {/* BAD */}
    <glass-object onLoad={() => {}} /> {/* BAD */}
    <glass-plane-scene onError={() => {}} /> {/* BAD */}
    <glass-light onProgress={() => {}} /> {/* BAD */}
  </>
);
