import { afterEach, beforeEach, describe, expect, test, vi } from "vitest";
import { ProtocolClient } from "../../src/protocol/client";
import { ServerError } from "../../src/protocol/errors";
import { encodeFrame } from "../../src/protocol/frame";
import { FakeSocket } from "./fake_socket";

let socket: FakeSocket;
let client: ProtocolClient;

async function connected(): Promise<void> {
  const hello = client.connect();
  socket.open();
  socket.hello();
  await hello;
}

function result(
  id: number,
  command: string,
  body: Record<string, unknown> = {},
  frames: unknown[] = [],
) {
  return JSON.stringify({ type: "result", id, command, result: body, frames });
}

beforeEach(() => {
  client = new ProtocolClient("ws://test/ws", (url) => (socket = new FakeSocket(url)));
});

afterEach(() => {
  vi.useRealTimers();
});

describe("connect", () => {
  test("resolves with the server's hello and sets binary frames to ArrayBuffer", async () => {
    const promise = client.connect();
    socket.open();
    socket.hello();
    const hello = await promise;
    expect(hello.server).toBe("occlusion test");
    expect(socket.binaryType).toBe("arraybuffer");
    expect(client.connected).toBe(true);
    expect(client.available("load")).toBe(true);
    expect(client.available("evaluate")).toBe(false);
    expect(client.available("no_such_command")).toBe(false);
  });

  test("refuses another protocol version", async () => {
    const promise = client.connect();
    socket.open();
    socket.hello({ protocol: 2 });
    await expect(promise).rejects.toThrow(/server speaks protocol 2, this viewer 1/);
  });

  test("fails when the socket closes or errors before hello", async () => {
    const promise = client.connect();
    socket.close(1006);
    await expect(promise).rejects.toMatchObject({ code: "disconnected" });
    const again = client.connect();
    socket.onerror?.({});
    await expect(again).rejects.toThrow(/cannot connect/);
  });

  test("fails after a timeout without hello", async () => {
    vi.useFakeTimers();
    const promise = client.connect(1000);
    socket.open();
    vi.advanceTimersByTime(1001);
    await expect(promise).rejects.toThrow(/no hello .* within 1000 ms/);
  });

  test("a binary message before hello is a protocol error", async () => {
    const promise = client.connect();
    socket.open();
    socket.receive(new ArrayBuffer(40));
    await expect(promise).rejects.toThrow(/binary message before hello/);
  });
});

describe("requests", () => {
  beforeEach(connected);

  test("sends id, command and params, and resolves with the result", async () => {
    const handle = client.request("list_files", { dir: "s3dis" });
    expect(socket.lastRequest()).toEqual({
      id: handle.id,
      command: "list_files",
      params: { dir: "s3dis" },
    });
    socket.receive(result(handle.id, "list_files", { entries: [] }));
    const reply = await handle.promise;
    expect(reply.result).toEqual({ entries: [] });
    expect(reply.command).toBe("list_files");
  });

  test("ids are distinct 32-bit integers", () => {
    const ids = new Set(Array.from({ length: 50 }, () => client.request("ping").id));
    expect(ids.size).toBe(50);
    for (const id of ids) expect(id >= 0 && id <= 0xffffffff && Number.isInteger(id)).toBe(true);
  });

  test("replies are matched by id, in any order", async () => {
    const slow = client.request("mesh_occlusion", { path: "a.obj" });
    const fast = client.request("ping");
    socket.receive(result(fast.id, "ping"));
    await expect(fast.promise).resolves.toMatchObject({ id: fast.id });
    socket.receive(result(slow.id, "mesh_occlusion", { occlusion_level: 0.25 }));
    await expect(slow.promise).resolves.toMatchObject({ result: { occlusion_level: 0.25 } });
  });

  test("progress goes to its request's callback", async () => {
    const seen: [string, number][] = [];
    const handle = client.request("scan", {}, { onProgress: (s, f) => seen.push([s, f]) });
    socket.receive(
      JSON.stringify({ type: "progress", id: handle.id, stage: "tracing", fraction: 0.5 }),
    );
    socket.receive(
      JSON.stringify({ type: "progress", id: handle.id, stage: "tracing", fraction: 1.7 }),
    );
    socket.receive(result(handle.id, "scan"));
    await handle.promise;
    expect(seen).toEqual([
      ["tracing", 0.5],
      ["tracing", 1],
    ]);
  });

  test("binary frames go to their request in order, before the result", async () => {
    const frames: ArrayBuffer[] = [];
    const handle = client.request("load", { path: "x" }, { onFrame: (b) => frames.push(b) });
    const a = encodeFrame("positions", handle.id, new Float32Array([1, 2, 3]));
    const b = encodeFrame("colours", handle.id, new Uint8Array([4, 5, 6]));
    socket.receive(a);
    socket.receive(b);
    const listed = [
      { kind: "positions", type: "float32", components: 3, count: 1, item: 0 },
      { kind: "colours", type: "uint8", components: 3, count: 1, item: 0 },
    ];
    socket.receive(result(handle.id, "load", { kind: "cloud" }, listed));
    const reply = await handle.promise;
    expect(frames).toEqual([a, b]);
    expect(reply.frames).toEqual(listed);
  });

  test("a result listing frames that did not arrive is a decode error", async () => {
    const handle = client.request("load", { path: "x" });
    socket.receive(
      result(handle.id, "load", {}, [
        { kind: "positions", type: "float32", components: 3, count: 1, item: 0 },
      ]),
    );
    await expect(handle.promise).rejects.toMatchObject({
      code: "decode_error",
      message: expect.stringMatching(/lists 1 binary frames, 0 arrived/),
    });
  });

  test("an error reply rejects with a ServerError carrying code and message", async () => {
    const handle = client.request("load", { path: "../etc/passwd" });
    socket.receive(
      JSON.stringify({
        type: "error",
        id: handle.id,
        command: "load",
        code: "path_outside_data",
        message: "'../etc/passwd' is outside the data directory",
      }),
    );
    const error = await handle.promise.catch((e: unknown) => e);
    expect(error).toBeInstanceOf(ServerError);
    expect(error).toMatchObject({ code: "path_outside_data", command: "load", id: handle.id });
    expect((error as Error).message).toContain("outside the data directory");
  });

  test("an error without an id goes to onStrayError", () => {
    const stray: ServerError[] = [];
    client.onStrayError = (e) => stray.push(e);
    socket.receive(
      JSON.stringify({ type: "error", id: null, code: "invalid_json", message: "not JSON" }),
    );
    expect(stray).toHaveLength(1);
    expect(stray[0]!.code).toBe("invalid_json");
  });

  test("malformed messages and frames for unknown requests are reported, not thrown", () => {
    const problems: string[] = [];
    client.onProtocolError = (e) => problems.push(e.message);
    socket.receive("{not json");
    socket.receive(JSON.stringify({ type: "mystery" }));
    socket.receive(JSON.stringify({ type: "result", id: "seven", result: {} }));
    socket.receive(result(999, "ping"));
    socket.receive(encodeFrame("labels", 4242, new Int32Array([1])));
    socket.receive(new ArrayBuffer(10));
    expect(problems).toEqual([
      expect.stringMatching(/not JSON/),
      expect.stringMatching(/unknown message type "mystery"/),
      expect.stringMatching(/result without a valid 'id'/),
      expect.stringMatching(/result for unknown request 999/),
      expect.stringMatching(/binary frame for unknown request 4242/),
      expect.stringMatching(/10 bytes without a frame header/),
    ]);
  });

  test("cancel sends a cancel request naming the target", async () => {
    const handle = client.request("cloud_occlusion", { path: "room" });
    handle.cancel();
    const cancel = socket.lastRequest();
    expect(cancel).toMatchObject({ command: "cancel", params: { target: handle.id } });
    socket.receive(result(cancel.id, "cancel", { target: handle.id, found: true }));
    socket.receive(
      JSON.stringify({
        type: "error",
        id: handle.id,
        command: "cloud_occlusion",
        code: "cancelled",
        message: "cancelled",
      }),
    );
    await expect(handle.promise).rejects.toMatchObject({ code: "cancelled" });
  });

  test("a request over the text limit is refused before sending", async () => {
    const before = socket.sent.length;
    const handle = client.request("save_polygon", { polygons: "x".repeat(2000) });
    await expect(handle.promise).rejects.toMatchObject({ code: "message_too_large" });
    expect(socket.sent.length).toBe(before);
  });

  test("a timeout rejects and cancels on the server", async () => {
    vi.useFakeTimers();
    const handle = client.request("scan", {}, { timeoutMs: 500 });
    vi.advanceTimersByTime(501);
    await expect(handle.promise).rejects.toMatchObject({ code: "timeout" });
    expect(socket.lastRequest()).toMatchObject({
      command: "cancel",
      params: { target: handle.id },
    });
    // Its late reply (the cancellation) is dropped quietly.
    const noise: unknown[] = [];
    client.onStrayError = (e) => noise.push(e);
    client.onProtocolError = (e) => noise.push(e);
    socket.receive(encodeFrame("visible_count", handle.id, new Uint16Array([1])));
    socket.receive(
      JSON.stringify({
        type: "error",
        id: handle.id,
        command: "scan",
        code: "cancelled",
        message: "cancelled",
      }),
    );
    expect(noise).toEqual([]);
  });

  test("closing the connection rejects every pending request", async () => {
    const closes: string[] = [];
    client.onClose = (why) => closes.push(why);
    const a = client.request("scan");
    const b = client.request("load", { path: "x" });
    socket.close(1006, "gone");
    await expect(a.promise).rejects.toMatchObject({ code: "disconnected" });
    await expect(b.promise).rejects.toMatchObject({ code: "disconnected" });
    expect(closes).toEqual([expect.stringContaining("code 1006: gone")]);
    expect(client.connected).toBe(false);
    expect(client.pendingCount).toBe(0);
  });

  test("requests while disconnected fail at once", async () => {
    client.close();
    await expect(client.request("ping").promise).rejects.toMatchObject({ code: "disconnected" });
  });

  test("ping measures a round trip", async () => {
    const promise = client.ping();
    socket.receive(result(socket.lastRequest().id, "ping"));
    expect(await promise).toBeGreaterThanOrEqual(0);
  });

  test("an id is reused only after its request finished", async () => {
    const first = client.request("ping");
    const ids = new Set<number>([first.id]);
    for (let i = 0; i < 5; ++i) ids.add(client.request("ping").id);
    expect(ids.size).toBe(6);
  });
});

describe("upload", () => {
  beforeEach(connected);

  test("announces the file, then sends header + bytes as one binary message", async () => {
    const file = new Blob([new Uint8Array([10, 20, 30, 40])]);
    const handle = client.upload("scan.ply", file);
    expect(socket.requests().at(-1)).toEqual({
      id: handle.id,
      command: "upload",
      params: { name: "scan.ply", size: 4 },
    });
    const binary = socket.sent.at(-1) as Blob;
    expect(binary).toBeInstanceOf(Blob);
    const bytes = new Uint8Array(await binary.arrayBuffer());
    expect(bytes.length).toBe(36);
    const v = new DataView(bytes.buffer);
    expect(v.getUint16(6, true)).toBe(100);
    expect(v.getUint32(8, true)).toBe(handle.id);
    expect(v.getBigUint64(16, true)).toBe(4n);
    expect(Array.from(bytes.subarray(32))).toEqual([10, 20, 30, 40]);
    socket.receive(result(handle.id, "upload", { path: "uploads/scan.ply" }));
    await expect(handle.promise).resolves.toMatchObject({ result: { path: "uploads/scan.ply" } });
  });
});
