// The Khronos validator's npm package ships no types: the part the tests use.
declare module 'gltf-validator' {
  export interface ValidationMessage { code: string; message: string; severity: number; pointer?: string }
  export interface ValidationReport { issues: { numErrors: number; messages: ValidationMessage[] } }
  export function validateBytes(data: Uint8Array, options?: {
    uri?: string; format?: 'glb' | 'gltf'; maxIssues?: number; writeTimestamp?: boolean;
    externalResourceFunction?: (uri: string) => Promise<Uint8Array>;
  }): Promise<ValidationReport>;
}

// draco3d's npm package ships no types: its two factories, as the tests use them.
declare module 'draco3d' {
  export function createDecoderModule(options?: object): Promise<unknown>;
  export function createEncoderModule(options?: object): Promise<unknown>;
  const draco3d: { createDecoderModule: typeof createDecoderModule; createEncoderModule: typeof createEncoderModule };
  export default draco3d;
}
