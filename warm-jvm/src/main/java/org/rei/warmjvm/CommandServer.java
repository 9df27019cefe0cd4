/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.warmjvm;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.PrintStream;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.net.StandardProtocolFamily;
import java.net.UnixDomainSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.Channels;
import java.nio.channels.ClosedChannelException;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermission;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * Serves one jar's command line to many requests in one JVM: {@code java -jar X.jar --serve SOCKET}.
 *
 * <p>
 * Why: a campaign runs a monitor replay and a case generation per run, and every short-lived JVM spends most of its
 * CPU on starting, loading classes and compiling rules whose work is thrown away (docs/performance.md). A warm JVM
 * keeps classes, JIT code and compiled rule bases between commands.
 *
 * <p>
 * Protocol, one request per connection on the Unix socket (UTF-8 lines; values hold no line break):
 *
 * <pre>
 * client: arg VALUE          (once per argument, in order)
 *         log PATH           (optional: the command's standard output and error go there, truncated first)
 *         run
 * server: exit CODE CPU_MS WALL_MS
 * </pre>
 *
 * A client that closes its connection before the answer cancels the command (its thread is interrupted). Commands run
 * concurrently, one thread each. The socket's folder must be private to the user (0700): whoever can connect can run
 * the jar's commands. The server prints {@code ready} on its standard output once it listens, and exits when its
 * standard input ends, so it never outlives the process that started it.
 */
public final class CommandServer {

	/** A jar's command line: what {@code main} does, without {@code System.exit}. */
	@FunctionalInterface
	public interface Command {
		int run(String[] args, PrintStream out, PrintStream err) throws Exception;
	}

	/** The protocol's words (contract/vocabulary.json, "warm_jvm"): request lines, then the answer's. */
	public static final List<String> REQUEST = List.of("arg", "log", "run");
	public static final String ANSWER = "exit";

	/** How long the commands still running when the owner lets go may take to finish (a run's live monitor). */
	static final long DRAIN_MILLIS = 30 * 60 * 1000L;

	private static final ThreadMXBean THREADS = ManagementFactory.getThreadMXBean();

	private final Command command;
	private final Path socket;
	private final AtomicInteger running = new AtomicInteger();

	public CommandServer(Command command, Path socket) {
		this.command = command;
		this.socket = socket;
	}

	/**
	 * {@code --serve SOCKET} in a jar's main: serve until standard input ends, then exit the JVM. Returns 2 (the
	 * usage exit code) with a message when the socket cannot be served.
	 */
	public static int serveUntilStdinCloses(Command command, String socket, PrintStream err) {
		CommandServer server = new CommandServer(command, Path.of(socket));
		ServerSocketChannel channel;
		try {
			channel = server.listen();
		} catch (IOException | IllegalArgumentException e) {
			err.println("--serve " + socket + ": " + e.getMessage());
			return 2;
		}
		Thread acceptor = new Thread(() -> server.accept(channel), "warm-jvm-accept");
		acceptor.setDaemon(true);
		acceptor.start();
		System.out.println("ready");
		System.out.flush();
		drain(System.in);
		try { // no new commands; the running ones (a run's live monitor) may finish
			channel.close();
			Files.deleteIfExists(server.socket);
		} catch (IOException e) {
			// exiting anyway
		}
		server.awaitIdle(DRAIN_MILLIS);
		return 0;
	}

	/** Binds the socket; refuses a folder other users can enter. */
	public ServerSocketChannel listen() throws IOException {
		Path folder = socket.toAbsolutePath().getParent();
		Set<PosixFilePermission> open = EnumSet.of(PosixFilePermission.GROUP_EXECUTE, PosixFilePermission.GROUP_READ,
				PosixFilePermission.GROUP_WRITE, PosixFilePermission.OTHERS_EXECUTE, PosixFilePermission.OTHERS_READ,
				PosixFilePermission.OTHERS_WRITE);
		Set<PosixFilePermission> mode = Files.getPosixFilePermissions(folder);
		mode.retainAll(open);
		if (!mode.isEmpty()) {
			throw new IllegalArgumentException("the socket's folder " + folder
					+ " is open to other users; it must be private (mode 700)");
		}
		Files.deleteIfExists(socket); // a socket file left by a server that was killed
		ServerSocketChannel channel = ServerSocketChannel.open(StandardProtocolFamily.UNIX);
		channel.bind(UnixDomainSocketAddress.of(socket));
		return channel;
	}

	/** Accepts connections until the channel is closed, each on its own thread. */
	public void accept(ServerSocketChannel channel) {
		while (channel.isOpen()) {
			try {
				SocketChannel client = channel.accept();
				Thread handler = new Thread(() -> handle(client), "warm-jvm-request");
				handler.setDaemon(true);
				handler.start();
			} catch (ClosedChannelException e) {
				return;
			} catch (IOException e) {
				// one failed accept does not end the server
			}
		}
	}

	/** Waits until no command runs, at most {@code millis}. */
	void awaitIdle(long millis) {
		long deadline = System.currentTimeMillis() + millis;
		while (running.get() > 0 && System.currentTimeMillis() < deadline) {
			try {
				Thread.sleep(50);
			} catch (InterruptedException e) {
				Thread.currentThread().interrupt();
				return;
			}
		}
	}

	/** Commands running now (for tests and the server's own account). */
	public int running() {
		return running.get();
	}

	private void handle(SocketChannel client) {
		try (client) {
			Request request = Request.read(Channels.newInputStream(client));
			if (request == null) {
				return;
			}
			OutputStream answer = Channels.newOutputStream(client);
			Thread worker = new Thread(() -> {
				try {
					answer.write(execute(request).getBytes(StandardCharsets.UTF_8));
					answer.flush();
				} catch (IOException e) {
					// the client is gone: nobody to tell
				} finally {
					try {
						client.close(); // ends the watch below; a client without an answer falls back
					} catch (IOException e) {
						// closed already
					}
				}
			}, "warm-jvm-command");
			worker.setDaemon(true);
			worker.start();
			watch(client, worker);
		} catch (IOException e) {
			// a client that went away mid-request
		}
	}

	/** Blocks until the connection closes: by the worker after its answer, or by the client - then cancel. */
	private static void watch(SocketChannel client, Thread worker) {
		ByteBuffer one = ByteBuffer.allocate(1);
		try {
			while (client.read(one) >= 0) {
				one.clear(); // nothing is expected while a command runs; extra bytes are ignored
			}
		} catch (IOException e) {
			return; // closed by the worker (asynchronous close): the command finished
		}
		worker.interrupt(); // end of stream: the client gave up waiting
	}

	private String execute(Request request) {
		running.incrementAndGet();
		long wall = System.nanoTime();
		long cpu = THREADS.getCurrentThreadCpuTime();
		int code;
		try (PrintStream out = request.log()) {
			try {
				code = command.run(request.args().toArray(String[]::new), out, out);
			} catch (Throwable e) { // one bad command (even out of memory) must not end the server unanswered
				e.printStackTrace(out);
				code = 1;
			}
		} catch (IOException e) {
			code = 2;
		} finally {
			running.decrementAndGet();
		}
		long cpuMs = (THREADS.getCurrentThreadCpuTime() - cpu) / 1_000_000;
		long wallMs = (System.nanoTime() - wall) / 1_000_000;
		return ANSWER + " " + code + " " + cpuMs + " " + wallMs + "\n";
	}

	private static void drain(InputStream in) {
		byte[] buffer = new byte[256];
		try {
			while (in.read(buffer) >= 0) {
				// the owner keeps standard input open while it wants the server
			}
		} catch (IOException e) {
			// treated as the end
		}
	}

	/** One request: the command's arguments and where its output goes. */
	record Request(List<String> args, Path logFile) {

		static Request read(InputStream in) throws IOException {
			BufferedReader reader = new BufferedReader(new java.io.InputStreamReader(in, StandardCharsets.UTF_8));
			List<String> args = new ArrayList<>();
			Path log = null;
			for (String line; (line = reader.readLine()) != null;) {
				if (line.equals(REQUEST.get(2))) {
					return new Request(List.copyOf(args), log);
				} else if (line.startsWith(REQUEST.get(0) + " ")) {
					args.add(line.substring(REQUEST.get(0).length() + 1));
				} else if (line.startsWith(REQUEST.get(1) + " ")) {
					log = Path.of(line.substring(REQUEST.get(1).length() + 1));
				} else {
					return null; // not this protocol: drop the connection
				}
			}
			return null;
		}

		PrintStream log() throws IOException {
			OutputStream sink = logFile != null ? Files.newOutputStream(logFile) : OutputStream.nullOutputStream();
			return new PrintStream(sink, true, StandardCharsets.UTF_8);
		}
	}
}
