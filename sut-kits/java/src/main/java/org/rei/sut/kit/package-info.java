/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
/**
 * REI's Java client kit for external systems under test (docs/sut.md): implement
 * {@link org.rei.sut.kit.SystemUnderTest}, answer every {@link org.rei.sut.kit.Tick} with a
 * {@link org.rei.sut.kit.Command}, report the goal's state on its {@link org.rei.sut.kit.Goal}, and start it with
 * {@link org.rei.sut.kit.SutClient#runAndExit}:
 *
 * <pre>
 * public class Forward implements SystemUnderTest {
 *     public Command onTick(Tick tick) {
 *         return new Command(0.1, 0);
 *     }
 *
 *     public static void main(String[] args) {
 *         SutClient.runAndExit(new Forward());
 *     }
 * }
 * </pre>
 *
 * The kit hides WAMP (jawampa, msgpack, WAMP-CRA), the joining order and the lockstep rules. The example
 * {@code examples/sut/java/GoToGoalSut.java} drives the simple navigation case.
 */
package org.rei.sut.kit;
