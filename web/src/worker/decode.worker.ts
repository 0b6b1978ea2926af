// The decode worker: validates each binary frame as it arrives (so a large
// cloud is checked while the rest is still on the wire), then, on `finish`,
// assembles them into geometry-ready arrays and transfers them back.

/// <reference lib="webworker" />

import { assemble } from "../decode/assemble";
import { transferables } from "../decode/types";
import { decodeFrame } from "../protocol/frame";
import type { Frame } from "../protocol/frame";
import type { FromWorker, ToWorker } from "./messages";

declare const self: DedicatedWorkerGlobalScope;

interface Collecting {
  frames: Frame[];
  error: string | null;
  decodeMs: number;
}

const requests = new Map<number, Collecting>();

function entry(request: number): Collecting {
  let e = requests.get(request);
  if (e === undefined) {
    e = { frames: [], error: null, decodeMs: 0 };
    requests.set(request, e);
  }
  return e;
}

function post(message: FromWorker, transfer: ArrayBuffer[] = []): void {
  self.postMessage(message, transfer);
}

self.onmessage = (event: MessageEvent<ToWorker>) => {
  const message = event.data;
  switch (message.op) {
    case "frame": {
      const e = entry(message.request);
      if (e.error !== null) return;
      const start = performance.now();
      try {
        e.frames.push(decodeFrame(message.buffer));
      } catch (error) {
        e.error = (error as Error).message;
      }
      e.decodeMs += performance.now() - start;
      return;
    }
    case "finish": {
      const e = entry(message.request);
      requests.delete(message.request);
      if (e.error !== null) {
        post({ op: "error", request: message.request, message: e.error });
        return;
      }
      const start = performance.now();
      try {
        const value = assemble(e.frames, message.frames, message.context);
        const decodeMs = e.decodeMs + performance.now() - start;
        post({ op: "done", request: message.request, value, decodeMs }, transferables(value));
      } catch (error) {
        post({ op: "error", request: message.request, message: (error as Error).message });
      }
      return;
    }
    case "drop":
      requests.delete(message.request);
      return;
  }
};
