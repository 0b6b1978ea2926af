import { describe, expect, test } from "vitest";
import {
  FRAME_HEADER_BYTES,
  FRAME_KINDS,
  FrameError,
  decodeFrame,
  encodeFrame,
  peekFrameId,
} from "../../src/protocol/frame";
import type { FrameKind } from "../../src/protocol/frame";
import { encodeFrameHeader } from "../../src/protocol/frame_header";

/** A header written field by field, as docs/protocol.md lays it out. */
function header(fields: {
  magic?: number;
  version?: number;
  kind?: number;
  id?: number;
  type?: number;
  components?: number;
  count?: bigint;
  item?: number;
  payloadBytes?: number;
}): ArrayBuffer {
  const buffer = new ArrayBuffer(FRAME_HEADER_BYTES + (fields.payloadBytes ?? 0));
  const v = new DataView(buffer);
  v.setUint32(0, fields.magic ?? 0x4f434342, false);
  v.setUint16(4, fields.version ?? 1, true);
  v.setUint16(6, fields.kind ?? 1, true);
  v.setUint32(8, fields.id ?? 7, true);
  v.setUint8(12, fields.type ?? 5);
  v.setUint8(13, fields.components ?? 3);
  v.setBigUint64(16, fields.count ?? 0n, true);
  v.setUint32(24, fields.item ?? 0, true);
  return buffer;
}

describe("decodeFrame", () => {
  test("reads the header and views the payload without copying", () => {
    const buffer = header({ id: 0xfffffffe, count: 2n, item: 3, payloadBytes: 24 });
    new Float32Array(buffer, 32, 6).set([1, 2, 3, 4, 5, 6]);
    const frame = decodeFrame(buffer);
    expect(frame).toMatchObject({
      kind: "positions",
      id: 0xfffffffe,
      item: 3,
      type: "float32",
      components: 3,
      count: 2,
    });
    expect(Array.from(frame.data)).toEqual([1, 2, 3, 4, 5, 6]);
    expect(frame.data.buffer).toBe(buffer);
    expect(frame.data.byteOffset).toBe(32);
  });

  test("round-trips every kind through encodeFrame", () => {
    for (const kind of Object.keys(FRAME_KINDS) as FrameKind[]) {
      const spec = FRAME_KINDS[kind];
      const values = Array.from({ length: spec.components * 4 }, (_, i) => i + 1);
      const typed =
        spec.type === "float32"
          ? new Float32Array(values)
          : spec.type === "int32"
            ? new Int32Array(values)
            : spec.type === "uint32"
              ? new Uint32Array(values)
              : spec.type === "uint16"
                ? new Uint16Array(values)
                : new Uint8Array(values);
      const frame = decodeFrame(encodeFrame(kind, 42, typed, { item: 1 }));
      expect(frame.kind).toBe(kind);
      expect(frame.count).toBe(4);
      expect(frame.item).toBe(1);
      expect(Array.from(frame.data)).toEqual(values);
    }
  });

  test("an empty frame is valid", () => {
    const frame = decodeFrame(header({ kind: 9, count: 0n }));
    expect(frame.kind).toBe("escape_directions");
    expect(frame.data.length).toBe(0);
  });

  test.each([
    ["shorter than the header", new ArrayBuffer(31), /shorter than the 32-byte header/],
    ["bad magic", header({ magic: 0x4f434343 }), /bad magic 0x4f434343/],
    ["unsupported version", header({ version: 2 }), /unsupported version 2/],
    ["unknown kind", header({ kind: 77 }), /unknown kind 77/],
    ["unknown element type", header({ type: 9 }), /positions: unknown element type 9/],
    [
      "wrong type for its kind",
      header({ kind: 2, type: 5 }),
      /colours: float32 x3, expected uint8 x3/,
    ],
    ["wrong components", header({ components: 2 }), /positions: float32 x2, expected float32 x3/],
    [
      "count beyond the payload",
      header({ count: 3n, payloadBytes: 24 }),
      /announces 3 elements \(36 bytes\), payload holds 24/,
    ],
    ["payload beyond the count", header({ count: 1n, payloadBytes: 24 }), /announces 1 elements/],
    ["a partial element", header({ count: 1n, payloadBytes: 13 }), /payload holds 13 bytes/],
    ["a count over 2^53", header({ count: 1n << 60n }), /announces/],
  ])("rejects a frame with %s", (_, buffer, message) => {
    expect(() => decodeFrame(buffer)).toThrow(FrameError);
    expect(() => decodeFrame(buffer)).toThrow(message);
  });

  test("errors name the module", () => {
    expect(() => decodeFrame(new ArrayBuffer(3))).toThrow(/^frame: /);
  });

  test("rejects what is not an ArrayBuffer", () => {
    expect(() => decodeFrame(new Uint8Array(40) as unknown as ArrayBuffer)).toThrow(
      /not an ArrayBuffer/,
    );
  });
});

describe("peekFrameId", () => {
  test("reads the id of a framed message, null otherwise", () => {
    expect(peekFrameId(header({ id: 12345 }))).toBe(12345);
    expect(peekFrameId(new ArrayBuffer(8))).toBeNull();
    expect(peekFrameId(header({ magic: 1 }))).toBeNull();
  });
});

describe("encodeFrameHeader", () => {
  test("announces an upload of N bytes", () => {
    const h = encodeFrameHeader("upload", 5, 1048576);
    const v = new DataView(h);
    expect(h.byteLength).toBe(32);
    expect(v.getUint32(0, false)).toBe(0x4f434342);
    expect(v.getUint16(6, true)).toBe(100);
    expect(v.getUint32(8, true)).toBe(5);
    expect(v.getUint8(12)).toBe(1);
    expect(v.getUint8(13)).toBe(1);
    expect(v.getBigUint64(16, true)).toBe(1048576n);
  });

  test("a header plus its bytes decodes as an upload frame", () => {
    const bytes = new Uint8Array([1, 2, 3]);
    const message = new Uint8Array(35);
    message.set(new Uint8Array(encodeFrameHeader("upload", 9, 3)));
    message.set(bytes, 32);
    const frame = decodeFrame(message.buffer);
    expect(frame.kind).toBe("upload");
    expect(Array.from(frame.data)).toEqual([1, 2, 3]);
  });
});
