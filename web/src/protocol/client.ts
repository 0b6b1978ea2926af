// The protocol client: one WebSocket, JSON requests with ids, progress events
// and binary frames routed to the request that asked for them, one promise per
// request settled by its `result` or `error` (docs/protocol.md). No three.js,
// no DOM: the socket is injected, so tests drive it with a fake.

import { ServerError } from "./errors";
import { encodeFrameHeader } from "./frame_header";
import { peekFrameId } from "./frame";
import { PROTOCOL_VERSION, ProtocolError, parseServerMessage } from "./messages";
import type { FrameInfo, HelloMessage } from "./messages";

/** What the client needs of a WebSocket (the browser's satisfies it). */
export interface SocketLike {
  binaryType: string;
  readonly readyState: number;
  readonly bufferedAmount: number;
  send(data: string | ArrayBuffer | Blob): void;
  close(code?: number, reason?: string): void;
  onopen: ((event: unknown) => void) | null;
  onclose: ((event: { code: number; reason: string }) => void) | null;
  onerror: ((event: unknown) => void) | null;
  onmessage: ((event: { data: unknown }) => void) | null;
}

export type SocketFactory = (url: string) => SocketLike;

export interface RequestOptions {
  /** Progress events of a job: stage name and fraction in [0, 1]. */
  onProgress?: (stage: string, fraction: number) => void;
  /** Each binary frame of this request, in arrival order (before the result). */
  onFrame?: (buffer: ArrayBuffer) => void;
  /** Reject with `timeout` (and cancel on the server) after this long. */
  timeoutMs?: number;
}

export interface Reply<R = Record<string, unknown>> {
  id: number;
  command: string;
  result: R;
  frames: FrameInfo[];
}

export interface RequestHandle<R = Record<string, unknown>> {
  id: number;
  command: string;
  promise: Promise<Reply<R>>;
  /** Asks the server to stop it; the promise then rejects with `cancelled`. */
  cancel(): void;
}

interface Pending {
  command: string;
  options: RequestOptions;
  framesReceived: number;
  resolve: (reply: Reply) => void;
  reject: (error: Error) => void;
  timer: ReturnType<typeof setTimeout> | undefined;
}

const OPEN = 1;
const MAX_ID = 0xffffffff;

export class ProtocolClient {
  hello: HelloMessage | null = null;
  /** The connection closed (after connect() succeeded). */
  onClose: ((reason: string) => void) | null = null;
  /** An error reply no pending request claims (id null or unknown). */
  onStrayError: ((error: ServerError) => void) | null = null;
  /** A message the client could not make sense of. */
  onProtocolError: ((error: Error) => void) | null = null;

  private socket: SocketLike | null = null;
  private readonly pending = new Map<number, Pending>();
  /** Requests given up (timed out) whose late replies are dropped quietly. */
  private readonly abandoned = new Set<number>();
  private nextId = 1;

  constructor(
    readonly url: string,
    private readonly createSocket: SocketFactory = (u) => new WebSocket(u) as SocketLike,
  ) {}

  get connected(): boolean {
    return this.socket !== null && this.socket.readyState === OPEN && this.hello !== null;
  }

  get pendingCount(): number {
    return this.pending.size;
  }

  /** Whether this server build runs `command` (hello.commands). */
  available(command: string): boolean {
    return this.hello?.commands[command] === true;
  }

  /** Opens the socket; resolves with the server's hello. */
  connect(timeoutMs = 10_000): Promise<HelloMessage> {
    this.close();
    return new Promise<HelloMessage>((resolve, reject) => {
      let settled = false;
      const fail = (message: string) => {
        if (settled) return;
        settled = true;
        clearTimeout(timer);
        socket.close();
        reject(new ServerError("disconnected", message));
      };
      const socket = this.createSocket(this.url);
      this.socket = socket;
      socket.binaryType = "arraybuffer";
      const timer = setTimeout(
        () => fail(`no hello from ${this.url} within ${timeoutMs} ms`),
        timeoutMs,
      );
      socket.onerror = () => fail(`cannot connect to ${this.url}`);
      socket.onclose = (event) => {
        if (!settled) fail(`connection to ${this.url} closed (code ${event.code})`);
        else this.closed(event.code, event.reason);
      };
      socket.onmessage = (event) => {
        if (settled) {
          this.receive(event.data);
          return;
        }
        try {
          if (typeof event.data !== "string")
            throw new ProtocolError("binary message before hello");
          const message = parseServerMessage(event.data);
          if (message.type !== "hello") throw new ProtocolError(`'${message.type}' before hello`);
          if (message.protocol !== PROTOCOL_VERSION) {
            throw new ProtocolError(
              `server speaks protocol ${message.protocol}, this viewer ${PROTOCOL_VERSION}`,
            );
          }
          this.hello = message;
          settled = true;
          clearTimeout(timer);
          resolve(message);
        } catch (error) {
          fail((error as Error).message);
        }
      };
    });
  }

  close(): void {
    const socket = this.socket;
    if (socket === null) return;
    this.socket = null;
    socket.onclose = null;
    socket.onmessage = null;
    socket.onerror = null;
    socket.close();
    this.rejectAll("connection closed by the viewer");
    this.hello = null;
  }

  request<R = Record<string, unknown>>(
    command: string,
    params: Record<string, unknown> = {},
    options: RequestOptions = {},
  ): RequestHandle<R> {
    const id = this.allocateId();
    const promise = new Promise<Reply<R>>((resolve, reject) => {
      const socket = this.socket;
      if (socket === null || socket.readyState !== OPEN) {
        reject(new ServerError("disconnected", "not connected to the server", command, id));
        return;
      }
      const text = JSON.stringify({ id, command, params });
      const limit = this.hello?.limits.max_text_bytes ?? 1 << 20;
      const bytes = new TextEncoder().encode(text).byteLength;
      if (bytes > limit) {
        reject(
          new ServerError(
            "message_too_large",
            `request of ${bytes} bytes is over the server's ${limit}-byte limit`,
            command,
            id,
          ),
        );
        return;
      }
      const entry: Pending = {
        command,
        options,
        framesReceived: 0,
        resolve: resolve as (reply: Reply) => void,
        reject,
        timer: undefined,
      };
      if (options.timeoutMs !== undefined) {
        entry.timer = setTimeout(() => {
          // Cancel on the server first (while the request is still pending), then give up.
          if (command !== "cancel") this.sendCancel(id);
          this.abandoned.add(id);
          this.settle(id)?.reject(
            new ServerError("timeout", `no answer within ${options.timeoutMs} ms`, command, id),
          );
        }, options.timeoutMs);
      }
      this.pending.set(id, entry);
      socket.send(text);
    });
    return { id, command, promise, cancel: () => this.sendCancel(id) };
  }

  /**
   * Uploads a file: the JSON announcement, then one binary message (header +
   * bytes) sent as a Blob so the file is streamed, not copied.
   */
  upload<R = Record<string, unknown>>(
    name: string,
    file: Blob,
    options: RequestOptions = {},
  ): RequestHandle<R> {
    const handle = this.request<R>("upload", { name, size: file.size }, options);
    if (this.pending.has(handle.id) && this.socket !== null) {
      this.socket.send(new Blob([encodeFrameHeader("upload", handle.id, file.size), file]));
    }
    return handle;
  }

  /** Round-trip time of a `ping`, in milliseconds. */
  async ping(timeoutMs = 5_000): Promise<number> {
    const start = performance.now();
    await this.request("ping", {}, { timeoutMs }).promise;
    return performance.now() - start;
  }

  /** Bytes queued in the socket (upload progress). */
  get bufferedAmount(): number {
    return this.socket?.bufferedAmount ?? 0;
  }

  private sendCancel(target: number): void {
    if (!this.pending.has(target) || !this.connected) return;
    this.request("cancel", { target }, { timeoutMs: 10_000 }).promise.catch(() => undefined);
  }

  private allocateId(): number {
    for (;;) {
      const id = this.nextId;
      this.nextId = id >= MAX_ID ? 1 : id + 1;
      if (!this.pending.has(id) && !this.abandoned.has(id)) return id;
    }
  }

  private settle(id: number): Pending | undefined {
    const entry = this.pending.get(id);
    if (entry === undefined) return undefined;
    this.pending.delete(id);
    if (entry.timer !== undefined) clearTimeout(entry.timer);
    return entry;
  }

  private receive(data: unknown): void {
    if (data instanceof ArrayBuffer) {
      this.receiveFrame(data);
      return;
    }
    if (typeof data !== "string") {
      this.onProtocolError?.(new ProtocolError("message of unknown type"));
      return;
    }
    let message;
    try {
      message = parseServerMessage(data);
    } catch (error) {
      this.onProtocolError?.(error as Error);
      return;
    }
    switch (message.type) {
      case "hello":
        this.hello = message;
        return;
      case "progress":
        this.pending.get(message.id)?.options.onProgress?.(message.stage, message.fraction);
        return;
      case "result": {
        if (this.abandoned.delete(message.id)) return;
        const entry = this.settle(message.id);
        if (entry === undefined) {
          this.onProtocolError?.(new ProtocolError(`result for unknown request ${message.id}`));
          return;
        }
        if (entry.framesReceived !== message.frames.length) {
          entry.reject(
            new ServerError(
              "decode_error",
              `the result lists ${message.frames.length} binary frames, ` +
                `${entry.framesReceived} arrived`,
              entry.command,
              message.id,
            ),
          );
          return;
        }
        entry.resolve({
          id: message.id,
          command: message.command || entry.command,
          result: message.result,
          frames: message.frames,
        });
        return;
      }
      case "error": {
        if (message.id !== null && this.abandoned.delete(message.id)) return;
        const entry = message.id === null ? undefined : this.settle(message.id);
        const error = new ServerError(
          message.code,
          message.message,
          message.command ?? entry?.command,
          message.id,
        );
        if (entry === undefined) this.onStrayError?.(error);
        else entry.reject(error);
        return;
      }
    }
  }

  private receiveFrame(buffer: ArrayBuffer): void {
    const id = peekFrameId(buffer);
    if (id === null) {
      this.onProtocolError?.(
        new ProtocolError(`binary message of ${buffer.byteLength} bytes without a frame header`),
      );
      return;
    }
    const entry = this.pending.get(id);
    if (entry === undefined) {
      if (this.abandoned.has(id)) return;
      this.onProtocolError?.(new ProtocolError(`binary frame for unknown request ${id}`));
      return;
    }
    entry.framesReceived += 1;
    entry.options.onFrame?.(buffer);
  }

  private closed(code: number, reason: string): void {
    this.socket = null;
    this.hello = null;
    const why = `connection closed (code ${code}${reason ? `: ${reason}` : ""})`;
    this.rejectAll(why);
    this.onClose?.(why);
  }

  private rejectAll(why: string): void {
    this.abandoned.clear();
    for (const id of [...this.pending.keys()]) {
      const entry = this.settle(id);
      entry?.reject(new ServerError("disconnected", why, entry.command, id));
    }
  }
}
