import { useState } from 'react';
import 'glass-plane-scene/react';

export function Viewer() {
  const [status, setStatus] = useState('loading…');
  return (
    <>
      <glass-plane-scene controls="trackball" glass-normal="0 1 0" glass-center="0 -1 0" glass-size="8 8"
        onerror={(e) => setStatus(`failed: ${e.detail.message}`)}>
        <glass-object src="/models/spot.obj" normalizeModel
          onload={(e) => setStatus(`loaded ${e.detail.url}`)}></glass-object>
      </glass-plane-scene>
      <p>{status}</p>
    </>
  );
}
