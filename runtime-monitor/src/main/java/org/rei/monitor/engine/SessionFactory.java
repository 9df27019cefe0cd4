/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.engine;

import java.nio.charset.StandardCharsets;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;
import java.util.concurrent.ConcurrentHashMap;
import java.util.stream.Collectors;

import org.kie.api.KieBase;
import org.kie.api.KieServices;
import org.kie.api.builder.Message;
import org.kie.api.builder.Results;
import org.kie.api.conf.EventProcessingOption;
import org.kie.api.io.Resource;
import org.kie.api.io.ResourceType;
import org.kie.api.runtime.KieSession;
import org.kie.api.runtime.KieSessionConfiguration;
import org.kie.api.runtime.conf.ClockTypeOption;
import org.kie.internal.utils.KieHelper;

/**
 * Builds the monitor's Drools session from .drl text: STREAM mode (events, temporal operators) with a pseudo clock
 * that the monitor drives with simulation time, never the wall clock. A build error in any file fails loudly with
 * the file and line.
 */
public final class SessionFactory {

	private SessionFactory() {
	}

	/**
	 * Rule bases of this JVM (a warm JVM serves many runs with the same rules), each built once: a caller that asks
	 * while the same rules are being built waits for that build instead of building them again beside it (a
	 * background service's first run arrives while the service builds the default rules; a campaign's first
	 * replays arrive together).
	 */
	private static final Map<List<DrlSources.Source>, CompletableFuture<KieBase>> BUILT = new ConcurrentHashMap<>();
	/** More distinct rule sets than this in one JVM: start over rather than grow without bound. */
	private static final int MAX_BUILT = 16;

	/**
	 * A new session of the rule base of {@code sources}: built once per distinct set of sources in this JVM, a
	 * session per call (rule bases are shared safely between sessions and threads).
	 */
	public static KieSession build(List<DrlSources.Source> sources) {
		KieSessionConfiguration conf = KieServices.Factory.get().newKieSessionConfiguration();
		conf.setOption(ClockTypeOption.PSEUDO);
		return base(sources).newKieSession(conf, null);
	}

	private static KieBase base(List<DrlSources.Source> sources) {
		List<DrlSources.Source> key = List.copyOf(sources);
		CompletableFuture<KieBase> building = BUILT.get(key);
		if (building == null) {
			if (BUILT.size() >= MAX_BUILT) {
				BUILT.clear(); // builds under way go on for those waiting on them
			}
			CompletableFuture<KieBase> mine = new CompletableFuture<>();
			building = BUILT.putIfAbsent(key, mine);
			if (building == null) {
				try {
					KieBase base = kieBase(sources);
					mine.complete(base);
					return base;
				} catch (Throwable e) { // whatever it is, those waiting must not wait for ever
					BUILT.remove(key, mine); // a failing build is not kept: the next caller tries again
					mine.completeExceptionally(e);
					throw e;
				}
			}
		}
		try {
			return building.join();
		} catch (CompletionException e) {
			if (e.getCause() instanceof RuntimeException cause) {
				throw cause; // the builder's own error (file and line), as if this caller had built
			}
			if (e.getCause() instanceof Error cause) {
				throw cause;
			}
			throw e;
		}
	}

	private static KieBase kieBase(List<DrlSources.Source> sources) {
		KieServices ks = KieServices.Factory.get();
		KieHelper helper = new KieHelper();
		Map<String, String> original = new HashMap<>(); // a message's path (no src/main/resources/) -> the file's
		for (DrlSources.Source s : sources) {
			Resource r = ks.getResources().newByteArrayResource(s.text().getBytes(StandardCharsets.UTF_8));
			String path = sourcePath(original.keySet(), s.path());
			original.put(path, s.path());
			r.setSourcePath("src/main/resources/" + path);
			helper.addResource(r, ResourceType.DRL);
		}
		Results results = helper.verify();
		if (results.hasMessages(Message.Level.ERROR)) {
			throw new IllegalArgumentException("rule files do not build:\n" + results.getMessages(Message.Level.ERROR)
					.stream().map(m -> "  " + original.getOrDefault(m.getPath(), m.getPath()) + ":" + m.getLine()
							+ ": " + m.getText().strip())
					.collect(Collectors.joining("\n")));
		}
		return helper.build(EventProcessingOption.STREAM);
	}

	// KieHelper files resources under src/main/resources; a folder named like the DRL package keeps Drools quiet, the
	// source folder and file name in the file name keep messages readable ("rei/queries_geometry.drl:12"). A number
	// keeps two files apart whose folder and name agree (a user's patterns/requirements.drl query file and the rules
	// compiled from patterns/requirements.vepl): one would silently replace the other. Messages name the original.
	private static String sourcePath(Set<String> taken, String path) {
		String[] parts = path.replace('\\', '/').split("/");
		String tail = parts.length > 1 ? parts[parts.length - 2] + "_" + parts[parts.length - 1] : parts[0];
		String candidate = "rei/" + tail;
		for (int n = 2; taken.contains(candidate); n++) {
			candidate = "rei/" + n + "_" + tail;
		}
		return candidate;
	}
}
