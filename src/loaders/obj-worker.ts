// Worker entry for large OBJ files: parses off the main thread and transfers the arrays back.
// Used as `new Worker(new URL('./obj-worker.ts', import.meta.url), { type: 'module' })`.
import { runObjJob, type ObjJobRequest } from './obj-job';

const scope = self as unknown as {
  addEventListener(type: 'message', listener: (e: MessageEvent<ObjJobRequest>) => void): void;
  postMessage(message: unknown, transfer: Transferable[]): void;
};

scope.addEventListener('message', (e) => {
  const { response, transfer } = runObjJob(e.data);
  scope.postMessage(response, transfer);
});
