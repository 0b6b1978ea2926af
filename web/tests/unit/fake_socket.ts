// A scripted WebSocket for the protocol client's tests.

import type { SocketLike } from "../../src/protocol/client";

export const HELLO = {
  type: "hello",
  protocol: 1,
  server: "occlusion test",
  commands: { ping: true, load: true, upload: true, cancel: true, evaluate: false },
  limits: { max_text_bytes: 1024, max_upload_bytes: 1 << 20, progress_per_second: 10 },
};

export class FakeSocket implements SocketLike {
  binaryType = "blob";
  readyState = 0;
  bufferedAmount = 0;
  readonly sent: (string | ArrayBuffer | Blob)[] = [];
  onopen: ((event: unknown) => void) | null = null;
  onclose: ((event: { code: number; reason: string }) => void) | null = null;
  onerror: ((event: unknown) => void) | null = null;
  onmessage: ((event: { data: unknown }) => void) | null = null;

  constructor(readonly url: string) {}

  send(data: string | ArrayBuffer | Blob): void {
    if (this.readyState !== 1) throw new Error("FakeSocket: send while not open");
    this.sent.push(data);
  }

  close(code = 1000, reason = ""): void {
    if (this.readyState === 3) return;
    this.readyState = 3;
    this.onclose?.({ code, reason });
  }

  /** The server side: open, say hello, send messages. */
  open(): void {
    this.readyState = 1;
    this.onopen?.({});
  }

  hello(overrides: Record<string, unknown> = {}): void {
    this.receive(JSON.stringify({ ...HELLO, ...overrides }));
  }

  receive(data: string | ArrayBuffer): void {
    this.onmessage?.({ data });
  }

  /** The JSON requests sent so far. */
  requests(): { id: number; command: string; params: Record<string, unknown> }[] {
    return this.sent.filter((m): m is string => typeof m === "string").map((m) => JSON.parse(m));
  }

  lastRequest() {
    const all = this.requests();
    return all[all.length - 1]!;
  }
}
