// Binary frames of the protocol (docs/protocol.md, "Binary frames"): a 32-byte
// little-endian header, then a tightly packed payload. Pure functions, no
// transport: decodeFrame(ArrayBuffer) validates every header field against the
// message length, so a truncated or corrupt message is a FrameError, never a
// typed array that reads past its data.

export const FRAME_MAGIC = 0x4f434342; // "OCCB", read big-endian
export const FRAME_VERSION = 1;
export const FRAME_HEADER_BYTES = 32;

export type ElementType = "uint8" | "uint16" | "uint32" | "int32" | "float32";

export type TypedArray = Uint8Array | Uint16Array | Uint32Array | Int32Array | Float32Array;

const TYPE_CODES: Record<number, ElementType> = {
  1: "uint8",
  2: "uint16",
  3: "uint32",
  4: "int32",
  5: "float32",
};

const TYPE_SIZES: Record<ElementType, number> = {
  uint8: 1,
  uint16: 2,
  uint32: 4,
  int32: 4,
  float32: 4,
};

export type FrameKind =
  | "positions"
  | "colours"
  | "labels"
  | "instances"
  | "indices"
  | "face_groups"
  | "face_visible_fraction"
  | "visible_count"
  | "escape_directions"
  | "point_clusters"
  | "covered_by"
  | "upload";

interface KindSpec {
  code: number;
  type: ElementType;
  components: number;
}

/** The kind table of the protocol: code, element type and components. */
export const FRAME_KINDS: Record<FrameKind, KindSpec> = {
  positions: { code: 1, type: "float32", components: 3 },
  colours: { code: 2, type: "uint8", components: 3 },
  labels: { code: 3, type: "int32", components: 1 },
  instances: { code: 4, type: "int32", components: 1 },
  indices: { code: 5, type: "uint32", components: 3 },
  face_groups: { code: 6, type: "uint32", components: 1 },
  face_visible_fraction: { code: 7, type: "float32", components: 1 },
  visible_count: { code: 8, type: "uint16", components: 1 },
  escape_directions: { code: 9, type: "float32", components: 3 },
  point_clusters: { code: 10, type: "int32", components: 1 },
  covered_by: { code: 11, type: "int32", components: 1 },
  upload: { code: 100, type: "uint8", components: 1 },
};

const KIND_BY_CODE = new Map<number, FrameKind>(
  (Object.keys(FRAME_KINDS) as FrameKind[]).map((kind) => [FRAME_KINDS[kind].code, kind]),
);

export interface Frame {
  kind: FrameKind;
  id: number;
  item: number;
  type: ElementType;
  components: number;
  /** Number of elements (data.length / components). */
  count: number;
  /** A view on the message's own buffer, starting at byte 32 (no copy). */
  data: TypedArray;
}

export class FrameError extends Error {
  constructor(message: string) {
    super(`frame: ${message}`);
    this.name = "FrameError";
  }
}

export function elementSize(type: ElementType): number {
  return TYPE_SIZES[type];
}

export function typeCode(type: ElementType): number {
  for (const [code, name] of Object.entries(TYPE_CODES)) if (name === type) return Number(code);
  throw new FrameError(`unknown element type '${type}'`);
}

/** The request id of a frame, read without validating the rest (routing). */
export function peekFrameId(buffer: ArrayBuffer): number | null {
  if (buffer.byteLength < FRAME_HEADER_BYTES) return null;
  const view = new DataView(buffer);
  if (view.getUint32(0, false) !== FRAME_MAGIC) return null;
  return view.getUint32(8, true);
}

function view(buffer: ArrayBuffer, type: ElementType, length: number): TypedArray {
  const offset = FRAME_HEADER_BYTES;
  switch (type) {
    case "uint8":
      return new Uint8Array(buffer, offset, length);
    case "uint16":
      return new Uint16Array(buffer, offset, length);
    case "uint32":
      return new Uint32Array(buffer, offset, length);
    case "int32":
      return new Int32Array(buffer, offset, length);
    case "float32":
      return new Float32Array(buffer, offset, length);
  }
}

export function decodeFrame(buffer: ArrayBuffer): Frame {
  if (!(buffer instanceof ArrayBuffer)) throw new FrameError("not an ArrayBuffer");
  if (buffer.byteLength < FRAME_HEADER_BYTES) {
    throw new FrameError(`${buffer.byteLength} bytes, shorter than the 32-byte header`);
  }
  const v = new DataView(buffer);
  const magic = v.getUint32(0, false);
  if (magic !== FRAME_MAGIC) {
    throw new FrameError(`bad magic 0x${magic.toString(16).padStart(8, "0")} (expected 'OCCB')`);
  }
  const version = v.getUint16(4, true);
  if (version !== FRAME_VERSION) {
    throw new FrameError(`unsupported version ${version} (this viewer reads ${FRAME_VERSION})`);
  }
  const kindCode = v.getUint16(6, true);
  const kind = KIND_BY_CODE.get(kindCode);
  if (kind === undefined) throw new FrameError(`unknown kind ${kindCode}`);
  const id = v.getUint32(8, true);
  const typeByte = v.getUint8(12);
  const type = TYPE_CODES[typeByte];
  if (type === undefined) throw new FrameError(`${kind}: unknown element type ${typeByte}`);
  const components = v.getUint8(13);
  const bigCount = v.getBigUint64(16, true);
  const item = v.getUint32(24, true);

  const spec = FRAME_KINDS[kind];
  if (type !== spec.type || components !== spec.components) {
    throw new FrameError(
      `${kind}: ${type} x${components}, expected ${spec.type} x${spec.components}`,
    );
  }
  const payload = buffer.byteLength - FRAME_HEADER_BYTES;
  const size = elementSize(type) * components;
  if (bigCount > BigInt(Number.MAX_SAFE_INTEGER) || bigCount * BigInt(size) !== BigInt(payload)) {
    throw new FrameError(
      `${kind}: header announces ${bigCount} elements (${bigCount * BigInt(size)} bytes), ` +
        `payload holds ${payload} bytes`,
    );
  }
  const count = Number(bigCount);
  return { kind, id, item, type, components, count, data: view(buffer, type, count * components) };
}

/** Builds a frame (header + payload copy); the client uses it for uploads, tests for fixtures. */
export function encodeFrame(
  kind: FrameKind,
  id: number,
  payload: ArrayBufferView,
  options: { item?: number; type?: ElementType; components?: number } = {},
): ArrayBuffer {
  const spec = FRAME_KINDS[kind];
  const type = options.type ?? spec.type;
  const components = options.components ?? spec.components;
  const size = elementSize(type) * components;
  if (payload.byteLength % size !== 0) {
    throw new FrameError(`${kind}: ${payload.byteLength} bytes is not a whole number of elements`);
  }
  const buffer = new ArrayBuffer(FRAME_HEADER_BYTES + payload.byteLength);
  const v = new DataView(buffer);
  v.setUint32(0, FRAME_MAGIC, false);
  v.setUint16(4, FRAME_VERSION, true);
  v.setUint16(6, spec.code, true);
  v.setUint32(8, id >>> 0, true);
  v.setUint8(12, typeCode(type));
  v.setUint8(13, components);
  v.setBigUint64(16, BigInt(payload.byteLength / size), true);
  v.setUint32(24, (options.item ?? 0) >>> 0, true);
  new Uint8Array(buffer, FRAME_HEADER_BYTES).set(
    new Uint8Array(payload.buffer, payload.byteOffset, payload.byteLength),
  );
  return buffer;
}
