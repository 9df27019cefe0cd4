/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.warmjvm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.StandardProtocolFamily;
import java.net.UnixDomainSocketAddress;
import java.nio.channels.Channels;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class CommandServerTest {

	@TempDir
	Path dir;

	private final CountDownLatch cancelled = new CountDownLatch(1);
	private ServerSocketChannel channel;
	private CommandServer server;
	private Path socket;

	/** echo ARGS... prints them and exits with their count; "wait" blocks until interrupted; "boom" throws. */
	private int command(String[] args, java.io.PrintStream out, java.io.PrintStream err) throws Exception {
		if (args.length > 0 && args[0].equals("wait")) {
			try {
				Thread.sleep(60_000);
			} catch (InterruptedException e) {
				cancelled.countDown();
				throw e;
			}
		}
		if (args.length > 0 && args[0].equals("boom")) {
			throw new IllegalStateException("boom");
		}
		out.println(String.join("|", args));
		return args.length;
	}

	@BeforeEach
	void start() throws IOException {
		Files.setPosixFilePermissions(dir, PosixFilePermissions.fromString("rwx------"));
		socket = dir.resolve("s.sock");
		server = new CommandServer(this::command, socket);
		channel = server.listen();
		Thread t = new Thread(() -> server.accept(channel));
		t.setDaemon(true);
		t.start();
	}

	@AfterEach
	void stop() throws IOException {
		channel.close();
	}

	private String[] request(String... lines) throws IOException {
		try (SocketChannel c = SocketChannel.open(StandardProtocolFamily.UNIX)) {
			c.connect(UnixDomainSocketAddress.of(socket));
			Channels.newOutputStream(c).write((String.join("\n", lines) + "\n").getBytes(StandardCharsets.UTF_8));
			String answer = new BufferedReader(new InputStreamReader(Channels.newInputStream(c), StandardCharsets.UTF_8))
					.readLine();
			return answer.split(" ");
		}
	}

	@Test
	void runsTheCommandWithItsArgumentsAndItsOutputInTheLog() throws IOException {
		Path log = dir.resolve("out.log");
		String[] answer = request("arg a b", "arg ", "arg c", "log " + log, "run");
		assertEquals("exit", answer[0]);
		assertEquals("3", answer[1]);
		assertEquals("a b||c", Files.readString(log).strip());
		assertEquals(4, answer.length, "exit CODE CPU_MS WALL_MS");
	}

	@Test
	void aCommandThatThrowsExitsOneAndTheServerGoesOn() throws IOException {
		Path log = dir.resolve("boom.log");
		assertEquals("1", request("arg boom", "log " + log, "run")[1]);
		assertTrue(Files.readString(log).contains("IllegalStateException: boom"));
		assertEquals("0", request("run")[1]);
	}

	@Test
	void aClientThatHangsUpCancelsItsCommand() throws Exception {
		try (SocketChannel c = SocketChannel.open(StandardProtocolFamily.UNIX)) {
			c.connect(UnixDomainSocketAddress.of(socket));
			Channels.newOutputStream(c).write("arg wait\nrun\n".getBytes(StandardCharsets.UTF_8));
			long deadline = System.nanoTime() + 5_000_000_000L;
			while (server.running() == 0 && System.nanoTime() < deadline) {
				Thread.sleep(10);
			}
			assertEquals(1, server.running());
		}
		assertTrue(cancelled.await(5, TimeUnit.SECONDS), "the command's thread is interrupted");
	}

	@Test
	void commandsRunConcurrently() throws Exception {
		Thread waiting = new Thread(() -> {
			try {
				request("arg wait", "run");
			} catch (IOException e) {
				// cancelled below
			}
		});
		waiting.start();
		long deadline = System.nanoTime() + 5_000_000_000L;
		while (server.running() == 0 && System.nanoTime() < deadline) {
			Thread.sleep(10);
		}
		assertEquals("2", request("arg x", "arg y", "run")[1], "answered while another command waits");
		waiting.interrupt();
	}

	@Test
	void refusesAFolderOtherUsersCanEnter() throws IOException {
		Path open = Files.createDirectory(dir.resolve("open"));
		Files.setPosixFilePermissions(open, PosixFilePermissions.fromString("rwxr-xr-x"));
		IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
				() -> new CommandServer(this::command, open.resolve("s.sock")).listen());
		assertTrue(e.getMessage().contains("mode 700"), e.getMessage());
	}
}
