/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.sut.kit;

import java.io.IOException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Map;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

import org.rei.wamp.auth.RouterCredentials;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.NullNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import ws.wamp.jawampa.ApplicationError;
import ws.wamp.jawampa.PublishFlags;
import ws.wamp.jawampa.WampClient;
import ws.wamp.jawampa.WampClientBuilder;
import ws.wamp.jawampa.WampSerialization;
import ws.wamp.jawampa.transport.netty.NettyWampConnectionConfig;

/**
 * Connects a {@link SystemUnderTest} to a run's router (docs/sut.md): WAMP-CRA as {@code sut}, msgpack over
 * WebSocket; subscribes to {@code tick}, {@code goal}, {@code cancel} and {@code end}, then calls {@code hello}
 * (the simulation starts only then) and answers every tick with one command.
 * <p>
 * jawampa delivers messages on its network thread; they are queued and the callbacks run on the thread that called
 * {@link #run}, one at a time in arrival order, so a slow callback never stalls the connection.
 *
 * <pre>
 * public static void main(String[] args) {
 *     SutClient.runAndExit(new MyNavigation());
 * }
 * </pre>
 */
public final class SutClient {

	/** A callback threw (or returned no command). */
	public static final int EXIT_CALLBACK = 1;
	/** Missing environment, refused connection or authentication, lost router, protocol error. */
	public static final int EXIT_CONNECTION = 2;

	public static final String ENV_ROUTER_URL = "REI_ROUTER_URL";
	public static final String ENV_REALM = "REI_REALM";
	public static final String ENV_RUN_ID = "REI_RUN_ID";
	public static final String ENV_AUTH_FILE = "REI_AUTH_FILE";
	/** Optional: the run's case folder, which {@code hello}'s {@code map.occupancy} is relative to. */
	public static final String ENV_CASE_DIR = "REI_CASE_DIR";

	/** The protocol's URIs, {@code name} one of the lists below (docs/sut.md; contract/vocabulary.json). */
	public static final String URI_TEMPLATE = "rei.run.{run_id}.sut.{name}";
	/**
	 * Largest message read (bytes; contract/vocabulary.json's max_message_size): hello carries the static map, which
	 * in a room from an occupancy map lists thousands of walls, beyond netty's default of 64 KB.
	 */
	public static final int MAX_MESSAGE_SIZE = 1 << 24;
	public static final String COMMAND = "command";
	public static final String STATUS = "status";
	public static final String HELLO = "hello";
	public static final List<String> FROM_SIMULATION = List.of("tick", "goal", "cancel", "end");
	public static final List<String> FROM_SUT = List.of(COMMAND, STATUS);
	public static final List<String> PROCEDURES = List.of(HELLO);
	/** Connecting, joining and hello's answer; REI's own --sut-join-timeout defaults to the same. */
	private static final long JOIN_MILLIS = 60_000;
	/** Between two hello calls while the simulation has not registered it yet. */
	private static final long HELLO_RETRY_MILLIS = 100;
	/** Leaving the router after end: REI sends SIGTERM 2 s after end. */
	private static final long CLOSE_MILLIS = 1_000;

	private final String routerUrl;
	private final String realm;
	private final String runId;
	private final RouterCredentials credentials;

	/** What the client's queue holds: the network thread's news for the callback thread. */
	private sealed interface Inbound {
	}

	private record Connected() implements Inbound {
	}

	private record Disconnected(Throwable reason) implements Inbound {
	}

	private record Subscribed() implements Inbound {
	}

	private record HelloAnswer(JsonNode result) implements Inbound {
	}

	private record HelloRefused(Throwable error) implements Inbound {
	}

	private record Event(String name, JsonNode payload) implements Inbound {
	}

	private record Failure(String message) implements Inbound {
	}

	public SutClient(String routerUrl, String realm, String runId, RouterCredentials credentials) {
		this.routerUrl = routerUrl;
		this.realm = realm;
		this.runId = runId;
		this.credentials = credentials;
	}

	/** The client REI's environment describes ({@code REI_ROUTER_URL}, {@code REI_REALM}, ...). */
	public static SutClient fromEnvironment() {
		return fromEnvironment(System.getenv());
	}

	static SutClient fromEnvironment(Map<String, String> env) {
		String url = require(env, ENV_ROUTER_URL);
		String realm = require(env, ENV_REALM);
		String runId = require(env, ENV_RUN_ID);
		String authFile = require(env, ENV_AUTH_FILE);
		try {
			return new SutClient(url, realm, runId, RouterCredentials.read(Path.of(authFile)));
		} catch (NoSuchFileException e) {
			throw new SutException(EXIT_CONNECTION, ENV_AUTH_FILE + ": " + authFile + ": no such file", e);
		} catch (IOException | RuntimeException e) {
			throw new SutException(EXIT_CONNECTION, ENV_AUTH_FILE + ": " + e.getMessage(), e);
		}
	}

	private static String require(Map<String, String> env, String name) {
		String value = env.get(name);
		if (value == null || value.isBlank()) {
			throw new SutException(EXIT_CONNECTION, "environment variable " + name
					+ " is not set: start this program with 'rei run ... --sut COMMAND', or with --sut-attach"
					+ " after loading OUT/sut.env");
		}
		return value;
	}

	/**
	 * For {@code main}: runs {@code sut} with the client of the environment and exits the JVM: 0 after {@code end},
	 * else the {@link SutException}'s code after printing why (and the callback's stack trace) to stderr.
	 */
	public static void runAndExit(SystemUnderTest sut) {
		int code = 0;
		try {
			fromEnvironment().run(sut);
		} catch (SutException e) {
			System.err.println("rei-sut-kit: " + e.getMessage());
			if (e.exitCode() == EXIT_CALLBACK && e.getCause() != null) {
				e.getCause().printStackTrace();
			}
			code = e.exitCode();
		}
		System.out.flush();
		System.err.flush();
		System.exit(code);
	}

	/** The full URI of one of the protocol's names ({@code tick}, {@code hello}, ...). */
	public String uri(String name) {
		return URI_TEMPLATE.replace("{run_id}", runId).replace("{name}", name);
	}

	/**
	 * Connects, runs {@code sut} until the simulation sends {@code end} and returns after {@code onEnd}.
	 *
	 * @throws SutException with {@link #EXIT_CALLBACK} if a callback threw, {@link #EXIT_CONNECTION} if the router
	 *                      could not be joined or went away, or the simulation sent something malformed
	 */
	public void run(SystemUnderTest sut) {
		BlockingQueue<Inbound> inbox = new LinkedBlockingQueue<>();
		WampClient client = connect(inbox);
		try {
			Dispatcher dispatcher = new Dispatcher(sut, (name, payload) -> publish(client, name, payload, inbox));
			serve(client, inbox, dispatcher, name(sut));
		} catch (InterruptedException e) {
			Thread.currentThread().interrupt();
			throw new SutException(EXIT_CONNECTION, "interrupted", e);
		} finally {
			try {
				client.close().timeout(CLOSE_MILLIS, TimeUnit.MILLISECONDS).toBlocking().lastOrDefault(null);
			} catch (RuntimeException e) {
				// leaving politely is best effort: the run is over or the router is gone
			}
		}
	}

	/** Opens the session; its state changes go to {@code inbox}. */
	private WampClient connect(BlockingQueue<Inbound> inbox) {
		WampClient client;
		try {
			client = new WampClientBuilder()
					.withConnectorProvider(new SubscribedSignal(() -> inbox.add(new Subscribed())))
					.withUri(routerUrl).withRealm(realm)
					.withConnectionConfiguration(
							new NettyWampConnectionConfig.Builder().withMaxFramePayloadLength(MAX_MESSAGE_SIZE).build())
					.withSerializations(new WampSerialization[] { WampSerialization.MessagePack })
					.withAuthId(credentials.authid()).withAuthMethod(credentials.authentication()).build();
		} catch (Exception e) {
			throw new SutException(EXIT_CONNECTION, "cannot use router " + routerUrl + ": " + describe(e), e);
		}
		client.statusChanged().subscribe(state -> {
			if (state instanceof WampClient.ConnectedState) {
				inbox.add(new Connected());
			} else if (state instanceof WampClient.DisconnectedState d) {
				inbox.add(new Disconnected(d.disconnectReason()));
			}
		}, e -> inbox.add(new Disconnected(e)));
		client.open();
		return client;
	}

	/** The callback thread's loop: joins the run, then hands every message to the dispatcher until end. */
	private void serve(WampClient client, BlockingQueue<Inbound> inbox, Dispatcher dispatcher, String sutName)
			throws InterruptedException {
		long joinDeadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(JOIN_MILLIS);
		boolean connected = false;
		String joining = "connecting"; // for the timeout's message
		int subscribed = 0;
		// the simulation may start once hello is called: its first events can overtake hello's answer
		List<Event> early = new ArrayList<>();
		while (true) {
			Inbound m = dispatcher.session() != null ? inbox.take()
					: inbox.poll(joinDeadline - System.nanoTime(), TimeUnit.NANOSECONDS);
			if (m == null) {
				throw new SutException(EXIT_CONNECTION, "could not join the run at " + routerUrl + " within "
						+ JOIN_MILLIS / 1000 + " s (still " + joining + ")");
			} else if (m instanceof Connected) {
				connected = true;
				joining = "subscribing";
				for (String topic : FROM_SIMULATION) {
					client.makeSubscription(uri(topic)).subscribe(
							ev -> inbox.add(new Event(topic, first(ev.arguments()))),
							e -> inbox.add(new Failure("cannot subscribe to " + uri(topic) + ": " + describe(e))));
				}
			} else if (m instanceof Disconnected d) {
				if (connected) {
					throw new SutException(EXIT_CONNECTION,
							"lost the router at " + routerUrl + " before the run ended: " + describe(d.reason()));
				} else if (d.reason() != null) {
					boolean refused = d.reason() instanceof ApplicationError a && a.uri().endsWith(".not_authorized");
					throw new SutException(EXIT_CONNECTION, "cannot join realm '" + realm + "' at " + routerUrl
							+ " as '" + credentials.authid() + "': " + describe(d.reason())
							+ (refused ? " (is " + ENV_AUTH_FILE + " the sut credentials of this run?)" : ""));
				} // else the state before open()
			} else if (m instanceof Subscribed && ++subscribed == FROM_SIMULATION.size()) {
				joining = "waiting for hello's answer";
				callHello(client, inbox, sutName);
			} else if (m instanceof HelloAnswer a) {
				dispatcher.hello(a.result());
				for (Event e : early) {
					if (dispatcher.dispatch(e.name(), e.payload())) {
						return;
					}
				}
				early.clear();
			} else if (m instanceof HelloRefused r) {
				// the simulation registers hello before it starts the SUT; an attached SUT may be quicker
				if (r.error() instanceof ApplicationError e && ApplicationError.NO_SUCH_PROCEDURE.equals(e.uri())
						&& System.nanoTime() - joinDeadline < 0) {
					Thread.sleep(HELLO_RETRY_MILLIS);
					callHello(client, inbox, sutName);
				} else {
					throw new SutException(EXIT_CONNECTION, "hello failed: " + describe(r.error()));
				}
			} else if (m instanceof Event e) {
				if (dispatcher.session() == null) {
					early.add(e);
				} else if (dispatcher.dispatch(e.name(), e.payload())) {
					return;
				}
			} else if (m instanceof Failure f) {
				throw new SutException(EXIT_CONNECTION, f.message());
			}
		}
	}

	/** The SUT's class name for hello's {@code name} (the simulation's log), null for lambdas and anonymous ones. */
	static String name(SystemUnderTest sut) {
		Class<?> type = sut.getClass();
		return type.isHidden() || type.isAnonymousClass() ? null : type.getSimpleName();
	}

	private void callHello(WampClient client, BlockingQueue<Inbound> inbox, String name) {
		ObjectNode call = JsonNodeFactory.instance.objectNode();
		if (name != null) {
			call.put("name", name);
		}
		ArrayNode args = JsonNodeFactory.instance.arrayNode().add(call);
		client.call(uri(HELLO), args, null).subscribe(
				reply -> inbox.add(new HelloAnswer(first(reply.arguments()))),
				e -> inbox.add(new HelloRefused(e)));
	}

	/**
	 * Publishes with an acknowledgement, so that a refusal is reported instead of silently waiting for the
	 * simulation's deadline. The callback thread does not wait for it: jawampa sends in call order.
	 */
	private void publish(WampClient client, String name, ObjectNode payload, BlockingQueue<Inbound> inbox) {
		ArrayNode args = JsonNodeFactory.instance.arrayNode().add(payload);
		client.publish(uri(name), EnumSet.of(PublishFlags.RequireAcknowledge), args, null).subscribe(id -> {
		}, e -> {
			if (!isConnectionLoss(e)) { // a loss shows up as Disconnected
				inbox.add(new Failure("the router refused " + name + " " + payload + ": " + describe(e)));
			}
		});
	}

	/** A message's payload: its first positional argument. */
	private static JsonNode first(ArrayNode arguments) {
		return arguments != null && arguments.size() > 0 ? arguments.get(0) : NullNode.getInstance();
	}

	private static boolean isConnectionLoss(Throwable e) {
		return e instanceof ApplicationError a && (ApplicationError.TRANSPORT_CLOSED.equals(a.uri())
				|| ApplicationError.NOT_CONNECTED.equals(a.uri()) || ApplicationError.CLIENT_CLOSED.equals(a.uri()));
	}

	private static String describe(Throwable e) {
		if (e == null) {
			return "connection closed";
		}
		if (e instanceof ApplicationError a) {
			StringBuilder s = new StringBuilder(a.uri());
			if (a.arguments() != null && a.arguments().size() > 0) {
				s.append(' ').append(a.arguments());
			}
			return s.toString();
		}
		return e.getMessage() != null ? e.getClass().getSimpleName() + ": " + e.getMessage() : e.toString();
	}
}
