// The viewpoints as light markers: the seed's three (centre, the midpoints
// towards the bounding box's max and min corners, i.e. patterns C, U and L),
// each a glowing sphere with a point light, toggled from the GUI and dragged
// with a transform gizmo before computing. Jobs get the enabled ones as
// explicit `viewpoints`.

import {
  Camera,
  Color,
  Group,
  Mesh,
  MeshBasicMaterial,
  Object3D,
  PointLight,
  SphereGeometry,
  Sprite,
  SpriteMaterial,
  CanvasTexture,
  Vector3,
} from "three";
import { TransformControls } from "three/examples/jsm/controls/TransformControls.js";
import { diagonal } from "../decode/robust_extent";
import type { Bounds, Vec3 } from "../decode/types";

import { patternPoints } from "./viewpoint_pattern";
import type { ViewpointName } from "./viewpoint_pattern";

export type { ViewpointName };

export const VIEWPOINT_NAMES: ViewpointName[] = ["centre", "max", "min"];

export const VIEWPOINT_LABELS: Record<ViewpointName, string> = {
  centre: "Center",
  max: "Viewpoint Max",
  min: "Viewpoint Min",
};

const COLOURS: Record<ViewpointName, number> = {
  centre: 0xffd166,
  max: 0xff7b54,
  min: 0x7bdff2,
};

export interface Marker {
  name: ViewpointName;
  object: Group;
  sphere: Mesh<SphereGeometry, MeshBasicMaterial>;
  light: PointLight;
  enabled: boolean;
}

function glowTexture(): CanvasTexture {
  const canvas = document.createElement("canvas");
  canvas.width = canvas.height = 64;
  const g = canvas.getContext("2d")!;
  const gradient = g.createRadialGradient(32, 32, 0, 32, 32, 32);
  gradient.addColorStop(0, "rgba(255,255,255,1)");
  gradient.addColorStop(0.3, "rgba(255,255,255,0.45)");
  gradient.addColorStop(1, "rgba(255,255,255,0)");
  g.fillStyle = gradient;
  g.fillRect(0, 0, 64, 64);
  return new CanvasTexture(canvas);
}

export class ViewpointMarkers {
  readonly group = new Group();
  readonly markers = new Map<ViewpointName, Marker>();
  readonly gizmo: TransformControls;
  /** Called when a marker moves or is toggled. */
  onChange: (() => void) | null = null;
  private selected: ViewpointName | null = null;
  private size = 0.1;
  private intensity = 1;

  constructor(camera: Camera, domElement: HTMLElement, overlays: Object3D) {
    const texture = glowTexture();
    for (const name of VIEWPOINT_NAMES) {
      const object = new Group();
      object.name = `viewpoint-${name}`;
      const colour = new Color(COLOURS[name]);
      const sphere = new Mesh(
        new SphereGeometry(1, 20, 14),
        new MeshBasicMaterial({ color: colour }),
      );
      sphere.userData.viewpoint = name;
      const glow = new Sprite(
        new SpriteMaterial({ map: texture, color: colour, transparent: true, depthWrite: false }),
      );
      glow.scale.setScalar(5);
      glow.userData.viewpoint = name;
      const light = new PointLight(colour, 1, 0, 0);
      object.add(sphere, glow, light);
      this.group.add(object);
      this.markers.set(name, { name, object, sphere, light, enabled: true });
    }
    overlays.add(this.group);
    this.gizmo = new TransformControls(camera, domElement);
    this.gizmo.setSize(0.8);
    this.gizmo.addEventListener("objectChange", () => this.onChange?.());
    overlays.add(this.gizmo.getHelper());
  }

  /** Puts the markers on the bounds' pattern points, sized to the scene. */
  reset(bounds: Bounds): void {
    const points = patternPoints(bounds);
    this.size = diagonal(bounds) * 0.012;
    for (const marker of this.markers.values()) {
      marker.object.position.set(...points[marker.name]);
      marker.object.scale.setScalar(this.size);
    }
    this.deselect();
    this.onChange?.();
  }

  setEnabled(name: ViewpointName, enabled: boolean): void {
    const marker = this.markers.get(name)!;
    marker.enabled = enabled;
    marker.object.visible = enabled;
    marker.light.intensity = enabled ? this.intensity : 0;
    if (!enabled && this.selected === name) this.deselect();
    this.onChange?.();
  }

  setLightIntensity(intensity: number): void {
    this.intensity = intensity;
    for (const marker of this.markers.values()) {
      marker.light.intensity = marker.enabled ? intensity : 0;
    }
  }

  enabled(): { name: ViewpointName; position: Vec3 }[] {
    return [...this.markers.values()]
      .filter((m) => m.enabled)
      .map((m) => ({ name: m.name, position: m.object.position.toArray() as Vec3 }));
  }

  position(name: ViewpointName): Vec3 {
    return this.markers.get(name)!.object.position.toArray() as Vec3;
  }

  setPosition(name: ViewpointName, position: Vec3): void {
    this.markers.get(name)!.object.position.set(...position);
    this.onChange?.();
  }

  /** Pickable objects (spheres and glows) for raycasting. */
  pickables(): Object3D[] {
    return [...this.markers.values()].filter((m) => m.enabled).flatMap((m) => m.object.children);
  }

  select(name: ViewpointName): void {
    this.selected = name;
    this.gizmo.attach(this.markers.get(name)!.object);
  }

  deselect(): void {
    this.selected = null;
    this.gizmo.detach();
  }

  get selection(): ViewpointName | null {
    return this.selected;
  }

  /** Marker sphere position as a Vector3 (for drawing rays from it). */
  vector(name: ViewpointName): Vector3 {
    return this.markers.get(name)!.object.position.clone();
  }
}
