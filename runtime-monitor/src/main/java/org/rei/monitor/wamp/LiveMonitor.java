/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.wamp;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.EnumSet;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import java.util.function.Function;

import org.msgpack.jackson.dataformat.MessagePackFactory;
import org.rei.monitor.config.CaseReader;
import org.rei.monitor.pipeline.Monitor;
import org.rei.monitor.signals.Signal;
import org.rei.wamp.auth.RouterCredentials;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;

import ws.wamp.jawampa.ApplicationError;
import ws.wamp.jawampa.PubSubData;
import ws.wamp.jawampa.PublishFlags;
import ws.wamp.jawampa.WampClient;
import ws.wamp.jawampa.WampClientBuilder;
import ws.wamp.jawampa.WampSerialization;
import ws.wamp.jawampa.transport.netty.NettyWampClientConnectorProvider;
import ws.wamp.jawampa.transport.netty.NettyWampConnectionConfig;

/**
 * Live mode: joins realm {@code rei} over WebSocket with msgpack (jawampa on netty; netty enables TCP_NODELAY on
 * its sockets by default), reads the configuration (from {@code --case} or the {@code config} RPC), subscribes to
 * the state and mission topics, publishes signals and serves the {@code snapshot} RPC. Events are re-encoded to
 * the payload's msgpack bytes and handed to one pipeline thread, so live and replay run the same code.
 * <p>
 * A restarted router is survived: jawampa reconnects (every 200 ms, forever) but forgets the session's
 * subscriptions and registrations, so every new session gets them again; signals go through a {@link SignalOutbox}
 * (acknowledged publications, sent again after a reconnection). Messages lost meanwhile show up as
 * {@code SIG_MONITOR_DATA_GAP} at the first message after the reconnection (their seq jumps).
 */
public final class LiveMonitor implements AutoCloseable {

	private static final ObjectMapper MSGPACK = new ObjectMapper(new MessagePackFactory());
	private static final ObjectMapper JSON = new ObjectMapper();
	/**
	 * Between two connection attempts to a router that went away. Short: a simulation that reconnects first publishes
	 * its queued messages at once, and the router drops those no subscriber waits for (measured: a 1 s interval lost
	 * ~6 s of simulated state after a restart, paced to real time).
	 */
	private static final int RECONNECT_MILLIS = 200;
	/**
	 * Largest message read (bytes; contract/vocabulary.json's max_message_size, the router's limit too). netty's
	 * default of 64 KB is less than the config RPC's world.json of a room from an occupancy map (the depot's: 404 KB);
	 * the router's limit is larger than 1 MiB for the snapshot this monitor answers (the XMI of a large map room).
	 */
	public static final int MAX_MESSAGE_SIZE = 1 << 24;
	/** Bounds of close(): the router may be gone for good. */
	private static final long CLOSE_OUTBOX_MILLIS = 5_000;
	private static final long CLOSE_SESSION_SECONDS = 10;

	private final WampClient client;
	private final ExecutorService pipeline = Executors.newSingleThreadExecutor(r -> {
		Thread t = new Thread(r, "rei-monitor-pipeline");
		t.setDaemon(true);
		return t;
	});
	private final CountDownLatch ended = new CountDownLatch(1);
	private final Consumer<String> log;
	private volatile Monitor monitor;
	private OutputStream stateRecording;
	private OutputStream missionRecording;

	// the session bookkeeping below is shared by start() and jawampa's thread (status changes) under this lock
	private final Object sessionLock = new Object();
	private Routes routes;
	private boolean connected;
	private boolean closing;
	private int connections;
	/** The connection whose subscriptions were made last: events of older ones' subscribers are ignored. */
	private volatile int routedConnection;

	/** What every session needs: known once start() has read the case. */
	private record Routes(String stateTopic, String missionTopic, String snapshotUri, SignalOutbox outbox) {
	}

	public LiveMonitor(String router, String realm, Consumer<String> log) throws Exception {
		this(router, realm, null, log);
	}

	/** @param credentials the monitor role's credentials (WAMP-CRA or ticket), or null to join anonymously */
	public LiveMonitor(String router, String realm, RouterCredentials credentials, Consumer<String> log)
			throws Exception {
		this.log = log;
		WampClientBuilder builder = new WampClientBuilder()
				.withConnectorProvider(new NettyWampClientConnectorProvider()).withUri(router).withRealm(realm)
				.withConnectionConfiguration(
						new NettyWampConnectionConfig.Builder().withMaxFramePayloadLength(MAX_MESSAGE_SIZE).build())
				.withSerializations(new WampSerialization[] { WampSerialization.MessagePack })
				.withInfiniteReconnects().withReconnectInterval(RECONNECT_MILLIS, TimeUnit.MILLISECONDS);
		if (credentials != null) {
			builder.withAuthId(credentials.authid()).withAuthMethod(credentials.authentication());
		}
		client = builder.build();
	}

	/**
	 * Connects and starts monitoring run {@code runId}.
	 *
	 * @param caseFromConfig   builds the case from the config RPC's result when no case folder was given
	 * @param monitorFactory   builds the monitor once the case is known
	 * @param recordDir        where received streams are recorded (for replay comparisons), or null
	 * @param timeoutMillis    how long joining the realm and (without a case) waiting for the run's config RPC
	 *                         may take
	 */
	public void start(String runId, CaseReader.Case givenCase, Function<CaseReader.Case, Monitor> monitorFactory,
			Path recordDir, Consumer<Signal> onSignal, long timeoutMillis) throws Exception {
		CountDownLatch joined = new CountDownLatch(1);
		client.statusChanged().subscribe(s -> {
			if (s instanceof WampClient.ConnectedState) {
				onConnected();
				joined.countDown();
			} else if (s instanceof WampClient.DisconnectedState d) {
				onDisconnected(d);
			}
		}, e -> log.accept("WAMP status error: " + e));
		client.open();
		if (!joined.await(timeoutMillis, TimeUnit.MILLISECONDS)) {
			throw new IOException("could not join the realm within " + timeoutMillis + " ms");
		}
		CaseReader.Case c = givenCase;
		String configUri = "rei.run." + runId + ".config";
		if (c == null) {
			JsonNode result = config(configUri, System.nanoTime() + timeoutMillis * 1_000_000);
			c = new CaseReader.Case(CaseReader.world(result.get("world")), CaseReader.monitor(result.get("monitor")));
		}
		Monitor m = monitorFactory.apply(c);
		monitor = m;
		String stateTopic = c.monitor().topic("state", runId);
		String missionTopic = c.monitor().topic("mission", runId);
		String signalTopic = c.monitor().topic("signal", runId);
		String snapshotUri = c.monitor().topic("snapshot", runId);
		if (recordDir != null) {
			Files.createDirectories(recordDir);
			stateRecording = Files.newOutputStream(recordDir.resolve("state.msgpack"));
			missionRecording = Files.newOutputStream(recordDir.resolve("mission.msgpack"));
		}
		SignalOutbox outbox = new SignalOutbox((s, done) -> publish(signalTopic, s, done));
		m.signals().addListener(s -> {
			outbox.offer(s);
			onSignal.accept(s);
		});
		synchronized (sessionLock) {
			routes = new Routes(stateTopic, missionTopic, snapshotUri, outbox);
			route();
		}
		log.accept("monitoring " + stateTopic + " and " + missionTopic + ", signals on " + signalTopic);
	}

	private void onConnected() {
		synchronized (sessionLock) {
			connected = true;
			connections++;
			route();
		}
	}

	private void onDisconnected(WampClient.DisconnectedState d) {
		synchronized (sessionLock) {
			if (!connected) {
				return; // the initial state, or a failed attempt
			}
			connected = false;
			if (routes != null) {
				routes.outbox().disconnected();
			}
			if (closing) {
				return;
			}
		}
		Throwable why = d.disconnectReason();
		log.accept("router connection lost: " + (why != null ? why : "closed") + " - reconnecting");
	}

	/**
	 * Subscribes, registers the snapshot RPC and flushes the outbox for the current connection, once per
	 * connection (start() and jawampa's thread may both get here). Holds {@link #sessionLock}.
	 */
	private void route() {
		Routes r = routes;
		if (r == null || !connected || routedConnection == connections) {
			return;
		}
		int connection = connections;
		routedConnection = connection;
		// a subscriber of an older connection can only receive this session's events if its subscription was
		// requested while this session was being set up: then both get them, and only the newest may take them
		client.makeSubscription(r.stateTopic()).subscribe(ev -> {
			if (routedConnection == connection) {
				accept(ev, true);
			}
		}, e -> log.accept("state subscription failed: " + e));
		client.makeSubscription(r.missionTopic()).subscribe(ev -> {
			if (routedConnection == connection) {
				accept(ev, false);
			}
		}, e -> log.accept("mission subscription failed: " + e));
		// registered after the subscriptions: WAMP messages of one session are handled in order, so a client whose
		// snapshot call succeeds knows the monitor's subscriptions are in place (tests start the run after that)
		client.registerProcedure(r.snapshotUri()).subscribe(request -> pipeline.execute(() -> {
			try {
				request.reply(monitor.snapshot());
			} catch (RuntimeException e) {
				try {
					request.replyError("rei.error.snapshot", e.toString());
				} catch (ApplicationError ignored) {
					// replyError rethrows the error it sent; nothing more to do
				}
			}
		}), e -> log.accept("snapshot registration failed: " + e));
		int again = r.outbox().connected();
		if (connection > 1) {
			log.accept("reconnected to the router (" + (connection - 1) + "): subscriptions restored"
					+ (again > 0 ? ", " + again + " unacknowledged signal(s) published again" : ""));
		}
	}

	/** Publishes one signal with an acknowledgement: without one a signal written into a dying connection is lost. */
	private void publish(String topic, Signal s, Consumer<SignalOutbox.Outcome> done) {
		ArrayNode arguments = JSON.createArrayNode().add(JSON.valueToTree(s.payload()));
		client.publish(topic, EnumSet.of(PublishFlags.RequireAcknowledge), arguments, null)
				.subscribe(id -> done.accept(SignalOutbox.Outcome.ACKNOWLEDGED), e -> {
					if (isConnectionLoss(e)) {
						done.accept(SignalOutbox.Outcome.LOST);
					} else {
						log.accept("the router refused signal " + s.seq() + ": " + e);
						done.accept(SignalOutbox.Outcome.REFUSED);
					}
				});
	}

	/** jawampa's errors for a request that met no session (as opposed to the router's answer). */
	private static boolean isConnectionLoss(Throwable e) {
		if (!(e instanceof ApplicationError a)) {
			return true;
		}
		return ApplicationError.TRANSPORT_CLOSED.equals(a.uri()) || ApplicationError.NOT_CONNECTED.equals(a.uri())
				|| ApplicationError.CLIENT_CLOSED.equals(a.uri());
	}

	/** How often the connection to the router was restored after a loss. */
	public int reconnections() {
		synchronized (sessionLock) {
			return Math.max(0, connections - 1);
		}
	}

	/**
	 * The run's configuration from its collector; a monitor started before the run waits for the collector to
	 * register the RPC (until the deadline, in {@link System#nanoTime()}).
	 */
	private JsonNode config(String uri, long deadline) throws Exception {
		boolean logged = false;
		while (true) {
			try {
				return client.call(uri, new Object[0]).toBlocking().single().arguments().get(0);
			} catch (RuntimeException e) {
				// toBlocking() wraps the checked ApplicationError in a RuntimeException
				// absent: the collector has not registered it yet; a connection loss: jawampa is reconnecting
				boolean retry = e.getCause() instanceof ApplicationError a
						&& (ApplicationError.NO_SUCH_PROCEDURE.equals(a.uri()) || isConnectionLoss(a));
				if (!retry || System.nanoTime() - deadline > 0) {
					throw e;
				}
				if (!logged) {
					log.accept("waiting for the run's configuration (" + uri + ")");
					logged = true;
				}
				Thread.sleep(100);
			}
		}
	}

	private void accept(PubSubData event, boolean state) {
		byte[] bytes;
		try {
			bytes = event.arguments() == null || event.arguments().size() == 0 ? new byte[] { (byte) 0xc0 }
					: MSGPACK.writeValueAsBytes(event.arguments().get(0));
		} catch (IOException e) {
			bytes = new byte[] { (byte) 0xc0 };
		}
		byte[] data = bytes;
		pipeline.execute(() -> {
			try {
				if (state) {
					record(stateRecording, data);
					monitor.onStateBytes(data, 0, data.length);
				} else {
					record(missionRecording, data);
					long before = monitor.missionsProcessed();
					monitor.onMissionBytes(data, 0, data.length);
					if (monitor.missionsProcessed() > before && monitor.model().model().getOwnedMissionState().isEnded()) {
						ended.countDown();
					}
				}
			} catch (RuntimeException e) {
				monitor.guard().problem("failed-message", e.toString());
			}
		});
	}

	private static void record(OutputStream out, byte[] data) {
		if (out != null) {
			try {
				out.write(data);
				out.flush();
			} catch (IOException e) {
				// a recording is a debugging aid: losing it must not stop monitoring
			}
		}
	}

	/** Waits for the mission's END event (or the timeout); true if it came. */
	public boolean awaitEnd(long millis) throws InterruptedException {
		return ended.await(millis, TimeUnit.MILLISECONDS);
	}

	/** Runs {@code task} on the pipeline thread and waits for it (e.g. the snapshot on exit). */
	public void onPipeline(Runnable task) throws Exception {
		pipeline.submit(task).get();
	}

	public Monitor monitor() {
		return monitor;
	}

	@Override
	public void close() throws Exception {
		try {
			pipeline.submit(() -> {
			}).get(10, TimeUnit.SECONDS); // drain what arrived
		} finally {
			pipeline.shutdown();
			Routes r;
			synchronized (sessionLock) {
				r = routes;
			}
			try { // the last acknowledgements; bounded: the router may be gone for good
				if (r != null && !r.outbox().awaitEmpty(CLOSE_OUTBOX_MILLIS)) {
					log.accept(r.outbox().pending() + " signal(s) not acknowledged by the router when closing");
				}
			} catch (InterruptedException e) {
				Thread.currentThread().interrupt();
			}
			synchronized (sessionLock) {
				closing = true;
			}
			try {
				client.close().timeout(CLOSE_SESSION_SECONDS, TimeUnit.SECONDS).toBlocking().lastOrDefault(null);
			} catch (RuntimeException e) {
				log.accept("leaving the router: " + e);
			}
			for (OutputStream out : new OutputStream[] { stateRecording, missionRecording }) {
				if (out != null) {
					out.close();
				}
			}
		}
	}
}
