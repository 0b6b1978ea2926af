// Main-thread side of the decode worker: forwards a request's binary frames
// (transferring, not copying, each buffer) and returns the assembled arrays.

import type { AssembleContext, Decoded } from "../decode/types";
import type { FrameInfo } from "../protocol/messages";
import type { FromWorker, ToWorker } from "./messages";

interface Waiting {
  resolve: (value: { value: Decoded | null; decodeMs: number }) => void;
  reject: (error: Error) => void;
}

export class DecodeError extends Error {
  constructor(message: string) {
    super(message);
    this.name = "DecodeError";
  }
}

export class FrameDecoder {
  private readonly worker: Worker;
  private readonly waiting = new Map<number, Waiting>();

  constructor() {
    this.worker = new Worker(new URL("./decode.worker.ts", import.meta.url), { type: "module" });
    this.worker.onmessage = (event: MessageEvent<FromWorker>) => {
      const message = event.data;
      const waiting = this.waiting.get(message.request);
      if (waiting === undefined) return;
      this.waiting.delete(message.request);
      if (message.op === "done") {
        waiting.resolve({ value: message.value, decodeMs: message.decodeMs });
      } else waiting.reject(new DecodeError(message.message));
    };
    this.worker.onerror = (event) => {
      const error = new DecodeError(`decode worker failed: ${event.message}`);
      for (const w of this.waiting.values()) w.reject(error);
      this.waiting.clear();
    };
  }

  private send(message: ToWorker, transfer: Transferable[] = []): void {
    this.worker.postMessage(message, transfer);
  }

  /** Hands one binary frame of `request` to the worker (the buffer moves there). */
  frame(request: number, buffer: ArrayBuffer): void {
    this.send({ op: "frame", request, buffer }, [buffer]);
  }

  finish(
    request: number,
    frames: FrameInfo[],
    context: AssembleContext,
  ): Promise<{ value: Decoded | null; decodeMs: number }> {
    return new Promise((resolve, reject) => {
      this.waiting.set(request, { resolve, reject });
      this.send({ op: "finish", request, frames, context });
    });
  }

  drop(request: number): void {
    this.send({ op: "drop", request });
  }
}
