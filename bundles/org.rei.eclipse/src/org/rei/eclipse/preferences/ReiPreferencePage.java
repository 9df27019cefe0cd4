// SPDX-License-Identifier: EPL-2.0
package org.rei.eclipse.preferences;

import org.eclipse.jface.preference.BooleanFieldEditor;
import org.eclipse.jface.preference.FieldEditorPreferencePage;
import org.eclipse.jface.preference.FileFieldEditor;
import org.eclipse.jface.preference.StringFieldEditor;
import org.eclipse.ui.IWorkbench;
import org.eclipse.ui.IWorkbenchPreferencePage;
import org.eclipse.ui.preferences.ScopedPreferenceStore;
import org.eclipse.core.runtime.preferences.InstanceScope;
import org.rei.eclipse.ReiIds;

/** Window > Preferences > REI. */
public final class ReiPreferencePage extends FieldEditorPreferencePage implements IWorkbenchPreferencePage {
	public ReiPreferencePage() {
		super(GRID);
		setPreferenceStore(new ScopedPreferenceStore(InstanceScope.INSTANCE, ReiIds.PLUGIN));
		setDescription("REI test cases (.rei) and temporal patterns (.vepl).");
	}

	@Override
	protected void createFieldEditors() {
		addField(new StringFieldEditor(ReiIds.PREF_OUTPUT_FOLDER,
				"Generate artifacts into (relative to the test case's folder; ${name} is its name):",
				getFieldEditorParent()));
		addField(new BooleanFieldEditor(ReiIds.PREF_GENERATE_ON_SAVE, "Generate artifacts when a .rei file is saved",
				getFieldEditorParent()));
		addField(new FileFieldEditor(ReiIds.PREF_LAUNCHER, "REI launcher for Run test case (the rei script; empty: rei on the PATH):",
				true, getFieldEditorParent()));
		addField(new BooleanFieldEditor(ReiIds.PREF_OPEN_REPORT, "Open the report when Run test case ends",
				getFieldEditorParent()));
		addField(new FileFieldEditor(ReiIds.PREF_JAVA, "Java for the language server and generator (empty: the workbench's):",
				true, getFieldEditorParent()));
	}

	@Override
	public void init(IWorkbench workbench) {
	}
}
