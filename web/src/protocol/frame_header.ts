// A frame header alone, for uploads: the client sends header + file as one
// Blob, so the browser streams the file without copying it into JS memory.

import { FRAME_HEADER_BYTES, FRAME_KINDS, FRAME_MAGIC, FRAME_VERSION, typeCode } from "./frame";
import type { FrameKind } from "./frame";

export function encodeFrameHeader(
  kind: FrameKind,
  id: number,
  count: number,
  item = 0,
): ArrayBuffer {
  const spec = FRAME_KINDS[kind];
  const buffer = new ArrayBuffer(FRAME_HEADER_BYTES);
  const v = new DataView(buffer);
  v.setUint32(0, FRAME_MAGIC, false);
  v.setUint16(4, FRAME_VERSION, true);
  v.setUint16(6, spec.code, true);
  v.setUint32(8, id >>> 0, true);
  v.setUint8(12, typeCode(spec.type));
  v.setUint8(13, spec.components);
  v.setBigUint64(16, BigInt(count), true);
  v.setUint32(24, item >>> 0, true);
  return buffer;
}
