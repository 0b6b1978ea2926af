// Runs a request with a progress row and a Cancel button, and turns every
// failure into a message: a job either returns its outcome or null, after
// telling the user why.

import type { Api, Outcome, RunOptions } from "../api";
import { ServerError } from "../protocol/errors";
import type { JobsPanel, JobRow } from "../ui/jobs_panel";
import type { Notices } from "../ui/notices";

export class JobRunner {
  constructor(
    private readonly api: Api,
    private readonly jobs: JobsPanel,
    private readonly notices: Notices,
  ) {}

  async run<R = Record<string, unknown>>(
    label: string,
    command: string,
    params: Record<string, unknown> = {},
    options: RunOptions<R> & {
      cancellable?: boolean;
      /** Called once sent, with the request id and a way to move its progress bar. */
      onStart?: (id: number, progress: (stage: string, fraction: number) => void) => void;
    } = {},
  ): Promise<Outcome<R> | null> {
    if (!this.api.client.connected) {
      this.notices.error(`${label}: not connected to the server`, "Waiting to reconnect…");
      return null;
    }
    let row: JobRow | null = null;
    const job = this.api.run<R>(command, params, {
      ...options,
      onProgress: (stage, fraction) => {
        row?.progress(stage, fraction);
        options.onProgress?.(stage, fraction);
      },
    });
    row = this.jobs.add(label, options.cancellable === false ? null : () => job.cancel());
    const bar = row;
    options.onStart?.(job.id, (stage, fraction) => bar.progress(stage, fraction));
    try {
      return await job.promise;
    } catch (error) {
      if (error instanceof ServerError && error.code === "cancelled") {
        this.notices.info(`${label}: cancelled`);
      } else {
        this.notices.fromError(error, label);
      }
      return null;
    } finally {
      row.finish();
    }
  }
}
