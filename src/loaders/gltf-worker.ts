// Worker entry for glTF files: reads them off the main thread and transfers the arrays back.
// Used as `new Worker(new URL('./gltf-worker.ts', import.meta.url), { type: 'module' })`.
import { runGltfJob, type GltfJobRequest } from './gltf-job';

const scope = self as unknown as {
  addEventListener(type: 'message', listener: (e: MessageEvent<GltfJobRequest>) => void): void;
  postMessage(message: unknown, transfer: Transferable[]): void;
};

scope.addEventListener('message', (e) => {
  void runGltfJob(e.data).then(({ response, transfer }) => scope.postMessage(response, transfer));
});
