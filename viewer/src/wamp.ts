// SPDX-License-Identifier: EPL-2.0
// The page's WAMP session: autobahn-js over WebSocket with msgpack, read-only (it only subscribes).
// autobahn's msgpack codec is answered by @msgpack/msgpack (shims/msgpack5.cjs).
import autobahn from "autobahn";
import type { RouterAuth, ViewConfig } from "./config";

export type LinkStatus = "connecting" | "open" | "retrying" | "closed";

export interface StreamHandlers {
  state(payload: unknown): void;
  mission(payload: unknown): void;
  signal(payload: unknown): void;
  /** The connection changed; `detail` is for people. */
  link(status: LinkStatus, detail: string): void;
  /** All three subscriptions are in place (the router now forwards every event). */
  subscribed(): void;
  /** Whether to reconnect after the connection was lost (not once the run has ended). */
  retry(): boolean;
}

function challengeAnswer(auth: RouterAuth) {
  return (_session: autobahn.Session, method: string, extra: { challenge?: string; salt?: string;
    iterations?: number; keylen?: number }): string => {
    if (method === "ticket") return auth.secret;
    if (method === "wampcra" && extra.challenge !== undefined) {
      const key = extra.salt !== undefined
        ? autobahn.auth_cra.derive_key(auth.secret, extra.salt, extra.iterations ?? 1000, extra.keylen ?? 32)
        : auth.secret;
      return autobahn.auth_cra.sign(key, extra.challenge);
    }
    throw new Error(`the router asks for ${method}, which the view does not speak`);
  };
}

function firstArgument(handler: (payload: unknown) => void): autobahn.EventHandler {
  return (args) => handler(args?.[0]);
}

/** Opens the session and subscribes; `stop()` closes it for good (no more retries). */
export function connect(config: ViewConfig, handlers: StreamHandlers): { stop(): void } {
  const auth = config.router.auth;
  const options: autobahn.ConnectionOptions = {
    url: config.router.url,
    realm: config.router.realm,
    serializers: [new autobahn.serializer.MsgpackSerializer()],
    use_es6_promises: true,
    max_retries: 20,
    initial_retry_delay: 0.5,
    max_retry_delay: 3,
    retry_delay_growth: 1.5,
  };
  if (auth !== null) {
    options.authid = auth.authid;
    options.authmethods = [auth.method];
    options.onchallenge = challengeAnswer(auth);
  }
  const connection = new autobahn.Connection(options);
  let stopped = false;
  connection.onopen = (session) => {
    handlers.link("open", `session ${session.id}`);
    Promise.all([
      session.subscribe(config.topics.state, firstArgument(handlers.state)),
      session.subscribe(config.topics.mission, firstArgument(handlers.mission)),
      session.subscribe(config.topics.signal, firstArgument(handlers.signal)),
    ]).then(() => handlers.subscribed(), (error: unknown) => {
      handlers.link("closed", `subscription refused: ${String(error)}`);
    });
  };
  connection.onclose = (reason, details) => {
    if (stopped) return true;
    if (!handlers.retry()) {
      handlers.link("closed", `${reason} after the run ended`);
      return true;
    }
    const retrying = details.will_retry === true;
    handlers.link(retrying ? "retrying" : "closed",
      `${reason}${details.reason !== undefined ? ` (${details.reason})` : ""}`);
    return false;
  };
  handlers.link("connecting", config.router.url);
  connection.open();
  return {
    stop() {
      stopped = true;
      try {
        connection.close();
      } catch {
        // already closed: nothing to stop
      }
    },
  };
}
