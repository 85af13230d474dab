// The element's side of the CPU renderer in a chunk of its own, loaded only when a scene is
// drawn by the CPU (`renderer="software"`, or `auto` where WebGL2 is missing): the backend and
// the host of its worker. The renderer itself is a further chunk (software-host.ts loads it).
export { SoftwareBackend } from './software-backend';
export { SoftwareHost } from './software-host';
