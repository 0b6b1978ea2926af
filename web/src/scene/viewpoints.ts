// The viewpoints as light markers, each a glowing sphere with a point light,
// toggled from the GUI and dragged with a transform gizmo before computing.
// On a cloud they start at -poc's default viewpoints as the server places them
// (its stations, else the grid of the robust frame); on a mesh at the seed's
// three (centre, the midpoints towards the bounding box's max and min
// corners, i.e. patterns C, U and L, -moc's pattern 7). Jobs get the enabled
// ones as explicit `viewpoints`, unless they are still a job's defaults.

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

/** A marker's id: the pattern's three ("centre", "max", "min") or one added ("vp4", …). */
export type MarkerId = string;
export type { ViewpointName };

/** The pattern viewpoints the GUI toggles one by one. */
export const VIEWPOINT_NAMES: ViewpointName[] = ["centre", "max", "min"];

export const VIEWPOINT_LABELS: Record<ViewpointName, string> = {
  centre: "Center",
  max: "Viewpoint Max",
  min: "Viewpoint Min",
};

/** Marker colours in order of creation: the rays and the legend use the same. */
const PALETTE = [0xffd166, 0xff7b54, 0x7bdff2, 0xc084fc, 0x4ade80, 0xf472b6, 0xfacc15, 0x60a5fa];

export interface Marker {
  name: MarkerId;
  label: string;
  colour: number;
  object: Group;
  sphere: Mesh<SphereGeometry, MeshBasicMaterial>;
  light: PointLight;
  enabled: boolean;
  /**
   * For a job's default viewpoint: where the server placed it (scene frame)
   * and whether the job warns that it stands outside the occupied space
   * (app/default_viewpoints.hpp); null for one added or planned.
   */
  placed: { position: Vec3; outside: boolean } | null;
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
  readonly markers = new Map<MarkerId, Marker>();
  readonly gizmo: TransformControls;
  /** Called when a marker moves or is toggled. */
  onChange: (() => void) | null = null;
  private selected: MarkerId | null = null;
  private size = 0.1;
  private intensity = 1;

  private readonly texture = glowTexture();
  private created = 0;
  /** Set by placeDefaults, cleared by adding, removing or placing others. */
  private defaults = false;

  constructor(camera: Camera, domElement: HTMLElement, overlays: Object3D) {
    for (const name of VIEWPOINT_NAMES) this.create(name, VIEWPOINT_LABELS[name]);
    overlays.add(this.group);
    this.gizmo = new TransformControls(camera, domElement);
    this.gizmo.setSize(0.8);
    this.gizmo.addEventListener("objectChange", () => this.onChange?.());
    overlays.add(this.gizmo.getHelper());
  }

  private create(name: MarkerId, label: string): Marker {
    const hex = PALETTE[this.created++ % PALETTE.length]!;
    const object = new Group();
    object.name = `viewpoint-${name}`;
    const colour = new Color(hex);
    const sphere = new Mesh(
      new SphereGeometry(1, 20, 14),
      new MeshBasicMaterial({ color: colour }),
    );
    sphere.userData.viewpoint = name;
    const glow = new Sprite(
      new SpriteMaterial({
        map: this.texture,
        color: colour,
        transparent: true,
        depthWrite: false,
      }),
    );
    glow.scale.setScalar(5);
    glow.userData.viewpoint = name;
    const light = new PointLight(colour, this.intensity, 0, 0);
    object.add(sphere, glow, light);
    object.scale.setScalar(this.size);
    this.group.add(object);
    const marker: Marker = {
      name,
      label,
      colour: hex,
      object,
      sphere,
      light,
      enabled: true,
      placed: null,
    };
    this.markers.set(name, marker);
    return marker;
  }

  /** Adds a viewpoint at `position`; returns its id. */
  add(position: Vec3): MarkerId {
    let k = this.markers.size + 1;
    while (this.markers.has(`vp${k}`)) ++k;
    const marker = this.create(`vp${k}`, `Viewpoint ${k}`);
    marker.object.position.set(...position);
    this.defaults = false;
    this.onChange?.();
    return marker.name;
  }

  /** Removes a viewpoint (any, the pattern's three included). */
  remove(name: MarkerId): void {
    const marker = this.markers.get(name);
    if (!marker) return;
    if (this.selected === name) this.deselect();
    this.defaults = false;
    this.setBadge(name, "", "");
    marker.object.removeFromParent();
    marker.sphere.geometry.dispose();
    marker.sphere.material.dispose();
    marker.light.dispose();
    this.markers.delete(name);
    this.onChange?.();
  }

  /** The marker's colour as 0..1 RGB (its rays are drawn in it). */
  colour(name: MarkerId): [number, number, number] {
    const c = new Color(this.markers.get(name)?.colour ?? 0xffffff);
    return [c.r, c.g, c.b];
  }

  label(name: MarkerId): string {
    return this.markers.get(name)?.label ?? name;
  }

  /** Back to the pattern's three on the bounds' pattern points (added ones go), sized to the scene. */
  reset(bounds: Bounds): void {
    this.deselect();
    this.defaults = false;
    for (const name of [...this.markers.keys()]) {
      if (!(VIEWPOINT_NAMES as string[]).includes(name)) this.remove(name);
    }
    const points = patternPoints(bounds);
    this.size = diagonal(bounds) * 0.012;
    for (const name of VIEWPOINT_NAMES) {
      const marker = this.markers.get(name) ?? this.create(name, VIEWPOINT_LABELS[name]);
      marker.object.position.set(...points[name]);
    }
    // Creation order (and so colour) stays centre, max, min.
    for (const marker of this.markers.values()) marker.object.scale.setScalar(this.size);
    this.onChange?.();
  }

  /** The markers at planned stations, named after them. */
  placeStations(stations: readonly { name: string; position: Vec3 }[]): void {
    this.place("station", stations);
    this.defaults = false;
    this.onChange?.();
  }

  /**
   * The markers at a cloud job's default viewpoints (the server's, which the
   * CLI takes with no viewpoint given), named as the job names them; `size`
   * of the scene, as reset takes it.
   */
  placeDefaults(
    viewpoints: readonly { name: string; position: Vec3; outside: boolean }[],
    bounds: Bounds,
  ): void {
    this.size = diagonal(bounds) * 0.012;
    this.place("default", viewpoints).forEach((marker, k) => {
      marker.placed = { position: [...viewpoints[k]!.position], outside: viewpoints[k]!.outside };
    });
    this.defaults = true;
    this.onChange?.();
  }

  /**
   * Whether the enabled markers are still a job's defaults, all of them, none
   * moved: then a job may be sent no viewpoints and take its own, as the CLI would.
   */
  get atDefaults(): boolean {
    return (
      this.defaults &&
      [...this.markers.values()].every((m) => m.enabled && this.atPlacedPosition(m))
    );
  }

  /** Whether the job warns at this marker, when it is still where the server placed it; else null. */
  placedOutside(name: MarkerId): boolean | null {
    const marker = this.markers.get(name);
    return marker && this.atPlacedPosition(marker) ? marker.placed!.outside : null;
  }

  private atPlacedPosition(marker: Marker): boolean {
    const placed = marker.placed?.position;
    return (
      placed !== undefined && marker.object.position.toArray().every((x, a) => x === placed[a])
    );
  }

  private place(prefix: string, list: readonly { name: string; position: Vec3 }[]): Marker[] {
    this.deselect();
    for (const name of [...this.markers.keys()]) this.remove(name);
    return list.map((entry, k) => {
      const marker = this.create(`${prefix}${k + 1}`, entry.name);
      marker.object.position.set(...entry.position);
      marker.object.scale.setScalar(this.size);
      return marker;
    });
  }

  /** Gives a marker another colour (0xRRGGBB): its sphere, glow, light, rays and list entry. */
  recolour(name: MarkerId, hex: number): void {
    const marker = this.markers.get(name);
    if (!marker) return;
    marker.colour = hex;
    marker.sphere.material.color.set(hex);
    marker.light.color.set(hex);
    for (const child of marker.object.children) {
      if (child instanceof Sprite && child.userData.badge !== true) child.material.color.set(hex);
    }
    this.onChange?.();
  }

  /**
   * A number beside the marker, in `colour` (a planned station's rank), or
   * none with an empty text. It moves with the marker.
   */
  setBadge(name: MarkerId, text: string, colour: string): void {
    const marker = this.markers.get(name);
    if (!marker) return;
    for (const child of [...marker.object.children]) {
      if (child.userData.badge === true) {
        child.removeFromParent();
        (child as Sprite).material.map?.dispose();
        (child as Sprite).material.dispose();
      }
    }
    if (text === "") return;
    const canvas = document.createElement("canvas");
    canvas.width = canvas.height = 64;
    const g = canvas.getContext("2d")!;
    g.fillStyle = colour;
    g.beginPath();
    g.arc(32, 32, 30, 0, 2 * Math.PI);
    g.fill();
    g.fillStyle = "#0b1220";
    g.font = "bold 34px sans-serif";
    g.textAlign = "center";
    g.textBaseline = "middle";
    g.fillText(text, 32, 34);
    const badge = new Sprite(
      new SpriteMaterial({ map: new CanvasTexture(canvas), depthTest: false, transparent: true }),
    );
    badge.userData.badge = true;
    badge.userData.viewpoint = name;
    badge.position.set(0, 0, 3.2);
    badge.scale.setScalar(3.2);
    badge.renderOrder = 2;
    marker.object.add(badge);
  }

  setEnabled(name: MarkerId, enabled: boolean): void {
    const marker = this.markers.get(name);
    if (!marker) return;
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

  enabled(): { name: MarkerId; position: Vec3 }[] {
    return [...this.markers.values()]
      .filter((m) => m.enabled)
      .map((m) => ({ name: m.name, position: m.object.position.toArray() as Vec3 }));
  }

  position(name: MarkerId): Vec3 {
    return this.markers.get(name)!.object.position.toArray() as Vec3;
  }

  setPosition(name: MarkerId, position: Vec3): void {
    this.markers.get(name)!.object.position.set(...position);
    this.onChange?.();
  }

  /** Pickable objects (spheres and glows) for raycasting. */
  pickables(): Object3D[] {
    return [...this.markers.values()].filter((m) => m.enabled).flatMap((m) => m.object.children);
  }

  select(name: MarkerId): void {
    this.selected = name;
    this.gizmo.attach(this.markers.get(name)!.object);
  }

  deselect(): void {
    this.selected = null;
    this.gizmo.detach();
  }

  get selection(): MarkerId | null {
    return this.selected;
  }

  /** Marker sphere position as a Vector3 (for drawing rays from it). */
  vector(name: MarkerId): Vector3 {
    return this.markers.get(name)!.object.position.clone();
  }
}
