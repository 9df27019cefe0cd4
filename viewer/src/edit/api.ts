// SPDX-License-Identifier: EPL-2.0
// The page's side of the `rei edit` HTTP API (docs/room-editor.md, "Page ⇄ HTTP server").
//
// The token comes from the page's own URL (`edit.html?token=...`, printed by `rei edit`) and goes into the
// X-REI-Token header of every /api request: the server refuses any other caller, so a web page the user happens
// to have open cannot edit their files. Requests run one at a time, in order: an operation sent while the
// previous one is still being applied must see its result, and a poll must not overtake an edit.
import type { Operation, State, Status } from "./types";

export class ApiError extends Error {
  constructor(readonly status: number, message: string) {
    super(message);
  }
}

export class Api {
  private queue: Promise<unknown> = Promise.resolve();
  /** Requests sent and not answered yet (a poll is skipped while an edit is on its way). */
  pending = 0;

  constructor(private readonly token: string) {}

  static fromLocation(location: Location): Api {
    return new Api(new URLSearchParams(location.search).get("token") ?? "");
  }

  get hasToken(): boolean {
    return this.token !== "";
  }

  state(): Promise<State> {
    return this.request<State>("GET", "/api/state");
  }

  status(): Promise<Status> {
    return this.request<Status>("GET", "/api/status");
  }

  /** One undo step; a refused batch is an ApiError 422 with the engine's message, the model unchanged. */
  apply(operations: readonly Operation[]): Promise<State> {
    return this.request<State>("POST", "/api/apply", { operations });
  }

  command(name: "undo" | "redo" | "save" | "reload" | "keep"): Promise<State> {
    return this.request<State>("POST", `/api/${name}`, {});
  }

  private request<T>(method: "GET" | "POST", path: string, body?: unknown): Promise<T> {
    this.pending += 1;
    const run = async (): Promise<T> => {
      try {
        const init: RequestInit = { method, headers: { "X-REI-Token": this.token }, cache: "no-store" };
        if (body !== undefined) {
          init.headers = { "X-REI-Token": this.token, "Content-Type": "application/json" };
          init.body = JSON.stringify(body);
        }
        let response: Response;
        try {
          response = await fetch(path, init);
        } catch (error) {
          throw new ApiError(0,
            `the editor's server does not answer (${String(error)}): is \`rei edit\` still running?`);
        }
        const text = await response.text();
        let json: unknown = null;
        try {
          json = text === "" ? null : JSON.parse(text);
        } catch {
          json = null;
        }
        if (!response.ok) {
          const said = typeof json === "object" && json !== null && "error" in json ? String(json.error) : text;
          const message = response.status === 403
            ? "refused (403): open the editor with the URL that `rei edit` printed (it carries the token)"
              + (said ? `: ${said}` : "")
            : said || `${method} ${path}: HTTP ${response.status}`;
          throw new ApiError(response.status, message);
        }
        return json as T;
      } finally {
        this.pending -= 1;
      }
    };
    const result = this.queue.then(run, run);
    this.queue = result.catch(() => undefined);
    return result;
  }
}
