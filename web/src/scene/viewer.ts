// The three.js side: renderer, camera (z up, as the scans are), orbit
// controls, lights and a render-on-demand loop. Everything drawn is added to
// `content` (the scene's cloud or mesh) or `overlays` (markers, rays, polygons).

import {
  Box3,
  Color,
  DirectionalLight,
  Group,
  HemisphereLight,
  PerspectiveCamera,
  Plane,
  Scene,
  Vector3,
  WebGLRenderer,
} from "three";
import { OrbitControls } from "three/examples/jsm/controls/OrbitControls.js";
import { diagonal } from "../decode/robust_extent";
import type { Bounds, Vec3 } from "../decode/types";

export const BACKGROUND = 0x0b1220;

export interface FrameHooks {
  before?: () => void;
  /** `continuous`: drawn while the camera moves or animates (a frame rate is measurable). */
  after?: (continuous: boolean) => void;
}

export class Viewer {
  readonly renderer: WebGLRenderer;
  readonly scene = new Scene();
  readonly camera: PerspectiveCamera;
  readonly controls: OrbitControls;
  readonly content = new Group();
  readonly overlays = new Group();
  readonly hemisphere = new HemisphereLight(0xffffff, 0x404050, 1.1);
  readonly headlight = new DirectionalLight(0xffffff, 0.9);
  /** Clip plane that hides everything above a height (the ceiling). */
  readonly sectionPlane = new Plane(new Vector3(0, 0, -1), Infinity);
  /**
   * Cut-away of the near walls: seen from outside the scene's box, the slab
   * along each wall (x and y) on the camera's side is hidden, as the ceiling
   * is, so the interior and the markers show. Updated as the camera moves.
   */
  readonly wallPlanes = [
    new Plane(new Vector3(1, 0, 0), Infinity),
    new Plane(new Vector3(0, 1, 0), Infinity),
  ];
  cutWalls = true;

  /** Every clip plane a scene layer takes (ceiling, near walls). */
  get clipPlanes(): Plane[] {
    return [this.sectionPlane, ...this.wallPlanes];
  }

  /** Frames actually rendered since start (render on demand). */
  framesRendered = 0;
  /** Per-frame callbacks that keep the loop rendering while they return true. */
  readonly animations = new Set<(time: number) => boolean>();
  hooks: FrameHooks = {};
  /**
   * Level of detail for big clouds: while the camera moves, draw 1/2^level
   * of the points, the level adapting to keep about 25 frames per second;
   * when it stops, one frame at full detail.
   */
  private lod: { maxLevel: number; apply: (level: number) => void } | null = null;
  private lodLevel = 0;
  private appliedLevel = 0;
  private lastMotion = -Infinity;
  private lastMovingRender = 0;
  private quickFrames = 0;
  /** Off: always full detail (to measure it). */
  lodEnabled = true;
  /** The last interval between two frames drawn while moving (ms; 0 until measured). */
  movingFrameMs = 0;
  private lastRender = 0;
  private lastContinuous = false;

  private dirty = true;
  private readonly afterRender: (() => void)[] = [];
  private bounds: Bounds = { min: [-1, -1, -1], max: [1, 1, 1] };

  constructor(readonly container: HTMLElement) {
    const params = new URLSearchParams(window.location.search);
    this.renderer = new WebGLRenderer({
      antialias: params.get("aa") !== "0",
      powerPreference: "high-performance",
    });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
    this.renderer.setClearColor(new Color(BACKGROUND));
    this.renderer.localClippingEnabled = true;
    this.renderer.domElement.dataset.testid = "viewer-canvas";
    this.renderer.domElement.className = "block h-full w-full outline-none";
    container.appendChild(this.renderer.domElement);

    this.camera = new PerspectiveCamera(50, 1, 0.01, 1000);
    this.camera.up.set(0, 0, 1);
    this.camera.position.set(6, -6, 5);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.enableDamping = true;
    this.controls.dampingFactor = 0.12;
    this.controls.addEventListener("change", () => {
      this.lastMotion = performance.now();
      this.requestRender();
    });

    this.hemisphere.position.set(0, 0, 1);
    this.scene.add(this.hemisphere, this.camera, this.content, this.overlays);
    this.headlight.position.set(0.3, 0.5, 1);
    this.camera.add(this.headlight);

    new ResizeObserver(() => this.resize()).observe(container);
    this.resize();
    this.renderer.setAnimationLoop((time) => this.tick(time));
  }

  requestRender(): void {
    this.dirty = true;
  }

  /** Resolves once the next frame has been drawn (and the GPU has finished it). */
  nextFrame(): Promise<number> {
    this.requestRender();
    return new Promise((resolve) => {
      this.afterRender.push(() => {
        const gl = this.renderer.getContext();
        const pixel = new Uint8Array(4);
        gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel); // waits for the frame
        resolve(performance.now());
      });
    });
  }

  setLevelOfDetail(lod: { maxLevel: number; apply: (level: number) => void } | null): void {
    this.lod = lod && lod.maxLevel > 0 ? lod : null;
    this.lodLevel = 0;
    this.appliedLevel = 0;
    this.quickFrames = 0;
  }

  /** The level used while moving (0: full detail). */
  get detailLevel(): number {
    return this.appliedLevel;
  }

  get sceneBounds(): Bounds {
    return this.bounds;
  }

  get diagonal(): number {
    return diagonal(this.bounds);
  }

  /** Looks at the bounds from outside, above a corner. */
  frame(bounds: Bounds): void {
    this.bounds = bounds;
    this.resize();
    const box = new Box3(new Vector3(...bounds.min), new Vector3(...bounds.max));
    const centre = box.getCenter(new Vector3());
    const diagonal = this.diagonal;
    const direction = new Vector3(-0.55, -1, 0.85).normalize();
    // Far enough for the bounding sphere to fit the narrower field of view.
    const vertical = (this.camera.fov * Math.PI) / 180;
    const horizontal = 2 * Math.atan(Math.tan(vertical / 2) * this.camera.aspect);
    const distance = diagonal / 2 / Math.sin(Math.min(vertical, horizontal) / 2);
    this.camera.near = diagonal / 1000;
    this.camera.far = diagonal * 20;
    this.camera.position.copy(centre).addScaledVector(direction, distance);
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(centre);
    this.controls.maxDistance = diagonal * 8;
    this.controls.update();
    this.requestRender();
  }

  /**
   * Puts the camera at `eye`, looking level towards `towards` (or along +x
   * when they meet); orbiting then turns the view around the eye.
   */
  lookFrom(eye: Vec3, towards: Vec3): void {
    const direction = new Vector3(towards[0] - eye[0], towards[1] - eye[1], 0);
    if (direction.lengthSq() < 1e-12) direction.set(1, 0, 0);
    direction.normalize();
    this.camera.near = this.diagonal / 5000;
    this.camera.updateProjectionMatrix();
    this.camera.position.set(...eye);
    this.controls.target.set(...eye).addScaledVector(direction, this.diagonal * 0.01);
    this.controls.update();
    this.requestRender();
  }

  /** Places the near-wall planes for the camera where it is (nothing cut from inside the box). */
  private updateWallCut(): void {
    const b = this.bounds;
    const eye = this.camera.position;
    this.wallPlanes.forEach((plane, a) => {
      const span = b.max[a]! - b.min[a]!;
      const slab = 0.04 * span;
      const at = eye.getComponent(a);
      plane.normal.set(0, 0, 0);
      if (this.cutWalls && at > b.max[a]!) {
        plane.normal.setComponent(a, -1);
        plane.constant = b.max[a]! - slab;
      } else if (this.cutWalls && at < b.min[a]!) {
        plane.normal.setComponent(a, 1);
        plane.constant = -(b.min[a]! + slab);
      } else {
        plane.normal.setComponent(a, 1);
        plane.constant = Infinity;
      }
    });
  }

  /** Hides what lies above `height` (Infinity: nothing hidden). */
  setSection(height: number): void {
    this.sectionPlane.constant = height;
    this.requestRender();
  }

  /** Turns the camera around the target and the up axis by `radians` (orbit benchmark). */
  orbitBy(radians: number): void {
    const offset = this.camera.position.clone().sub(this.controls.target);
    offset.applyAxisAngle(this.camera.up, radians);
    this.camera.position.copy(this.controls.target).add(offset);
    this.camera.lookAt(this.controls.target);
    this.requestRender();
  }

  private resize(): void {
    const width = Math.max(1, this.container.clientWidth);
    const height = Math.max(1, this.container.clientHeight);
    this.renderer.setSize(width, height, false);
    this.camera.aspect = width / height;
    this.camera.updateProjectionMatrix();
    this.requestRender();
  }

  /** Adapts the moving level from the time between two moving frames. */
  private adapt(interval: number, maxLevel: number): void {
    const target = 40; // ms, 25 frames per second
    if (interval > target * 1.4) {
      const steps = Math.max(1, Math.round(Math.log2(interval / target)));
      this.lodLevel = Math.min(maxLevel, this.lodLevel + steps);
      this.quickFrames = 0;
    } else if (interval < target * 0.5 && this.lodLevel > 0) {
      // Finer only after a run of quick frames (hysteresis against flicker).
      if (++this.quickFrames >= 20) {
        this.lodLevel -= 1;
        this.quickFrames = 0;
      }
    } else this.quickFrames = 0;
  }

  private tick(time: number): void {
    if (this.controls.update()) this.dirty = true;
    for (const animate of this.animations) if (animate(time)) this.dirty = true;
    const lod = this.lodEnabled ? this.lod : null;
    const moving = performance.now() - this.lastMotion < 250;
    if (lod !== null) {
      if (this.dirty && moving) {
        if (this.lastMovingRender > 0) this.adapt(time - this.lastMovingRender, lod.maxLevel);
        this.lastMovingRender = time;
      } else if (!moving) this.lastMovingRender = 0;
    }
    const level = lod !== null && moving ? this.lodLevel : 0;
    if (level !== this.appliedLevel) {
      (lod ?? this.lod)?.apply(level);
      this.appliedLevel = level;
      this.dirty = true;
    }
    if (!this.dirty) return;
    const animating = this.dirty && !moving && this.animations.size > 0;
    this.dirty = false;
    this.hooks.before?.();
    this.updateWallCut();
    this.renderer.render(this.scene, this.camera);
    this.framesRendered += 1;
    const now = performance.now();
    if (moving && this.lastContinuous) this.movingFrameMs = now - this.lastRender;
    this.lastRender = now;
    // A frame rate needs two frames in a row drawn in motion (not idle time before the first).
    const continuous = (moving || animating) && this.lastContinuous;
    this.lastContinuous = moving || animating;
    this.hooks.after?.(continuous);
    const callbacks = this.afterRender.splice(0);
    for (const callback of callbacks) callback();
  }
}
