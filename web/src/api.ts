// Requests with their binary data: sends a command through the protocol
// client, routes its frames to the decode worker, and resolves with the JSON
// result and the decoded arrays together.

import type { ProtocolClient, RequestHandle } from "./protocol/client";
import type { AssembleContext, Decoded } from "./decode/types";
import type { FrameDecoder } from "./worker/decoder";
import { ServerError } from "./protocol/errors";

export interface Outcome<R = Record<string, unknown>> {
  id: number;
  command: string;
  result: R;
  decoded: Decoded | null;
  /** Milliseconds: request sent → result, and worker decode time. */
  timings: { serverMs: number; decodeMs: number; totalMs: number };
}

export interface Job<R = Record<string, unknown>> {
  id: number;
  command: string;
  promise: Promise<Outcome<R>>;
  cancel(): void;
}

export interface RunOptions<R> {
  onProgress?: (stage: string, fraction: number) => void;
  /** Class names, groups, viewpoint count: what the decoder needs from the result. */
  context?: (result: R) => AssembleContext;
  timeoutMs?: number;
  /** For uploads: the file to send after the announcement. */
  upload?: { name: string; file: Blob };
}

export class Api {
  constructor(
    readonly client: ProtocolClient,
    private readonly decoder: FrameDecoder,
  ) {}

  run<R = Record<string, unknown>>(
    command: string,
    params: Record<string, unknown> = {},
    options: RunOptions<R> = {},
  ): Job<R> {
    const start = performance.now();
    let id = -1;
    const requestOptions = {
      onFrame: (buffer: ArrayBuffer) => this.decoder.frame(id, buffer),
      ...(options.onProgress ? { onProgress: options.onProgress } : {}),
      ...(options.timeoutMs !== undefined ? { timeoutMs: options.timeoutMs } : {}),
    };
    const handle: RequestHandle<R> = options.upload
      ? this.client.upload<R>(options.upload.name, options.upload.file, requestOptions)
      : this.client.request<R>(command, params, requestOptions);
    id = handle.id;
    const promise = handle.promise.then(
      async (reply) => {
        const serverMs = performance.now() - start;
        const context = options.context ? options.context(reply.result) : {};
        try {
          const { value, decodeMs } = await this.decoder.finish(id, reply.frames, context);
          return {
            id,
            command: reply.command,
            result: reply.result,
            decoded: value,
            timings: { serverMs, decodeMs, totalMs: performance.now() - start },
          };
        } catch (error) {
          throw new ServerError("decode_error", (error as Error).message, reply.command, id);
        }
      },
      (error: unknown) => {
        this.decoder.drop(id);
        throw error;
      },
    );
    return { id, command: handle.command, promise, cancel: handle.cancel };
  }
}
