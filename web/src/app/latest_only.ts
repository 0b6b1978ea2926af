// Runs an async task for the latest value only: while one run is in flight,
// new values replace each other and the last one runs when it returns. A
// station dragged across a scan asks for dozens of positions a second; the
// server traces only the ones the user can still see, never a queue of stale ones.

export class LatestOnly<T> {
  private pending: { value: T } | null = null;
  private running = false;
  /** Values handed to `run` so far (for the tests and the status line). */
  runs = 0;
  /** Values replaced before they ran. */
  skipped = 0;

  constructor(private readonly run: (value: T) => Promise<void>) {}

  /** Asks for `value`: runs now if idle, else after the run in flight (replacing any waiting value). */
  push(value: T): void {
    if (this.pending !== null) this.skipped += 1;
    this.pending = { value };
    if (!this.running) void this.drain();
  }

  /** Drops a waiting value (the run in flight finishes). */
  cancel(): void {
    if (this.pending !== null) this.skipped += 1;
    this.pending = null;
  }

  get busy(): boolean {
    return this.running;
  }

  private async drain(): Promise<void> {
    this.running = true;
    try {
      while (this.pending !== null) {
        const { value } = this.pending;
        this.pending = null;
        this.runs += 1;
        try {
          await this.run(value);
        } catch {
          // `run` reports its own failures; the next value still runs.
        }
      }
    } finally {
      this.running = false;
    }
  }
}
