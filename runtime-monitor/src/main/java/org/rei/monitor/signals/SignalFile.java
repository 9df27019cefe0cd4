/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.signals;

import java.io.BufferedWriter;
import java.io.Closeable;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.Consumer;

import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * {@code --signals-out FILE}: every signal as one JSON line {@code {seq, t, signal, subject, object, distance}},
 * the payload of the signal topic with numbers that read back to the same doubles (so a replay can be compared
 * with a live run exactly). Each line is flushed as it is written.
 */
public final class SignalFile implements Consumer<Signal>, Closeable {

	private static final ObjectMapper JSON = new ObjectMapper();

	private final BufferedWriter out;

	public SignalFile(Path file) throws IOException {
		out = Files.newBufferedWriter(file, StandardCharsets.UTF_8);
	}

	@Override
	public synchronized void accept(Signal s) {
		try {
			out.write(JSON.writeValueAsString(s.payload()));
			out.newLine();
			out.flush();
		} catch (IOException e) {
			throw new UncheckedIOException(e);
		}
	}

	@Override
	public synchronized void close() throws IOException {
		out.close();
	}
}
