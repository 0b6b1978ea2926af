// Text messages of the protocol (docs/protocol.md): what the server sends, and
// a checked parser so a malformed message becomes a readable ProtocolError.

import type { ElementType, FrameKind } from "./frame";

export const PROTOCOL_VERSION = 1;

export interface Limits {
  max_text_bytes: number;
  max_upload_bytes: number;
  progress_per_second: number;
}

export interface HelloMessage {
  type: "hello";
  /** Per command, its keys' declarations (default, range, doc), when the server publishes them. */
  keys: Record<string, unknown>;
  protocol: number;
  server: string;
  commands: Record<string, boolean>;
  limits: Limits;
  /** File name endings `load` and `upload` read (every reader's); empty from a server that does not say. */
  upload_suffixes: string[];
}

export interface ProgressMessage {
  type: "progress";
  id: number;
  stage: string;
  fraction: number;
}

export interface FrameInfo {
  kind: FrameKind | string;
  type: ElementType | string;
  components: number;
  count: number;
  item: number;
}

export interface ResultMessage {
  type: "result";
  id: number;
  command: string;
  result: Record<string, unknown>;
  frames: FrameInfo[];
}

export interface ErrorMessage {
  type: "error";
  id: number | null;
  command?: string;
  code: string;
  message: string;
}

export type ServerMessage = HelloMessage | ProgressMessage | ResultMessage | ErrorMessage;

export class ProtocolError extends Error {
  constructor(message: string) {
    super(`protocol: ${message}`);
    this.name = "ProtocolError";
  }
}

function isObject(value: unknown): value is Record<string, unknown> {
  return typeof value === "object" && value !== null && !Array.isArray(value);
}

function isId(value: unknown): value is number {
  return typeof value === "number" && Number.isInteger(value) && value >= 0 && value <= 0xffffffff;
}

function need(condition: boolean, what: string): asserts condition {
  if (!condition) throw new ProtocolError(what);
}

function parseFrameInfo(value: unknown, index: number): FrameInfo {
  need(isObject(value), `result frame ${index} is not an object`);
  const { kind, type, components, count, item } = value;
  need(typeof kind === "string", `result frame ${index}: 'kind' is not a string`);
  need(typeof type === "string", `result frame ${index}: 'type' is not a string`);
  need(typeof components === "number", `result frame ${index}: 'components' is not a number`);
  need(typeof count === "number", `result frame ${index}: 'count' is not a number`);
  return { kind, type, components, count, item: typeof item === "number" ? item : 0 };
}

export function parseServerMessage(text: string): ServerMessage {
  let value: unknown;
  try {
    value = JSON.parse(text);
  } catch {
    throw new ProtocolError(`message is not JSON: ${text.slice(0, 80)}`);
  }
  need(isObject(value), "message is not a JSON object");
  switch (value.type) {
    case "hello": {
      need(typeof value.protocol === "number", "hello without 'protocol'");
      need(isObject(value.commands), "hello without 'commands'");
      const commands: Record<string, boolean> = {};
      // Key declarations (issue 11), top-level `keys` or per command: kept for settings_defaults.
      const keys: Record<string, unknown> = isObject(value.keys) ? { ...value.keys } : {};
      for (const [name, on] of Object.entries(value.commands)) {
        commands[name] = on === true || isObject(on);
        if (isObject(on) && isObject(on.keys)) keys[name] = on.keys;
      }
      // `jobs`: per job, its keys as a list of declarations, each with its `name`.
      for (const [job, entry] of Object.entries(isObject(value.jobs) ? value.jobs : {})) {
        if (!isObject(entry) || !Array.isArray(entry.keys)) continue;
        const named = entry.keys.filter((k): k is Record<string, unknown> => isObject(k));
        keys[job] = Object.fromEntries(
          named.filter((k) => typeof k.name === "string").map((k) => [k.name as string, k]),
        );
      }
      const limits = isObject(value.limits) ? value.limits : {};
      return {
        type: "hello",
        protocol: value.protocol,
        server: typeof value.server === "string" ? value.server : "unknown server",
        commands,
        keys,
        limits: {
          max_text_bytes: Number(limits.max_text_bytes ?? 1 << 20),
          max_upload_bytes: Number(limits.max_upload_bytes ?? 256 << 20),
          progress_per_second: Number(limits.progress_per_second ?? 10),
        },
        upload_suffixes: Array.isArray(value.upload_suffixes)
          ? value.upload_suffixes.filter((s): s is string => typeof s === "string")
          : [],
      };
    }
    case "progress": {
      need(isId(value.id), "progress without a valid 'id'");
      need(typeof value.fraction === "number", "progress without 'fraction'");
      return {
        type: "progress",
        id: value.id,
        stage: typeof value.stage === "string" ? value.stage : "",
        fraction: Math.min(1, Math.max(0, value.fraction)),
      };
    }
    case "result": {
      need(isId(value.id), "result without a valid 'id'");
      need(isObject(value.result), `result ${value.id} without a 'result' object`);
      const frames = Array.isArray(value.frames) ? value.frames.map(parseFrameInfo) : [];
      return {
        type: "result",
        id: value.id,
        command: typeof value.command === "string" ? value.command : "",
        result: value.result,
        frames,
      };
    }
    case "error": {
      need(value.id === null || value.id === undefined || isId(value.id), "error with a bad 'id'");
      const message: ErrorMessage = {
        type: "error",
        id: isId(value.id) ? value.id : null,
        code: typeof value.code === "string" ? value.code : "unknown",
        message: typeof value.message === "string" ? value.message : "(no message)",
      };
      if (typeof value.command === "string") message.command = value.command;
      return message;
    }
    default:
      throw new ProtocolError(`unknown message type ${JSON.stringify(value.type)}`);
  }
}
