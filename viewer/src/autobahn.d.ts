// SPDX-License-Identifier: EPL-2.0
// The part of autobahn-js (MIT) this page uses, typed from its sources (lib/connection.js, lib/session.js,
// lib/transport/websocket.js). Written here rather than taken from @types/autobahn, which lacks `serializers`.
declare module "autobahn" {
  namespace autobahn {
    /** What autobahn's websocket transport needs of a serializer (lib/serializer.js). */
    interface Serializer {
      readonly SERIALIZER_ID: string;
      readonly BINARY: boolean;
      serialize(message: unknown): Uint8Array | string;
      unserialize(payload: ArrayBuffer | string): unknown;
    }
    const serializer: { MsgpackSerializer: new () => Serializer };
    type EventHandler = (args: unknown[] | undefined, kwargs: unknown, details: unknown) => void;
    interface Subscription {
      readonly topic: string;
    }
    interface Session {
      readonly id: number;
      subscribe(topic: string, handler: EventHandler): PromiseLike<Subscription>;
    }
    interface ConnectionOptions {
      url: string;
      realm: string;
      serializers?: Serializer[];
      use_es6_promises?: boolean;
      max_retries?: number;
      initial_retry_delay?: number;
      max_retry_delay?: number;
      retry_delay_growth?: number;
      authid?: string;
      authmethods?: string[];
      onchallenge?: (session: Session, method: string, extra: { challenge?: string; salt?: string;
        iterations?: number; keylen?: number }) => string;
    }
    interface CloseDetails {
      reason?: string;
      message?: string;
      will_retry?: boolean;
      retry_count?: number;
      retry_delay?: number;
    }
    class Connection {
      constructor(options: ConnectionOptions);
      onopen: (session: Session, details: unknown) => void;
      /** Return true to stop retrying. */
      onclose: (reason: string, details: CloseDetails) => boolean;
      open(): void;
      close(reason?: string, message?: string): void;
    }
    const auth_cra: {
      derive_key(secret: string, salt: string, iterations: number, keylen: number): string;
      sign(key: string, challenge: string): string;
    };
  }
  export default autobahn;
}
