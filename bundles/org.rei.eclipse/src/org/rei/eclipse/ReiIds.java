// SPDX-License-Identifier: EPL-2.0
package org.rei.eclipse;

/** The identifiers other bundles (and the UI test) refer to; plugin.xml declares the same ones. */
public final class ReiIds {
	public static final String PLUGIN = "org.rei.eclipse";
	/** Problem markers from REI's language server (a problem and text marker, not persisted). */
	public static final String PROBLEM_MARKER = PLUGIN + ".problem";
	public static final String GENERATE_COMMAND = PLUGIN + ".generate";
	public static final String RUN_COMMAND = PLUGIN + ".run";
	/** Job family of Generate artifacts and Run test case, to wait for or cancel them. */
	public static final String JOB_FAMILY = PLUGIN + ".jobs";

	public static final String PREF_OUTPUT_FOLDER = "outputFolder";
	public static final String PREF_GENERATE_ON_SAVE = "generateOnSave";
	public static final String PREF_LAUNCHER = "launcher";
	public static final String PREF_JAVA = "java";
	public static final String PREF_OPEN_REPORT = "openReport";

	private ReiIds() {
	}
}
