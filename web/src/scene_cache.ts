// Decoded scenes kept in the browser, so going back to a scene is instant:
// keyed by path, modification time and size (as the server's cache), least
// recently used dropped first beyond the limit. Its size is the stats panel's
// "cache" figure.

import { byteSize } from "./decode/types";
import type { Decoded } from "./decode/types";

export interface CachedScene<R> {
  result: R;
  decoded: Decoded;
  bytes: number;
}

export function cacheKey(path: string, mtime?: number, size?: number): string {
  return `${path}|${mtime ?? "-"}|${size ?? "-"}`;
}

export class SceneCache<R> {
  private readonly entries = new Map<string, CachedScene<R>>();
  private total = 0;

  constructor(readonly limitBytes: number) {}

  get bytes(): number {
    return this.total;
  }

  get size(): number {
    return this.entries.size;
  }

  get(key: string): CachedScene<R> | undefined {
    const entry = this.entries.get(key);
    if (entry !== undefined) {
      this.entries.delete(key); // move to the back: most recently used
      this.entries.set(key, entry);
    }
    return entry;
  }

  put(key: string, result: R, decoded: Decoded): void {
    this.delete(key);
    const bytes = byteSize(decoded);
    if (bytes > this.limitBytes) return;
    this.entries.set(key, { result, decoded, bytes });
    this.total += bytes;
    for (const [k, e] of this.entries) {
      if (this.total <= this.limitBytes) break;
      this.entries.delete(k);
      this.total -= e.bytes;
    }
  }

  delete(key: string): void {
    const entry = this.entries.get(key);
    if (entry === undefined) return;
    this.entries.delete(key);
    this.total -= entry.bytes;
  }

  /** Drops every entry of a path (any mtime/size). */
  forget(path: string): void {
    for (const key of [...this.entries.keys()]) if (key.startsWith(`${path}|`)) this.delete(key);
  }
}
