// Messages between the main thread and the decode worker.

import type { FrameInfo } from "../protocol/messages";
import type { AssembleContext, Decoded } from "../decode/types";

export type ToWorker =
  /** One binary frame of request `request` (the buffer is transferred). */
  | { op: "frame"; request: number; buffer: ArrayBuffer }
  /** The request's result arrived: assemble its frames. */
  | { op: "finish"; request: number; frames: FrameInfo[]; context: AssembleContext }
  /** The request failed: forget its frames. */
  | { op: "drop"; request: number };

export type FromWorker =
  | { op: "done"; request: number; value: Decoded | null; decodeMs: number }
  | { op: "error"; request: number; message: string };
