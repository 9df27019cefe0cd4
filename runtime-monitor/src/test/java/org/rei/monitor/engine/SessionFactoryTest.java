/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;

import org.junit.jupiter.api.Test;
import org.kie.api.KieBase;
import org.kie.api.runtime.KieSession;

/** Rule bases are built once per JVM, also when several callers ask for the same rules at the same time. */
class SessionFactoryTest {

	/** Rules no other test builds (a text of their own), so the first caller really builds them. */
	private static List<DrlSources.Source> freshRules(String body) {
		return List.of(new DrlSources.Source("test/fresh.drl", "package rei;\n// " + UUID.randomUUID() + "\n" + body));
	}

	private static final String RULE = "rule \"nothing\"\nwhen\n  String(this == \"never\")\nthen\nend\n";

	@Test
	void callersAtTheSameTimeShareOneBuild() throws Exception {
		List<DrlSources.Source> rules = freshRules(RULE);
		List<KieBase> bases = together(4, () -> {
			KieSession session = SessionFactory.build(rules);
			KieBase base = session.getKieBase();
			session.dispose();
			return base;
		});
		for (KieBase base : bases) {
			assertSame(bases.get(0), base, "a second build of the same rules beside the first");
		}
		KieSession later = SessionFactory.build(rules);
		assertSame(bases.get(0), later.getKieBase());
		later.dispose();
	}

	@Test
	void aFailingBuildFailsEveryCallerWithItsMessageAndIsNotKept() throws Exception {
		List<DrlSources.Source> broken = freshRules("rule \"broken\"\nwhen\n  Nonsense(\nthen\nend\n");
		List<String> messages = together(3, () -> {
			try {
				SessionFactory.build(broken);
				return "built";
			} catch (IllegalArgumentException e) {
				return e.getMessage();
			}
		});
		for (String message : messages) {
			assertTrue(message.startsWith("rule files do not build:\n  test/fresh.drl:"), message);
		}
		IllegalArgumentException again = assertThrows(IllegalArgumentException.class,
				() -> SessionFactory.build(broken));
		assertEquals(messages.get(0), again.getMessage());
	}

	/** {@code n} threads released together, each running {@code task}; their results. */
	private static <T> List<T> together(int n, Callable<T> task) throws InterruptedException, ExecutionException {
		ExecutorService pool = Executors.newFixedThreadPool(n);
		try {
			CountDownLatch start = new CountDownLatch(1);
			List<Future<T>> futures = new ArrayList<>();
			for (int i = 0; i < n; i++) {
				futures.add(pool.submit(() -> {
					start.await();
					return task.call();
				}));
			}
			start.countDown();
			List<T> results = new ArrayList<>();
			for (Future<T> future : futures) {
				results.add(future.get());
			}
			return results;
		} finally {
			pool.shutdownNow();
		}
	}
}
