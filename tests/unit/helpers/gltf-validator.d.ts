// The Khronos validator's npm package ships no types: the part the tests use.
declare module 'gltf-validator' {
  export interface ValidationMessage { code: string; message: string; severity: number; pointer?: string }
  export interface ValidationReport { issues: { numErrors: number; messages: ValidationMessage[] } }
  export function validateBytes(data: Uint8Array, options?: {
    uri?: string; format?: 'glb' | 'gltf'; maxIssues?: number; writeTimestamp?: boolean;
    externalResourceFunction?: (uri: string) => Promise<Uint8Array>;
  }): Promise<ValidationReport>;
}
