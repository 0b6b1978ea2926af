// The point picker's marker material: plain orange, or (GUI "Use shader
// material", as in the seed) a shader blinking between white and black.

import { Material, MeshBasicMaterial, ShaderMaterial } from "three";

export class PickerMaterials {
  readonly basic = new MeshBasicMaterial({ color: 0xff9f1c, depthTest: false, transparent: true });
  readonly blinking = new ShaderMaterial({
    uniforms: { time: { value: 0 } },
    vertexShader: /* glsl */ `
      void main() {
        gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
      }`,
    fragmentShader: /* glsl */ `
      uniform float time;
      void main() {
        float k = 0.5 + 0.5 * sin(time * 6.0);
        gl_FragColor = vec4(vec3(k), 1.0);
      }`,
    depthTest: false,
    transparent: true,
  });
  useShader = false;

  get current(): Material {
    return this.useShader ? this.blinking : this.basic;
  }

  /** Advances the blink; true while it needs frames. */
  animate(timeMs: number): boolean {
    if (!this.useShader) return false;
    this.blinking.uniforms.time!.value = timeMs / 1000;
    return true;
  }
}
