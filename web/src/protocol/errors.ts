// Errors a request can end with, and how the viewer words them for people.

export class ServerError extends Error {
  readonly code: string;
  readonly command: string | undefined;
  readonly id: number | null;

  constructor(code: string, message: string, command?: string, id: number | null = null) {
    super(message);
    this.name = "ServerError";
    this.code = code;
    this.command = command;
    this.id = id;
  }
}

const HINTS: Record<string, string> = {
  invalid_json: "The server could not read the request.",
  invalid_request: "A parameter was refused.",
  duplicate_id: "A request with this id is still running.",
  unknown_command: "The server does not know this command.",
  not_available: "This server build cannot run this command yet.",
  path_outside_data: "Only files inside the server's data directory can be used.",
  not_found: "No such file in the data directory.",
  input_error: "The file could not be read.",
  output_error: "A result file could not be written.",
  message_too_large: "The request or upload is too large.",
  unexpected_binary: "The server did not expect binary data.",
  busy: "The server is busy; try again shortly.",
  cancelled: "Cancelled.",
  internal: "The server hit an internal error (a bug); it keeps serving.",
  disconnected: "The connection to the server was lost.",
  timeout: "The server did not answer in time.",
  decode_error: "The server's data could not be decoded.",
};

/**
 * A readable message: title "Loading x failed: the file could not be read."
 * (context, else the command), detail "input_error: x.ply:3: reason".
 */
export function describeError(
  error: unknown,
  context?: string,
): { title: string; detail: string; code: string } {
  if (error instanceof ServerError) {
    const hint = HINTS[error.code] ?? "The server reported an error.";
    const what = context ?? (error.command ? error.command.replace(/_/g, " ") : "Request");
    return {
      title: `${what} failed: ${hint.charAt(0).toLowerCase()}${hint.slice(1)}`,
      detail: `${error.code}: ${error.message}`,
      code: error.code,
    };
  }
  const what = context ? `${context} failed` : "Something went wrong in the viewer";
  if (error instanceof Error) return { title: what, detail: error.message, code: error.name };
  return { title: what, detail: String(error), code: "unknown" };
}
